//! Seed 004, *3D Fractal Landscapes* (FL3), in Filled mode, as its
//! article describes: one triangular landscape, point down (its vertex A
//! nearest the viewer, B and C at the back), drawn by `DrawTriangle`'s
//! recursion (the point-down calls as printed: CA-BC-C, AB-B-BC, the
//! inside triangle, A-AB-CA), each triangle projected by `Project`'s
//! single-point perspective and drawn by `Canvas.Polygon` (brush green on
//! land, blue at sea level under water, split at the crossing; pen
//! black), then vertical quadrilaterals from sea level along the two
//! front edges.
//!
//! The landscape is the half of our triangle generator's square on the
//! back-right side of its diagonal ((0,0), (n,0), (n,n): one of the
//! generator's own two triangles), pulled to an equilateral one. What the
//! article does not give, chosen here: the vanishing point (0.5, 2, 1.1
//! in its 0..1 coordinates: the back edge at depth 1), the sea's height
//! (0.12), the height scale (the field's own relief against its width),
//! the point-up calls' order (back, right, inside, left: "back to front,
//! right to left"), the side quadrilaterals' brush (the land's green) and
//! the window (black). The colours are Outline mode's green and blue.

use crate::canvas::Canvas;
use mountains::terrain::Heightfield;

const GREEN: u32 = 0x0000_d000;
const BLUE: u32 = 0x0000_00ff;
const PEN: u32 = 0;
const VANISHING: [f64; 3] = [0.5, 2.0, 1.1];
const SEA: f64 = 0.12;

/// A vertex in grid coordinates (column, row) of the field.
type V = (usize, usize);

struct Fl3<'f> {
    field: &'f Heightfield,
    n: f64,
    scale: f64,
    size: [f64; 2],
}

/// Draws `field`'s triangle into `canvas`.
pub fn draw(field: &Heightfield, canvas: &mut Canvas) {
    let n = field.size() - 1;
    let fl3 = Fl3 {
        field,
        n: n as f64,
        scale: 1.0 / f64::from(field.extent()),
        size: [canvas.width as f64, canvas.height as f64],
    };
    // Point down: A front (n, n), B back left (0, 0), C back right (n, 0).
    let (a, b, c) = ((n, n), (0, 0), (n, 0));
    fl3.triangle(canvas, a, b, c, true);
    fl3.sides(canvas, [a, b]);
    fl3.sides(canvas, [a, c]);
}

impl Fl3<'_> {
    /// `DrawTriangle(A, B, C, PointDn)`: down to one grid cell's half.
    fn triangle(&self, canvas: &mut Canvas, a: V, b: V, c: V, down: bool) {
        let mid = |p: V, q: V| ((p.0 + q.0) / 2, (p.1 + q.1) / 2);
        let len = a.0.abs_diff(b.0).max(a.1.abs_diff(b.1));
        if len <= 1 {
            return self.draw3(canvas, [a, b, c]);
        }
        let (ab, bc, ca) = (mid(a, b), mid(b, c), mid(c, a));
        if down {
            self.triangle(canvas, ca, bc, c, true);
            self.triangle(canvas, ab, b, bc, true);
            self.triangle(canvas, bc, ca, ab, false);
            self.triangle(canvas, a, ab, ca, true);
        } else {
            // A is the point at the back, B and C in front.
            self.triangle(canvas, a, ab, ca, false);
            let (right, left) = if self.world(b)[0] > self.world(c)[0] {
                ((ab, b, bc), (ca, bc, c))
            } else {
                ((ca, bc, c), (ab, b, bc))
            };
            self.triangle(canvas, right.0, right.1, right.2, false);
            self.triangle(canvas, bc, ca, ab, true);
            self.triangle(canvas, left.0, left.1, left.2, false);
        }
    }

    /// A vertex's place in FL3's 0..1 space: x across, y depth, z height.
    fn world(&self, v: V) -> [f64; 3] {
        let (u, w) = (v.0 as f64 / self.n, v.1 as f64 / self.n);
        let h = f64::from(self.field.get(v.0, v.1));
        [u - 0.5 * w, 1.0 - w, SEA + h * self.scale]
    }

    /// `Project`: single-point perspective towards the vanishing point.
    fn project(&self, p: [f64; 3]) -> [f64; 2] {
        let v = VANISHING;
        let ratio = p[1] / v[1];
        [
            (self.size[0] * ((v[0] - p[0]) * ratio + p[0])).round(),
            self.size[1] - (self.size[1] * ((v[2] - p[2]) * ratio + p[2])).round(),
        ]
    }

    /// `Draw3Vertices`: above the sea, below it (at sea level), or both.
    fn draw3(&self, canvas: &mut Canvas, v: [V; 3]) {
        let p = v.map(|v| self.world(v));
        let wet = p.map(|p| p[2] < SEA);
        if wet.iter().all(|&w| w) {
            return self.polygon(canvas, &p.map(|p| [p[0], p[1], SEA]), BLUE);
        }
        if !wet.iter().any(|&w| w) {
            return self.polygon(canvas, &p, GREEN);
        }
        let odd = (0..3).find(|&k| wet[k] != wet[(k + 1) % 3] && wet[k] != wet[(k + 2) % 3]);
        let k = odd.unwrap_or(0);
        let (a, s0, s1) = (p[k], p[(k + 1) % 3], p[(k + 2) % 3]);
        let cross = |q: [f64; 3]| {
            let f = (SEA - a[2]) / (q[2] - a[2]);
            [a[0] + (q[0] - a[0]) * f, a[1] + (q[1] - a[1]) * f, SEA]
        };
        let (m0, m1) = (cross(s0), cross(s1));
        let flat = |q: [f64; 3]| [q[0], q[1], SEA];
        if wet[k] {
            self.polygon(canvas, &[flat(a), m0, m1], BLUE);
            self.polygon(canvas, &[m0, s0, s1, m1], GREEN);
        } else {
            self.polygon(canvas, &[flat(s0), flat(s1), m1, m0], BLUE);
            self.polygon(canvas, &[a, m0, m1], GREEN);
        }
    }

    /// `Canvas.Polygon`: filled with the brush, outlined with the pen.
    fn polygon(&self, canvas: &mut Canvas, p: &[[f64; 3]], brush: u32) {
        let q: Vec<[f64; 2]> = p.iter().map(|&p| self.project(p)).collect();
        for k in 1..q.len() - 1 {
            canvas.triangle([q[0], q[k], q[k + 1]], brush);
        }
        for k in 0..q.len() {
            canvas.line(q[k], q[(k + 1) % q.len()], PEN);
        }
    }

    /// The vertical quadrilaterals from sea level up to the vertices of a
    /// front edge that stand above it.
    fn sides(&self, canvas: &mut Canvas, e: [V; 2]) {
        let steps = e[0].0.abs_diff(e[1].0).max(e[0].1.abs_diff(e[1].1));
        let at = |k: usize| {
            let t = |a: usize, b: usize| {
                (a as f64 + (b as f64 - a as f64) * k as f64 / steps as f64) as usize
            };
            (t(e[0].0, e[1].0), t(e[0].1, e[1].1))
        };
        for k in 0..steps {
            let (p, q) = (self.world(at(k)), self.world(at(k + 1)));
            if p[2] <= SEA && q[2] <= SEA {
                continue;
            }
            let top = |r: [f64; 3]| [r[0], r[1], r[2].max(SEA)];
            let foot = |r: [f64; 3]| [r[0], r[1], SEA];
            self.polygon(canvas, &[top(p), top(q), foot(q), foot(p)], GREEN);
        }
    }
}
