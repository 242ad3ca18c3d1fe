//! Mountain Terrain 3.0's colours (seed 003's help file, "Technical
//! Information"): `look = "mountain-terrain"` under a colour filter.
//!
//! "The user chooses a color preference. This preference is translated in
//! a hexadecimal code, representing a solid color of that choice. Gray is
//! 0x00FFFFFF, Purple is 0x00FF00FF, and so forth. Then, after the normal
//! of a triangle is determined, it checks ... the theoretical possible
//! directions it could face ... In total, there are 9 possible facings ...
//! it creates a solid windows brush with a darkness value from the facing
//! combined with the color preference using a logical AND." And: "Darkening
//! water is simply a subtraction of the average height of the Field values
//! at that location from Pure Blue, up to a reasonable maximum."
//!
//! The help file gives the mechanism, not the nine darknesses: ours light
//! the faces from the left (brightest facing left, darkest facing right),
//! flat land in between; the "reasonable maximum" leaves the deepest water
//! a quarter blue.

use glam::Vec3;

use crate::settings::ColorMode;

/// The colour preference's solid colour, for the filters the help file's
/// scheme covers ("Gray is 0x00FFFFFF, Purple is 0x00FF00FF, and so forth").
pub fn preference(mode: ColorMode) -> Option<u32> {
    let hex = match mode {
        ColorMode::Gray => 0x00ff_ffff,
        ColorMode::Red => 0x00ff_0000,
        ColorMode::Green => 0x0000_ff00,
        ColorMode::Blue => 0x0000_00ff,
        ColorMode::Yellow => 0x00ff_ff00,
        ColorMode::Cyan => 0x0000_ffff,
        ColorMode::Purple => 0x00ff_00ff,
        _ => return None,
    };
    Some(hex)
}

/// The nine facings a triangle can have: flat, or sloping towards one of
/// eight directions.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Facing {
    /// Near level.
    Flat,
    /// Sloping down towards the right, then round through the back (the
    /// turn from the right towards the back is positive): 0 right, 1 back
    /// right, 2 back, 3 back left, 4 left, 5 front left, 6 front, 7 front right.
    Towards(u8),
}

/// How far from level (the horizontal part of a unit normal) a face still
/// counts as flat: about 11.5 degrees.
const FLAT: f32 = 0.2;

/// Darkness of a flat face, and of each of the eight slopes (right, back
/// right, back, back left, left, front left, front, front right): grey
/// levels, lit from the left.
const FLAT_LEVEL: u32 = 0xc0;
const SLOPE_LEVELS: [u32; 8] = [0x60, 0x80, 0xa0, 0xe0, 0xff, 0xe0, 0xa0, 0x80];

/// Water's colour, pure blue.
pub const PURE_BLUE: u32 = 0x0000_00ff;
/// The most the depth takes from pure blue (the help file's "reasonable
/// maximum ... to prevent it from looping over into some other color").
pub const MAX_DARKENING: u32 = 0xbf;

/// Which of the nine facings a face of unit normal `normal` (z up, y
/// towards the back) has.
pub fn facing(normal: Vec3) -> Facing {
    let across = normal.x.hypot(normal.y);
    // NaN (a degenerate face) counts as flat.
    if across.is_nan() || across < FLAT {
        return Facing::Flat;
    }
    let turns = normal.y.atan2(normal.x) / std::f32::consts::FRAC_PI_4;
    Facing::Towards((turns.round() as i32).rem_euclid(8) as u8)
}

/// The grey darkness of a facing, as a Windows colour (the level in every
/// channel).
pub fn darkness(f: Facing) -> u32 {
    let level = match f {
        Facing::Flat => FLAT_LEVEL,
        Facing::Towards(d) => SLOPE_LEVELS[usize::from(d & 7)],
    };
    level * 0x0001_0101
}

/// The brush of a land face: the preference ANDed with its facing's darkness.
pub fn brush(preference: u32, normal: Vec3) -> u32 {
    preference & darkness(facing(normal))
}

/// Water over ground `depth` height units deep: pure blue, less the depth
/// (one level a whole unit) when `relative` (Relative Water Depth), at most
/// [`MAX_DARKENING`].
pub fn water(depth: f32, relative: bool) -> u32 {
    if !relative || depth.is_nan() || depth <= 0.0 {
        return PURE_BLUE;
    }
    PURE_BLUE - (depth as u32).min(MAX_DARKENING)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nine_facings_and_their_darknesses() {
        assert_eq!(facing(Vec3::Z), Facing::Flat);
        let slope = |x: f32, y: f32| facing(Vec3::new(x, y, 1.0).normalize());
        assert_eq!(slope(1.0, 0.0), Facing::Towards(0));
        assert_eq!(slope(0.0, 1.0), Facing::Towards(2));
        assert_eq!(slope(-1.0, 0.0), Facing::Towards(4));
        assert_eq!(slope(0.0, -1.0), Facing::Towards(6));
        assert_eq!(slope(1.0, -1.0), Facing::Towards(7));
        assert_eq!(slope(0.1, 0.1), Facing::Flat);
        assert_eq!(brush(0x00ff_00ff, Vec3::Z), 0x00c0_00c0);
        assert_eq!(
            brush(0x00ff_ffff, Vec3::new(-1.0, 0.0, 1.0).normalize()),
            0x00ff_ffff
        );
    }

    #[test]
    fn water_is_pure_blue_less_its_depth() {
        assert_eq!(water(30.0, false), 0xff);
        assert_eq!(water(0.0, true), 0xff);
        assert_eq!(water(30.0, true), 0xff - 30);
        assert_eq!(water(1e6, true), 0xff - MAX_DARKENING);
    }
}
