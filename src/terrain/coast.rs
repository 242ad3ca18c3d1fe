//! `water_line = "coast"`: a water line that gives every mountain a coast.
//!
//! Fields started from four random corners are often a tilted plane: with
//! the water line at the generator's zero about one map in six is nearly all
//! sea and as many nearly all land. Putting the water line at a fixed share
//! of the heights ([`COAST_SEA_SHARE`]) makes every map part land, part sea;
//! holding the front rows low (xmountains' `force_front`) puts the water in
//! front of the viewer and keeps a ridge on the near edge from hiding the
//! land behind it. The subdivision itself is untouched: with
//! `water_line = "generator"` the square generator is Mountain Terrain's.

use super::Heightfield;
use crate::settings::COAST_SEA_SHARE;

/// Heights sampled for the water line: enough for a percentile good to a
/// fraction of a percent, few enough to cost well under a millisecond.
const SAMPLES: usize = 1 << 16;
/// Share of the rows, at the front, that are lowered into the sea.
const FRONT_BAND: f32 = 0.18;
/// Depth the front edge is lowered to, as a fraction of the grid's width.
const FRONT_DEPTH: f32 = 0.01;

/// The height with [`COAST_SEA_SHARE`] of the (sampled) heights below it.
/// NaN heights count as the lowest.
pub(crate) fn reference(heights: &[f32]) -> f32 {
    if heights.is_empty() {
        return 0.0;
    }
    let stride = heights.len().div_ceil(SAMPLES).max(1);
    let mut sample: Vec<f32> = heights.iter().step_by(stride).copied().collect();
    let k = ((sample.len() - 1) as f32 * COAST_SEA_SHARE) as usize;
    let (_, &mut at, _) = sample.select_nth_unstable_by(k, |a, b| a.total_cmp(b));
    if at.is_finite() { at } else { 0.0 }
}

/// Lowers the front rows smoothly to [`FRONT_DEPTH`] below the water line
/// (ground already deeper keeps its depth).
pub(crate) fn lower_the_front(field: &mut Heightfield) {
    let n = field.size();
    let floor = -FRONT_DEPTH * field.extent();
    let last = (n - 1).max(1) as f32;
    let heights = field.heights_mut();
    for (y, row) in heights.chunks_mut(n).enumerate() {
        let t = smoothstep(1.0 - FRONT_BAND, 1.0, y as f32 / last);
        if t <= 0.0 {
            continue;
        }
        for h in row {
            if *h > floor {
                *h += (floor - *h) * t;
            }
        }
    }
}

/// Hermite step from 0 at `e0` to 1 at `e1`.
fn smoothstep(e0: f32, e1: f32, x: f32) -> f32 {
    let t = ((x - e0) / (e1 - e0)).clamp(0.0, 1.0);
    t * t * (3.0 - 2.0 * t)
}
