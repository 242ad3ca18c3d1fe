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

use crate::render::base::colour::smoothstep;
use crate::settings::worlds::COAST;
use crate::settings::{Clouds, World};
use crate::terrain::curves::hermite;
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
/// How far under the cloud's threshold (or over its full thickness) a sum
/// must stay for the finer octaves to be skipped: far above the rounding
/// of a few additions, so that the sky is the same as with every octave
/// summed.
const CLEAR_MARGIN: f32 = 1e-3;

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
            let u = splitmix::unit(splitmix::mix(draw ^ 0xC10D_5EED));
            if u < CLEAR_SHARE {
                0.0
            } else {
                0.2 + 0.8 * (u - CLEAR_SHARE) / (1.0 - CLEAR_SHARE)
            }
        }
    }
}

/// The amount of cloud `choice` means for a mountain of identity `draw`
/// in `world`: under "varied", each world draws from its own sky ([`skies`]);
/// the temperate world's is [`amount`]'s.
pub(crate) fn amount_in(choice: Clouds, world: World, draw: u64) -> f32 {
    match (choice, skies(world)) {
        (Clouds::Varied, Some((clear, least, most))) => {
            let u = splitmix::unit(splitmix::mix(draw ^ 0xC10D_5EED));
            if u < clear {
                0.0
            } else {
                least + (most - least) * (u - clear) / (1.0 - clear)
            }
        }
        _ => amount(choice, draw),
    }
}

/// A world's varied sky: the share of its slides left clear, and the
/// least and the most cloud over the others. The desert is mostly clear,
/// its cloud thin; winter's and autumn's often grey over; the tropics'
/// seldom clear, seldom overcast. None for the temperate world.
fn skies(world: World) -> Option<(f32, f32, f32)> {
    match world {
        World::Desert => Some((0.55, 0.1, 0.45)),
        World::Winter => Some((0.3, 0.3, 1.0)),
        World::Autumn => Some((0.3, 0.25, 1.0)),
        World::Tropical => Some((0.2, 0.2, 0.75)),
        World::Alpine => Some((0.45, 0.2, 0.85)),
        COAST | World::Temperate => None,
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
                splitmix::signed_unit(bits)
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

    /// The sheet along the screen row `up` frame heights above the horizon
    /// line: what does not change along it, worked out once. `None` where
    /// the row sees no cloud (below the line, or where it has faded out).
    pub(crate) fn row(&self, up: f32) -> Option<SheetRow<'_>> {
        // NaN sees none either.
        if up.is_nan() || up <= 0.0 {
            return None;
        }
        let fade = smoothstep(0.0, FADE, up);
        if fade <= 0.0 {
            return None;
        }
        let t = REACH / up;
        let mut y = self.origin[1] + t * self.along;
        let layers = std::array::from_fn(|_| {
            let j = floor(y);
            let mask = LATTICE as i32 - 1;
            let layer = Layer {
                rows: [j, j + 1].map(|j| (j & mask) as usize * LATTICE),
                ty: hermite(y - j as f32),
            };
            // Not exactly 2: the layers' lattices never line up.
            y = y * 1.97 + 31.7;
            layer
        });
        Some(SheetRow {
            sheet: self,
            fade,
            scale: t * self.across,
            layers,
        })
    }
}

/// No cloud.
const NONE: Cover = Cover {
    opacity: 0.0,
    thickness: 0.0,
};

/// One noise layer along a screen row: the lattice's two rows it blends
/// (offsets into the lattice) and how far between them it lies.
#[derive(Debug, Clone, Copy)]
struct Layer {
    rows: [usize; 2],
    ty: f32,
}

/// The cloud sheet along one screen row ([`CloudSheet::row`]).
pub(crate) struct SheetRow<'a> {
    sheet: &'a CloudSheet,
    fade: f32,
    /// Noise cells per frame height across.
    scale: f32,
    layers: [Layer; OCTAVES],
}

impl SheetRow<'_> {
    /// The cloud seen `across` frame heights right of the frame's middle.
    pub(crate) fn seen(&self, across: f32) -> Cover {
        let sheet = self.sheet;
        let mut x = sheet.origin[0] + across * self.scale;
        let (mut sum, mut weight) = (0.0, 1.0);
        // Below this sum, no cloud; above `full`, the cloud's heart.
        let clear = sheet.threshold * NOISE_RANGE - CLEAR_MARGIN;
        let full = (sheet.threshold + sheet.span) * NOISE_RANGE + CLEAR_MARGIN;
        for layer in &self.layers {
            sum += weight * sheet.value(x, layer);
            weight *= 0.5;
            x = x * 2.03 + 17.1;
            // The layers left add less than twice the next one's weight
            // (each value lies in -1..1): where even that cannot reach the
            // cloud's threshold, or take the sum below its full thickness,
            // the finer layers need not be looked at.
            if sum + 2.0 * weight < clear {
                return NONE;
            }
            if sum - 2.0 * weight > full {
                return self.cover_of(1.0);
            }
        }
        self.cover(sum)
    }

    /// The cover where the layers sum to `sum`.
    fn cover(&self, sum: f32) -> Cover {
        let sheet = self.sheet;
        let n = sum / NOISE_RANGE;
        let thickness = ((n - sheet.threshold) / sheet.span).clamp(0.0, 1.0);
        if thickness <= 0.0 {
            return NONE;
        }
        self.cover_of(thickness)
    }

    /// The cover of cloud `thickness` (0..=1) thick.
    fn cover_of(&self, thickness: f32) -> Cover {
        Cover {
            opacity: smoothstep(0.0, 0.6, thickness) * self.fade,
            thickness,
        }
    }
}

impl CloudSheet {
    /// One layer at lattice column `x` of `layer`'s rows: the lattice's
    /// values blended smoothly between its points.
    #[inline]
    fn value(&self, x: f32, layer: &Layer) -> f32 {
        let mask = LATTICE as i32 - 1;
        let i = floor(x);
        let tx = hermite(x - i as f32);
        let (i0, i1) = ((i & mask) as usize, ((i + 1) & mask) as usize);
        let [r0, r1] = layer.rows;
        let l = &self.lattice;
        let top = l[r0 + i0] + (l[r0 + i1] - l[r0 + i0]) * tx;
        let bottom = l[r1 + i0] + (l[r1 + i1] - l[r1 + i0]) * tx;
        top + (bottom - top) * layer.ty
    }
}

/// The whole number at or below `x` (saturating far out, where the sheet
/// has faded to nothing). Without SSE 4.1 `f32::floor` is a call.
#[inline]
fn floor(x: f32) -> i32 {
    let i = x as i32;
    if (i as f32) > x { i - 1 } else { i }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each world's varied sky keeps its share clear and its cloud within
    /// its least and most; the temperate world's is the plain draw's.
    #[test]
    fn each_world_draws_its_own_sky() {
        for world in crate::settings::worlds::OWN_LOOKS {
            let (clear, least, most) = skies(world).expect("a world's sky");
            let amounts: Vec<f32> = (0..3000u64)
                .map(|d| amount_in(Clouds::Varied, world, splitmix::mix(d)))
                .collect();
            let cleared = amounts.iter().filter(|&&a| a == 0.0).count() as f32 / 3000.0;
            assert!((cleared - clear).abs() < 0.04, "{world:?}: clear {cleared}");
            for &a in amounts.iter().filter(|&&a| a > 0.0) {
                assert!((least..=most).contains(&a), "{world:?}: {a}");
            }
            assert_eq!(amount_in(Clouds::Amount(0.3), world, 7), 0.3);
        }
        for d in 0..100 {
            let (a, b) = (
                amount(Clouds::Varied, d),
                amount_in(Clouds::Varied, World::Temperate, d),
            );
            assert_eq!(a.to_bits(), b.to_bits());
        }
    }

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
                covered +=
                    usize::from(sheet.row(up).map_or(0.0, |r| r.seen(across).opacity) > 0.05);
                assert!(sheet.row(-up).is_none());
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
    fn the_layers_skipped_change_no_cover() {
        // Every layer summed, as before any was skipped.
        let summed = |row: &SheetRow, across: f32| {
            let sheet = row.sheet;
            let mut x = sheet.origin[0] + across * row.scale;
            let (mut sum, mut weight) = (0.0, 1.0);
            for layer in &row.layers {
                sum += weight * sheet.value(x, layer);
                weight *= 0.5;
                x = x * 2.03 + 17.1;
            }
            row.cover(sum)
        };
        let (mut clear, mut full) = (0, 0);
        for amount in [0.15, 0.4, 0.7, 1.0] {
            let sheet = CloudSheet::new(amount, 42);
            for i in 0..4000 {
                let (across, up) = (
                    (i % 80) as f32 * 0.021 - 0.84,
                    0.004 + (i / 80) as f32 * 0.01,
                );
                let Some(row) = sheet.row(up) else { continue };
                let seen = row.seen(across);
                assert_eq!(
                    seen,
                    summed(&row, across),
                    "amount {amount} at ({across}, {up})"
                );
                clear += usize::from(seen == NONE);
                full += usize::from(seen.thickness == 1.0);
            }
        }
        // Both ways out are taken.
        assert!(clear > 1000 && full > 1000, "{clear} clear, {full} full");
    }

    #[test]
    fn the_sheet_fades_out_towards_the_horizon() {
        let sheet = CloudSheet::new(1.0, 42);
        let seen = |up: f32| sheet.row(up).map_or(NONE, |r| r.seen(0.0));
        let (low, high) = (seen(0.005), seen(0.3));
        assert!(
            low.opacity < 0.1 * high.opacity.max(0.1),
            "{low:?} {high:?}"
        );
    }
}
