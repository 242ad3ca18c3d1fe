//! The essay's turns (seed 002, `left()` and `right()`): its square seen
//! from any multiple of 11.25 degrees (`increment = 0.125 * 0.5 *
//! Math.PI`). Its first view, `theta = Math.PI / 4`, is edge-on:
//! `theta` is the angle to a corner's diagonal, so `origin()` puts the
//! corners at (+-1024, +-1024), the front edge across the view. Our
//! turn counts from our own edge-on view (0 degrees), so our 45 degrees
//! is corner-on, not the essay's first view; the steps divide 45
//! degrees, so every view the essay reaches is one of ours, under
//! another number. `look = "essay"` turns each mountain by its own
//! number of steps, drawn from its identity as `sun = "varied"` draws
//! the light, so a slide show walks round the square and one seed is
//! always seen from one side.
//!
//! The field is resampled onto a grid of the same size turned by the
//! angle, wide enough to hold the turned square; points outside the
//! square are NaN, and the painters leave cells touching them undrawn.

use crate::terrain::Heightfield;

/// One press of the essay's buttons, in degrees.
pub const STEP_DEGREES: f32 = 11.25;
/// Where our turns start: 45 degrees, the square corner-on (the essay's
/// own first view, `theta = PI/4`, is edge-on: our 0 or 90; see the
/// module's comment). Kept so each seed keeps its view.
pub const START_DEGREES: f32 = 45.0;
/// Steps in a whole turn.
const STEPS: u64 = 32;

/// The turn, in degrees, the essay's look gives the mountain of `identity`:
/// its start and a whole number of steps.
pub fn essay_degrees(identity: u64) -> f32 {
    // The identity's high bits: its low ones also pick the light.
    let steps = (identity.rotate_left(23).wrapping_mul(0x9e37_79b9_7f4a_7c15) >> 59) % STEPS;
    START_DEGREES + STEP_DEGREES * steps as f32
}

/// `field` turned by `degrees` about its centre (seen from above, the
/// back edge moving towards the left), on a grid of the same number of
/// points whose extent holds the whole turned square; points outside it
/// are NaN. Heights between grid points are blended bilinearly.
pub fn turned_by(field: &Heightfield, degrees: f32) -> Heightfield {
    let n = field.size();
    let turn = Turn::new(n, degrees);
    let mut out = Heightfield::flat(field.exponent(), field.extent() * turn.grow);
    out.set_seed(field.seed());
    for y in 0..n {
        for x in 0..n {
            let (sx, sy) = turn.source(x as f32, y as f32);
            out.set(x, y, sample(field, sx, sy, turn.last));
        }
    }
    out
}

/// How [`turned_by`] maps its grid onto the field's: where a point of the
/// turned grid comes from, and where the square's sides cross it.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Turn {
    sin: f32,
    cos: f32,
    /// The turned grid's steps per field step (its extent's growth).
    grow: f32,
    centre: f32,
    last: f32,
}

impl Turn {
    /// The turn of a field `size` points a side by `degrees`.
    pub(crate) fn new(size: usize, degrees: f32) -> Self {
        let (sin, cos) = degrees.to_radians().sin_cos();
        let last = (size - 1) as f32;
        Turn {
            sin,
            cos,
            grow: sin.abs() + cos.abs(),
            centre: 0.5 * last,
            last,
        }
    }

    /// The field's grid position of turned grid position (`x`, `y`).
    #[inline]
    pub(crate) fn source(&self, x: f32, y: f32) -> (f32, f32) {
        // In source grid steps from the centre.
        let (u, v) = ((x - self.centre) * self.grow, (y - self.centre) * self.grow);
        (
            self.centre + self.cos * u - self.sin * v,
            self.centre + self.sin * u + self.cos * v,
        )
    }

    /// How far turned grid position (`x`, `y`) lies inside each of the
    /// square's four sides, in field steps (all at least 0 inside).
    pub(crate) fn inside(&self, x: f32, y: f32) -> [f32; 4] {
        let (sx, sy) = self.source(x, y);
        [sx, self.last - sx, sy, self.last - sy]
    }

    /// The field's height at turned grid position (`x`, `y`), taken to the
    /// square's nearest point if it lies outside.
    pub(crate) fn height(&self, field: &Heightfield, x: f32, y: f32) -> f32 {
        let (sx, sy) = self.source(x, y);
        let last = self.last;
        sample(field, sx.clamp(0.0, last), sy.clamp(0.0, last), last)
    }
}

/// The field's height at grid position (`x`, `y`), bilinear; NaN outside
/// `0..=last` (a hair's tolerance keeps the square's own edge).
fn sample(field: &Heightfield, x: f32, y: f32, last: f32) -> f32 {
    const HAIR: f32 = 1e-3;
    if !(-HAIR..=last + HAIR).contains(&x) || !(-HAIR..=last + HAIR).contains(&y) {
        return f32::NAN;
    }
    let (x, y) = (x.clamp(0.0, last), y.clamp(0.0, last));
    let (x0, y0) = (x.floor() as usize, y.floor() as usize);
    let (x1, y1) = ((x0 + 1).min(last as usize), (y0 + 1).min(last as usize));
    let (fx, fy) = (x - x0 as f32, y - y0 as f32);
    let top = field.get(x0, y0) * (1.0 - fx) + field.get(x1, y0) * fx;
    let bottom = field.get(x0, y1) * (1.0 - fx) + field.get(x1, y1) * fx;
    top * (1.0 - fy) + bottom * fy
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn turns_are_the_essays_steps() {
        let mut seen = std::collections::BTreeSet::new();
        for id in 0..200u64 {
            let d = essay_degrees(id.wrapping_mul(0x2545_f491_4f6c_dd1d));
            let steps = (d - START_DEGREES) / STEP_DEGREES;
            assert_eq!(steps, steps.round(), "{d}");
            assert!((0.0..32.0).contains(&steps), "{d}");
            seen.insert(steps as u32);
        }
        assert!(seen.len() > 24, "{seen:?}");
    }

    #[test]
    fn a_turned_square_is_a_diamond_of_its_own_area() {
        let mut f = Heightfield::flat(6, 100.0);
        f.set(32, 32, 7.0);
        let t = turned_by(&f, 45.0);
        let n = t.size();
        assert!((t.extent() - 100.0 * std::f32::consts::SQRT_2).abs() < 1e-3);
        // Corner-on: the corners of the grid are outside, the middles of
        // its sides on the square's corners, the centre its centre.
        assert!(t.get(0, 0).is_nan() && t.get(n - 1, n - 1).is_nan());
        assert!(!t.get(n / 2, 0).is_nan() && !t.get(0, n / 2).is_nan());
        assert_eq!(t.get(n / 2, n / 2), 7.0);
        let inside = t.heights().iter().filter(|h| !h.is_nan()).count() as f32;
        let share = inside / (n * n) as f32;
        assert!((share - 0.5).abs() < 0.03, "{share}");
        // No turn: the same heights.
        let same = turned_by(&f, 0.0);
        assert_eq!(same.heights(), f.heights());
    }
}
