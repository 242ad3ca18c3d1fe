//! What each look (`look = ...`) sets: the keys whose values the seed
//! program's document gives, in place of their defaults. A key a person
//! sets to anything but its default keeps that value (`keys::apply`
//! layers the look under the keys); the parts of a look no key can say
//! (seed 000's HSV ramp and tilt, Mountain Terrain's facings, FL3's
//! pseudo-normal numbers, the essay's numbers, turns and camera) are read from
//! `Settings::look` by the renderer and the generator.
//!
//! Only data here, each key named by its row's constant and each choice by
//! its enum: the key table (`keys/`) checks every value against its key's
//! range, and a test applies every preset.

use super::keys::table::{
    CLIFFS, COLOR, CONTOUR, DETAIL, ELEVATION, EROSION, GENERATOR, HEIGHT, LAKES, PROFILE,
    RELATIVE_DEPTH, ROUGHNESS, SEA_LEVEL, SHADING, SHADOWS, SUN, VIEW, WATER_LINE,
};
use super::{ColorMode, Generator, Look, Profile, Shading, Sun, ViewKind, WaterLine};

/// A key's value as a look gives it (the key table's `Value`, in a form
/// a constant can hold).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Preset {
    /// A whole number.
    Int(i64),
    /// A number.
    Float(f64),
    /// `true` or `false`.
    Bool(bool),
    /// One of a choice's names.
    Str(&'static str),
}

use Preset::{Bool, Float, Int, Str};

/// Seed 000, *Fractal Mountain Climbing*: `menuCk = {3,6,5,5,1}` is
/// Iterations 5 (33x33 points), Contour 1.50, Smoothness 2.00, Height 5,
/// Profile #1; the sea at the generator's zero (`DrawTriangle` splits at
/// `z = 0`); `_DrawTriangle`'s light, one colour a face, no shadows;
/// `CalcPoint3`'s parallelogram seen from the front.
const FRACTAL_MOUNTAIN_CLIMBING: &[(&str, Preset)] = &[
    (GENERATOR.name, Str(Generator::Triangle.name())),
    (DETAIL.name, Int(5)),
    (CONTOUR.name, Float(1.5)),
    (ROUGHNESS.name, Float(2.0)),
    (HEIGHT.name, Int(5)),
    (PROFILE.name, Str(Profile::Slope.name())),
    (EROSION.name, Float(0.0)),
    (CLIFFS.name, Float(0.0)),
    (LAKES.name, Bool(false)),
    (WATER_LINE.name, Str(WaterLine::Generator.name())),
    (SEA_LEVEL.name, Float(0.0)),
    (RELATIVE_DEPTH.name, Bool(false)),
    (SHADOWS.name, Bool(false)),
    (SUN.name, Str(Sun::Classic.name())),
    (SHADING.name, Str(Shading::Flat.name())),
    (VIEW.name, Str(ViewKind::Oblique.name())),
];

/// Seed 003, *Mountain Terrain 3.0*'s help file: square subdivision of a
/// 64 by 64 array ("currently hardcoded with a range of 64 by 64"),
/// Elevation 100, the corners from -Elevation/2 to Elevation/2 about its
/// water level, a parallelogram drawn in stripes, one facing's darkness a
/// triangle ANDed with the colour preference ("Gray is 0x00FFFFFF").
const MOUNTAIN_TERRAIN: &[(&str, Preset)] = &[
    (GENERATOR.name, Str(Generator::Square.name())),
    (DETAIL.name, Int(6)),
    (ELEVATION.name, Float(100.0)),
    (EROSION.name, Float(0.0)),
    (CLIFFS.name, Float(0.0)),
    (LAKES.name, Bool(false)),
    (WATER_LINE.name, Str(WaterLine::Generator.name())),
    (SEA_LEVEL.name, Float(0.0)),
    (COLOR.name, Str(ColorMode::Gray.name())),
    (SHADOWS.name, Bool(false)),
    (SUN.name, Str(Sun::Classic.name())),
    (SHADING.name, Str(Shading::Flat.name())),
    (VIEW.name, Str(ViewKind::Oblique.name())),
];

/// Seed 004, FL3: triangles fractured ply by ply (eight plys: "eight
/// plys is hardly too fine a resolution"), Filled mode, sea level where
/// the generator's zero is, single-point perspective, no sun.
const FL3: &[(&str, Preset)] = &[
    (GENERATOR.name, Str(Generator::Triangle.name())),
    (DETAIL.name, Int(8)),
    (EROSION.name, Float(0.0)),
    (CLIFFS.name, Float(0.0)),
    (LAKES.name, Bool(false)),
    (WATER_LINE.name, Str(WaterLine::Generator.name())),
    (SEA_LEVEL.name, Float(0.0)),
    (COLOR.name, Str(ColorMode::Filled.name())),
    (RELATIVE_DEPTH.name, Bool(false)),
    (SHADOWS.name, Bool(false)),
    (SHADING.name, Str(Shading::Flat.name())),
    (VIEW.name, Str(ViewKind::Perspective.name())),
];

/// Seed 002, the essay's final program: each square's centre and four edge
/// midpoints displaced from the means of their ends (`terrain()`: our
/// square generator, one random value a point from its common array), the
/// square's outer edges undisplaced, no sea ("mountain" colours only), a
/// perspective view, sun shading one colour a face with no cast shadows
/// (its stated limitation: "surfaces lit that should be in shadow").
///
/// Its program goes to `max_iteration = 9` on a 2048-wide square; we take
/// 8 (257 points a side). Its centres rise by up to 0.2 of their square's
/// side at every level (`center_roughness`), about twice our relief at the
/// default height: height 10.
const ESSAY: &[(&str, Preset)] = &[
    (GENERATOR.name, Str(Generator::Square.name())),
    (DETAIL.name, Int(8)),
    (HEIGHT.name, Int(10)),
    (WATER_LINE.name, Str(WaterLine::Generator.name())),
    (SEA_LEVEL.name, Float(-1.0)),
    (EROSION.name, Float(0.0)),
    (CLIFFS.name, Float(0.0)),
    (LAKES.name, Bool(false)),
    (SHADOWS.name, Bool(false)),
    (SHADING.name, Str(Shading::Flat.name())),
    (VIEW.name, Str(ViewKind::Perspective.name())),
];

/// The keys `look` sets and their values (none for ours).
pub fn presets(look: Look) -> &'static [(&'static str, Preset)] {
    match look {
        Look::Ours => &[],
        Look::FractalMountainClimbing => FRACTAL_MOUNTAIN_CLIMBING,
        Look::MountainTerrain => MOUNTAIN_TERRAIN,
        Look::Fl3 => FL3,
        Look::Essay => ESSAY,
    }
}

/// The value `look` gives key `name`, if it gives one.
pub fn preset(look: Look, name: &str) -> Option<Preset> {
    presets(look)
        .iter()
        .find(|(key, _)| *key == name)
        .map(|&(_, p)| p)
}
