//! A moon rising ahead: of the full nights of the varied draw (those a
//! world's twilight left, `dusk.rs`), half see the moon low ahead, its
//! disc and its pale glow in the frame over the land's dark outline. The
//! other half keep the night's moon high to the side, out of the frame,
//! its light on the slopes turned to it. Nights sat close together in
//! the slide show (dark sky over dark land, whatever the world); a moon
//! in the sky is a night of another kind. The temperate world named keeps
//! its nights, the pictures from before the worlds.

use crate::settings::World;

/// How many in 256 of a world's full varied nights see the moon rise.
const RISING_IN_256: u64 = 128;

/// Degrees above the horizon a rising moon stands, least and most: within
/// the vista's frame, whose top sees the sky a few degrees over the far
/// land (`weather.rs`: the sky is a backdrop over the land's far edge).
pub(super) const HEIGHTS: (f32, f32) = (1.0, 3.5);

/// Degrees either way from straight ahead a rising moon stands: within
/// the view's width.
pub(super) const TURNS: f32 = 10.0;

/// Mixed into a mountain's identity for its moonrise, so it is not
/// another draw's again.
const MOONRISE_KEY: u64 = 0x6d6f_6f6e_7269_7365;

/// Where the moon of the mountain `identity` in `world` stands, in
/// degrees up and round from the viewer's left (90 ahead), on a full
/// night of its varied draw that sees it rise; None for a night whose
/// moon stands high to the side, and always for the temperate world
/// named.
pub(super) fn rising(world: World, identity: u64) -> Option<(f32, f32)> {
    if world == World::Temperate {
        return None;
    }
    let draw = crate::terrain::splitmix::mix(identity ^ MOONRISE_KEY);
    if draw & 0xff >= RISING_IN_256 {
        return None;
    }
    let unit = |shift: u32| ((draw >> shift) & 0xffff) as f32 / 65535.0;
    let elevation = HEIGHTS.0 + (HEIGHTS.1 - HEIGHTS.0) * unit(8);
    let azimuth = 90.0 + TURNS * (2.0 * unit(24) - 1.0);
    Some((elevation, azimuth))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::settings::worlds::{COAST, OWN_LOOKS};

    /// Half of every world's full nights see the moon rise, the temperate
    /// coast of the varied draw's (`worlds::COAST`) too, each moon within
    /// its heights and turns and over most of them; the temperate world
    /// named sees none.
    #[test]
    fn half_a_worlds_full_nights_see_the_moon_rise_within_the_view() {
        for world in OWN_LOOKS.into_iter().chain([COAST]) {
            let moons: Vec<(f32, f32)> = (0..2000).filter_map(|i| rising(world, i)).collect();
            let share = moons.len() as f32 / 2000.0;
            assert!((share - 0.5).abs() < 0.05, "{world:?}: {share}");
            let (lo, hi) = moons
                .iter()
                .fold((f32::MAX, f32::MIN), |(a, b), m| (a.min(m.0), b.max(m.0)));
            assert!(lo >= HEIGHTS.0 && hi <= HEIGHTS.1, "{lo}..{hi}");
            assert!(hi - lo >= 0.9 * (HEIGHTS.1 - HEIGHTS.0), "{lo}..{hi}");
            let (left, right) = moons
                .iter()
                .fold((f32::MAX, f32::MIN), |(a, b), m| (a.min(m.1), b.max(m.1)));
            assert!(
                left >= 90.0 - TURNS && right <= 90.0 + TURNS,
                "{left}..{right}"
            );
            assert!(right - left >= 1.8 * TURNS, "{left}..{right}");
        }
        assert!((0..500).all(|i| rising(World::Temperate, i).is_none()));
    }
}
