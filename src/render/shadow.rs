//! Cast shadows: which grid points see the light (a horizon sweep).
//!
//! Light rays are parallel, so the shadow a point receives depends only on
//! the terrain along the line from it towards the light. The sweep visits
//! points starting from the light's side and carries, per point, the height
//! of the highest shadow ray passing over it (`horizon`): the ray from the
//! point's neighbour towards the light, lowered by one step of the light's
//! slope, or the point itself if it stands higher. The neighbour falls between
//! two grid points, so its horizon is interpolated. Every point is visited
//! once: O(points), rows in memory order, one row of state per pass, and the
//! points of a row are independent (a light closer to the x axis sweeps the
//! transposed grid). One thread: the output cannot depend on thread count.
//!
//! A point is fully lit when it stands at or above the horizon arriving from
//! its neighbour, and fully dark once it is as far below it as the light
//! rises over `PENUMBRA` cells: shadow edges get a soft rim about two cells
//! wide, on the shadow side only, so no truly lit point is darkened.

use crate::terrain::Heightfield;
use glam::Vec3;

/// Width of the soft shadow edge, in heights the light ray drops per cell.
const PENUMBRA: f32 = 2.0;

/// Height of "no occluder": far below any terrain yet finite, so that a
/// zero interpolation weight times it is 0 and not NaN. Interpolations are
/// written `a * (1 - w) + b * w` so a weight of 1 returns `b` exactly.
const NONE: f32 = -1.0e30;

/// Per grid point, how much direct light arrives (1 lit, 0 shadowed).
#[derive(Debug, Clone)]
pub struct ShadowMap {
    size: usize,
    /// Light per point in 1/255ths, row-major.
    lit: Vec<u8>,
}

impl ShadowMap {
    /// Every point lit (shadows off).
    pub fn all_lit(field: &Heightfield) -> Self {
        Self::uniform(field, 255)
    }

    /// Every point with the same light, in 1/255ths.
    fn uniform(field: &Heightfield, level: u8) -> Self {
        ShadowMap {
            size: field.size(),
            lit: vec![level; field.size() * field.size()],
        }
    }

    /// Points per side, the same as the field's.
    pub fn size(&self) -> usize {
        self.size
    }

    /// Light reaching the grid point at column `x`, row `y`.
    #[inline]
    pub fn lit(&self, x: usize, y: usize) -> f32 {
        self.lit[y * self.size + x] as f32 * (1.0 / 255.0)
    }
}

/// Computes which points of `field` the light from direction `light` reaches.
///
/// `light` points from the ground towards the light, z up, y towards the back
/// (row 0). A light straight overhead (or an unusable vector) casts no
/// shadows; a light at or below the horizon leaves every point dark.
pub fn cast(field: &Heightfield, light: Vec3) -> ShadowMap {
    // Grid rows run from the back, so the light's grid direction flips y.
    let (gx, gy) = (light.x, -light.y);
    let flat = gx.hypot(gy);
    if !(flat.is_finite() && light.z.is_finite()) || flat < 1e-6 * light.z.abs() {
        return ShadowMap::all_lit(field);
    }
    if light.z <= 0.0 {
        return ShadowMap::uniform(field, 0);
    }
    let n = field.size();
    let spacing = field.extent().abs() / (n - 1) as f32;
    let rise = light.z / flat * spacing;
    let mut map = ShadowMap::uniform(field, 255);
    if gy.abs() >= gx.abs() {
        sweep(
            field.heights(),
            n,
            &mut map.lit,
            gx / gy.abs(),
            gy > 0.0,
            rise,
        );
    } else {
        // Sweeping along columns would make every point wait for its
        // neighbour; on the transposed grid the rows are independent again.
        let heights = transpose(field.heights(), n);
        let mut lit = vec![255; n * n];
        sweep(&heights, n, &mut lit, gy / gx.abs(), gx > 0.0, rise);
        map.lit = transpose(&lit, n);
    }
    map
}

/// Light in 1/255ths for a point at `h` under a ray arriving at `ray`.
#[inline]
fn light_level(h: f32, ray: f32, per_height: f32) -> u8 {
    let t = 1.0 + (h - ray) * per_height;
    // NaN (from bad heights) casts to 0: dark, never a panic.
    (t.clamp(0.0, 1.0) * 255.0 + 0.5) as u8
}

/// The horizon sweep over an `n` x `n` row-major grid for a light whose rays
/// reach each row from the row before (nearer the light), offset by `dx`
/// columns (|dx| <= 1). `towards_end` is true when the light lies towards
/// the last row, so the sweep starts there. `rise` is the light's rise per
/// cell of horizontal distance.
fn sweep(heights: &[f32], n: usize, lit: &mut [u8], dx: f32, towards_end: bool, rise: f32) {
    let drop = rise * (1.0 + dx * dx).sqrt();
    let per_height = 1.0 / (PENUMBRA * rise);
    // dx = 1 exactly takes all of the right source, keeping the slice in range.
    let base = dx.floor().min(0.0);
    let w = dx - base;
    // Index of the left source in rows padded with NONE on both sides.
    let first = (base as isize + 1) as usize;
    let mut prev = vec![NONE; n + 2];
    let mut next = vec![NONE; n + 2];
    for k in 0..n {
        let y = if towards_end { n - 1 - k } else { k };
        let row = &heights[y * n..(y + 1) * n];
        let out = &mut lit[y * n..(y + 1) * n];
        let left = &prev[first..first + n];
        let right = &prev[first + 1..first + 1 + n];
        let horizon = &mut next[1..=n];
        for x in 0..n {
            let ray = left[x] * (1.0 - w) + right[x] * w - drop;
            out[x] = light_level(row[x], ray, per_height);
            horizon[x] = ray.max(row[x]);
        }
        std::mem::swap(&mut prev, &mut next);
    }
}

/// The `n` x `n` grid with rows and columns swapped, in cache-sized tiles.
fn transpose<T: Copy>(grid: &[T], n: usize) -> Vec<T> {
    const TILE: usize = 32;
    let mut out = grid.to_vec();
    for ty in (0..n).step_by(TILE) {
        for tx in (0..n).step_by(TILE) {
            for y in ty..(ty + TILE).min(n) {
                for x in tx..(tx + TILE).min(n) {
                    out[x * n + y] = grid[y * n + x];
                }
            }
        }
    }
    out
}
