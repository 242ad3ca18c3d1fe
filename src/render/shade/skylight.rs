//! Light from the sky, less in valleys and under cliffs: how much of the
//! sky each point sees, from horizon sweeps in eight directions.
//!
//! Ambient light that reaches every face alike flattens a landscape; with
//! the sky's share per point, valley floors and gullies darken and ridges
//! stand out even in the shade. The sweeps run on a coarse copy of the
//! field (at most [`COARSE_CELLS`] cells a side) and are sampled
//! bilinearly at each grid point: occlusion varies slowly, so a finer grid
//! shows nothing more for many times the cost.

use glam::Vec3;

use super::index;
use super::shadow;
use crate::terrain::Heightfield;

/// Cells a side of the grid the sweeps run on.
const COARSE_CELLS: usize = 256;
/// Directions the sky is sampled in, evenly around the horizon.
const DIRECTIONS: usize = 8;
/// Elevation of the sampled sky, in degrees: the middle of the visible dome.
const ELEVATION: f32 = 28.0;

/// Share of the sky each grid point sees (0..=1).
#[derive(Debug, Clone)]
pub(crate) struct SkyLight {
    /// Points a side of the coarse grid.
    size: usize,
    /// Fine grid steps per coarse step.
    stride: f32,
    seen: Vec<f32>,
}

impl SkyLight {
    /// Sweeps `field` (water counts as a flat surface at sea level).
    pub(crate) fn new(field: &Heightfield) -> Self {
        let levels = (field.size() - 1).div_ceil(COARSE_CELLS).max(1).ilog2();
        let mut coarse = field.coarsened(levels);
        for h in coarse.heights_mut() {
            *h = if h.is_finite() { h.max(0.0) } else { 0.0 };
        }
        let n = coarse.size();
        let mut seen = vec![0.0f32; n * n];
        let (sin_el, cos_el) = ELEVATION.to_radians().sin_cos();
        for d in 0..DIRECTIONS {
            let az = (d as f32 + 0.5) * std::f32::consts::TAU / DIRECTIONS as f32;
            let towards = Vec3::new(az.cos() * cos_el, az.sin() * cos_el, sin_el);
            let map = shadow::cast(&coarse, towards);
            for (i, s) in seen.iter_mut().enumerate() {
                *s += map.lit(i % n, i / n);
            }
        }
        seen.iter_mut().for_each(|s| *s /= DIRECTIONS as f32);
        SkyLight {
            size: n,
            stride: (field.size() - 1) as f32 / (n - 1).max(1) as f32,
            seen,
        }
    }

    /// The share of the sky seen at fine grid point (`x`, `y`).
    #[cfg(test)]
    pub(crate) fn at(&self, x: usize, y: usize) -> f32 {
        self.blend(self.rows_at(y), x)
    }

    /// The coarse rows above and below fine row `y`, and the weight of the
    /// lower: found once per row, then [`SkyLight::blend`] per point.
    #[inline]
    pub(crate) fn rows_at(&self, y: usize) -> (usize, usize, f32) {
        let fy = y as f32 / self.stride;
        let y0 = index(fy).min(self.size - 1);
        (y0, (y0 + 1).min(self.size - 1), fy - y0 as f32)
    }

    /// The bilinear sample at fine column `x` between coarse `rows`.
    #[inline]
    pub(crate) fn blend(&self, (y0, y1, ty): (usize, usize, f32), x: usize) -> f32 {
        let fx = x as f32 / self.stride;
        let last = self.size - 1;
        let x0 = index(fx).min(last);
        let x1 = (x0 + 1).min(last);
        let tx = fx - x0 as f32;
        let row = |y: usize| {
            let (a, b) = (self.seen[y * self.size + x0], self.seen[y * self.size + x1]);
            a + (b - a) * tx
        };
        let (top, bottom) = (row(y0), row(y1));
        top + (bottom - top) * ty
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A V-shaped valley running back to front between two ridges.
    fn valley() -> Heightfield {
        let mut f = Heightfield::flat(6, 64.0);
        let n = f.size();
        for y in 0..n {
            for x in 0..n {
                f.set(x, y, (x as f32 - 32.0).abs() * 2.0);
            }
        }
        f
    }

    #[test]
    fn a_valley_floor_sees_less_sky_than_the_ridge_above_it() {
        let sky = SkyLight::new(&valley());
        let (floor, ridge) = (sky.at(32, 32), sky.at(0, 32));
        assert!(floor < 0.8 * ridge, "floor {floor}, ridge {ridge}");
        assert!((0.0..=1.0).contains(&floor) && (0.0..=1.0).contains(&ridge));
    }

    #[test]
    fn flat_ground_sees_the_whole_sky() {
        let sky = SkyLight::new(&Heightfield::flat(5, 32.0));
        assert!((sky.at(16, 16) - 1.0).abs() < 1e-6);
    }
}
