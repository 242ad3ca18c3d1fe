//! The square grid of elevations every generator fills and every renderer reads.

use std::sync::Arc;

use super::lakes::Lakes;

/// The grid exponents a heightfield can have (the `detail` key's range).
pub use crate::settings::{MAX_GRID_EXPONENT as MAX_EXPONENT, MIN_GRID_EXPONENT as MIN_EXPONENT};

/// The coarsest grid [`Heightfield::coarsened`] makes (17x17): the passes
/// that coarsen (Sonar's legible mesh, shadows, sky light, erosion) were
/// tuned no coarser, though a field itself may be 9x9 (`detail = 3`).
pub const COARSENED_LEAST_EXPONENT: u32 = 4;

/// Most a field is drawn spanning, from the lower of its lowest point and
/// sea level to the higher of its highest point and sea level, in widths
/// (see [`Heightfield::drawn`]).
pub const MAX_DRAWN_RELIEF: f32 = 2.0;

/// A square grid of `2^n + 1` points a side of `f32` elevations, sea level at 0.
///
/// Row `y` runs from the back of the mountain (`y = 0`) to the front
/// (`y = size - 1`); column `x` from left to right. `extent` is the width of
/// the whole grid in the same units as the heights, so a renderer knows the
/// true aspect of the relief. `seed` is the seed that made the heights,
/// where one did: the mountain's identity at every grid size.
#[derive(Debug, Clone, PartialEq)]
pub struct Heightfield {
    exponent: u32,
    size: usize,
    extent: f32,
    heights: Vec<f32>,
    seed: Option<u64>,
    lakes: Option<Arc<Lakes>>,
}

impl Heightfield {
    /// A flat field at sea level with `2^exponent + 1` points a side.
    ///
    /// Panics if `exponent` is outside `MIN_EXPONENT..=MAX_EXPONENT`: callers
    /// validate user input before this point.
    pub fn flat(exponent: u32, extent: f32) -> Self {
        assert!(
            (MIN_EXPONENT..=MAX_EXPONENT).contains(&exponent),
            "grid exponent {exponent} outside {MIN_EXPONENT}..={MAX_EXPONENT}"
        );
        let size = (1usize << exponent) + 1;
        Heightfield {
            exponent,
            size,
            extent,
            heights: zeroed(size * size),
            seed: None,
            lakes: None,
        }
    }

    /// Wraps existing heights (row-major, `size * size` of them).
    ///
    /// Returns `None` if `size` is not `2^n + 1` with n in range, or the
    /// number of heights does not match.
    pub fn from_heights(size: usize, extent: f32, heights: Vec<f32>) -> Option<Self> {
        let exponent = (MIN_EXPONENT..=MAX_EXPONENT).find(|&n| (1usize << n) + 1 == size)?;
        (heights.len() == size * size).then_some(Heightfield {
            exponent,
            size,
            extent,
            heights,
            seed: None,
            lakes: None,
        })
    }

    /// The grid exponent n: the field has `2^n + 1` points a side.
    pub fn exponent(&self) -> u32 {
        self.exponent
    }

    /// Points per side.
    pub fn size(&self) -> usize {
        self.size
    }

    /// Width of the whole grid in height units.
    pub fn extent(&self) -> f32 {
        self.extent
    }

    /// Changes the horizontal extent (e.g. after a heightmap is loaded).
    pub fn set_extent(&mut self, extent: f32) {
        self.extent = extent;
    }

    /// Elevation at column `x`, row `y`.
    #[inline]
    pub fn get(&self, x: usize, y: usize) -> f32 {
        self.heights[y * self.size + x]
    }

    /// Sets the elevation at column `x`, row `y`.
    #[inline]
    pub fn set(&mut self, x: usize, y: usize, h: f32) {
        self.heights[y * self.size + x] = h;
    }

    /// One row of elevations, back (`y = 0`) to front.
    pub fn row(&self, y: usize) -> &[f32] {
        &self.heights[y * self.size..(y + 1) * self.size]
    }

    /// The seed that made these heights, if known (a generated field, or a
    /// data set whose file names its seed).
    pub fn seed(&self) -> Option<u64> {
        self.seed
    }

    /// Records the seed that made these heights (`None`: not known).
    pub fn set_seed(&mut self, seed: Option<u64>) {
        self.seed = seed;
    }

    /// The number a mountain's scene is drawn from (its time of day, its
    /// sea): the same at every grid size, so a seed looks the same at every
    /// frame size, detail and `low_detail`. It comes from the seed where
    /// there is one: the heights at the points every grid size shares are
    /// not the same at every size (erosion runs on the grid itself below
    /// 129 points a side, and the water line is a percentile of each grid's
    /// own heights). A field without a seed (a foreign data set) is shown as
    /// it is at every frame size, so its [`Heightfield::fingerprint`] serves.
    pub fn identity(&self) -> u64 {
        match self.seed {
            Some(seed) => super::splitmix::mix(seed ^ IDENTITY_KEY),
            None => self.fingerprint(),
        }
    }

    /// A value-stable hash of the size, extent and (sampled) heights: the
    /// same grid always gives the same number. It changes with the grid
    /// size; [`Heightfield::identity`] does not.
    pub fn fingerprint(&self) -> u64 {
        let step = |z: u64| super::splitmix::mix(z.wrapping_add(super::splitmix::GOLDEN));
        let stride = (self.heights.len() / 4096).max(1);
        let mut h = step(self.size as u64 ^ u64::from(self.extent.to_bits()) << 32);
        for v in self.heights.iter().step_by(stride) {
            h = step(h ^ u64::from(v.to_bits()));
        }
        h
    }

    /// The lakes over these heights, if they were looked for
    /// (`lakes = true`): basins above the sea filled to their lowest lip.
    pub fn lakes(&self) -> Option<&Lakes> {
        self.lakes.as_deref()
    }

    /// Sets the lakes (`None`: no lakes drawn). They must belong to these
    /// heights: a change to the heights drops them (see `heights_mut`).
    pub fn set_lakes(&mut self, lakes: Option<Arc<Lakes>>) {
        self.lakes = lakes.filter(|l| l.size() == self.size);
    }

    /// All elevations, row-major.
    pub fn heights(&self) -> &[f32] {
        &self.heights
    }

    /// All elevations, row-major, for generators that fill them in place.
    /// The lakes, which the old heights held, are dropped.
    pub fn heights_mut(&mut self) -> &mut [f32] {
        self.lakes = None;
        &mut self.heights
    }

    /// Lowest elevation.
    pub fn min(&self) -> f32 {
        self.min_max().0
    }

    /// Highest elevation.
    pub fn max(&self) -> f32 {
        self.min_max().1
    }

    /// Lowest and highest elevation, in one pass over the field (a 4K
    /// frame's grid holds four million points).
    pub fn min_max(&self) -> (f32, f32) {
        min_max(&self.heights)
    }

    /// What its heights are multiplied by to be drawn: 1, unless its land
    /// and sea span more than [`MAX_DRAWN_RELIEF`] widths. A data set can be
    /// far taller than it is wide (a spike on a tiny grid, land lifted far
    /// over its sea by its file's keys): drawn true, it is a needle thinner
    /// than a pixel, or nothing at all.
    pub fn drawn_scale(&self) -> f32 {
        let (lo, hi) = self.min_max();
        let span = hi.max(0.0) - lo.min(0.0);
        let most = MAX_DRAWN_RELIEF * self.extent;
        if span > most && most > 0.0 {
            most / span
        } else {
            1.0
        }
    }

    /// The field as it is drawn: itself, or with its heights (and lakes'
    /// levels) scaled by [`Heightfield::drawn_scale`].
    pub fn drawn(&self) -> Option<Heightfield> {
        let f = self.drawn_scale();
        (f < 1.0).then(|| Heightfield {
            heights: self.heights.iter().map(|h| h * f).collect(),
            lakes: self.lakes.as_ref().map(|l| Arc::new(l.scaled(f))),
            ..*self
        })
    }

    /// Every `2^levels`-th point in both directions: the same mountain on a
    /// coarser grid. Subdivision grids nest, so for a generated field this is
    /// exactly what a lower detail level would have produced from the same
    /// seed. `levels` is limited so the result keeps 17x17
    /// ([`COARSENED_LEAST_EXPONENT`]); a smaller field is returned as it is.
    pub fn coarsened(&self, levels: u32) -> Heightfield {
        let levels = levels.min(self.exponent.saturating_sub(COARSENED_LEAST_EXPONENT));
        let exponent = self.exponent - levels;
        let stride = 1usize << levels;
        let size = (1usize << exponent) + 1;
        let mut heights = Vec::with_capacity(size * size);
        for y in 0..size {
            let row = self.row(y * stride);
            heights.extend((0..size).map(|x| row[x * stride]));
        }
        Heightfield {
            exponent,
            size,
            extent: self.extent,
            heights,
            seed: self.seed,
            lakes: None,
        }
    }
}

/// Mixed into a seed for [`Heightfield::identity`], so the scene's draws
/// are not the terrain noise's own first numbers.
const IDENTITY_KEY: u64 = 0x7363_656e_6520_6964;

/// Fields this large ask the kernel for huge pages: faulting in a fresh
/// field of many MiB one 4 KiB page at a time costs about as much as
/// generating it.
const HUGE_PAGE_BYTES: usize = 8 << 20;

/// `len` zeros, backed by transparent huge pages where the OS offers them
/// on request (Linux with THP in `madvise` mode). Only a hint: elsewhere,
/// or if refused, an ordinary zeroed vector.
fn zeroed(len: usize) -> Vec<f32> {
    let bytes = len * std::mem::size_of::<f32>();
    if bytes < HUGE_PAGE_BYTES {
        return vec![0.0; len];
    }
    let mut v: Vec<f32> = Vec::with_capacity(len);
    crate::platform::os::advise_huge_pages(v.as_mut_ptr().cast(), bytes);
    v.resize(len, 0.0);
    v
}

/// Lowest and highest of `heights` (NaN is skipped unless all are NaN:
/// `f32::min` and `max` prefer the number).
///
/// Eight running extremes, one per lane, so the steps do not wait on each
/// other: every scene looks at its whole field's extremes (the palette's
/// zones, how tall it is drawn), millions of points at 4K (callgrind, 1080p
/// seed 42: 5.5 M instructions a pass before, 4.1 M after).
pub fn min_max(heights: &[f32]) -> (f32, f32) {
    const LANES: usize = 8;
    let mut lo = [f32::INFINITY; LANES];
    let mut hi = [f32::NEG_INFINITY; LANES];
    let chunks = heights.chunks_exact(LANES);
    let rest = chunks.remainder();
    for chunk in chunks {
        for i in 0..LANES {
            lo[i] = lo[i].min(chunk[i]);
            hi[i] = hi[i].max(chunk[i]);
        }
    }
    let start = (lo.into_iter().fold(f32::INFINITY, f32::min))
        .min(rest.iter().copied().fold(f32::INFINITY, f32::min));
    let end = (hi.into_iter().fold(f32::NEG_INFINITY, f32::max))
        .max(rest.iter().copied().fold(f32::NEG_INFINITY, f32::max));
    (start, end)
}

#[cfg(test)]
mod tests {
    use super::min_max;

    /// The lanes give what one running pair gives: the extremes wherever
    /// they stand (in a lane or in the tail), NaN skipped, empty as
    /// (inf, -inf).
    #[test]
    fn extremes_are_found_in_every_lane_and_the_tail() {
        let one_by_one = |h: &[f32]| {
            h.iter()
                .fold((f32::INFINITY, f32::NEG_INFINITY), |(lo, hi), &v| {
                    (lo.min(v), hi.max(v))
                })
        };
        for len in 0..40 {
            for at in 0..len.max(1) {
                let mut h: Vec<f32> = (0..len).map(|i| (i * 7 % 5) as f32).collect();
                if len > 0 {
                    h[at] = -3.5;
                    h[(at + 3) % len] = 9.25;
                    h[(at + 5) % len] = f32::NAN;
                }
                let (a, b) = (min_max(&h), one_by_one(&h));
                assert_eq!(
                    (a.0.to_bits(), a.1.to_bits()),
                    (b.0.to_bits(), b.1.to_bits()),
                    "{h:?}"
                );
            }
        }
    }
}
