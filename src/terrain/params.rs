//! The generator's view of `Settings`: every value clamped to its range, so
//! no setting, however wild, can panic or stall a generator.

use super::heightfield::{MAX_EXPONENT, MIN_EXPONENT};
use super::{SQUARE_EXTENT, TRIANGLE_EXTENT};
use crate::settings::{Generator, Profile, Settings, WaterLine};

/// Validated generator parameters.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Params {
    pub(crate) generator: Generator,
    pub(crate) exponent: u32,
    pub(crate) cragginess: f32,
    pub(crate) elevation: f32,
    pub(crate) roughness: f32,
    pub(crate) contour: f32,
    pub(crate) profile: Profile,
    pub(crate) height: f32,
    pub(crate) erosion: f32,
    pub(crate) sea_level: f32,
    pub(crate) water_line: WaterLine,
}

impl Params {
    /// Clamps each setting into the range `settings.rs` documents; a NaN
    /// falls back to the default.
    pub(crate) fn from_settings(s: &Settings) -> Self {
        let d = Settings::default();
        Params {
            generator: s.generator,
            exponent: s.grid_exponent().clamp(MIN_EXPONENT, MAX_EXPONENT),
            cragginess: s.cragginess.clamp(1, 128) as f32,
            elevation: clamp(s.elevation, 0.0, 1000.0, d.elevation),
            roughness: clamp(s.roughness, 1.0, 5.0, d.roughness),
            contour: clamp(s.contour, 0.25, 5.0, d.contour),
            profile: s.profile,
            height: s.height.clamp(1, 10) as f32,
            erosion: clamp(s.erosion, 0.0, 1.0, d.erosion),
            sea_level: clamp(s.sea_level, -1.0, 1.0, d.sea_level),
            water_line: s.water_line,
        }
    }

    /// Width of the grid in height units for this generator.
    pub(crate) fn extent(&self) -> f32 {
        match self.generator {
            Generator::Square | Generator::Diamond => SQUARE_EXTENT,
            Generator::Triangle => TRIANGLE_EXTENT,
        }
    }
}

/// `value` clamped to `lo..=hi`, or `fallback` if it is NaN.
fn clamp(value: f32, lo: f32, hi: f32, fallback: f32) -> f32 {
    if value.is_nan() {
        fallback
    } else {
        value.clamp(lo, hi)
    }
}
