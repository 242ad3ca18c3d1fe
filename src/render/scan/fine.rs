//! A screen triangle's planes through what its corners say of the relief
//! below the grid (see `shade::relief`), read at pixel centres: each pixel
//! is made lighter or darker by the finer terrain's light there, four
//! pixels at a time.

use glam::Vec4;

use super::gradient::Gradient;
pub(crate) use crate::render::shade::relief::LANES;
use crate::render::shade::relief::Relief;

/// Pixels whose factors are worked out before they are set: a span is
/// done in pieces of this many.
pub(crate) const PIECE: usize = 64;

/// How much lighter or darker four pixels are (factors near 1), given
/// their blended corner values (each value's four pixels in a vector).
pub(crate) trait Gain {
    /// The factors of four pixels whose blended values are `q`.
    fn gains(&self, q: [Vec4; LANES]) -> Vec4;
}

impl<F: Fn([Vec4; LANES]) -> Vec4> Gain for F {
    #[inline(always)]
    fn gains(&self, q: [Vec4; LANES]) -> Vec4 {
        self(q)
    }
}

/// The mountain's finer terrain lights each pixel.
impl Gain for &Relief {
    #[inline(always)]
    fn gains(&self, q: [Vec4; LANES]) -> Vec4 {
        Relief::gains(self, q)
    }
}

/// One row's values where it crosses the first corner's column.
pub(crate) type FineRow = [f32; LANES];

/// [`LANES`] values blended across a triangle, and what they make of a
/// pixel's light.
pub(crate) struct Fine<G> {
    /// The values at the first corner, their change per pixel to the
    /// right and per row down, and their least and greatest corner values
    /// (a sliver's planes may overshoot its corners).
    at0: [f32; LANES],
    dx: [f32; LANES],
    dy: [f32; LANES],
    lo: [f32; LANES],
    hi: [f32; LANES],
    origin: [f32; 2],
    gain: G,
}

impl<G: Gain> Fine<G> {
    /// Planes through the corner values `q` over the triangle of
    /// `gradient`, read by `gain`.
    #[inline]
    pub(crate) fn new(gradient: &Gradient, q: [[f32; LANES]; 3], gain: G) -> Self {
        let slopes: [(f32, f32); LANES] =
            std::array::from_fn(|i| gradient.slopes(q[1][i] - q[0][i], q[2][i] - q[0][i]));
        Fine {
            at0: q[0],
            dx: slopes.map(|s| s.0),
            dy: slopes.map(|s| s.1),
            lo: std::array::from_fn(|i| q[0][i].min(q[1][i]).min(q[2][i])),
            hi: std::array::from_fn(|i| q[0][i].max(q[1][i]).max(q[2][i])),
            origin: gradient.origin,
            gain,
        }
    }

    /// Row `y`'s start, for [`Fine::gains`].
    #[inline]
    pub(crate) fn row(&self, y: u32) -> FineRow {
        let oy = y as f32 + 0.5 - self.origin[1];
        std::array::from_fn(|i| self.at0[i] + self.dy[i] * oy)
    }

    /// The factors of pixels `x0..x0 + out.len()` of a row, each pixel's
    /// from its own column alone (a span cut anywhere gets the same).
    #[inline]
    pub(crate) fn gains(&self, row: &FineRow, x0: u32, out: &mut [f32]) {
        for (k, four) in out.chunks_mut(4).enumerate() {
            let x = x0 + 4 * k as u32;
            let ox = self.across([x, x + 1, x + 2, x + 3]);
            let q = std::array::from_fn(|i| self.held(Vec4::splat(row[i]) + ox * self.dx[i], i));
            let g = self.gain.gains(q).to_array();
            four.copy_from_slice(&g[..four.len()]);
        }
    }

    /// The factors of the pixels (`xs[i]`, `ys[i]`), four at a time
    /// whatever their rows (a small face's rows are a pixel or two long):
    /// each pixel's the same as [`Fine::gains`] gives it.
    #[inline]
    pub(crate) fn gains_at(&self, xs: &[u32], ys: &[u32], out: &mut [f32]) {
        let chunks = xs.chunks(4).zip(ys.chunks(4));
        for ((x, y), four) in chunks.zip(out.chunks_mut(4)) {
            // A short last four repeats its last pixel.
            let lane = |v: &[u32], j: usize| v[j.min(v.len() - 1)];
            let ox = self.across(std::array::from_fn(|j| lane(x, j)));
            let rows: [u32; 4] = std::array::from_fn(|j| lane(y, j));
            let oy = Vec4::from_array(rows.map(|y| y as f32)) + 0.5 - self.origin[1];
            let q = std::array::from_fn(|i| {
                self.held(
                    Vec4::splat(self.at0[i]) + self.dy[i] * oy + ox * self.dx[i],
                    i,
                )
            });
            let g = self.gain.gains(q).to_array();
            four.copy_from_slice(&g[..four.len()]);
        }
    }

    /// How far the centres of columns `x` lie right of the first corner.
    #[inline(always)]
    fn across(&self, x: [u32; 4]) -> Vec4 {
        Vec4::from_array(x.map(|x| x as f32)) + 0.5 - self.origin[0]
    }

    /// Value `i` of four pixels held to the corners' range.
    #[inline(always)]
    fn held(&self, v: Vec4, i: usize) -> Vec4 {
        v.clamp(Vec4::splat(self.lo[i]), Vec4::splat(self.hi[i]))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::base::fixed::to_fixed;

    #[test]
    fn the_planes_read_each_corner_back_and_stay_within_them() {
        let v = [to_fixed(0.5, 0.5), to_fixed(40.5, 0.5), to_fixed(0.5, 20.5)];
        let corner = |a: f32, b: f32| {
            let mut q = [0.0; LANES];
            (q[0], q[LANES - 1]) = (a, b);
            q
        };
        let q = [corner(0.0, 1.0), corner(40.0, 3.0), corner(0.0, -1.0)];
        let fine = Fine::new(&Gradient::new(v), q, |q: [Vec4; LANES]| {
            q[0] + q[LANES - 1] * 100.0
        });
        let at = |x: u32, y: u32| {
            let mut out = [0.0; 1];
            fine.gains(&fine.row(y), x, &mut out);
            out[0]
        };
        // The first corner's pixel centre is the corner itself.
        assert!((at(0, 0) - 100.0).abs() < 1e-3);
        // Along the top edge the first lane runs 0..40 and the last 1..3.
        assert!((at(20, 0) - (20.0 + 200.0)).abs() < 1e-2, "{}", at(20, 0));
        // Past the triangle the planes are held to the corners' range.
        // (At (80, 30) the first lane's 80 is held to 40; the last's 2 is
        // within -1..=3.)
        let far = at(80, 30);
        assert!((far - 240.0).abs() < 1e-2, "{far}");
        // A pixel's factor is its own, wherever its piece of a span starts.
        let mut span = [0.0; 11];
        fine.gains(&fine.row(5), 3, &mut span);
        for (i, g) in span.iter().enumerate() {
            assert_eq!(*g, at(3 + i as u32, 5), "pixel {}", 3 + i);
        }
    }
}
