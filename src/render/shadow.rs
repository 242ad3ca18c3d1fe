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
    let heights = field.heights();
    if gy.abs() >= gx.abs() {
        sweep(
            heights,
            n,
            &mut map.lit,
            gx / gy.abs(),
            gy > 0.0,
            rise,
            false,
        );
    } else {
        // Sweeping along rows would make every point wait for its left or
        // right neighbour; sweeping columns keeps a line's points independent.
        sweep(
            heights,
            n,
            &mut map.lit,
            gy / gx.abs(),
            gx > 0.0,
            rise,
            true,
        );
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

/// The horizon sweep over an `n` x `n` row-major grid, one line at a time:
/// rows, or columns if `columns`. The light's rays reach each line from the
/// line before (nearer the light), offset by `dx` points along it (|dx| <= 1).
/// `towards_end` is true when the light lies towards the last line, so the
/// sweep starts there. `rise` is the light's rise per cell of horizontal
/// distance.
fn sweep(
    heights: &[f32],
    n: usize,
    lit: &mut [u8],
    dx: f32,
    towards_end: bool,
    rise: f32,
    columns: bool,
) {
    let mut sweeper = Sweeper::new(n, dx, rise);
    let order = |k: usize| if towards_end { n - 1 - k } else { k };
    if !columns {
        for k in 0..n {
            let span = order(k) * n..(order(k) + 1) * n;
            sweeper.line(&heights[span.clone()], &mut lit[span]);
        }
        return;
    }
    // Columns a block at a time: reading one column alone would touch a
    // cache line per point, in lines a power of two apart that evict each
    // other; a block uses every line it reads in full. The block's own lines
    // are padded apart so that its write streams do not collide either.
    let stride = n.div_ceil(16) * 16 + 16 * 5;
    let mut block = vec![0.0; COLUMN_BLOCK * stride];
    let mut block_lit = vec![0u8; COLUMN_BLOCK * stride];
    for k0 in (0..n).step_by(COLUMN_BLOCK) {
        let count = COLUMN_BLOCK.min(n - k0);
        let lo = order(k0).min(order(k0 + count - 1));
        for (j, row) in heights.chunks_exact(n).enumerate() {
            for (b, &h) in row[lo..lo + count].iter().enumerate() {
                block[b * stride + j] = h;
            }
        }
        for k in k0..k0 + count {
            let span = (order(k) - lo) * stride..(order(k) - lo) * stride + n;
            sweeper.line(&block[span.clone()], &mut block_lit[span]);
        }
        for (j, row) in lit.chunks_exact_mut(n).enumerate() {
            for (b, l) in row[lo..lo + count].iter_mut().enumerate() {
                *l = block_lit[b * stride + j];
            }
        }
    }
}

/// Columns swept per block in a column sweep: two cache lines of heights
/// per row, which the processor fetches as a pair. Each row is a page or
/// more from the next, so a block pays a miss per row: 32 columns took the
/// 4K sweep from 24 to 16 ms against 16 (64 was slower again: its write
/// streams collide).
const COLUMN_BLOCK: usize = 32;

/// The state of a sweep: the horizons over the last line swept.
struct Sweeper {
    /// Horizons of the last line, padded with `NONE` at both ends.
    prev: Vec<f32>,
    /// The line being swept, the same shape.
    next: Vec<f32>,
    /// Index in `prev` of the left source of a line's first point.
    first: usize,
    /// Weight of the right of the two source points.
    w: f32,
    /// How far a ray falls from one line to the next.
    drop: f32,
    /// Light lost per height unit below the arriving ray.
    per_height: f32,
}

impl Sweeper {
    /// A sweep over lines of `n` points whose rays come `dx` points across.
    fn new(n: usize, dx: f32, rise: f32) -> Self {
        // dx = 1 exactly takes all of the right source, keeping slices in range.
        let base = dx.floor().min(0.0);
        Sweeper {
            prev: vec![NONE; n + 2],
            next: vec![NONE; n + 2],
            first: (base as isize + 1) as usize,
            w: dx - base,
            drop: rise * (1.0 + dx * dx).sqrt(),
            per_height: 1.0 / (PENUMBRA * rise),
        }
    }

    /// Lights the next line of `heights` into `out` from the horizons of the
    /// line before, and keeps this line's horizons for the one after.
    #[inline]
    fn line(&mut self, heights: &[f32], out: &mut [u8]) {
        let n = heights.len();
        let left = &self.prev[self.first..self.first + n];
        let right = &self.prev[self.first + 1..self.first + 1 + n];
        let (out, horizon) = (&mut out[..n], &mut self.next[1..=n]);
        for x in 0..n {
            let ray = left[x] * (1.0 - self.w) + right[x] * self.w - self.drop;
            out[x] = light_level(heights[x], ray, self.per_height);
            horizon[x] = ray.max(heights[x]);
        }
        std::mem::swap(&mut self.prev, &mut self.next);
    }
}
