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
use super::curves::smoothstep;
use crate::settings::COAST_SEA_SHARE;

/// Share of the rows, at the front, that are lowered into the sea.
const FRONT_BAND: f32 = 0.3;
/// How far the front edge is lowered, as a fraction of the grid's width:
/// the band is tilted down by this much, so the new shore follows the
/// land's own contours rather than a straight line.
const FRONT_DROP: f32 = 0.1;
/// Depth the front edge ends at, at least, as a fraction of the grid's width.
const FRONT_DEPTH: f32 = 0.01;
/// Where in the band (0 back, 1 front) land still standing above the sea
/// starts to be pressed down to [`FRONT_DEPTH`].
const FRONT_PRESS: f32 = 0.6;

/// The height with [`COAST_SEA_SHARE`] of the heights below it, among
/// the points of the lattice every detail shares
/// ([`SHARED_EXPONENT`](super::SHARED_EXPONENT): 16641 points, a percentile
/// good to a fraction of a percent, for well under a millisecond), so the
/// water line, and with it every height, is the same at every detail.
/// NaN heights count as the lowest.
pub(crate) fn reference(field: &Heightfield) -> f32 {
    let stride = 1usize << field.exponent().saturating_sub(super::SHARED_EXPONENT);
    let mut sample: Vec<f32> = (0..field.size())
        .step_by(stride)
        .flat_map(|y| field.row(y).iter().step_by(stride).copied())
        .collect();
    if sample.is_empty() {
        return 0.0;
    }
    let k = ((sample.len() - 1) as f32 * COAST_SEA_SHARE) as usize;
    let (_, &mut at, _) = sample.select_nth_unstable_by(k, |a, b| a.total_cmp(b));
    if at.is_finite() { at } else { 0.0 }
}

/// Tilts the front rows down by up to [`FRONT_DROP`], and presses what
/// still stands at the very front down to [`FRONT_DEPTH`] below the water
/// line (ground already deeper keeps its depth).
pub(crate) fn lower_the_front(field: &mut Heightfield) {
    let n = field.size();
    let floor = -FRONT_DEPTH * field.extent();
    let drop = FRONT_DROP * field.extent();
    let last = (n - 1).max(1) as f32;
    let heights = field.heights_mut();
    for (y, row) in heights.chunks_mut(n).enumerate() {
        let t = smoothstep(1.0 - FRONT_BAND, 1.0, y as f32 / last);
        if t <= 0.0 {
            continue;
        }
        let press = smoothstep(FRONT_PRESS, 1.0, t);
        for h in row {
            let tilted = *h - drop * t;
            *h = if tilted > floor {
                tilted + (floor - tilted) * press
            } else {
                tilted
            };
        }
    }
}
