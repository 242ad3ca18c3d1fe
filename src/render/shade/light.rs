//! The light on the land and the sky behind it: the sun's direction and
//! colour, the ambient light from the sky, and the sky's own colours.
//!
//! `sun = "varied"` draws morning, midday, evening, sunset or night per
//! mountain from the mountain's identity ([`Heightfield::identity`]: its
//! seed, or the heights of a data set without one), so one seed always gets
//! the same light, at every frame size, detail and `low_detail`, and a long
//! slide show gets many. At night the moon takes the sun's place (its light
//! about two stops down and blue, "day for night"), and `night` tells the
//! sky to show stars and the palette to take the colour out of the land
//! (rod vision). `sun = "classic"` is seed 000's light as its listing
//! computes it: from the back right, 28 degrees up, brightness
//! `0.5 + 0.5 cos` (faces turned fully away reach 0; see docs/classics.md).

use glam::Vec3;

use crate::render::base::colour::{Rgb, luminance};
use crate::settings::Sun;
use crate::terrain::Heightfield;

/// Seed 000's light, towards the light in the palette's frame (z up, y
/// towards the back): the listing's `(-1, 1, 1) / sqrt 3`, given in its
/// screen frame (y down) and dotted with normals that point into the
/// ground, turned back through its tilt `xTh = -1.396`:
/// `(1, cos xTh' + sin xTh', sin xTh' - cos xTh') / sqrt 3` with
/// `xTh' = 1.396`. From the back right (49 degrees round from the right),
/// 27.9 degrees above the horizon. Written out so no platform's `sin` can
/// move a pixel; docs/classics.md works it through.
const CLASSIC_LIGHT: Vec3 = Vec3::new(0.577_350_3, 0.668_958_2, 0.468_147);
/// Seed 000's `0.5 + 0.5 cos`: the share of the brightness that follows the
/// cosine, either way from half.
const CLASSIC_HALF: f32 = 0.5;

/// The light of one mountain.
#[derive(Debug, Clone)]
pub struct Lighting {
    /// Unit vector from the ground towards the sun.
    pub sun: Vec3,
    /// Colour and strength of direct sunlight on a face square to it.
    pub direct: Rgb,
    /// Colour and strength of the light from the sky on a flat face.
    pub ambient: Rgb,
    /// Sky colour at the top of the frame.
    pub zenith: Rgb,
    /// Sky colour at the horizon; distant land fades towards it.
    pub horizon: Rgb,
    /// Seed 000's model: brightness `0.5 + 0.5 cos`, no colours; faces
    /// turned away from the light go darker than half (to 0).
    pub classic: bool,
    /// How much of the night's look (0 by day, 1 under the moon): stars,
    /// the moon's disc for the sun's, colourless land, dark water.
    pub night: f32,
    /// Colour of the light's glitter on the water: the sun's direct light,
    /// or the moon's, brighter than what it lends the land.
    pub glints: Rgb,
}

/// A time of day: where the sun stands and what colours it brings.
#[derive(Debug, Clone, Copy)]
pub(super) struct Time {
    /// Degrees above the horizon.
    pub(super) elevation: f32,
    /// Degrees from the viewer's left (0) through the back (90) to the right (180).
    pub(super) azimuth: f32,
    pub(super) direct: Rgb,
    pub(super) ambient: Rgb,
    pub(super) zenith: Rgb,
    pub(super) horizon: Rgb,
}

pub(super) const MORNING: Time = Time {
    elevation: 17.0,
    azimuth: 18.0,
    direct: [1.00, 0.90, 0.76],
    ambient: [0.36, 0.39, 0.46],
    zenith: [0.27, 0.45, 0.76],
    horizon: [0.86, 0.85, 0.80],
};

pub(super) const MIDDAY: Time = Time {
    elevation: 40.0,
    azimuth: 35.0,
    direct: [1.00, 0.98, 0.94],
    ambient: [0.34, 0.37, 0.43],
    zenith: [0.17, 0.36, 0.72],
    horizon: [0.72, 0.82, 0.92],
};

pub(super) const EVENING: Time = Time {
    elevation: 13.0,
    azimuth: 165.0,
    direct: [1.00, 0.74, 0.48],
    ambient: [0.33, 0.31, 0.42],
    zenith: [0.16, 0.22, 0.46],
    horizon: [0.95, 0.70, 0.50],
};

/// Evening looking into the sun: low ahead of the viewer, so the land stands
/// against a glowing sky, its near faces in their own shade, and the water
/// below the sun glitters. Five degrees up: high enough that the sight
/// lines off the far water, mirrored, come near it (they leave the water
/// 7 to 19 degrees up in the vista), low enough that its glow fills the top
/// of the frame.
pub(super) const SUNSET: Time = Time {
    elevation: 5.0,
    azimuth: 90.0,
    direct: [1.00, 0.70, 0.44],
    ambient: [0.40, 0.35, 0.46],
    zenith: [0.18, 0.20, 0.45],
    horizon: [0.98, 0.72, 0.52],
};

/// Night under the moon: "day for night" in numbers, the light about two
/// stops down and tinted blue. The moon stands ahead of the viewer, above
/// the frame (its glow, faint beside the sun's, is left out): the near
/// faces stand as silhouettes against the sky, and its glitter lies across
/// the water in front (sight lines off the water leave
/// it 7 to 19 degrees up in the vista). The nights turn it aside
/// ([`NIGHT_TURN`]), so slopes turned to it catch its light. The sky stays
/// a deep blue, lighter towards the horizon, so the land stands out
/// against it and the frame is never black.
pub(super) const NIGHT: Time = Time {
    elevation: 9.0,
    azimuth: 90.0,
    direct: [0.56, 0.64, 0.82],
    ambient: [0.21, 0.25, 0.35],
    zenith: [0.015, 0.030, 0.085],
    horizon: [0.08, 0.11, 0.20],
};

/// Degrees `sun = "night"` turns [`NIGHT`]'s moon to the viewer's left:
/// its glitter still shows in the left of the frame, and slopes facing
/// left are moonlit. Varied nights turn it at least this far either way.
pub(super) const NIGHT_TURN: f32 = -16.0;

/// The moon's glitter on the water: a pale silver, brighter than the light
/// it lends the land (the water mirrors the disc itself).
const MOON_GLINTS: Rgb = [0.80, 0.85, 0.95];

/// How many in 256 slides `sun = "varied"` makes night, where it may:
/// one in sixteen, a night now and then in an evening's slides (dark
/// slides are alike, and one in eight made them common).
pub const NIGHTS_IN_256: u64 = 16;

/// Degrees a varied night's moon may stand above [`NIGHT`]'s, and turn
/// further aside than [`NIGHT_TURN`] (either way): never further behind
/// the range than `sun = "night"`'s.
const MOON_RISE: f32 = 10.0;
const MOON_TURN: f32 = 30.0;

/// How bright a varied night's moon is against `sun = "night"`'s, least
/// and most, on the land: a thinner or a fuller moon, so two nights are
/// not one.
const MOON_PHASES: (f32, f32) = (0.8, 1.7);

/// The sky light left on ground that sees none of the sky (light bounced
/// off the land around it).
const SKY_FLOOR: f32 = 0.35;

/// Degrees a varied sun's azimuth may turn from its time's, always towards
/// the viewer's side: turned the other way, a low evening sun from behind
/// the range throws the whole foreground into one near-black shadow.
const AZIMUTH_JITTER: f32 = 20.0;
/// Degrees the sunset's sun may turn either way from straight ahead: it
/// stays within the view's width.
const SUNSET_JITTER: f32 = 15.0;

impl Lighting {
    /// The light `sun` asks for on `field`; a varied draw may make it
    /// night. `sun = "clock"` without an hour given is lit as midday (see
    /// [`Lighting::at_hour`]).
    pub fn new(sun: Sun, field: &Heightfield) -> Self {
        Self::drawn(sun, field, true)
    }

    /// [`Lighting::new`], with `nights` saying whether a varied draw may
    /// make night (the colour filters and the seed programs' looks keep
    /// their pictures).
    pub fn drawn(sun: Sun, field: &Heightfield, nights: bool) -> Self {
        let draw = field.identity();
        let (time, turn) = match sun {
            Sun::Classic => return Self::classic(),
            Sun::Morning => (&MORNING, 0.0),
            Sun::Midday | Sun::Clock => (&MIDDAY, 0.0),
            Sun::Evening => (&EVENING, 0.0),
            Sun::Sunset => (&SUNSET, 0.0),
            Sun::Night => return Self::moon(0.0, NIGHT_TURN),
            // Bits of the identity the day's draw below does not read.
            Sun::Varied if nights && (draw >> 40) & 0xff < NIGHTS_IN_256 => {
                let unit = |shift: u32| ((draw >> shift) & 0xff) as f32 / 255.0;
                let side = if (draw >> 63) == 1 { -1.0 } else { 1.0 };
                let turn = side * (NIGHT_TURN.abs() + unit(56) * MOON_TURN);
                let phase = MOON_PHASES.0 + unit(32) * (MOON_PHASES.1 - MOON_PHASES.0);
                return Self::moon(unit(48) * MOON_RISE, turn).phased(phase);
            }
            Sun::Varied => {
                // Morning, midday or evening; half the evenings look into
                // the sun.
                let mut i = (draw % 3) as usize;
                if i == 2 && (draw >> 24) & 1 == 1 {
                    i = 3;
                }
                let unit = ((draw >> 8) & 0xffff) as f32 / 65535.0;
                let turn = match i {
                    // Towards the viewer's side of the range.
                    0 | 1 => -unit * AZIMUTH_JITTER,
                    2 => unit * AZIMUTH_JITTER,
                    // Ahead: either way, which only lowers it towards the
                    // viewer's side.
                    _ => (2.0 * unit - 1.0) * SUNSET_JITTER,
                };
                ([&MORNING, &MIDDAY, &EVENING, &SUNSET][i], turn)
            }
        };
        Self::at(time, turn)
    }

    /// Seed 000's light: white, from the back right, `0.5 + 0.5 cos`.
    pub fn classic() -> Self {
        Lighting {
            sun: CLASSIC_LIGHT.normalize(),
            direct: [CLASSIC_HALF; 3],
            ambient: [1.0 - CLASSIC_HALF; 3],
            zenith: [0.02, 0.05, 0.14],
            horizon: [0.10, 0.16, 0.28],
            classic: true,
            night: 0.0,
            glints: [CLASSIC_HALF; 3],
        }
    }

    /// The night's light, its moon `rise` degrees above [`NIGHT`]'s and
    /// turned `turn` degrees.
    fn moon(rise: f32, turn: f32) -> Self {
        let time = Time {
            elevation: NIGHT.elevation + rise,
            ..NIGHT
        };
        Self::at(&time, turn).under_moon(1.0)
    }

    /// This night's light with its moon `elevation` degrees up and
    /// `azimuth` round from the viewer's left (`moonrise.rs`): its colours
    /// and its phase kept.
    pub(super) fn moon_at(self, elevation: f32, azimuth: f32) -> Self {
        Lighting {
            sun: towards(elevation, azimuth),
            ..self
        }
    }

    /// This light on the land `k` times as bright (a moon's phase; the
    /// night sky stays the night's).
    fn phased(mut self, k: f32) -> Self {
        for c in [&mut self.direct, &mut self.ambient] {
            *c = c.map(|v| v * k);
        }
        self
    }

    /// This light with `night` (0..=1) of the night's look, its glitter
    /// turned that far to the moon's silver.
    pub(super) fn under_moon(mut self, night: f32) -> Self {
        self.night = night;
        self.glints = crate::render::base::colour::mix(self.glints, MOON_GLINTS, night);
        self
    }

    /// The light of `time`, its sun turned `turn` degrees.
    pub(super) fn at(time: &Time, turn: f32) -> Self {
        Lighting {
            sun: towards(time.elevation, time.azimuth + turn),
            direct: time.direct,
            ambient: time.ambient,
            zenith: time.zenith,
            horizon: time.horizon,
            classic: false,
            night: 0.0,
            glints: time.direct,
        }
    }

    /// Light on a face with unit `normal` (z up) receiving `lit` of the
    /// direct light (1 in the sun, 0 in cast shadow), per channel.
    #[inline]
    pub fn on(&self, normal: Vec3, lit: f32) -> Rgb {
        self.on_under(normal, lit, 1.0)
    }

    /// [`Lighting::on`] for a face that sees `seen` (0..=1) of the sky.
    #[inline]
    pub fn on_under(&self, normal: Vec3, lit: f32, seen: f32) -> Rgb {
        let cos = normal.dot(self.sun);
        let direct = if self.classic {
            // The listing's cosine runs negative on faces turned away (a
            // cast shadow only takes away what the light would add).
            let cos = if cos.is_nan() {
                0.0
            } else {
                cos.clamp(-1.0, 1.0)
            };
            cos.min(cos * unit(lit))
        } else {
            unit(cos) * unit(lit)
        };
        // Faces turned to the sky see more of it than steep ones, and open
        // ground more than a valley floor.
        let sky = if self.classic {
            1.0
        } else {
            facing_sky(normal.z) * open_sky(seen)
        };
        [0, 1, 2].map(|i| self.direct[i] * direct + self.ambient[i] * sky)
    }

    /// How bright level open ground is under this light against under
    /// [`MIDDAY`]'s, at most 1: by it a world's water colour, tuned in the
    /// midday sun, dims under a low sun or a dull day, as the land does
    /// (the palette's `lit_water`).
    pub(crate) fn level_share(&self) -> f32 {
        let midday = luminance(Self::at(&MIDDAY, 0.0).on(Vec3::Z, 1.0));
        let here = luminance(self.on(Vec3::Z, 1.0));
        if here.is_finite() && midday > 0.0 {
            (here / midday).clamp(0.0, 1.0)
        } else {
            1.0
        }
    }

    /// Of the light [`Lighting::on_under`] gives a face along unit
    /// `normal` (its brightness), the share the direct light brings per
    /// unit of its cosine, and the share the sky brings per unit of the
    /// normal's upward part: how much a slightly turned normal changes
    /// it (the finer relief's light).
    pub(crate) fn shares(&self, normal: Vec3, lit: f32, seen: f32) -> glam::Vec2 {
        let direct = luminance(self.direct) * unit(lit);
        let sky = luminance(self.ambient) * open_sky(seen);
        let total = direct * unit(normal.dot(self.sun)) + sky * facing_sky(normal.z);
        if total <= 0.0 || self.classic {
            return glam::Vec2::ZERO;
        }
        glam::Vec2::new(direct, SKY_TILT * sky) / total
    }
}

/// The share of the sky a wall sees.
const SKY_WALL: f32 = 0.6;
/// How much more of the sky a flat face sees than a wall.
const SKY_TILT: f32 = 0.4;
// A flat face sees all of the sky.
const _: () = assert!(SKY_WALL + SKY_TILT == 1.0);

/// The share of the sky a face whose unit normal rises `z` sees (a flat
/// face all of it, a wall [`SKY_WALL`]).
#[inline]
fn facing_sky(z: f32) -> f32 {
    SKY_WALL + SKY_TILT * unit(z)
}

/// How much of the sky's light reaches a point that sees `seen` of the
/// sky: even a valley floor gets [`SKY_FLOOR`].
#[inline]
fn open_sky(seen: f32) -> f32 {
    SKY_FLOOR + (1.0 - SKY_FLOOR) * unit(seen)
}

/// `v` limited to 0..=1, with NaN as 0.
#[inline]
fn unit(v: f32) -> f32 {
    if v > 0.0 { v.min(1.0) } else { 0.0 }
}

/// The unit vector towards a light `elevation` degrees up and `azimuth`
/// round from the viewer's left (90 ahead, behind the range), z up and y
/// towards the back.
fn towards(elevation: f32, azimuth: f32) -> Vec3 {
    let (el, az) = (elevation.to_radians(), azimuth.to_radians());
    Vec3::new(-az.cos() * el.cos(), az.sin() * el.cos(), el.sin()).normalize()
}
