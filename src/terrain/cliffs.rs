//! `cliffs`: the occasional sharp edge FL3's author missed in every
//! subdivided landscape ("cliffs, mesas, canyons"). After the subdivision,
//! the erosion and the water line, the land is cut into terraces: within
//! each step of [`STEP_SHARE`] of the grid's width in height, a height is
//! raised to a power that grows with `cliffs`, so most of the step becomes
//! a nearly level bench and its top a steep face, the rock of the next
//! bench standing over it as a mesa's rim. The steps are level, as strata
//! are: where a slope is gentle a bench is wide, where it is steep the
//! faces stack into a cliff.
//!
//! The first step above the sea is left alone, so the coast keeps its
//! shape and the lowlands their slopes.
//!
//! Pointwise, so the same at every detail and on any thread count; at
//! `cliffs = 0` it is not run at all, and every height keeps its bits.

use super::heightfield::Heightfield;
use super::normalize::{PowTable, map_in_place};

/// Height of one step, as a share of the grid's width in height units
/// (7.5 for the square generators' 250: a dozen steps in their relief).
pub const STEP_SHARE: f32 = 0.03;
/// The power on a step's share at `cliffs = 1`: the last tenth of a step
/// holds two thirds of its rise.
const MAX_POWER: f32 = 11.0;

/// Terraces the land of `field` above its first step with `strength`
/// in `0..=1`; 0 (or NaN) leaves every height as it is.
pub(crate) fn terrace(field: &mut Heightfield, strength: f32, threads: usize) {
    if strength.is_nan() || strength <= 0.0 {
        return;
    }
    let step = STEP_SHARE * field.extent();
    if step.is_nan() || step <= 0.0 || step.is_infinite() {
        return;
    }
    // Squared: the faces sharpen gently at first (a power of 3.5 at 0.5
    // already makes sheer mesas).
    let c = strength.min(1.0);
    let power = PowTable::new(1.0 + (MAX_POWER - 1.0) * c * c);
    let inverse = 1.0 / step;
    map_in_place(field.heights_mut(), threads, |h| {
        // The first step, the shore and the lowlands, keeps its slopes: a
        // bench at sea level would flatten every coast into a beach.
        if h.is_nan() || h <= step || h.is_infinite() {
            return h;
        }
        let u = h * inverse;
        let k = u.floor();
        (k + power.of(u - k)) * step
    });
}
