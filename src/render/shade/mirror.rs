//! The water's mirror: the sight line to a point of the water, reflected
//! off its surface and followed over the heightfield to the land it
//! meets, or out to the sky; how much of that the water shows (Fresnel,
//! broken up by the wind's streaks, which also tilt the line), and where
//! the reflected line points near the sun, for its glitter.
//!
//! A line reflected off level water keeps its direction across the ground,
//! so it runs in the vertical plane through the eye and the point it left
//! the water at. The ground under a fan of such planes, one profile each
//! (a grid row per sample, out from the eye), is all a line needs: made the
//! first time a line needs it. Lines off the sea all come from the eye's
//! mirror image below sea level, so a profile also holds, for each of its
//! samples, the first sample a line off the sea there meets (one sweep
//! from the back), and what the water there mirrors, worked out the first
//! time a face asks. A lake's lines are followed along the profile (what
//! they show kept, for one lake's level a profile). A point of the water
//! shows the four samples around it blended: the two profiles either side
//! and, along each, the samples either side. What a line meets stands for
//! a piece of the land [`FOOTPRINT`] times as wide as the water's points a
//! grid step apart see there.
//!
//! A line off the sea also knows how far it passes over the land (its
//! margin: negative where it meets it), which runs on smoothly from one
//! sample to the next where what it meets does not: the mirrored outline
//! of the land against the sky is where the margin is 0, found between the
//! samples as finely as the drawing asks (`Look::margin`), so the outline
//! does not step from sample to sample.
//!
//! Everything here is a function of the scene (the field, the eye, the
//! light), never of pixels or of the order faces are drawn in: a cached
//! sample is the same whoever works it out first.
//!
//! World units: x right, y towards the front, z up (the camera's); grid
//! positions in grid steps.

use std::sync::OnceLock;
use std::sync::atomic::{AtomicU32, Ordering};

use glam::{Vec2, Vec3};

use super::index;
use super::kept_points::KeptPoints;
use crate::render::base::colour::{Rgb, blend_packed, to_u32};
use crate::render::framing::tops::finite;
use crate::terrain::Heightfield;

/// Samples of a profile skipped at once where a lake's line passes over
/// all of them, and the coarser skip above that.
const BLOCK: usize = 16;
const SPAN: usize = 256;
/// The space between two profiles of the fan at the grid's back edge, as
/// a share of the grid's width: the reflections' finest detail across the
/// view (3 steps of the 1025-point grid a 1080p frame draws). A share of
/// the world, not of the grid, so that a seed mirrors alike at every frame
/// size, and a finer grid costs no more profiles.
const FAN_STEP: f32 = 3.0 / 1024.0;
/// The space between two samples of a profile, as a share of the grid's
/// width (whole grid rows, at least one): the reflections' finest detail
/// along the view (the sky and far land are mirrored across many rows of
/// near water). 3 rows of the 1080p grid rather than 2: the water as close
/// to the scene drawn finer, for less work, but a softer image along the
/// view (the mirror's part of the reflection figure that
/// examples/reflection_shore measures).
const STRIDE: f32 = 3.0 / 1024.0;
/// How far a line off the sea may pass over the land, in samples' steps,
/// for the land's side of the outline to be worked out at it: farther,
/// the outline is not between it and the samples beside it, whose look
/// is all a point of the water blends.
const BAND: f32 = 4.0;
/// How many of the water's grid steps across a mirrored point's colour
/// stands for: water a step apart mirrors land farther apart where the
/// land stands far behind it, and near water then showed the far land's
/// finest texture (snow, rock) one point a corner, as blocks the corners
/// wide. Two, so that the colours of neighbouring corners overlap and
/// blend without edges.
const FOOTPRINT: f32 = 2.0;
/// The largest grid whose land points the mirror keeps (see
/// [`Mirror::land_point`]): a 4K frame's 2049 points a side ask for more
/// points than the table holds (0.9% of the frame's instructions saved,
/// against 2-7% at 1080p), and its slide show's peak is within a megabyte
/// of issue 33's 100 MB.
const KEPT_UP_TO: usize = 1025;
/// Water's reflectance looking straight down (Schlick's `F0`).
const F0: f32 = 0.02;
/// The mirror's share is Schlick's term times this, at most [`MOST`]:
/// stylised, so that it reads at the vista's angles.
const GAIN: f32 = 2.2;
/// The most the water mirrors (some of its own colour always shows).
const MOST: f32 = 0.85;
/// How far the streaks tilt the reflected line up or down (its slope per
/// unit of ripple): wind on the water smears reflections up and down.
const TILT: f32 = 0.008;
/// Cosine of the widest angle from the sun at which a reflected line may
/// glint (its facets tilt it further, see [`Mirror::glint`]).
const NEAR_SUN: f32 = 0.9;
/// The tilt of the sparkling facets that throw the sun's glitter, up and
/// down the view and across it: more along, so the glitter runs in a path
/// from below the sun towards the viewer, as on wind-ruffled water.
const GLINT_TILT: f32 = 0.45;
const GLINT_TILT_ACROSS: f32 = 0.2;
/// Cosine of the widest angle between a facet's reflected line and the sun
/// that still glints.
const GLINT_COS: f32 = 0.99;
/// Only facets whose sparkle exceeds this glint (they sparkle apart).
const SPARKLE: f32 = 0.2;
/// A cached sample not yet worked out (no packed look is this: its share
/// is at most [`SHARE_MAX`]).
const EMPTY: u32 = u32::MAX;
/// The largest share a look packs (7 bits, below all ones).
const SHARE_MAX: u32 = 126;
/// No sample met.
const NONE: u32 = u32::MAX;

/// What a reflected line meets.
#[derive(Debug, Clone, Copy)]
pub(crate) enum Seen {
    /// The ground at grid position `at` (on a grid row), height `height`,
    /// its colour standing for the land `across` grid steps wide there (at
    /// least 1, see [`FOOTPRINT`]).
    Land { at: Vec2, height: f32, across: f32 },
    /// Nothing: the sky along this direction.
    Sky(Vec3),
}

/// What the water at one point shows of what it mirrors.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Look {
    /// The colour mirrored.
    pub colour: u32,
    /// The two sides of the mirrored outline of the land against the sky:
    /// the land's colour there (the land a line meets, or the land it
    /// passes nearest over) and the sky's. On a lake both are `colour`.
    pub land: u32,
    pub sky: u32,
    /// How far a line off the sea here passes over the land (grid steps
    /// along the view of its point on the water; at most 0 where it meets
    /// it): `colour` is `land` where this is at most 0, else `sky`, and
    /// between points of the water the outline is where it crosses 0. 0 on
    /// a lake.
    pub margin: f32,
    /// How much of it the water shows, 0..=1 (before the streaks).
    pub share: f32,
    /// The reflected line's direction (unit, up), where it points near
    /// the sun (it may glint there).
    pub near_sun: Option<Vec3>,
}

/// The water at one point under a mirror, its own colour mixed with what
/// it mirrors on each side of the mirrored outline (see [`Look`]): what a
/// drawn point of the water keeps, so that a face blends its corners' and
/// finds the outline between them.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Mirrored {
    /// The water with the land's side mixed in, and with the sky's.
    pub land: u32,
    pub sky: u32,
    /// [`Look::margin`].
    pub margin: f32,
    /// [`Look::near_sun`].
    pub near_sun: Option<Vec3>,
}

/// A sample's look unpacked (see [`Sampled::pack`]), or several blended.
#[derive(Debug, Clone, Copy)]
struct Sampled {
    /// What is seen, the land's side and the sky's, and the margin (see
    /// [`Look`]).
    colour: u32,
    land: u32,
    sky: u32,
    margin: f32,
    /// In 1/[`SHARE_MAX`]ths.
    share: f32,
    /// Whether the line points near the sun (any of those blended).
    sun: bool,
}

impl Sampled {
    /// A look packed in a `u32`, as the sea's samples are cached: the
    /// colour in the low three bytes, the share in 7 bits above (at most
    /// [`SHARE_MAX`], so never [`EMPTY`]), whether it points near the sun
    /// in the top bit.
    fn pack(colour: u32, share: u32, sun: bool) -> u32 {
        (colour & 0x00ff_ffff) | share.min(SHARE_MAX) << 24 | u32::from(sun) << 31
    }

    /// A look whose land's side is [`Sampled::pack`]ed in `packed`, its
    /// sky's colour `sky`, passing `margin` over the land.
    fn of(packed: u32, sky: u32, margin: f32) -> Self {
        let land = packed & 0x00ff_ffff;
        Sampled {
            colour: if margin <= 0.0 { land } else { sky },
            land,
            sky,
            margin,
            share: ((packed >> 24) & 0x7f) as f32,
            sun: packed >> 31 != 0,
        }
    }

    /// This look `t` (0..=1) of the way to `other`'s.
    fn towards(self, other: Sampled, t: f32) -> Self {
        let w = (t * 256.0) as u32;
        Sampled {
            colour: blend_packed(self.colour, other.colour, w),
            land: blend_packed(self.land, other.land, w),
            sky: blend_packed(self.sky, other.sky, w),
            margin: self.margin + (other.margin - self.margin) * t,
            share: self.share + (other.share - self.share) * t,
            sun: self.sun || other.sun,
        }
    }
}

/// The mirror of one scene's water.
#[derive(Debug)]
pub(crate) struct Mirror {
    eye: Vec3,
    /// Width of a grid step in height units.
    cell: f32,
    /// The eye over the ground, in grid steps (in front of the grid).
    origin: Vec2,
    /// The grid's last row and column.
    last: usize,
    /// Grid rows between two samples of a profile.
    stride: usize,
    /// The fan: the first profile's spread (grid steps across per step
    /// back), the spread between two, and the profiles.
    first: f32,
    apart: f32,
    profiles: Vec<OnceLock<Profile>>,
    /// Towards the sun, in world units.
    sun: Vec3,
    /// The sun's direct colour, packed.
    sun_colour: u32,
    /// The colours of the land's grid points the samples are the mean of,
    /// kept on grids of at most [`KEPT_UP_TO`] points a side.
    land_points: Option<KeptPoints>,
}

/// The ground under one profile of the fan: sample `k` lies on grid row
/// `last - stride k`, `u0 + stride k` steps back from the eye (`u0`: the
/// grid's near edge).
#[derive(Debug)]
struct Profile {
    /// Grid steps across per step back.
    spread: f32,
    heights: Vec<f32>,
    /// The highest of each [`BLOCK`] and each [`SPAN`] samples.
    block_top: Vec<f32>,
    span_top: Vec<f32>,
    /// What the sea along the profile mirrors, made when the sea first
    /// asks: lakes never do, and a world of lakes alone (seeds 1 and 5 at
    /// 4K: 250 and 340 profiles) then keeps a fifth of a profile's bytes.
    sea: OnceLock<Sea>,
    /// What a lake along the profile mirrors, for the first lake's level
    /// that asks (see [`LakeLooks`]).
    lake: OnceLock<LakeLooks>,
}

/// What the lake at one level mirrors at each sample of a profile, packed
/// ([`EMPTY`] until asked): a point of the water blends four samples, and
/// its neighbours ask for most of them again (worked out anew each time,
/// seed 5's whole render at 1080p took 3,374 M instructions once a
/// sample's colour was the mean of several land points; kept, 3,001 M).
/// One level a profile, 4 bytes a sample (0.3 MB for seed 1 at 4K): a
/// lake at another level crossing the same profile works its samples out
/// each time, as every lake did before.
#[derive(Debug)]
struct LakeLooks {
    level: f32,
    look: Vec<AtomicU32>,
}

/// What the sea along one profile mirrors.
#[derive(Debug)]
struct Sea {
    /// For each sample, the land a line off the sea there shows on the
    /// land's side of the outline, and the line's margin (see [`SeaLines`]).
    lines: SeaLines,
    /// What the sea at each sample mirrors, packed: the land's side
    /// ([`EMPTY`] until asked; stored last) and the sky's colour.
    look: Vec<AtomicU32>,
    sky: Vec<AtomicU32>,
}

impl Mirror {
    /// The mirror of `field` seen from `eye` (world units), a grid step
    /// `cell` units wide, lit by `sun` (the palette's frame: y towards the
    /// back) of colour `sun_colour`. `None` unless the eye stands in front
    /// of the grid, above the sea (as the vista's and the perspective's do).
    pub(crate) fn new(
        field: &Heightfield,
        eye: Vec3,
        cell: f32,
        sun: Vec3,
        sun_colour: Rgb,
    ) -> Option<Self> {
        let cell = Some(cell).filter(|c| c.is_finite() && *c > 0.0)?;
        let origin = Vec2::new(eye.x, eye.y) / cell;
        let last = field.size().checked_sub(1).filter(|&l| l > 0)?;
        let (near, far) = (origin.y - last as f32, origin.y);
        if !(near > 0.0 && eye.z > 0.0 && origin.x.is_finite()) {
            return None;
        }
        // Every spread that reaches the grid, [`FAN_STEP`] apart at the back.
        let spread = |x: f32, u: f32| (x - origin.x) / u;
        let ends = [
            spread(0.0, near),
            spread(0.0, far),
            spread(last as f32, near),
            spread(last as f32, far),
        ];
        let first = ends.iter().copied().fold(f32::INFINITY, f32::min);
        let end = ends.iter().copied().fold(f32::NEG_INFINITY, f32::max);
        let apart = FAN_STEP * last as f32 / far;
        let stride = ((STRIDE * last as f32).round() as usize).max(1);
        let count = (((end - first) / apart).ceil() as usize + 1).clamp(2, 1 << 20);
        Some(Mirror {
            eye,
            cell,
            origin,
            last,
            stride,
            first,
            apart,
            profiles: (0..count).map(|_| OnceLock::new()).collect(),
            sun: Vec3::new(sun.x, -sun.y, sun.z).normalize_or(Vec3::Z),
            sun_colour: to_u32(sun_colour),
            land_points: (last < KEPT_UP_TO).then(KeptPoints::default),
        })
    }

    /// The colour of the land's grid point (`x`, `y`), which `colour()`
    /// works out the first time: a line's sample is the mean of several
    /// points, and its neighbours' of most of the same.
    pub(crate) fn land_point(&self, x: usize, y: usize, colour: impl FnOnce() -> u32) -> u32 {
        match &self.land_points {
            Some(kept) => kept.get_or(x, y, colour),
            None => colour(),
        }
    }

    /// What the water at grid position `g`, on a surface at `level`, with
    /// a streak of `ripple` (-1..1, tilting it), mirrors: `colour` says the
    /// colour of what a line meets. `None` where the eye does not look down
    /// at the water there.
    pub(crate) fn look(
        &self,
        field: &Heightfield,
        g: Vec2,
        level: f32,
        ripple: f32,
        colour: impl Fn(Seen) -> u32,
    ) -> Option<Look> {
        let rise = self.eye.z - level;
        let u = self.origin.y - g.y;
        if !(rise > 0.0 && u > 0.0) {
            return None;
        }
        // The fan's place (`index` takes NaN and negatives to 0, and
        // truncates: the floor of a positive number).
        let i = (((g.x - self.origin.x) / u - self.first) / self.apart).max(0.0);
        let last = self.profiles.len() - 1;
        let i0 = index(i).min(last);
        let t = (i - i0 as f32).min(1.0);
        // The streak tilts the water: the line leaves as one off level
        // water nearer or farther would.
        let slope = rise / u;
        let tilted = (slope + TILT * self.cell * ripple).max(0.2 * slope);
        let u = rise / tilted;
        let j = (u - self.near()) / self.stride as f32;
        // Nearer than the grid by over half a sample (or not a number): no
        // water there.
        if j.is_nan() || j < -0.5 {
            return None;
        }
        // The samples either side, across the fan and along the profiles,
        // blended: the nearest one alone showed the mirrored land as steps
        // a sample deep (rows of pixels at 4K) and aliased against the
        // scene drawn finer (water 43.9 dB against 45.2).
        let j = j.max(0.0);
        let along = (index(j), j - index(j) as f32);
        let near = self.between(field, i0, along, level, rise, &colour);
        let seen = if t > 0.0 {
            let far = self.between(field, (i0 + 1).min(last), along, level, rise, &colour);
            near.towards(far, t)
        } else {
            near
        };
        let spread = self.first + self.apart * i;
        Some(Look {
            colour: seen.colour,
            land: seen.land,
            sky: seen.sky,
            margin: seen.margin,
            share: seen.share * (1.0 / SHARE_MAX as f32),
            near_sun: seen.sun.then(|| self.direction(spread, rise / u)),
        })
    }

    /// What the line off the water between sample `j` and the next of the
    /// fan's profile `i` (`(j, t)`: `t` of the way to the next) shows.
    fn between(
        &self,
        field: &Heightfield,
        i: usize,
        (j, t): (usize, f32),
        level: f32,
        rise: f32,
        colour: &impl Fn(Seen) -> u32,
    ) -> Sampled {
        let profile = self.profile(field, i);
        let last = profile.heights.len() - 1;
        let a = self.sample(profile, j.min(last), level, rise, colour);
        if t > 0.0 && j < last {
            let b = self.sample(profile, j + 1, level, rise, colour);
            a.towards(b, t)
        } else {
            a
        }
    }

    /// What a line off the water at sample `j` (at most the last) of
    /// `profile`, on a surface at `level` `rise` below the eye, shows;
    /// lines off the sea cached.
    fn sample(
        &self,
        profile: &Profile,
        j: usize,
        level: f32,
        rise: f32,
        colour: &impl Fn(Seen) -> u32,
    ) -> Sampled {
        if level != 0.0 {
            let lake = profile.lake.get_or_init(|| LakeLooks {
                level,
                look: (0..profile.heights.len())
                    .map(|_| AtomicU32::new(EMPTY))
                    .collect(),
            });
            let cached = (lake.level == level).then(|| &lake.look[j]);
            let packed = match cached.map(|c| c.load(Ordering::Relaxed)) {
                Some(packed) if packed != EMPTY => packed,
                _ => {
                    let met = profile.lake(self, j, level, rise);
                    let packed = self.pack(met, profile, j, rise, colour);
                    if let Some(c) = cached {
                        c.store(packed, Ordering::Relaxed);
                    }
                    packed
                }
            };
            return Sampled::of(packed, packed & 0x00ff_ffff, 0.0);
        }
        let sea = profile.sea(self);
        let margin = sea.lines.margin[j];
        // The sky's colour is stored before the land's side, which says
        // the sample is worked out.
        match sea.look[j].load(Ordering::Acquire) {
            EMPTY => {
                let land = match sea.lines.land[j] {
                    NONE => None,
                    k => Some((k as usize, profile.heights[k as usize])),
                };
                // Far from the outline (or with nothing ahead but the sky)
                // both sides are what the line meets.
                let band = BAND * self.stride as f32;
                let (packed, sky) = match land {
                    Some(_) if margin < -band => {
                        let packed = self.pack(land, profile, j, rise, colour);
                        (packed, packed)
                    }
                    Some(_) if margin <= band => (
                        self.pack(land, profile, j, rise, colour),
                        self.pack(None, profile, j, rise, colour),
                    ),
                    _ => {
                        let sky = self.pack(None, profile, j, rise, colour);
                        (sky, sky)
                    }
                };
                let sky = sky & 0x00ff_ffff;
                sea.sky[j].store(sky, Ordering::Relaxed);
                sea.look[j].store(packed, Ordering::Release);
                Sampled::of(packed, sky, margin)
            }
            cached => Sampled::of(cached, sea.sky[j].load(Ordering::Relaxed), margin),
        }
    }

    /// How far the grid's near edge lies in front of the eye, in grid steps.
    fn near(&self) -> f32 {
        self.origin.y - self.last as f32
    }

    /// How far sample `k` of a profile lies in front of the eye, in grid steps.
    fn back(&self, k: usize) -> f32 {
        self.near() + (self.stride * k) as f32
    }

    /// The profile `i` of the fan, made if it is not yet.
    fn profile(&self, field: &Heightfield, i: usize) -> &Profile {
        self.profiles[i]
            .get_or_init(|| Profile::under(field, self, self.first + self.apart * i as f32))
    }

    /// The unit direction of a line along a profile of `spread`, rising
    /// `slope` height units per step back.
    fn direction(&self, spread: f32, slope: f32) -> Vec3 {
        Vec3::new(spread * self.cell, -self.cell, slope).normalize()
    }

    /// The land at sample `k` of `profile`, `height` high, met by a line
    /// off the water at sample `j`.
    fn land(&self, profile: &Profile, (j, k): (usize, usize), height: f32) -> Seen {
        let y = (self.last - self.stride * k) as f32;
        let x = self.origin.x + profile.spread * self.back(k);
        // The lines from the eye's image spread out: water a step apart
        // across mirrors land `back(k) / back(j)` steps apart.
        Seen::Land {
            at: Vec2::new(x, y),
            height,
            across: (FOOTPRINT * self.back(k) / self.back(j)).max(1.0),
        }
    }

    /// What a line off the water at sample `j` of `profile`, `rise` below
    /// the eye, shows, packed: the colour of what it `met` (a sample and
    /// its height; `None`: the sky), its share, whether it points near the
    /// sun.
    fn pack(
        &self,
        met: Option<(usize, f32)>,
        profile: &Profile,
        j: usize,
        rise: f32,
        colour: &impl Fn(Seen) -> u32,
    ) -> u32 {
        let u = self.back(j);
        let dir = self.direction(profile.spread, rise / u);
        let seen = match met {
            Some((k, height)) => self.land(profile, (j, k), height),
            None => Seen::Sky(dir),
        };
        // The sight line down to the water is the reflected one, mirrored.
        let down = dir.z;
        let schlick = F0 + (1.0 - F0) * (1.0 - down).powi(5);
        let share = ((GAIN * schlick).min(MOST) * SHARE_MAX as f32) as u32;
        let near = dir.dot(self.sun) > NEAR_SUN;
        Sampled::pack(colour(seen), share, near)
    }

    /// The sun's glitter on a facet whose line would be `dir` were it level,
    /// tilted by `sparkle` and `sideways` (-1..1, the fine ripples): the
    /// sun's colour, and how strongly it shows (0..=1).
    pub(crate) fn glint(&self, dir: Vec3, sparkle: f32, sideways: f32) -> Option<(u32, f32)> {
        if sparkle < SPARKLE {
            return None;
        }
        let tilted = Vec3::new(
            dir.x + GLINT_TILT_ACROSS * sideways,
            dir.y,
            dir.z + GLINT_TILT * (sparkle - 0.5),
        );
        let cos = tilted.try_normalize()?.dot(self.sun);
        if cos <= GLINT_COS {
            return None;
        }
        let t = ((cos - GLINT_COS) / (1.0 - GLINT_COS)).min(1.0);
        let strength = t.sqrt() * ((sparkle - SPARKLE) / (1.0 - SPARKLE)).min(1.0).sqrt();
        Some((self.sun_colour, strength))
    }
}

impl Profile {
    /// The ground of `field` under the profile of `spread` of `mirror`'s fan.
    fn under(field: &Heightfield, mirror: &Mirror, spread: f32) -> Self {
        let last = mirror.last;
        let size = last + 1;
        let samples = last / mirror.stride + 1;
        let all = field.heights();
        // Off the grid's sides, no land.
        let mut heights = vec![f32::NEG_INFINITY; samples];
        for (k, h) in heights.iter_mut().enumerate() {
            let y = last - mirror.stride * k;
            let x = mirror.origin.x + spread * mirror.back(k);
            if x >= 0.0 && x <= last as f32 {
                let x0 = index(x).min(last - 1);
                let i = y * size + x0;
                let (a, b) = (finite(all[i]), finite(all[i + 1]));
                *h = a + (b - a) * (x - x0 as f32);
            }
        }
        let tops = |n: usize| {
            heights
                .chunks(n)
                .map(|c| c.iter().copied().fold(f32::NEG_INFINITY, f32::max))
                .collect()
        };
        Profile {
            spread,
            block_top: tops(BLOCK),
            span_top: tops(SPAN),
            sea: OnceLock::new(),
            lake: OnceLock::new(),
            heights,
        }
    }

    /// What the sea along the profile of `mirror`'s fan mirrors, made if
    /// it is not yet.
    fn sea(&self, mirror: &Mirror) -> &Sea {
        self.sea.get_or_init(|| {
            let (heights, samples) = (&self.heights, self.heights.len());
            Sea {
                lines: sea_lines(heights, mirror.near(), mirror.stride as f32, mirror.eye.z),
                look: (0..samples).map(|_| AtomicU32::new(EMPTY)).collect(),
                sky: (0..samples).map(|_| AtomicU32::new(0)).collect(),
            }
        })
    }

    /// The first sample past `j` a line off a lake at `level` there meets,
    /// rising `rise` (the eye over the lake) over the steps from the eye to
    /// `j`: the sample and its height.
    fn lake(&self, mirror: &Mirror, j: usize, level: f32, rise: f32) -> Option<(usize, f32)> {
        let uj = mirror.back(j);
        let z = |k: usize| level + rise * (mirror.back(k) / uj - 1.0);
        let n = self.heights.len();
        let mut k = j + 1;
        while k < n {
            let zk = z(k);
            if k.is_multiple_of(SPAN) && self.span_top[k / SPAN] < zk {
                k += SPAN;
            } else if k.is_multiple_of(BLOCK) && self.block_top[k / BLOCK] < zk {
                k += BLOCK;
            } else if self.heights[k] >= zk {
                return Some((k, self.heights[k]));
            } else {
                k += 1;
            }
        }
        None
    }
}

/// What the lines off the sea at the samples of one profile show.
#[derive(Debug)]
struct SeaLines {
    /// The sample whose land shows on the land's side of the outline: the
    /// first a line meets, or, if it meets none, the one it passes nearest
    /// over; [`NONE`]: no land ahead.
    land: Vec<u32>,
    /// How far the line passes over the land, in grid steps along the
    /// view of its sample: `min c_k - u_j` (see [`sea_lines`]), at most 0
    /// where it meets the land. It changes smoothly from sample to sample
    /// where what a line meets jumps, so the outline can be found between
    /// them.
    margin: Vec<f32>,
}

/// For each sample of a profile of `heights` (sample `k` is `u0 + step k`
/// steps back from the eye, which stands `eye` above the sea), the first
/// sample past it that a line off the sea there meets, and the line's
/// margin (see [`SeaLines`]).
///
/// The line off sample `j` rises `eye / u_j` a step, so it is below the
/// ground at a farther `k` when `u_k <= u_j (1 + h_k / eye)`: when
/// `c_k = u_k eye / (eye + h_k)` is at most `u_j` (land below the sea
/// never meets it). Swept from the back, a sample farther than a nearer
/// one of no greater `c` is never the first met, so the candidates left
/// grow in `c` towards the front, and the first met is the nearest whose
/// `c` is at most `u_j`: found by halving. The bottom candidate has the
/// least `c` of all: the land the line passes nearest over.
fn sea_lines(heights: &[f32], u0: f32, step: f32, eye: f32) -> SeaLines {
    let n = heights.len();
    let mut hits = vec![NONE; n];
    let mut margin = vec![0.0; n];
    // With no land ahead, the margin over a shore at the back.
    let back = u0 + step * n.saturating_sub(1) as f32;
    // (c, k), c growing from the bottom of the stack to its top.
    let mut stack: Vec<(f32, u32)> = Vec::new();
    for j in (0..n).rev() {
        let uj = u0 + step * j as f32;
        if let Some(k) = Some(j + 1).filter(|&k| k < n && heights[k] > 0.0) {
            let c = (u0 + step * k as f32) * eye / (eye + heights[k]);
            while stack.last().is_some_and(|&(top, _)| top >= c) {
                stack.pop();
            }
            stack.push((c, k as u32));
        }
        // The candidates met are the bottom ones (c <= u_j); the nearest
        // of them is the last. (A land sample is asked for too: the water
        // of a face by the shore may lie nearest to it.)
        let met = match stack.last() {
            Some(&(c, k)) if c <= uj => Some(k),
            _ => stack
                .partition_point(|&(c, _)| c <= uj)
                .checked_sub(1)
                .map(|i| stack[i].1),
        };
        let nearest = stack.first().copied();
        margin[j] = nearest.map_or(back, |(c, _)| c) - uj;
        hits[j] = met.or(nearest.map(|(_, k)| k)).unwrap_or(NONE);
    }
    SeaLines { land: hits, margin }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A sea 1 deep with one square tower `height` tall around grid point
    /// (`x`, `y`), on a 65-point grid of unit steps.
    fn tower(x: usize, y: usize, height: f32) -> Heightfield {
        let mut f = Heightfield::flat(6, 64.0);
        for gy in 0..f.size() {
            for gx in 0..f.size() {
                let near = gx.abs_diff(x) <= 2 && gy.abs_diff(y) <= 2;
                f.set(gx, gy, if near { height } else { -1.0 });
            }
        }
        f
    }

    const EYE: Vec3 = Vec3::new(32.0, 100.0, 10.0);

    fn mirror(field: &Heightfield) -> Mirror {
        Mirror::new(field, EYE, 1.0, Vec3::new(0.0, 1.0, 0.2), [1.0; 3]).unwrap()
    }

    /// What the water at (`x`, `y`) on `level` mirrors: the land's grid
    /// position, or `None` for the sky (the sea's lines passing over the
    /// land, by their margin).
    fn seen(m: &Mirror, f: &Heightfield, x: f32, y: f32, level: f32) -> Option<Vec2> {
        let found = std::cell::Cell::new(None);
        let look = m
            .look(f, Vec2::new(x, y), level, 0.0, |s| {
                if let Seen::Land { at, .. } = s {
                    found.set(Some(at));
                }
                0
            })
            .expect("the eye looks down at the water");
        found.get().filter(|_| look.margin <= 0.0)
    }

    #[test]
    fn the_sea_before_a_tower_mirrors_it_and_the_sea_beside_it_the_sky() {
        let f = tower(32, 10, 10.0);
        let m = mirror(&f);
        let at = seen(&m, &f, 32.0, 40.0, 0.0).expect("the tower");
        assert!(
            (at.y - 12.0).abs() < 1.5 && (at.x - 32.0).abs() < 1.5,
            "{at}"
        );
        assert!(seen(&m, &f, 10.0, 40.0, 0.0).is_none(), "beside the tower");
        // Behind the tower, looking away from it.
        assert!(seen(&m, &f, 32.0, 5.0, 0.0).is_none(), "behind the tower");
        // Close to the eye the line rises too steeply to meet it.
        assert!(seen(&m, &f, 32.0, 63.0, 0.0).is_none(), "at the near edge");
    }

    /// How wide the land the water at (`x`, `y`) on the sea mirrors stands
    /// for ([`Seen::Land`]'s `across`), and where the land is. (A mirror of
    /// its own: the sea's looks are worked out once.)
    fn footprint(f: &Heightfield, x: f32, y: f32) -> (f32, Vec2) {
        let found = std::cell::Cell::new(None);
        mirror(f)
            .look(f, Vec2::new(x, y), 0.0, 0.0, |s| {
                if let Seen::Land { at, across, .. } = s {
                    found.set(Some((across, at)));
                }
                0
            })
            .expect("the eye looks down at the water");
        found
            .get()
            .unwrap_or_else(|| panic!("no land seen from {x}, {y}"))
    }

    /// Water mirrors land [`FOOTPRINT`] times as wide as the land its
    /// corners a grid step apart meet: wider the nearer the water is to the
    /// eye and the farther the land behind it (the near water's blocks of
    /// far snow and rock, one point a corner, came from a footprint of one
    /// point).
    #[test]
    fn near_water_mirrors_far_land_as_wide_as_its_corners_see_it() {
        let f = tower(32, 10, 40.0);
        let eye = EYE.y;
        for y in [30.0, 45.0, 60.0] {
            let (across, at) = footprint(&f, 32.0, y);
            let expected = FOOTPRINT * (eye - at.y) / (eye - y);
            assert!(
                (across - expected).abs() < 0.1 * expected,
                "water at {y}: {across} against {expected}"
            );
        }
        let near = footprint(&f, 32.0, 60.0).0;
        let far = footprint(&f, 32.0, 30.0).0;
        assert!(near > 1.5 * far, "{near} against {far}");
        // Land right behind the water: the footprint's least.
        let (close, _) = footprint(&tower(32, 40, 40.0), 32.0, 48.0);
        assert!((FOOTPRINT..1.25 * FOOTPRINT).contains(&close), "{close}");
    }

    #[test]
    fn a_lake_mirrors_as_the_sea_does() {
        // Water 3 high before the tower: the same tower, seen from it.
        let f = tower(32, 10, 30.0);
        let m = mirror(&f);
        let at = seen(&m, &f, 32.0, 40.0, 3.0).expect("the tower");
        assert!((at.y - 12.0).abs() < 1.5, "{at}");
        assert!(seen(&m, &f, 10.0, 40.0, 3.0).is_none());
    }

    /// A lake's looks are kept for the first level that asks a profile:
    /// asked again, or after a lake at another level, or by a mirror that
    /// met the levels the other way round, each point shows the same.
    #[test]
    fn a_lakes_kept_looks_are_what_working_them_out_gives() {
        let f = tower(32, 10, 30.0);
        let colour = |s: Seen| match s {
            Seen::Land { at, across, .. } => (at.y * 1000.0 + across * 10.0) as u32,
            Seen::Sky(d) => (d.z * 1e6) as u32,
        };
        let points = [(32.0, 40.0), (31.3, 44.5), (33.0, 30.2), (20.0, 40.0)];
        let looks = |m: &Mirror, level: f32| -> Vec<(u32, u32)> {
            points
                .iter()
                .map(|&(x, y)| {
                    let l = m
                        .look(&f, Vec2::new(x, y), level, 0.3, colour)
                        .expect("water");
                    (l.colour, (l.share * 1000.0) as u32)
                })
                .collect()
        };
        let (one, other) = (mirror(&f), mirror(&f));
        let (a, b) = (looks(&one, 3.0), looks(&one, 5.0));
        assert_ne!(a, b, "two levels see apart");
        assert_eq!(looks(&other, 5.0), b);
        assert_eq!(looks(&other, 3.0), a);
        assert_eq!((looks(&one, 3.0), looks(&one, 5.0)), (a, b));
    }

    #[test]
    fn the_sweep_finds_the_first_sample_each_line_meets() {
        // Against following each line off the sea sample by sample, on
        // rough profiles (from land samples too: lines from the sea by them).
        let mut state = 12345u32;
        let mut next = || {
            state = state.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
            (state >> 8) as f32 / (1 << 24) as f32
        };
        for _ in 0..50 {
            let heights: Vec<f32> = (0..200).map(|_| 30.0 * next() - 12.0).collect();
            let (u0, eye, step) = (5.0 + 40.0 * next(), 2.0 + 20.0 * next(), 0.5 + 2.0 * next());
            let lines = sea_lines(&heights, u0, step, eye);
            let u = |k: usize| u0 + step * k as f32;
            for (j, &hit) in lines.land.iter().enumerate() {
                let z = |k: usize| eye * (u(k) / u(j) - 1.0);
                let want = (j + 1..heights.len()).find(|&k| heights[k] > 0.0 && heights[k] >= z(k));
                let met = lines.margin[j] <= 0.0;
                let got = (hit != NONE && met).then_some(hit as usize);
                // Rounding may decide a graze either way.
                if want != got {
                    let k = want.or(got).unwrap();
                    assert!(
                        (heights[k] - z(k)).abs() < 1e-3,
                        "sample {j}: {want:?} != {got:?}"
                    );
                }
            }
        }
    }

    #[test]
    fn the_margin_is_how_far_a_line_passes_over_the_land() {
        // Against the least `c` of the land ahead, followed sample by
        // sample; the land shown beside a line that meets none is the one
        // it passes nearest over.
        let mut state = 777u32;
        let mut next = || {
            state = state.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
            (state >> 8) as f32 / (1 << 24) as f32
        };
        for _ in 0..50 {
            let heights: Vec<f32> = (0..120).map(|_| 20.0 * next() - 12.0).collect();
            let (u0, eye, step) = (5.0 + 40.0 * next(), 2.0 + 20.0 * next(), 0.5 + 2.0 * next());
            let lines = sea_lines(&heights, u0, step, eye);
            let u = |k: usize| u0 + step * k as f32;
            for j in 0..heights.len() {
                let c = |k: usize| u(k) * eye / (eye + heights[k]);
                let nearest = (j + 1..heights.len())
                    .filter(|&k| heights[k] > 0.0)
                    .min_by(|&a, &b| c(a).total_cmp(&c(b)));
                let Some(k) = nearest else {
                    assert_eq!(lines.land[j], NONE, "sample {j}");
                    continue;
                };
                let margin = c(k) - u(j);
                assert!(
                    (lines.margin[j] - margin).abs() < 1e-3,
                    "sample {j}: margin {} != {margin}",
                    lines.margin[j]
                );
                if margin > 1e-3 {
                    assert_eq!(lines.land[j] as usize, k, "sample {j}");
                }
            }
        }
    }

    #[test]
    fn the_mirror_is_stronger_at_grazing_angles() {
        let f = tower(32, 10, 5.0);
        let m = mirror(&f);
        let share = |y: f32| {
            m.look(&f, Vec2::new(40.0, y), 0.0, 0.0, |_| 0)
                .unwrap()
                .share
        };
        // At the eye's feet it looks steeply down: little mirror.
        assert!(share(63.0) < share(30.0) && share(30.0) <= share(2.0));
        assert!(
            share(63.0) < 0.7 * share(2.0),
            "{} {}",
            share(63.0),
            share(2.0)
        );
    }

    #[test]
    fn the_sun_glints_where_the_mirrored_line_points_at_it() {
        let f = tower(32, 10, 5.0);
        // Straight ahead of the eye, low: where lines off the far water go.
        let sun_ahead = Vec3::new(0.0, 1.0, 0.12).normalize();
        let m = Mirror::new(&f, EYE, 1.0, sun_ahead, [1.0, 0.8, 0.5]).unwrap();
        let look = m.look(&f, Vec2::new(32.0, 20.0), 0.0, 0.0, |_| 0).unwrap();
        let dir = look.near_sun.expect("the line points near the sun");
        let sparkles: Vec<f32> = (0..200).map(|i| i as f32 / 100.0 - 1.0).collect();
        let glints = sparkles
            .iter()
            .flat_map(|&a| sparkles.iter().map(move |&b| (a, b)))
            .filter_map(|(a, b)| m.glint(dir, a, b))
            .count();
        assert!(glints > 0, "no facet glints");
        // Not every facet: they sparkle apart.
        assert!(glints < 200 * 200 / 2, "{glints} of 40000 facets glint");
        // The sun behind the viewer: no line points near it.
        let behind = Vec3::new(0.0, -1.0, 0.12).normalize();
        let m = Mirror::new(&f, EYE, 1.0, behind, [1.0; 3]).unwrap();
        let look = m.look(&f, Vec2::new(32.0, 20.0), 0.0, 0.0, |_| 0).unwrap();
        assert!(look.near_sun.is_none());
    }

    #[test]
    fn only_an_eye_in_front_of_the_grid_above_the_sea_has_a_mirror() {
        let f = tower(32, 10, 5.0);
        let sun = Vec3::Z;
        assert!(Mirror::new(&f, Vec3::new(32.0, 30.0, 10.0), 1.0, sun, [1.0; 3]).is_none());
        assert!(Mirror::new(&f, Vec3::new(32.0, 80.0, -1.0), 1.0, sun, [1.0; 3]).is_none());
    }
}
