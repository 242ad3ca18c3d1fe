//! The generator's view of `Settings`: every value clamped to its range, so
//! no setting, however wild, can panic or stall a generator.

use super::heightfield::{MAX_EXPONENT, MIN_EXPONENT};
use super::noise::Spread;
use super::{SQUARE_EXTENT, TRIANGLE_EXTENT};
use crate::settings::handles::{
    CLIFFS, CONTOUR, CRAGGINESS, ELEVATION, EROSION, HEIGHT, HURST, ROUGHNESS, SEA_LEVEL,
};
use crate::settings::{Generator, Look, Profile, Settings, WaterLine};

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
    pub(crate) hurst: f32,
    pub(crate) height: f32,
    pub(crate) erosion: f32,
    pub(crate) sea_level: f32,
    pub(crate) water_line: WaterLine,
    pub(crate) lakes: bool,
    pub(crate) cliffs: f32,
    /// How the deviations are spread: FL3's pseudo-normal ones (`look =
    /// "fl3"`), the essay's `cos(random * PI)` (`look = "essay"`), ours
    /// uniform.
    pub(crate) spread: Spread,
    /// The essay's square with its outer edges undisplaced (`look =
    /// "essay"`): the border's points keep their ends' mean.
    pub(crate) still_edges: bool,
    /// What an edge midpoint's displacement is scaled by against a
    /// centre's (the square generators), where it is not the same: the
    /// essay's `side_roughness = 0.15` against `center_roughness = 0.2`.
    pub(crate) edge_share: Option<f32>,
    /// The most the land may stand above its water line, in grid widths,
    /// where its world drew its height (`worlds::height_drawn`): none
    /// where a person set it, or the world keeps the key's own.
    pub(crate) tallest: Option<f32>,
}

/// The essay's edge midpoints' roughness against its centres'.
const ESSAY_EDGE_SHARE: f32 = 0.15 / 0.2;

impl Params {
    /// Clamps each setting into its range in the key table; a NaN falls
    /// back to the default.
    pub(crate) fn from_settings(s: &Settings) -> Self {
        Params {
            generator: s.generator,
            exponent: s.grid_exponent().clamp(MIN_EXPONENT, MAX_EXPONENT),
            cragginess: CRAGGINESS.clamp(s.cragginess) as f32,
            elevation: ELEVATION.clamp(s.elevation),
            roughness: ROUGHNESS.clamp(s.roughness),
            contour: CONTOUR.clamp(s.contour),
            profile: s.profile,
            hurst: HURST.clamp(s.hurst),
            height: HEIGHT.clamp(s.height) as f32,
            erosion: EROSION.clamp(s.erosion),
            sea_level: SEA_LEVEL.clamp(s.sea_level),
            water_line: s.water_line,
            lakes: s.lakes,
            cliffs: CLIFFS.clamp(s.cliffs),
            spread: match s.look {
                Look::Fl3 => Spread::Triangle,
                Look::Essay => Spread::Arcsine,
                _ => Spread::Uniform,
            },
            still_edges: s.look == Look::Essay,
            edge_share: (s.look == Look::Essay).then_some(ESSAY_EDGE_SHARE),
            tallest: None,
        }
    }

    /// Width of the grid in height units for this generator.
    pub(crate) fn extent(&self) -> f32 {
        match self.generator {
            Generator::Square | Generator::Diamond | Generator::Brownian => SQUARE_EXTENT,
            Generator::Triangle => TRIANGLE_EXTENT,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::settings::keys::{self, Key, Kind};

    fn range(key: &Key) -> (f32, f32) {
        match key.kind {
            Kind::Float { min, max } => (min as f32, max as f32),
            Kind::Int { min, max } => (min as f32, max as f32),
            other => panic!("{}: {other:?}", key.name),
        }
    }

    /// Out-of-range values land on the key table's bounds (elevation was
    /// clamped at 0 here while the table's least is 1).
    #[test]
    fn ranges_are_the_key_tables() {
        let low = Settings {
            elevation: -5.0,
            roughness: -5.0,
            contour: -5.0,
            erosion: -5.0,
            sea_level: -5.0,
            cragginess: 0,
            height: 0,
            ..Settings::default()
        };
        let p = Params::from_settings(&low);
        let got = [
            p.elevation,
            p.roughness,
            p.contour,
            p.erosion,
            p.sea_level,
            p.cragginess,
            p.height,
        ];
        let rows = [
            keys::ELEVATION,
            keys::ROUGHNESS,
            keys::CONTOUR,
            keys::EROSION,
            keys::SEA_LEVEL,
            keys::CRAGGINESS,
            keys::HEIGHT,
        ];
        for (key, got) in rows.iter().zip(got) {
            assert_eq!(got, range(key).0, "{}", key.name);
        }
        let high = Settings {
            elevation: 1e9,
            roughness: 1e9,
            cragginess: u32::MAX,
            height: u32::MAX,
            ..Settings::default()
        };
        let p = Params::from_settings(&high);
        assert_eq!(p.elevation, range(&keys::ELEVATION).1);
        // A NaN takes the key's default.
        let nan = Settings {
            roughness: f32::NAN,
            ..Settings::default()
        };
        assert_eq!(
            Params::from_settings(&nan).roughness,
            Settings::default().roughness
        );
        assert_eq!(p.roughness, range(&keys::ROUGHNESS).1);
        assert_eq!(p.cragginess, range(&keys::CRAGGINESS).1);
        assert_eq!(p.height, range(&keys::HEIGHT).1);
    }
}
