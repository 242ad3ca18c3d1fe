//! A screen triangle's planes through what its corners say of the relief
//! below the grid (see `shade::relief`), read at pixel centres: each pixel
//! is made lighter or darker by the finer terrain's light there.

use glam::Vec4;

use super::gradient::Gradient;
use crate::render::shade::relief::Relief;

/// How much lighter or darker a pixel is (a factor near 1), given its
/// blended corner values.
pub(crate) trait Gain {
    /// The factor at a pixel whose blended values are `q`.
    fn gain(&self, q: [Vec4; 2]) -> f32;
}

impl<F: Fn([Vec4; 2]) -> f32> Gain for F {
    #[inline(always)]
    fn gain(&self, q: [Vec4; 2]) -> f32 {
        self(q)
    }
}

/// The mountain's finer terrain lights each pixel.
impl Gain for &Relief {
    #[inline(always)]
    fn gain(&self, q: [Vec4; 2]) -> f32 {
        Relief::gain(self, q)
    }
}

/// One row's values where it crosses the first corner's column.
pub(crate) type FineRow = [Vec4; 2];

/// Eight values blended across a triangle, and what they make of a
/// pixel's light.
pub(crate) struct Fine<G> {
    /// The values at the first corner, their change per pixel to the
    /// right and per row down, and their least and greatest corner values
    /// (a sliver's planes may overshoot its corners).
    at0: [Vec4; 2],
    dx: [Vec4; 2],
    dy: [Vec4; 2],
    lo: [Vec4; 2],
    hi: [Vec4; 2],
    origin: [f32; 2],
    gain: G,
}

impl<G: Gain> Fine<G> {
    /// Planes through the corner values `q` over the triangle of
    /// `gradient`, read by `gain`.
    #[inline]
    pub(crate) fn new(gradient: &Gradient, q: [[Vec4; 2]; 3], gain: G) -> Self {
        let lanes = |i: usize| {
            let (dx, dy) = gradient.slopes(q[1][i] - q[0][i], q[2][i] - q[0][i]);
            let lo = q[0][i].min(q[1][i]).min(q[2][i]);
            let hi = q[0][i].max(q[1][i]).max(q[2][i]);
            (dx, dy, lo, hi)
        };
        let (l0, l1) = (lanes(0), lanes(1));
        Fine {
            at0: q[0],
            dx: [l0.0, l1.0],
            dy: [l0.1, l1.1],
            lo: [l0.2, l1.2],
            hi: [l0.3, l1.3],
            origin: gradient.origin,
            gain,
        }
    }

    /// Row `y`'s start, for [`Fine::gain_at`].
    #[inline]
    pub(crate) fn row(&self, y: u32) -> FineRow {
        let oy = y as f32 + 0.5 - self.origin[1];
        [0, 1].map(|i| self.at0[i] + self.dy[i] * oy)
    }

    /// The factor at the centre of pixel `x` of a row.
    #[inline(always)]
    pub(crate) fn gain_at(&self, row: &FineRow, x: u32) -> f32 {
        let ox = x as f32 + 0.5 - self.origin[0];
        let q = [0, 1].map(|i| (row[i] + self.dx[i] * ox).max(self.lo[i]).min(self.hi[i]));
        self.gain.gain(q)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::base::fixed::to_fixed;

    #[test]
    fn the_planes_read_each_corner_back_and_stay_within_them() {
        let v = [to_fixed(0.5, 0.5), to_fixed(40.5, 0.5), to_fixed(0.5, 20.5)];
        let q = [
            [Vec4::splat(0.0), Vec4::splat(1.0)],
            [Vec4::splat(40.0), Vec4::splat(3.0)],
            [Vec4::splat(0.0), Vec4::splat(-1.0)],
        ];
        let fine = Fine::new(&Gradient::new(v), q, |q: [Vec4; 2]| q[0].x + 100.0 * q[1].x);
        // The first corner's pixel centre is the corner itself.
        assert!((fine.gain_at(&fine.row(0), 0) - 100.0).abs() < 1e-3);
        // Along the top edge the first lane runs 0..40 and the second 1..3.
        let at = fine.gain_at(&fine.row(0), 20);
        assert!((at - (20.0 + 200.0)).abs() < 1e-2, "{at}");
        // Past the triangle the planes are held to the corners' range.
        let far = fine.gain_at(&fine.row(30), 80);
        assert!((-100.0..=340.0).contains(&far), "{far}");
    }
}
