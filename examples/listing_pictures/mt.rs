//! Seed 003, *Mountain Terrain 3.0*, drawn as its help file's "Technical
//! Information" describes: a parallelogram holding the zero level fitted
//! to the window, stripes from the back, two triangles a cell, corners
//! below the water set to zero, a triangle all at zero pure blue (darker
//! by the average depth under Relative Depth), else one of nine facings'
//! darkness ANDed with the colour preference, and a solid rectangle below
//! the right and the front edges down to sea level.
//!
//! What the help does not give, chosen here: the parallelogram's shape
//! (the back edge at 40% of the height, the front at 92%, each row half a
//! cell to the left of the one behind it, as seed 000's), the diagonal
//! (back left to front right), the height scale (a height unit as wide as
//! the grid's unit), the facings' darkness (light from the upper left:
//! 0xFF to 0x50) and the rectangles' darkness (0x90 right, 0x70 front).

use crate::canvas::Canvas;
use mountains::terrain::Heightfield;

/// Pure blue, and the most Relative Depth takes away from it.
const BLUE: u32 = 0x0000_00ff;
const DEEPEST: f64 = 191.0;

/// The parallelogram on screen: `(x, y, h)` of the grid to pixels.
struct Frame {
    origin: [f64; 2],
    col: f64,
    row: [f64; 2],
    up: f64,
}

impl Frame {
    fn place(&self, x: f64, y: f64, h: f64) -> [f64; 2] {
        [
            self.origin[0] + x * self.col + y * self.row[0],
            self.origin[1] + y * self.row[1] - h * self.up,
        ]
    }
}

/// Draws `field` (the sea at 0) with colour preference `preference`
/// (Gray 0xFFFFFF) into `canvas`, black behind.
pub fn draw(field: &Heightfield, preference: u32, relative_depth: bool, canvas: &mut Canvas) {
    let n = field.size() - 1;
    let (w, h) = (canvas.width as f64, canvas.height as f64);
    let (back, front) = (0.40 * h, 0.92 * h);
    let shift = 0.5; // each row half a cell to the left
    let col = w / (n as f64 * (1.0 + shift));
    let frame = Frame {
        origin: [n as f64 * shift * col, back],
        col,
        row: [-shift * col, (front - back) / n as f64],
        up: col * n as f64 / f64::from(field.extent()),
    };
    let height = |x: usize, y: usize| f64::from(field.get(x, y));
    for y in 0..n {
        for x in 0..n {
            let cells = [
                [(x, y), (x + 1, y + 1), (x + 1, y)],
                [(x, y), (x, y + 1), (x + 1, y + 1)],
            ];
            for c in cells {
                let depth = c
                    .iter()
                    .map(|&(x, y)| (-height(x, y)).max(0.0))
                    .sum::<f64>()
                    / 3.0;
                let z = c.map(|(x, y)| height(x, y).max(0.0));
                let p = [0, 1, 2].map(|k| frame.place(c[k].0 as f64, c[k].1 as f64, z[k]));
                let colour = if z.iter().all(|&z| z == 0.0) {
                    let darker = if relative_depth {
                        depth.min(DEEPEST) as u32
                    } else {
                        0
                    };
                    BLUE - darker
                } else {
                    let g = c.map(|(x, y)| [x as f64 * frame.col, y as f64 * frame.col]);
                    preference & facing(g, z, frame.up)
                };
                canvas.triangle(p, colour);
            }
            if x == n - 1 {
                slice(
                    canvas,
                    &frame,
                    [(n, y), (n, y + 1)],
                    &height,
                    preference & grey(0x90),
                );
            }
        }
        if y == n - 1 {
            for x in 0..n {
                slice(
                    canvas,
                    &frame,
                    [(x, n), (x + 1, n)],
                    &height,
                    preference & grey(0x70),
                );
            }
        }
    }
}

/// A grey of level `d` in every channel.
fn grey(d: u32) -> u32 {
    d * 0x0001_0101
}

/// The solid rectangle below an edge of the map, down to sea level.
fn slice(
    canvas: &mut Canvas,
    frame: &Frame,
    e: [(usize, usize); 2],
    height: &impl Fn(usize, usize) -> f64,
    colour: u32,
) {
    let z = e.map(|(x, y)| height(x, y).max(0.0));
    if z.iter().all(|&z| z == 0.0) {
        return;
    }
    let top = [0, 1].map(|k| frame.place(e[k].0 as f64, e[k].1 as f64, z[k]));
    let foot = [0, 1].map(|k| frame.place(e[k].0 as f64, e[k].1 as f64, 0.0));
    canvas.triangle([top[0], top[1], foot[1]], colour);
    canvas.triangle([top[0], foot[1], foot[0]], colour);
}

/// The darkness of the facing of a triangle with ground corners `g`
/// (pixels of the grid, y towards the front) and heights `z` (scaled by
/// `up`): flat, or sloping down towards one of eight directions, lit from
/// the upper left.
fn facing(g: [[f64; 2]; 3], z: [f64; 3], up: f64) -> u32 {
    let a = [g[1][0] - g[0][0], g[1][1] - g[0][1], (z[1] - z[0]) * up];
    let b = [g[2][0] - g[0][0], g[2][1] - g[0][1], (z[2] - z[0]) * up];
    let mut n = [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ];
    if n[2] < 0.0 {
        n = n.map(|c| -c);
    }
    let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
    if n[2] / len > 0.97 {
        return grey(0xC0); // flat
    }
    // Eight directions, 0 = facing left (towards -x), going round by the back.
    let angle = (-n[1]).atan2(-n[0]);
    let sector = ((angle / std::f64::consts::FRAC_PI_4).round() as i64).rem_euclid(8);
    const LEVELS: [u32; 8] = [0xF0, 0xFF, 0xE0, 0xB0, 0x70, 0x50, 0x80, 0xC0];
    grey(LEVELS[sector as usize])
}
