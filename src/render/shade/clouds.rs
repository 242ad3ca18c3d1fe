//! Cloud on the sky behind the land: noise on a sheet seen in perspective
//! above the horizon line, so the clouds shrink and crowd towards it and
//! fade out before it.
//!
//! The views see only the lowest degrees of the real sky over the land's
//! far edge (the vista's camera looks down; the top of its frame is within
//! three degrees of level), where a true cloud layer would be a few
//! sub-pixel streaks. So the sky is a backdrop, and the sheet hangs over
//! the backdrop's horizon line: a point of the screen `up` frame heights
//! above that line and `across` frame heights right of the middle sees the
//! sheet at distance `REACH / up`. Measured in frame heights it is the same
//! at every frame size; its pattern is drawn from the mountain's identity,
//! so a seed has the same sky at every size, detail and `low_detail`; and
//! the water mirrors it through the same function.

use crate::settings::Clouds;
use crate::terrain::splitmix;

/// How far the sheet lies for a point one frame height above the horizon
/// line, in the sheet's own units.
const REACH: f32 = 0.08;
/// Size of the largest clouds (one noise cell) along the view, in the
/// sheet's units; across the view they are this much longer (wind-stretched).
const CELL: f32 = 0.09;
const STRETCH: f32 = 2.2;
/// Noise layers, each twice as fine and half as strong as the last.
const OCTAVES: usize = 5;
/// Points less than this far above the horizon line (in frame heights)
/// see the cloud thin out to none: there the sheet crowds into noise.
const FADE: f32 = 0.06;
/// Lattice points a side of the noise's table (a power of two).
const LATTICE: usize = 128;
/// The noise's greatest sum over its octaves (1 + 1/2 + 1/4 ...).
const NOISE_RANGE: f32 = 1.9375;

/// Share of the slides that `clouds = "varied"` leaves clear.
const CLEAR_SHARE: f32 = 0.36;

/// The amount of cloud `choice` means for a mountain of identity `draw`:
/// the amount set, or for "varied" one drawn from the identity (about a
/// third of the slides clear, the rest spread from broken cloud to
/// overcast).
pub(crate) fn amount(choice: Clouds, draw: u64) -> f32 {
    match choice {
        Clouds::Amount(a) => a.clamp(0.0, 1.0),
        Clouds::Varied => {
            let u = (splitmix::mix(draw ^ 0xC10D_5EED) >> 40) as f32 / (1u64 << 24) as f32;
            if u < CLEAR_SHARE {
                0.0
            } else {
                0.2 + 0.8 * (u - CLEAR_SHARE) / (1.0 - CLEAR_SHARE)
            }
        }
    }
}

/// One slide's cloud sheet.
#[derive(Debug, Clone)]
pub(crate) struct CloudSheet {
    /// The noise level above which a point of the sheet is cloud, and the
    /// span over which it thickens to full.
    threshold: f32,
    span: f32,
    /// Noise cells per sheet unit across and along the view.
    across: f32,
    along: f32,
    /// Where the pattern starts on the sheet (drawn per mountain).
    origin: [f32; 2],
    /// The noise's values at the lattice points, -1..1.
    lattice: Box<[f32]>,
}

/// What a sight line sees of the sheet: how opaque the cloud is (0..1) and
/// how thick, 0 at its edges to 1 in its heart.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Cover {
    pub opacity: f32,
    pub thickness: f32,
}

impl CloudSheet {
    /// The sheet of `amount` (0..=1, more than 0) of cloud, its pattern
    /// drawn from `draw`.
    pub(crate) fn new(amount: f32, draw: u64) -> Self {
        let seed = splitmix::mix(draw ^ 0x5C1E_5EED);
        let lattice = (0..LATTICE * LATTICE)
            .map(|i| {
                let bits =
                    splitmix::mix(seed.wrapping_add((i as u64).wrapping_mul(splitmix::GOLDEN)));
                (bits >> 40) as f32 / (1u64 << 23) as f32 - 1.0
            })
            .collect();
        let unit = |bits: u64| (bits & 0xffff) as f32 / 65536.0 * LATTICE as f32;
        // 0 leaves only the tops of the highest noise; 1 covers the sky.
        let threshold = 0.5 - 1.15 * amount;
        CloudSheet {
            threshold,
            span: 0.35 + 0.25 * amount,
            across: 1.0 / (CELL * STRETCH),
            along: 1.0 / CELL,
            origin: [unit(seed >> 16), unit(seed >> 32)],
            lattice,
        }
    }

    /// The cloud seen at the point `up` frame heights above the horizon
    /// line and `across` frame heights right of the frame's middle.
    pub(crate) fn seen(&self, across: f32, up: f32) -> Cover {
        let none = Cover {
            opacity: 0.0,
            thickness: 0.0,
        };
        // NaN sees none either.
        if up.is_nan() || up <= 0.0 {
            return none;
        }
        let fade = smoothstep(0.0, FADE, up);
        let t = REACH / up;
        let (x, y) = (across * t * self.across, t * self.along);
        let n = self.noise(self.origin[0] + x, self.origin[1] + y) / NOISE_RANGE;
        let thickness = ((n - self.threshold) / self.span).clamp(0.0, 1.0);
        if thickness <= 0.0 {
            return none;
        }
        Cover {
            opacity: smoothstep(0.0, 0.6, thickness) * fade,
            thickness,
        }
    }

    /// Layered value noise at lattice position (`x`, `y`).
    fn noise(&self, x: f32, y: f32) -> f32 {
        let (mut sum, mut weight, mut p) = (0.0, 1.0, [x, y]);
        for _ in 0..OCTAVES {
            sum += weight * self.value(p[0], p[1]);
            weight *= 0.5;
            // Not exactly 2: the layers' lattices never line up.
            p = [p[0] * 2.03 + 17.1, p[1] * 1.97 + 31.7];
        }
        sum
    }

    /// One layer: the lattice's values blended smoothly between its points.
    fn value(&self, x: f32, y: f32) -> f32 {
        let mask = LATTICE as i64 - 1;
        let (fx, fy) = (x.floor(), y.floor());
        let (tx, ty) = (fade_curve(x - fx), fade_curve(y - fy));
        let (ix, iy) = (fx as i64, fy as i64);
        let at =
            |i: i64, j: i64| self.lattice[((j & mask) as usize) * LATTICE + (i & mask) as usize];
        let top = at(ix, iy) + (at(ix + 1, iy) - at(ix, iy)) * tx;
        let bottom = at(ix, iy + 1) + (at(ix + 1, iy + 1) - at(ix, iy + 1)) * tx;
        top + (bottom - top) * ty
    }
}

/// 3t^2 - 2t^3: the lattice's blend, smooth across its cells' edges.
#[inline]
fn fade_curve(t: f32) -> f32 {
    t * t * (3.0 - 2.0 * t)
}

/// 0 below `e0`, 1 above `e1`, smooth between.
#[inline]
pub(crate) fn smoothstep(e0: f32, e1: f32, x: f32) -> f32 {
    fade_curve(((x - e0) / (e1 - e0)).clamp(0.0, 1.0))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn varied_leaves_about_a_third_clear_and_a_third_cloudy() {
        let amounts: Vec<f32> = (0..3000u64)
            .map(|d| amount(Clouds::Varied, splitmix::mix(d)))
            .collect();
        let share = |f: &dyn Fn(f32) -> bool| {
            amounts.iter().filter(|&&a| f(a)).count() as f32 / amounts.len() as f32
        };
        let clear = share(&|a| a == 0.0);
        let cloudy = share(&|a| a >= 0.45);
        assert!((0.33..0.40).contains(&clear), "clear {clear}");
        assert!(cloudy > 0.4, "cloudy {cloudy}");
        assert_eq!(amount(Clouds::Amount(0.3), 7), 0.3);
    }

    #[test]
    fn more_cloud_covers_more_of_the_sky_and_none_lies_below_the_horizon() {
        let cover = |amount: f32| {
            let sheet = CloudSheet::new(amount, 42);
            let mut covered = 0;
            for i in 0..400 {
                let (across, up) = ((i % 20) as f32 * 0.08 - 0.8, 0.08 + (i / 20) as f32 * 0.02);
                covered += usize::from(sheet.seen(across, up).opacity > 0.05);
                assert_eq!(sheet.seen(across, -up).opacity, 0.0);
            }
            covered
        };
        let (thin, broken, overcast) = (cover(0.1), cover(0.5), cover(1.0));
        assert!(
            thin < broken && broken < overcast,
            "{thin} {broken} {overcast}"
        );
        assert!(overcast > 380, "overcast covers nearly all: {overcast}");
    }

    #[test]
    fn the_sheet_fades_out_towards_the_horizon() {
        let sheet = CloudSheet::new(1.0, 42);
        let low = sheet.seen(0.0, 0.005);
        let high = sheet.seen(0.0, 0.3);
        assert!(
            low.opacity < 0.1 * high.opacity.max(0.1),
            "{low:?} {high:?}"
        );
    }
}
