//! Seed 000, *Fractal Mountain Climbing* (MacTech 1991,
//! MountainsAlgorithm.c), drawn as its listing draws: `NormalizeMap`'s
//! heights, `DrawMountains`' order and cells, `DrawTriangle`'s split at the
//! water line, `CalcPoint3`'s view and `_DrawTriangle`'s light, HSV ramp
//! and QuickDraw polygon at truncated corners, in colour (`colorF`).

use crate::canvas::Canvas;
use mountains::terrain::Heightfield;

/// The listing's `maxIter`.
const MAX_ITER: i32 = 9;
/// The listing's `xTh`, the tilt (-80 degrees; the article says -70).
const X_TH: f64 = -1.396;

/// A listing `point3`: map column, row and height, then viewing space.
#[derive(Clone, Copy)]
struct P3 {
    x: f64,
    y: f64,
    z: f64,
}

/// `DrawMountains`' drawing state.
struct Listing {
    map: Vec<i64>,
    map_s: usize,
    xc: f64,
    sc: f64,
    tm: [[f64; 3]; 3],
    normal_height: f64,
}

/// Draws `field` (a grid of `2^nIter + 1` points, the sea at 0) at the
/// Height menu's `height` into `canvas`, its window `canvas.width` wide.
pub fn draw(field: &Heightfield, height: u32, canvas: &mut Canvas) {
    let listing = Listing::new(field, height, canvas.width as f64);
    let cells = listing.map_s - 1;
    for y in 0..cells {
        for x in 0..cells {
            listing.draw_triangle(canvas, [(x, y), (x, y + 1), (x + 1, y + 1)]);
            listing.draw_triangle(canvas, [(x, y), (x + 1, y + 1), (x + 1, y)]);
        }
    }
}

impl Listing {
    fn new(field: &Heightfield, height: u32, wd: f64) -> Self {
        let n_iter = field.exponent() as i32;
        let normal_height = 10_000.0 * f64::from(height);
        // NormalizeMap: the highest point at normalHeight (our field has
        // had its contour already), each point truncated to a long.
        let top = f64::from(field.max()).max(f64::MIN_POSITIVE);
        let map = field
            .heights()
            .iter()
            .map(|&h| (f64::from(h) / top * normal_height) as i64)
            .collect();
        let mut tm = [[0.0; 3]; 3];
        tm[0][0] = 1.0;
        tm[1][1] = X_TH.cos();
        tm[2][1] = X_TH.sin();
        tm[1][2] = -X_TH.sin();
        tm[2][2] = X_TH.cos();
        Listing {
            map,
            map_s: field.size(),
            xc: 0.4073 * f64::from(1 << (MAX_ITER - n_iter)),
            sc: wd / 630.0,
            tm,
            normal_height,
        }
    }

    fn at(&self, x: usize, y: usize) -> i64 {
        self.map[x + self.map_s * y]
    }

    /// `DrawTriangle`: whole, or cut in three at the water line.
    fn draw_triangle(&self, canvas: &mut Canvas, c: [(usize, usize); 3]) {
        let z = c.map(|(x, y)| self.at(x, y));
        let mut p = [0, 1, 2].map(|k| P3 {
            x: c[k].0 as f64,
            y: c[k].1 as f64,
            z: z[k] as f64,
        });
        if z.iter().all(|&z| z <= 0) {
            p.iter_mut().for_each(|p| p.z = 0.0);
            return self.paint(canvas, p);
        }
        if z.iter().all(|&z| z >= 0) {
            return self.paint(canvas, p);
        }
        let w = z.map(|z| z < 0);
        let (mut ap, mut s) = if w[0] != w[1] && w[0] != w[2] {
            (p[0], [p[1], p[2]])
        } else if w[1] != w[0] {
            (p[1], [p[2], p[0]])
        } else {
            (p[2], [p[0], p[1]])
        };
        let m = s.map(|s| {
            let f = -ap.z / (s.z - ap.z);
            P3 {
                x: ap.x - (ap.x - s.x) * f,
                y: ap.y - (ap.y - s.y) * f,
                z: 0.0,
            }
        });
        if ap.z < 0.0 {
            ap.z = 0.0;
        } else {
            s[0].z = 0.0;
            s[1].z = 0.0;
        }
        self.paint(canvas, [ap, m[0], m[1]]);
        self.paint(canvas, [m[0], s[0], s[1]]);
        self.paint(canvas, [m[0], s[1], m[1]]);
    }

    /// `CalcPoint3`.
    fn calc_point3(&self, p: P3) -> P3 {
        let map_d = (self.map_s - 1) as f64;
        let xp = (p.x * 2.0 - p.y + map_d) * self.xc;
        let yp = (p.y * 2.0) * self.xc;
        let zp = p.z * 0.00217;
        P3 {
            x: xp * self.sc,
            y: (yp * self.tm[1][1] + zp * self.tm[2][1] + 230.0) * self.sc,
            z: (yp * self.tm[1][2] + zp * self.tm[2][2]) * self.sc,
        }
    }

    /// `_DrawTriangle`: the colour class, the view, the normal, the light,
    /// and `PaintPoly` at the corners truncated to integers.
    fn paint(&self, canvas: &mut Canvas, p: [P3; 3]) {
        let water = p.iter().all(|p| p.z == 0.0);
        let treeline = 0.4 * self.normal_height + 10_000.0;
        let az = (p[0].z + p[1].z + p[2].z) / 3.0;
        let color: i64 = if az > treeline + 9000.0 {
            150
        } else if az < treeline {
            0
        } else {
            ((az - treeline) / 60.0) as i64
        };
        let p = p.map(|p| self.calc_point3(p));
        let (v1, v2) = (
            [p[1].x - p[0].x, p[1].y - p[0].y, p[1].z - p[0].z],
            [p[2].x - p[0].x, p[2].y - p[0].y, p[2].z - p[0].z],
        );
        let n = [
            v1[1] * v2[2] - v1[2] * v2[1],
            v1[2] * v2[0] - v1[0] * v2[2],
            v1[0] * v2[1] - v1[1] * v2[0],
        ];
        let lx = -1.0 / 3f64.sqrt();
        let (ly, lz) = (-lx, -lx);
        let colour = if water {
            rgb16(0x9FFF, 0x9FFF, 0xFFFF)
        } else {
            let rest = (150 - color) as u32;
            let hue = rest * (0x5555 - 0x2000) / 150 + 0x2000;
            let sat = (0xFFFF * rest) / 150;
            let val = 0xEFFF - rest * (0xEFFF - 0xAAAA) / 150;
            let i = (lx * n[0] + ly * n[1] + lz * n[2])
                / (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt()
                * 0.5
                + 0.5;
            // `c.blue *= i`: an unsigned short times a double, stored back.
            let val = (f64::from(val as u16) * i) as u16;
            hsv2rgb(hue as u16, sat as u16, val)
        };
        let q = p.map(|p| [p.x.trunc(), p.y.trunc()]);
        canvas.triangle(q, colour);
    }
}

/// A QuickDraw `RGBColor` shown by each channel's high byte.
fn rgb16(r: u16, g: u16, b: u16) -> u32 {
    (u32::from(r >> 8) << 16) | (u32::from(g >> 8) << 8) | u32::from(b >> 8)
}

/// The Color Picker's `HSV2RGB` for 16-bit fractions (the six sectors of
/// the hexcone; its own rounding is not in the listing: nearest).
fn hsv2rgb(h: u16, s: u16, v: u16) -> u32 {
    let (s, v) = (f64::from(s) / 65535.0, f64::from(v) / 65535.0);
    let h6 = f64::from(h) / 65536.0 * 6.0;
    let sector = h6.floor();
    let f = h6 - sector;
    let (p, q, t) = (v * (1.0 - s), v * (1.0 - s * f), v * (1.0 - s * (1.0 - f)));
    let [r, g, b] = match sector as u32 {
        0 => [v, t, p],
        1 => [q, v, p],
        2 => [p, v, t],
        3 => [p, q, v],
        4 => [t, p, v],
        _ => [v, p, q],
    };
    let c = |x: f64| (x * 65535.0).round() as u16;
    rgb16(c(r), c(g), c(b))
}
