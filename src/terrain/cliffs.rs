//! `cliffs`: the occasional sharp edge FL3's author missed in every
//! subdivided landscape ("cliffs, mesas, canyons"). After the subdivision,
//! the erosion and the water line, the land is cut into terraces: within
//! each rock bed, a height's share of the bed is raised to a power that
//! grows with `cliffs`, so most of the bed becomes a nearly level bench
//! and its top a steep face, the rock of the next bench standing over it
//! as a mesa's rim. The beds are level, as strata are: where a slope is
//! gentle a bench is wide, where it is steep the faces stack into a cliff.
//!
//! The beds are of unequal thickness, drawn per mountain from its seed
//! (from under half to over one and a half times [`STEP_SHARE`] of the
//! grid's width in height): thick beds stand as tall cliffs, thin ones as
//! ledges between them, and no two mountains are cut alike. Equal steps
//! stacked every desert into the same stepped pyramid.
//!
//! The first step above the sea is left alone, so the coast keeps its
//! shape and the lowlands their slopes.
//!
//! Pointwise, so the same at every detail and on any thread count; at
//! `cliffs = 0` it is not run at all, and every height keeps its bits.

use super::heightfield::Heightfield;
use super::normalize::{PowTable, map_in_place};

/// The beds' mean thickness and the height of the untouched first step,
/// as a share of the grid's width in height units (7.5 for the square
/// generators' 250: a dozen beds in their relief).
pub const STEP_SHARE: f32 = 0.03;
/// The power on a bed's share at `cliffs = 1`: the last tenth of a bed
/// holds two thirds of its rise.
const MAX_POWER: f32 = 11.0;
/// The thinnest bed, in steps.
const THINNEST: f32 = 0.45;
/// How much thicker than the thinnest a bed may be, in steps.
const THICKER_BY: f32 = 1.2;
/// Mixed into the seed for the beds, apart from every other draw.
const STRATA_KEY: u64 = 0x7374_7261_7461_2121;
/// Beds drawn (over twice the grid's width in height, above any
/// generator's relief); above them the beds repeat.
const BEDS: usize = 160;

/// The rock beds of one mountain: where each begins and ends in height.
#[derive(Debug, Clone)]
pub struct Strata {
    /// Bed `j` runs from `bounds[j]` to `bounds[j + 1]`; `bounds[0]` is
    /// the first step's top.
    bounds: Vec<f32>,
    /// Per slice of [`THINNEST`] steps above the first step, the bed its
    /// bottom lies in (a slice holds at most one bound).
    slices: Vec<u16>,
    slice: f32,
}

impl Strata {
    /// The beds of the mountain of `seed` on a grid `extent` wide.
    pub fn of(seed: u64, extent: f32) -> Self {
        let step = STEP_SHARE * extent;
        let mut bounds = Vec::with_capacity(BEDS + 1);
        let mut top = step;
        bounds.push(top);
        for j in 0..BEDS as u64 {
            let draw = super::splitmix::mix(seed ^ STRATA_KEY ^ j.wrapping_mul(0x9e37_79b9));
            let u = super::splitmix::unit(draw);
            top += step * (THINNEST + THICKER_BY * u);
            bounds.push(top);
        }
        let slice = step * THINNEST;
        let count = ((top - step) / slice) as usize + 1;
        let mut bed = 0;
        let slices = (0..count)
            .map(|s| {
                let bottom = step + s as f32 * slice;
                while bed + 1 < BEDS && bounds[bed + 1] <= bottom {
                    bed += 1;
                }
                bed as u16
            })
            .collect();
        Strata {
            bounds,
            slices,
            slice,
        }
    }

    /// The bed height `h` (above the first step) lies in: its bottom and
    /// top. Above the drawn beds they repeat from the first.
    #[inline]
    pub fn bed(&self, h: f32) -> (f32, f32) {
        let (first, last) = (self.bounds[0], self.bounds[BEDS]);
        let span = last - first;
        let wrapped = if h < last {
            0.0
        } else {
            ((h - first) / span).floor() * span
        };
        let x = h - wrapped;
        let s = (((x - first) / self.slice) as usize).min(self.slices.len() - 1);
        let mut bed = self.slices[s] as usize;
        while bed + 1 < BEDS && self.bounds[bed + 1] <= x {
            bed += 1;
        }
        (self.bounds[bed] + wrapped, self.bounds[bed + 1] + wrapped)
    }
}

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
    let strata = Strata::of(field.seed().unwrap_or(0), field.extent());
    map_in_place(field.heights_mut(), threads, |h| {
        // The first step, the shore and the lowlands, keeps its slopes: a
        // bench at sea level would flatten every coast into a beach.
        if h.is_nan() || h <= step || h.is_infinite() {
            return h;
        }
        let (bottom, top) = strata.bed(h);
        let thick = top - bottom;
        (bottom + power.of((h - bottom) / thick) * thick).clamp(bottom, top)
    });
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_height_lies_in_its_bed_and_the_beds_follow_each_other() {
        let strata = Strata::of(7, 250.0);
        let step = STEP_SHARE * 250.0;
        let mut last = strata.bed(step * 1.001);
        assert_eq!(last.0, step, "the first bed starts at the first step's top");
        for i in 0..200_000 {
            let h = step * 1.001 + i as f32 * 0.01;
            let bed = strata.bed(h);
            let (bottom, top) = bed;
            assert!(bottom <= h && h < top, "{h} in {bottom}..{top}");
            assert!(top - bottom >= THINNEST * step * 0.999, "{bottom}..{top}");
            assert!(top - bottom <= (THINNEST + THICKER_BY) * step * 1.001);
            // The same bed as the height before, or the one on top of it.
            assert!(bed == last || bottom == last.1, "{bed:?} after {last:?}");
            last = bed;
        }
    }

    #[test]
    fn two_seeds_cut_their_beds_apart() {
        let (a, b) = (Strata::of(1, 250.0), Strata::of(2, 250.0));
        assert_ne!(a.bed(40.0), b.bed(40.0));
    }
}
