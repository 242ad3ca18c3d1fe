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
//! A field finer than `MAX_SWEPT` points a side is swept at every
//! `2^shift`-th point, read in place (a coarser copy would be another field
//! held beside the frame while the next mountain is made).
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

/// Finest grid the sweep runs on, in points a side: a finer field (a 4K
/// frame's 2049) is swept on every second point and its light read back
/// bilinearly. The sweep's lines wait on memory and run while the other
/// cores wait, so a finer sweep is a large share of a 4K frame's start;
/// its shadows at 4 to 8 pixels a swept cell look no different (compared
/// at 1:1), the faces keep their own slopes.
const MAX_SWEPT: usize = 1025;

/// Per grid point, how much direct light arrives (1 lit, 0 shadowed).
#[derive(Debug, Clone)]
pub struct ShadowMap {
    /// Points a side of the field it answers for.
    size: usize,
    /// Points a side of the swept grid: every `2^shift`-th of the field's.
    swept: usize,
    shift: u32,
    /// Light per swept point in 1/255ths, row-major.
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
            swept: field.size(),
            shift: 0,
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
        if self.shift == 0 {
            return self.lit[y * self.swept + x] as f32 * (1.0 / 255.0);
        }
        let (step, mask) = (1u32 << self.shift, (1usize << self.shift) - 1);
        let (x0, y0) = (x >> self.shift, y >> self.shift);
        let (x1, y1) = ((x0 + 1).min(self.swept - 1), (y0 + 1).min(self.swept - 1));
        let (tx, ty) = ((x & mask) as u32, (y & mask) as u32);
        let at = |x: usize, y: usize| u32::from(self.lit[y * self.swept + x]);
        let top = at(x0, y0) * (step - tx) + at(x1, y0) * tx;
        let bottom = at(x0, y1) * (step - tx) + at(x1, y1) * tx;
        let sum = top * (step - ty) + bottom * ty;
        sum as f32 * (1.0 / (255 << (2 * self.shift)) as f32)
    }
}

/// Computes which points of `field` the light from direction `light` reaches.
///
/// `light` points from the ground towards the light, z up, y towards the back
/// (row 0). A light straight overhead (or an unusable vector) casts no
/// shadows; a light at or below the horizon leaves every point dark.
pub fn cast(field: &Heightfield, light: Vec3) -> ShadowMap {
    cast_within(field, light, MAX_SWEPT)
}

/// [`cast`], sweeping at most `max_swept` points a side.
fn cast_within(field: &Heightfield, light: Vec3, max_swept: usize) -> ShadowMap {
    // Grid rows run from the back, so the light's grid direction flips y.
    let (gx, gy) = (light.x, -light.y);
    let flat = gx.hypot(gy);
    if !(flat.is_finite() && light.z.is_finite()) || flat < 1e-6 * light.z.abs() {
        return ShadowMap::all_lit(field);
    }
    if light.z <= 0.0 {
        return ShadowMap::uniform(field, 0);
    }
    let mut shift = 0;
    while (field.size() - 1) >> shift > max_swept - 1 {
        shift += 1;
    }
    // The field's every `2^shift`-th point both ways (the points a
    // coarsened field holds), read in place: such a copy of a 4K slide's
    // field took 4 MB, made while the frame on screen and the next field
    // were held.
    let heights = Grid {
        heights: field.heights(),
        side: field.size(),
        step: 1 << shift,
        n: ((field.size() - 1) >> shift) + 1,
    };
    let n = heights.n;
    let spacing = field.extent().abs() / (n - 1) as f32;
    let rise = light.z / flat * spacing;
    let mut map = ShadowMap {
        size: field.size(),
        swept: n,
        shift,
        lit: vec![255; n * n],
    };
    if gy.abs() >= gx.abs() {
        sweep(heights, &mut map.lit, gx / gy.abs(), gy > 0.0, rise, false);
    } else {
        // Sweeping along rows would make every point wait for its left or
        // right neighbour; sweeping columns keeps a line's points independent.
        sweep(heights, &mut map.lit, gy / gx.abs(), gx > 0.0, rise, true);
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

/// The points a shadow sweep reads: every `step`-th of a field's
/// (`side` points a side, row-major) both ways, `n` a side.
#[derive(Clone, Copy)]
struct Grid<'a> {
    heights: &'a [f32],
    side: usize,
    step: usize,
    n: usize,
}

impl<'a> Grid<'a> {
    /// Where point `x` of row `y` lies in `heights`.
    fn at(&self, x: usize, y: usize) -> usize {
        (y * self.side + x) * self.step
    }

    /// Row `y`: in place when every point is read, else gathered into `buf`.
    fn row<'b>(&self, y: usize, buf: &'b mut Vec<f32>) -> &'b [f32]
    where
        'a: 'b,
    {
        let row = &self.heights[self.at(0, y)..];
        if self.step == 1 {
            return &row[..self.n];
        }
        buf.clear();
        buf.extend(row.iter().step_by(self.step).take(self.n));
        buf
    }
}

/// The horizon sweep over the grid `heights`, one line at a time: rows, or
/// columns if `columns`. The light's rays reach each line from the line
/// before (nearer the light), offset by `dx` points along it (|dx| <= 1).
/// `towards_end` is true when the light lies towards the last line, so the
/// sweep starts there. `rise` is the light's rise per cell of horizontal
/// distance.
fn sweep(heights: Grid, lit: &mut [u8], dx: f32, towards_end: bool, rise: f32, columns: bool) {
    let n = heights.n;
    let mut sweeper = Sweeper::new(n, dx, rise);
    let order = |k: usize| if towards_end { n - 1 - k } else { k };
    if !columns {
        let mut buf = Vec::new();
        for k in 0..n {
            let span = order(k) * n..(order(k) + 1) * n;
            sweeper.line(heights.row(order(k), &mut buf), &mut lit[span]);
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
    let step = heights.step;
    for k0 in (0..n).step_by(COLUMN_BLOCK) {
        let count = COLUMN_BLOCK.min(n - k0);
        let lo = order(k0).min(order(k0 + count - 1));
        for j in 0..n {
            let ahead = heights.at(lo, j + AHEAD);
            prefetch(heights.heights.get(ahead..ahead + (count - 1) * step + 1));
            let row = &heights.heights[heights.at(lo, j)..];
            if step == 1 {
                for (b, &h) in row[..count].iter().enumerate() {
                    block[b * stride + j] = h;
                }
            } else {
                for (b, &h) in row.iter().step_by(step).take(count).enumerate() {
                    block[b * stride + j] = h;
                }
            }
        }
        for k in k0..k0 + count {
            let span = (order(k) - lo) * stride..(order(k) - lo) * stride + n;
            sweeper.line(&block[span.clone()], &mut block_lit[span]);
        }
        for j in 0..n {
            prefetch(lit.get((j + AHEAD) * n + lo..(j + AHEAD) * n + lo + count));
            let row = &mut lit[j * n..(j + 1) * n];
            for (b, l) in row[lo..lo + count].iter_mut().enumerate() {
                *l = block_lit[b * stride + j];
            }
        }
    }
}

/// Rows ahead whose part of a block is fetched early: every row lies a page
/// or more from the next, where the processor's own prefetching stops, so a
/// block's gather and scatter otherwise wait on a miss per row. From 4 to
/// 8 rows ahead did alike (of 4 to 24 tried); far fewer leave the misses,
/// far more fetch lines evicted before their use.
const AHEAD: usize = 8;

/// Asks for the cache lines holding the first and last item of `items`
/// (none: nothing), ahead of their use. Only a hint: the same results
/// without it.
#[inline(always)]
fn prefetch<T>(items: Option<&[T]>) {
    #[cfg(target_arch = "x86_64")]
    if let Some(items) = items {
        use std::arch::x86_64::{_MM_HINT_T0, _mm_prefetch};
        for p in [items.first(), items.last()].into_iter().flatten() {
            // SAFETY: SSE is part of every x86-64 processor, and a prefetch
            // never faults or changes memory; both pointers lie in `items`.
            unsafe { _mm_prefetch::<_MM_HINT_T0>((p as *const T).cast()) };
        }
    }
    #[cfg(not(target_arch = "x86_64"))]
    let _ = items;
}

/// Columns swept per block in a column sweep: two cache lines of heights
/// per row, which the processor fetches as a pair. Each row is a page or
/// more from the next, so a block pays a miss per row, and a wider block
/// shares it among more columns; at 64 its write streams collide.
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::settings::{Detail, Settings};

    fn mountain(exponent: u32) -> Heightfield {
        let settings = Settings {
            detail: Detail::Level(exponent),
            ..Settings::default()
        };
        crate::terrain::generate(&settings, 42)
    }

    const SUN: Vec3 = Vec3::new(0.6, 0.55, 0.35);

    #[test]
    fn a_fine_field_is_swept_on_every_second_point_and_read_between_them() {
        let field = mountain(11);
        let map = cast(&field, SUN);
        let swept = cast(&field.coarsened(1), SUN);
        assert_eq!((map.size(), swept.size()), (2049, 1025));
        for y in (0..1024).step_by(7) {
            for x in (0..1024).step_by(5) {
                let at = |x, y| swept.lit(x, y);
                assert_eq!(map.lit(2 * x, 2 * y), at(x, y));
                let across = (at(x, y) + at(x + 1, y)) / 2.0;
                let down = (at(x, y) + at(x, y + 1)) / 2.0;
                assert!((map.lit(2 * x + 1, 2 * y) - across).abs() < 1e-6);
                assert!((map.lit(2 * x, 2 * y + 1) - down).abs() < 1e-6);
            }
        }
        assert_eq!(map.lit(2048, 2048), swept.lit(1024, 1024));
    }

    #[test]
    fn a_fine_field_read_in_place_is_lit_as_its_coarsened_copy() {
        let field = mountain(11);
        // A sweep along columns, then one along rows.
        for sun in [SUN, Vec3::new(-0.3, 0.8, 0.25)] {
            let (map, copy) = (cast(&field, sun), cast(&field.coarsened(1), sun));
            assert_eq!((map.swept, map.shift, copy.shift), (1025, 1, 0));
            assert!(map.lit == copy.lit, "{sun}: another light somewhere");
        }
    }

    #[test]
    fn shadows_swept_coarse_match_the_full_sweep() {
        let field = mountain(11);
        for sun in [SUN, Vec3::new(-0.3, 0.8, 0.25), Vec3::new(0.9, -0.1, 0.3)] {
            let fine = cast_within(&field, sun, usize::MAX);
            let coarse = cast(&field, sun);
            let n = field.size();
            let (mut off, mut shade_fine, mut shade_coarse) = (0usize, 0.0, 0.0);
            for y in 0..n {
                for x in 0..n {
                    let (a, b) = (fine.lit(x, y), coarse.lit(x, y));
                    off += usize::from((a - b).abs() > 0.5);
                    shade_fine += 1.0 - a;
                    shade_coarse += 1.0 - b;
                }
            }
            let points = (n * n) as f32;
            // The same share of the land in shadow, and few points whose
            // light is turned round (at the shadows' edges).
            assert!(shade_fine / points > 0.05, "{sun}: hardly any shadow");
            assert!((shade_coarse / shade_fine - 1.0).abs() < 0.08, "{sun}");
            assert!((off as f32) < 0.02 * points, "{sun}: {off} points");
        }
    }
}
