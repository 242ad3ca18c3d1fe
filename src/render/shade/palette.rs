//! Face colours: Lambert shading, the natural palette, filters, water depth.
//!
//! Everything costly happens once in [`Palette::new`]: the base colour of
//! every (steepness, height) pair goes into a table that already carries the
//! colour filter, and water colours by depth go into another. [`Palette::land`]
//! is then a table lookup, one multiply per channel and a pack.
//!
//! The treeline follows seed 000: with `normalHeight = 10000 * height` its
//! treeline sits at `0.4 * normalHeight + 10000` and the blend to grey spans
//! 9000 units above it. As fractions of the highest peak that is a treeline
//! at `0.4 + 1 / height` and a band `0.9 / height` wide, which is how we
//! place it on any field: at height 10 the top 40 % of the relief is above
//! the treeline, at height 1 none of it is.
//!
//! Colour filters are luminance tints, not seed 003's bitwise AND: each
//! colour is replaced by the filter's tint at the same luminance (the tint
//! darkened; colours lighter than the tint blend it part way to white).
//! The AND keeps only some channels of the *natural* colour, so a green
//! lowland turns black under the red filter; the tint keeps every face's
//! brightness, stays in the filter's hue family, and snow turns a pale tint.

use super::cover;
use super::dither;
use super::dusk;
use super::essay;
use super::facings;
use super::hour::SunAt;
use super::index;
use super::light::Lighting;
use super::listing;
use super::moonrise;
use super::night;
use super::strata;
use crate::render::base::colour::{
    Rgb, luminance, mix, mix_packed, pack, ramp, scale_packed, scale_packed3, smoothstep, to_u32,
    unpack,
};
use crate::settings::worlds::COAST;
use crate::settings::{ColorMode, Look, Settings, Sun, World, worlds};
use crate::terrain::Heightfield;
use crate::terrain::wetness::ORDINARY;
use glam::{Vec2, Vec3};

/// Height classes in the land table, from sea level to the highest peak.
const HEIGHT_BINS: usize = 512;
/// Steepness classes in the land table, from flat to the field's steepest.
const STEEP_BINS: usize = 8;
/// Water colours from the shore to the deepest point.
const DEPTH_BINS: usize = 256;
/// Per-face height jitter, in height bins either side, so that faces of one
/// height do not make flat bands and the snow line is ragged.
const JITTER_BINS: i32 = 10;

/// How far a colour filter blends its tint towards white for the lightest
/// colours (1 would keep their luminance but turn snow and sand white).
const WHITENING: f32 = 0.6;

/// How much of the sky's horizon colour water reflects (beyond the classic light).
const WATER_REFLECTS: f32 = 0.12;

/// FL3's land and water colours ("outlines 'land' triangles in green and
/// water triangles in blue"), and its pen in Filled mode: `Canvas.Polygon`
/// outlines with the canvas's pen, Delphi's default `clBlack`.
const FL3_GREEN: u32 = 0x0000_d000;
const FL3_BLUE: u32 = 0x0030_60ff;
const FL3_PEN: u32 = 0;

/// Natural colours, shaded brightness 1 (full sun).
mod natural {
    use super::Rgb;
    pub const SAND: Rgb = [0.76, 0.70, 0.50];
    pub const MEADOW: Rgb = [0.36, 0.60, 0.22];
    pub const FOREST: Rgb = [0.21, 0.46, 0.17];
    pub const ALPINE: Rgb = [0.47, 0.52, 0.28];
    pub const BROWN: Rgb = [0.50, 0.40, 0.28];
    pub const ROCK: Rgb = [0.56, 0.53, 0.50];
    pub const SNOW: Rgb = [0.96, 0.97, 1.00];
    pub const CLIFF: Rgb = [0.46, 0.40, 0.33];
    pub const EARTH: Rgb = [0.50, 0.38, 0.26];
    pub const SHALLOW: Rgb = [0.16, 0.46, 0.74];
    pub const DEEP: Rgb = [0.02, 0.10, 0.30];
    pub const SEA: Rgb = [0.10, 0.34, 0.66];
}

/// The land table of the faces turned to a mountain's sunward side, and
/// that side (`cover::sunward`).
type Sunward = (Box<[u32]>, Vec2);

/// The land tables of the ground where water runs (`terrain::wetness`:
/// its `land` and, where the world tells facings apart, its sunward
/// table); the palette's own tables are then the driest ground's.
type Wet = (Box<[u32]>, Option<Box<[u32]>>);

/// Colours for one mountain under one set of settings.
#[derive(Debug, Clone)]
pub struct Palette {
    lighting: Lighting,
    /// Lighting in colour (natural) rather than in brightness only.
    coloured: bool,
    mode: ColorMode,
    /// `STEEP_BINS` rows of `HEIGHT_BINS` filtered base colours, packed.
    land: Box<[u32]>,
    /// Where the world's ground differs by the way a slope faces
    /// (`cover::faces`): the table of the faces turned to the mountain's
    /// sunward side, and that side; `land` is then the faces turned from it.
    sunward: Option<Sunward>,
    /// Where the world's ground follows the water (`cover::wets`): its
    /// tables along the streams, `land` (and `sunward`) being the driest
    /// ridges'.
    wet: Option<Wet>,
    /// Height bins per height unit (heights below 0 clamp to bin 0).
    height_scale: f32,
    /// Steepness bins per unit of `1 - normal.z`.
    steep_scale: f32,
    /// Filtered, toned water colours from the shore to the deepest point.
    water: Box<[u32]>,
    /// Depth bins per depth unit (0 when every depth has the same colour).
    depth_scale: f32,
    /// Filtered skirt (earth) colour, in 0..=255.
    skirt: Rgb,
    /// Final tone curve `out = shaded * gain - offset` (Mono's contrast
    /// stretch; 1 and 0 otherwise), offset in 0..=255 units.
    gain: f32,
    offset: f32,
    /// Seed 000's HSV ramp for the land (`look =
    /// "fractal-mountain-climbing"` in the natural colours, and its
    /// patterns in Mono).
    listing: Option<listing::Ramp>,
    /// Mountain Terrain 3.0's colour preference (`look =
    /// "mountain-terrain"` under a filter): land is it ANDed with a facing's
    /// darkness, water pure blue.
    preference: Option<u32>,
    /// The essay's green by its sun (`look = "essay"` in the natural colours).
    essay: bool,
    /// The background of a seed program's look: black windows, the
    /// essay's white page.
    backdrop: Option<u32>,
    /// The world whose cover, water and air these are (`cover.rs`).
    world: World,
    /// The mountain's draw of its air within its world (`cover::air_draw`).
    air: f32,
}

/// The world `field` is coloured and lit in under `settings`: the one its
/// seed draws ([`worlds::drawn_world`]), which settings already drawn for
/// it hold, so the palette of a scene and one made from the preferences
/// themselves agree (a "varied" left in them is not taken for the
/// temperate coast of the varied draw).
fn world_of(settings: &Settings, field: &Heightfield) -> World {
    worlds::drawn_world(settings, field.seed())
}

impl Palette {
    /// Prepares the colours for `field` (treeline, depth range) under `settings`.
    pub fn new(settings: &Settings, field: &Heightfield) -> Self {
        Self::lit_by(settings, field, Self::lighting_for(settings, field))
    }

    /// The light `Palette::new` colours `field` under `settings` with: cheap,
    /// so the shadows (which need only the sun) can start before the tables.
    pub fn lighting_for(settings: &Settings, field: &Heightfield) -> Lighting {
        Self::lighting_at(settings, field, None)
    }

    /// [`Palette::lighting_for`] with the sun of `sun = "clock"` where
    /// `hour` puts it (without one, that key lights as midday).
    pub fn lighting_at(settings: &Settings, field: &Heightfield, hour: Option<SunAt>) -> Lighting {
        let sun = match settings.color {
            // Mono's tone curve is tuned to seed 000's light.
            ColorMode::Mono => Sun::Classic,
            _ => settings.sun,
        };
        if let (Sun::Clock, Some(at)) = (sun, hour) {
            return Lighting::at_hour(at);
        }
        // The colour filters and the seed programs' looks keep the
        // pictures a varied draw gave them before there were nights.
        let nights = settings.color == ColorMode::Natural && settings.look == Look::Ours;
        let mut light = Lighting::drawn(sun, field, nights);
        let world = world_of(settings, field);
        // A world's varied day is lit by an hour of its own drawing, and
        // some of its nights are twilight.
        let own = match light.night > 0.0 {
            false => cover::sun(world, field.identity()),
            true => dusk::twilight(world, field.identity()),
        };
        match (sun, own) {
            (Sun::Varied, Some(at)) => light = Lighting::at_hour(at),
            // Half the full nights see the moon rise ahead.
            (Sun::Varied, None) if light.night >= 1.0 => {
                if let Some((up, round)) = moonrise::rising(world, field.identity()) {
                    light = light.moon_at(up, round);
                }
            }
            _ => {}
        }
        cover::light(world, light, cover::light_draw(field.identity()))
    }

    /// [`Palette::new`] with its light worked out already
    /// ([`Palette::lighting_for`]).
    pub fn lit_by(settings: &Settings, field: &Heightfield, lighting: Lighting) -> Self {
        let mode = settings.color;
        let (lowest, highest) = field.min_max();
        let top = positive_or(highest, 1.0);
        let (gain, offset) = tone(mode);
        let world = world_of(settings, field);
        let zones = Zones::new(settings.height, lowest < 0.0, world);
        let zones = Zones {
            draw: cover::draw(field.identity()),
            ..zones
        };
        let steep_ref = steepness_reference(field);
        let (land, sunward, wet) = land_tables(mode, &zones, lighting.night, || {
            cover::sunward(field.identity(), settings.quarter_turns())
        });
        let deepest = positive_or(-lowest, 1.0);
        let waters = Waters {
            relative: settings.relative_depth,
            deepest,
            reflected: (!lighting.classic).then_some(lighting.horizon),
            night: lighting.night,
            world,
            draw: zones.draw,
            lit: lighting.level_share(),
        };
        let listing = (settings.look == Look::FractalMountainClimbing
            && matches!(mode, ColorMode::Natural | ColorMode::Mono))
        .then(|| listing::Ramp::new(settings.height, top));
        let preference = (settings.look == Look::MountainTerrain)
            .then(|| facings::preference(mode))
            .flatten();
        let (water, depth_scale) = match (&listing, preference) {
            // The listing's one light blue, unshaded.
            (Some(_), _) if !settings.relative_depth => listing_water(mode),
            (_, Some(_)) => mountain_terrain_water(settings.relative_depth),
            _ => water_table(mode, &waters, gain, offset),
        };
        Palette {
            coloured: !lighting.classic && mode == ColorMode::Natural,
            lighting,
            mode,
            land,
            sunward,
            wet,
            height_scale: HEIGHT_BINS as f32 / top,
            steep_scale: STEEP_BINS as f32 / steep_ref,
            water,
            depth_scale,
            skirt: finish(mode, natural::EARTH),
            gain,
            offset,
            listing,
            preference,
            essay: settings.look == Look::Essay && mode == ColorMode::Natural,
            backdrop: match settings.look {
                Look::FractalMountainClimbing | Look::MountainTerrain => Some(0),
                Look::Essay => Some(essay::BACKGROUND),
                _ => None,
            },
            world,
            air: cover::air_draw(field.identity()),
        }
    }

    /// Unit vector pointing from the ground towards the light (z up, y towards the back).
    pub fn light(&self) -> Vec3 {
        self.lighting.sun
    }

    /// Whether the land's colours are its ground's lit by the sun's and
    /// the sky's colours (the natural colours of our light), rather than
    /// a brightness, a filter's or a look's own.
    pub(crate) fn coloured(&self) -> bool {
        self.coloured && self.preference.is_none() && !self.essay && self.listing.is_none()
    }

    /// The sun, sky and ambient light these colours were made with.
    pub fn lighting(&self) -> &Lighting {
        &self.lighting
    }

    /// A natural colour (0..=1) through this palette's colour filter.
    pub(crate) fn filtered(&self, c: Rgb) -> Rgb {
        filter(self.mode, c)
    }

    /// The colour mode these colours were made for.
    pub fn mode(&self) -> ColorMode {
        self.mode
    }

    /// Colour of a land face: its mean height, unit normal (z up), and how
    /// much direct light reaches it (1 = lit, 0 = in cast shadow).
    ///
    /// Under the classic light a face is `0.5 + 0.5 cos` bright (seed
    /// 000's listing: 0 turned fully away, half bright in cast shadow);
    /// otherwise faces away from the sun or in shadow get only the sky's light.
    #[inline]
    pub fn land(&self, mean_height: f32, normal: Vec3, lit: f32) -> u32 {
        self.land_in(mean_height, normal, lit, 1.0, ORDINARY)
    }

    /// Whether the water is a dry basin's sand and salt
    /// ([`cover::dry_basin`]).
    pub fn dry_basin(&self) -> bool {
        cover::dry_basin(self.world)
    }

    /// Whether the ground's colour follows where water runs (`wet` of
    /// [`Palette::land_in`]; a world's own cover, never the temperate's).
    pub fn follows_water(&self) -> bool {
        self.wet.is_some()
    }

    /// [`Palette::land`] for a face that sees `sky` (0..=1) of the sky: the
    /// sky's light on it scales with that share (the classic light ignores
    /// it); `wet` where water runs there (`terrain::Wetness`, 0 a dry
    /// ridge, 1 a stream), which only a world's own cover follows.
    #[inline]
    pub fn land_in(&self, mean_height: f32, normal: Vec3, lit: f32, sky: f32, wet: f32) -> u32 {
        if let Some(ramp) = &self.listing {
            let i = f64::from(luminance(self.lighting.on(normal, lit)));
            return match self.mode {
                // In black and white the listing picks a pattern, not a colour.
                ColorMode::Mono => dither::grey(ramp.pattern(mean_height, i)),
                _ => ramp.colour(mean_height, i),
            };
        }
        if let Some(preference) = self.preference {
            return facings::brush(preference, normal);
        }
        if self.essay {
            return essay::colour(normal);
        }
        // Clamped as floats (NaN stays NaN and casts to bin 0).
        let h = index(
            (mean_height * self.height_scale + jitter(mean_height))
                .clamp(0.0, (HEIGHT_BINS - 1) as f32),
        );
        let s = index(((1.0 - normal.z) * self.steep_scale).clamp(0.0, (STEEP_BINS - 1) as f32));
        let base = self.base(s * HEIGHT_BINS + h, self.facing(normal), wet);
        self.lit_base(base, normal, lit, sky)
    }

    /// Colour of the land at one point of the ground (smooth shading, where
    /// colours are blended across faces): its height, unit normal, direct
    /// light and share of the sky as for [`Palette::land_in`]. No jitter and
    /// no steps between steepness classes: blended across a face, a point's
    /// random or stepped colour would draw streaks along the grid.
    #[inline]
    pub fn land_at_point(&self, height: f32, normal: Vec3, lit: f32, sky: f32) -> u32 {
        self.land_at_wet_point(height, normal, lit, sky, ORDINARY)
    }

    /// [`Palette::land_at_point`] where water runs `wet` (as
    /// [`Palette::land_in`]'s).
    #[inline]
    pub fn land_at_wet_point(
        &self,
        height: f32,
        normal: Vec3,
        lit: f32,
        sky: f32,
        wet: f32,
    ) -> u32 {
        self.land_and_rock_at_point(height, normal, lit, sky, wet).0
    }

    /// [`Palette::land_at_wet_point`]'s colour and how strongly the rock's
    /// strata show there (0..=1): on steep ground whose colour is rock's,
    /// not snow's or ice's (a pale base colour), in the looks of our own.
    #[inline]
    pub(crate) fn land_and_rock_at_point(
        &self,
        height: f32,
        normal: Vec3,
        lit: f32,
        sky: f32,
        wet: f32,
    ) -> (u32, f32) {
        if let Some(preference) = self.preference {
            return (facings::brush(preference, normal), 0.0);
        }
        if self.essay {
            return (essay::colour(normal), 0.0);
        }
        let h = index((height * self.height_scale).clamp(0.0, (HEIGHT_BINS - 1) as f32));
        // Between the middles of the two nearest steepness classes.
        let s = ((1.0 - normal.z) * self.steep_scale - 0.5).clamp(0.0, (STEEP_BINS - 1) as f32);
        let s0 = index(s);
        let s1 = (s0 + 1).min(STEEP_BINS - 1);
        let facing = self.facing(normal);
        let base = mix_packed(
            self.base(s0 * HEIGHT_BINS + h, facing, wet),
            self.base(s1 * HEIGHT_BINS + h, facing, wet),
            s - s0 as f32,
        );
        let rock = strata::weight(self.steepness(normal));
        let rock = if rock > 0.0 {
            rock * strata::bare(base)
        } else {
            0.0
        };
        (self.lit_base(base, normal, lit, sky), rock)
    }

    /// How steep ground of unit normal `normal` is for the palette: 1 at
    /// the field's 90th percentile of steepness (`steepness_reference`).
    #[inline]
    pub(crate) fn steepness(&self, normal: Vec3) -> f32 {
        (1.0 - normal.z) * self.steep_scale / STEEP_BINS as f32
    }

    /// `1 - normal.z` at steepness 1 ([`Palette::steepness`]).
    pub(crate) fn steep_reference(&self) -> f32 {
        STEEP_BINS as f32 / self.steep_scale
    }

    /// How far a face of unit normal `normal` turns to the sunward side
    /// (`cover::facing_weight`), where the world tells facings apart.
    #[inline]
    fn facing(&self, normal: Vec3) -> f32 {
        self.sunward
            .as_ref()
            .map_or(0.0, |(_, side)| cover::facing_weight(normal, *side))
    }

    /// The base colour of the land table's bin `i` on a face turned
    /// `facing` ([`Palette::facing`]) to the sunward side, where water
    /// runs `wet`.
    #[inline]
    fn base(&self, i: usize, facing: f32, wet: f32) -> u32 {
        let dry = match &self.sunward {
            None => self.land[i],
            Some((toward, _)) => mix_packed(self.land[i], toward[i], facing),
        };
        let Some((wet_land, wet_toward)) = &self.wet else {
            return dry;
        };
        let streams = match wet_toward {
            None => wet_land[i],
            Some(toward) => mix_packed(wet_land[i], toward[i], facing),
        };
        mix_packed(dry, streams, cover::streams(self.world, wet))
    }

    /// A land base colour under this light.
    #[inline]
    fn lit_base(&self, base: u32, normal: Vec3, lit: f32, sky: f32) -> u32 {
        if self.coloured {
            return scale_packed3(base, self.lighting.on_under(normal, lit, sky));
        }
        let b = self.brightness(normal, lit);
        if self.offset == 0.0 {
            scale_packed(base, b)
        } else {
            pack(unpack(base).map(|c| c * 255.0), b, self.offset)
        }
    }

    /// Colour of water over ground `depth` (>= 0) units below sea level.
    ///
    /// Deeper water is never lighter; it keeps its hue and stops darkening at
    /// the field's deepest point instead of wrapping into another colour.
    #[inline]
    pub fn water(&self, depth: f32) -> u32 {
        let last = self.water.len() - 1;
        self.water[index(depth * self.depth_scale).min(last)]
    }

    /// Colour of a skirt face (the cut side of the map) facing `normal`.
    ///
    /// Earth, shaded like land but never in cast shadow. One colour for
    /// all heights: painters give one height per skirt column, so any
    /// height banding would show as vertical stripes.
    pub fn skirt(&self, normal: Vec3) -> u32 {
        if let Some(preference) = self.preference {
            // Mountain Terrain's "solid color rectangle" down to sea level.
            return preference & facings::darkness(facings::Facing::Towards(1));
        }
        pack(self.skirt, self.brightness(normal, 1.0), self.offset)
    }

    /// How thick the air's haze is at the back edge, where the world
    /// draws it per mountain (`cover::haze`).
    pub(crate) fn haze(&self) -> Option<f32> {
        cover::haze(self.world, self.air)
    }

    /// The sky behind the mountain, top and horizon colours, filtered
    /// (black in Mono, Sonar and Outline).
    pub fn sky(&self) -> (u32, u32) {
        if let Some(backdrop) = self.backdrop {
            return (backdrop, backdrop);
        }
        match self.mode {
            ColorMode::Mono | ColorMode::Sonar | ColorMode::Filled | ColorMode::Outline => (0, 0),
            mode => {
                let l = &self.lighting;
                let sky = cover::air(self.world, [l.zenith, l.horizon], self.air, l.night);
                let [top, bottom] = sky.map(|c| to_u32(filter(mode, c)));
                (top, bottom)
            }
        }
    }

    /// Edge colour of land faces in the wire modes: white for Sonar, FL3's
    /// green for Outline (and white in every other mode, should one want
    /// edges). The renderer's edges read it here (an unused copy here once
    /// disagreed with theirs).
    pub fn outline_land(&self) -> u32 {
        match self.mode {
            ColorMode::Outline => FL3_GREEN,
            ColorMode::Filled => FL3_PEN,
            _ => 0x00ff_ffff,
        }
    }

    /// Edge colour of water faces in the wire modes: white for Sonar, FL3's
    /// blue for Outline.
    pub fn outline_water(&self) -> u32 {
        match self.mode {
            ColorMode::Outline => FL3_BLUE,
            ColorMode::Filled => FL3_PEN,
            _ => 0x00ff_ffff,
        }
    }

    /// The flat fills of a land and a water cell in the outlined modes:
    /// black in Sonar; FL3's green and blue in Filled (no shading: "Rendered
    /// mode in turn differs from Filled mode in basing each triangle's
    /// color on the angle it presents to a ray from the sun").
    pub fn fills(&self) -> (u32, u32) {
        match self.mode {
            ColorMode::Filled => (FL3_GREEN, FL3_BLUE),
            _ => (0, 0),
        }
    }

    /// Brightness: Lambert cosine times cast light over the ambient floor
    /// (`0.5 + 0.5 cos`, 0..=1, under the classic light).
    #[inline]
    fn brightness(&self, normal: Vec3, lit: f32) -> f32 {
        luminance(self.lighting.on(normal, lit)) * self.gain
    }
}

/// `value` if it is a positive finite number, else `fallback`.
fn positive_or(value: f32, fallback: f32) -> f32 {
    if value.is_finite() && value > 0.0 {
        value
    } else {
        fallback
    }
}

/// A few bins of deterministic jitter from the bits of a face's height.
#[inline]
fn jitter(mean_height: f32) -> f32 {
    let mixed = mean_height.to_bits().wrapping_mul(0x9e37_79b1) >> 16;
    // Multiply-shift maps 16 random bits onto 0..=2J without a division.
    (((mixed * (2 * JITTER_BINS as u32 + 1)) >> 16) as i32 - JITTER_BINS) as f32
}

/// The tint each colour filter multiplies luminance by; `None` for modes
/// that keep their own colours.
fn tint(mode: ColorMode) -> Option<Rgb> {
    let t = match mode {
        ColorMode::Gray | ColorMode::Mono => [1.0, 1.0, 1.0],
        ColorMode::Red => [1.0, 0.20, 0.14],
        ColorMode::Green => [0.24, 1.0, 0.26],
        ColorMode::Blue => [0.22, 0.38, 1.0],
        ColorMode::Yellow => [1.0, 0.86, 0.22],
        ColorMode::Cyan => [0.16, 0.92, 1.0],
        ColorMode::Purple => [0.78, 0.22, 1.0],
        _ => return None,
    };
    Some(t)
}

/// Applies the colour filter of `mode` to a natural colour (0..=1).
fn filter(mode: ColorMode, c: Rgb) -> Rgb {
    match mode {
        ColorMode::Sonar | ColorMode::Filled | ColorMode::Outline => [0.0; 3],
        _ => match tint(mode) {
            Some(t) => {
                // Darker than the tint: the tint scaled down, at the same
                // luminance. Lighter: the tint blended part way to white, so
                // sand and snow stay tinted instead of washing out. Either
                // way the channel order is the tint's.
                let (y, yt) = (luminance(c).clamp(0.0, 1.0), luminance(t));
                if y <= yt {
                    t.map(|v| v * y / yt)
                } else {
                    mix(t, [1.0; 3], WHITENING * (y - yt) / (1.0 - yt))
                }
            }
            None => c,
        },
    }
}

/// Gain and offset of the final tone curve. Mono follows seed 000's pattern
/// choice, `pattern = 36 * value - 10` of 16: shaded values from 0.28 to
/// 0.75 spread over all 17 dither levels, so shading, not colour, carries
/// the picture.
fn tone(mode: ColorMode) -> (f32, f32) {
    match mode {
        ColorMode::Mono => (36.0 / 16.0, 10.0 / 16.0 * 255.0),
        _ => (1.0, 0.0),
    }
}

/// A filtered natural colour (0..=1) as a table entry (0..=255).
fn finish(mode: ColorMode, c: Rgb) -> Rgb {
    match mode {
        ColorMode::Mono => [mono_value(c) * 255.0; 3],
        _ => filter(mode, c).map(|v| v * 255.0),
    }
}

/// Seed 000's HSV value for Mono: 2/3 for green land rising to 0.94 for
/// snow, here from the natural colour's luminance.
fn mono_value(c: Rgb) -> f32 {
    let snow = ((luminance(c) - 0.45) / 0.5).clamp(0.0, 1.0);
    2.0 / 3.0 + 0.27 * snow
}

/// Mono water: half grey at the shore (seed 000's middle pattern), darker
/// with depth in step with the natural blue.
fn mono_water(c: Rgb) -> u32 {
    let v = 0.5 * luminance(c) / luminance(natural::SHALLOW);
    to_u32([v.min(1.0); 3])
}

/// Where the green, brown and snow zones lie, as fractions of the highest peak.
struct Zones {
    treeline: f32,
    band: f32,
    beach: bool,
    world: World,
    /// A number from 0 to 1 drawn per mountain: where in its range the
    /// world's cover lies on this one (`cover::draw`).
    draw: f32,
}

impl Zones {
    /// Seed 000's treeline for a height setting of `height` (1..=10).
    fn new(height: u32, has_water: bool, world: World) -> Self {
        let h = crate::settings::handles::HEIGHT.clamp(height) as f32;
        Zones {
            treeline: 0.4 + 1.0 / h,
            band: 0.9 / h,
            beach: has_water,
            world,
            draw: 0.5,
        }
    }

    /// The natural colour at height fraction `u` (0 sea, 1 highest peak) on
    /// a face of relative steepness `steep` (0 flat, 1 the field's steep
    /// faces) turned `facing` (`cover::land`'s) to the sunward side, where
    /// water runs `wet` (which the temperate world's cover ignores).
    fn colour(&self, u: f32, steep: f32, facing: f32, wet: f32) -> Rgb {
        use natural::*;
        if !matches!(self.world, World::Temperate | COAST) {
            return cover::land(self.world, (u, steep, facing, wet), self.beach, self.draw);
        }
        let low = u / self.treeline;
        let lowland = if self.beach {
            ramp(
                &[
                    (0.0, SAND),
                    (0.025, SAND),
                    (0.06, MEADOW),
                    (0.45, FOREST),
                    (1.0, ALPINE),
                ],
                low,
            )
        } else {
            ramp(&[(0.0, MEADOW), (0.45, FOREST), (1.0, ALPINE)], low)
        };
        let cliff = smoothstep(0.7, 1.0, steep) * 0.5;
        let lowland = mix(lowland, CLIFF, cliff);
        // Steep faces shed snow: they meet it higher up.
        let t = (u - self.treeline) / self.band - 0.45 * smoothstep(0.4, 1.0, steep);
        if t <= 0.0 {
            return lowland;
        }
        let alpine = ramp(&[(0.0, ALPINE), (0.4, BROWN), (0.68, ROCK), (1.0, SNOW)], t);
        mix(lowland, alpine, smoothstep(0.0, 0.15, t))
    }
}

/// The land's tables in `mode` for `zones` under a night of `night` (0
/// day, 1 full night): the faces turned from the sunward side, or every
/// face where the world does not tell facings apart; and where it does,
/// the faces turned to it, with that side (`sunward()`); where the
/// world's cover follows the water, those two along the streams (the
/// first two being then the driest ridges').
fn land_tables(
    mode: ColorMode,
    zones: &Zones,
    night: f32,
    sunward: impl FnOnce() -> Vec2,
) -> (Box<[u32]>, Option<Sunward>, Option<Wet>) {
    let lit = |table| match mode {
        ColorMode::Natural => night::land(table, night),
        _ => table,
    };
    let faces = cover::faces(zones.world);
    let wets = cover::wets(zones.world) && mode == ColorMode::Natural;
    let dry = if wets { 0.0 } else { ORDINARY };
    let away = lit(land_table(mode, zones, -1.0, dry));
    let toward = faces.then(|| (lit(land_table(mode, zones, 1.0, dry)), sunward()));
    let wet = wets.then(|| {
        let toward = faces.then(|| lit(land_table(mode, zones, 1.0, 1.0)));
        (lit(land_table(mode, zones, -1.0, 1.0)), toward)
    });
    (away, toward, wet)
}

/// The filtered base colour of every (steepness, height) bin, for faces
/// turned `facing` to the sunward side where water runs `wet`.
fn land_table(mode: ColorMode, zones: &Zones, facing: f32, wet: f32) -> Box<[u32]> {
    let mut table = Vec::with_capacity(STEEP_BINS * HEIGHT_BINS);
    for s in 0..STEEP_BINS {
        let steep = (s as f32 + 0.5) / STEEP_BINS as f32;
        for h in 0..HEIGHT_BINS {
            let u = (h as f32 + 0.5) / HEIGHT_BINS as f32;
            table.push(pack(
                finish(mode, zones.colour(u, steep, facing, wet)),
                1.0,
                0.0,
            ));
        }
    }
    table.into_boxed_slice()
}

/// What decides the water's colours.
struct Waters {
    /// Darker over deeper ground.
    relative: bool,
    /// Depth of the deepest point (> 0).
    deepest: f32,
    /// The sky colour the surface reflects, if any.
    reflected: Option<Rgb>,
    /// How much of the night's look (0 by day).
    night: f32,
    /// The world whose water it is (`cover.rs`; the temperate's is ours).
    world: World,
    /// The mountain's draw within its world (`cover::draw`).
    draw: f32,
    /// How much of its midday brightness a world's water keeps in this
    /// light ([`Lighting::level_share`]); the temperate's keeps its own.
    lit: f32,
}

/// A world's water colour `c` in the light of `w`: by day, dimmed by the
/// square root of how dim level ground is against the midday sun (the
/// whole of it turned a low sun's ice to mud, the mirror, unchanged, then
/// showing more than the ice); the night's look dims it on its own
/// (`night::water`).
fn lit_water(c: Rgb, w: &Waters) -> Rgb {
    let lit = w.lit.sqrt();
    let k = lit + (1.0 - lit) * w.night.clamp(0.0, 1.0);
    c.map(|v| v * k)
}

/// Water colours by depth and the depth-to-bin scale.
fn water_table(mode: ColorMode, w: &Waters, gain: f32, offset: f32) -> (Box<[u32]>, f32) {
    let (relative, deepest) = (w.relative, w.deepest);
    let table = (0..DEPTH_BINS)
        .map(|i| {
            let t = i as f32 / (DEPTH_BINS - 1) as f32;
            let c = match (relative, w.world) {
                // Most of the darkening near the shore, where it shows.
                (true, World::Temperate | COAST) => mix(natural::SHALLOW, natural::DEEP, t.sqrt()),
                (false, World::Temperate | COAST) => natural::SEA,
                (true, world) => lit_water(cover::water(world, t, w.draw), w),
                (false, world) => lit_water(cover::water(world, 0.35, w.draw), w),
            };
            let c = w.reflected.map_or(c, |sky| mix(c, sky, WATER_REFLECTS));
            let c = night::water(c, w.night);
            match mode {
                ColorMode::Mono => mono_water(c),
                _ => pack(finish(mode, c), gain, offset),
            }
        })
        .collect();
    let scale = if relative {
        (DEPTH_BINS - 1) as f32 / deepest
    } else {
        0.0
    };
    (table, scale)
}

/// The water of seed 000's listing (`look = "fractal-mountain-climbing"`
/// without `relative_depth`): its one light blue, unshaded (Mono's grey
/// pattern), at every depth.
fn listing_water(mode: ColorMode) -> (Box<[u32]>, f32) {
    let water = match mode {
        ColorMode::Mono => dither::grey(listing::WATER_PATTERN),
        _ => listing::WATER,
    };
    (vec![water].into(), 0.0)
}

/// Mountain Terrain's water by depth, one bin a height unit: pure blue,
/// less the depth under Relative Depth.
fn mountain_terrain_water(relative: bool) -> (Box<[u32]>, f32) {
    let table = (0..=facings::MAX_DARKENING)
        .map(|d| facings::water(d as f32, relative))
        .collect();
    (table, if relative { 1.0 } else { 0.0 })
}

/// Relative steepness of the field's steep faces: the 90th percentile of
/// `1 - normal.z` over (a sample of) its cells, so "steep" means steep for
/// this mountain whatever its vertical scale.
fn steepness_reference(field: &Heightfield) -> f32 {
    let n = field.size();
    let spacing = field.extent() / (n - 1) as f32;
    let step = (n / 256).max(1);
    let mut samples = Vec::with_capacity((n / step + 1) * (n / step + 1));
    for y in (0..n - 1).step_by(step) {
        for x in (0..n - 1).step_by(step) {
            let dx = field.get(x + 1, y) - field.get(x, y);
            let dy = field.get(x, y + 1) - field.get(x, y);
            let normal = Vec3::new(-dx, -dy, spacing).normalize_or_zero();
            samples.push(1.0 - normal.z);
        }
    }
    let k = samples.len() * 9 / 10;
    let (_, &mut p90, _) = samples.select_nth_unstable_by(k, f32::total_cmp);
    positive_or(p90, 0.05).clamp(0.005, 1.0)
}
