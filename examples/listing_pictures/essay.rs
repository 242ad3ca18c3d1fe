//! Seed 002, the 2017 essay's program (its `proceed_fractal` and
//! `terrain`), drawn as its JavaScript draws: the square's corners from
//! `origin(center)` turned by `theta`, `projection` from `camera =
//! [500,100,0]` onto `screen = 600`, each leaf square split as its
//! `orientation` says, `hsl(100, 80%, L%)` with `L = round(20 cos + 10)`
//! to the sun's rays `[-5,5,0]`, every triangle pushed with the mean of
//! its corners' depth, `draw_data.sort()` (JavaScript's default sort: the
//! entries compared as strings) reversed, then stroked and filled, on a
//! white 1000x600 canvas (here scaled to the frame's width).
//!
//! The heights are the look's field (its square generator, edges
//! undisplaced, its numbers the essay's `cos(random * PI)`): the field's
//! width is the essay's 2048 (`N = 11`) and its heights are in the same
//! units, standing up (the essay's y grows downwards) from its corners at
//! the essay's base.

use crate::canvas::Canvas;
use mountains::terrain::Heightfield;

const CAMERA: [f64; 3] = [500.0, 100.0, 0.0];
const SCREEN: f64 = 600.0;
const CENTER: [f64; 3] = [500.0, 850.0, 2400.0];
const SUN: [f64; 3] = [-5.0, 5.0, 0.0];

/// Draws `field` seen from `theta` (radians; the essay starts at PI/4)
/// into `canvas` (the essay's 1000x600 canvas scaled to its width).
pub fn draw(field: &Heightfield, theta: f64, canvas: &mut Canvas) {
    let m = field.size() - 1;
    let side = 2048.0;
    let hyp = side / 2f64.sqrt();
    let phi = std::f64::consts::FRAC_PI_2 - theta;
    let c = CENTER;
    // origin(center): P1, P2, P3, P4.
    let sq = [
        [c[0] - hyp * theta.cos(), c[1], c[2] + hyp * theta.sin()],
        [c[0] - hyp * phi.cos(), c[1], c[2] - hyp * phi.sin()],
        [c[0] + hyp * theta.cos(), c[1], c[2] - hyp * theta.sin()],
        [c[0] + hyp * phi.cos(), c[1], c[2] + hyp * phi.sin()],
    ];
    let up = side / f64::from(field.extent());
    // The essay's corners stand at its `center`'s height, y = 850: the
    // field's corners (all at one height, its edges undisplaced) go there.
    let base = [(0, 0), (m, 0), (0, m), (m, m)]
        .iter()
        .map(|&(x, y)| f64::from(field.get(x, y)))
        .sum::<f64>()
        / 4.0;
    // Array point (i, j): i from P1 towards P4 (our columns), j from P1
    // towards P2 (our rows, back to front).
    let point = |i: usize, j: usize| -> [f64; 3] {
        let (u, v) = (i as f64 / m as f64, j as f64 / m as f64);
        let mut p = [0.0; 3];
        for k in 0..3 {
            p[k] = sq[0][k] + v * (sq[1][k] - sq[0][k]) + u * (sq[3][k] - sq[0][k]);
        }
        p[1] -= (f64::from(field.get(i, j)) - base) * up;
        p
    };
    let scale = canvas.width as f64 / 1000.0;
    let project = |p: [f64; 3]| -> [f64; 2] {
        let r = SCREEN / (p[2] - CAMERA[2]);
        [
            (CAMERA[0] - (CAMERA[0] - p[0]) * r) * scale,
            (CAMERA[1] - (CAMERA[1] - p[1]) * r) * scale,
        ]
    };
    let mut draw_data: Vec<(String, [[f64; 2]; 3], u32)> = Vec::new();
    for i in 0..m {
        for j in 0..m {
            let (p1, p2, p3, p4) = (
                point(i, j),
                point(i, j + 1),
                point(i + 1, j + 1),
                point(i + 1, j),
            );
            // The quadrant the last split put this square in.
            let orientation = (i + j) % 2;
            let faces = if orientation == 0 {
                [
                    ([p1, p2, p4], cross(sub(p4, p1), sub(p2, p1))),
                    ([p2, p4, p3], cross(sub(p3, p2), sub(p3, p4))),
                ]
            } else {
                [
                    ([p1, p2, p3], cross(sub(p1, p2), sub(p3, p2))),
                    ([p1, p3, p4], cross(sub(p4, p3), sub(p4, p1))),
                ]
            };
            for (t, normal) in faces {
                let cosine = dot(normal, SUN) / (dot(normal, normal).sqrt() * dot(SUN, SUN).sqrt());
                let amplitude = (30.0 - -10.0) / 2.0;
                let color = js_round(amplitude * cosine + (amplitude + -10.0));
                let z = (t[0][2] + t[1][2] + t[2][2]) / 3.0;
                let q = t.map(project);
                let key = format!(
                    "{},{},{},{},{},{},{},{},100",
                    z, q[0][0], q[0][1], q[1][0], q[1][1], q[2][0], q[2][1], color
                );
                draw_data.push((key, q, hsl(100.0, 0.8, color / 100.0)));
            }
        }
    }
    // `sort()` compares the entries' strings; then `reverse()`.
    draw_data.sort_by(|a, b| a.0.encode_utf16().cmp(b.0.encode_utf16()));
    for (_, q, colour) in draw_data.iter().rev() {
        for k in 0..3 {
            canvas.line(q[k], q[(k + 1) % 3], *colour);
        }
        canvas.triangle(*q, *colour);
    }
}

fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// JavaScript's `Math.round`: halves towards +infinity.
fn js_round(x: f64) -> f64 {
    (x + 0.5).floor()
}

/// CSS `hsl(h, s, l)` (lightness clamped to 0..1) in 8-bit channels.
fn hsl(h: f64, s: f64, l: f64) -> u32 {
    let l = l.clamp(0.0, 1.0);
    let c = (1.0 - (2.0 * l - 1.0).abs()) * s;
    let h6 = h / 60.0;
    let x = c * (1.0 - (h6 % 2.0 - 1.0).abs());
    let (r, g, b) = match h6 as u32 {
        0 => (c, x, 0.0),
        1 => (x, c, 0.0),
        2 => (0.0, c, x),
        3 => (0.0, x, c),
        4 => (x, 0.0, c),
        _ => (c, 0.0, x),
    };
    let m = l - c / 2.0;
    let byte = |v: f64| ((v + m) * 255.0).round().clamp(0.0, 255.0) as u32;
    (byte(r) << 16) | (byte(g) << 8) | byte(b)
}
