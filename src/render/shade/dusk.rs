//! A world's twilights: of the varied slides that fall after sunset in a
//! world of its own (not the temperate world, whose nights are its
//! pictures from before the worlds), a share is the blue hour rather
//! than the moon's night: the sun a few degrees below the horizon, the
//! sky deep blue over the last of the afterglow, the land dim and
//! colourless but not yet moonlit (`hour.rs` lights a sun below the
//! horizon). Full nights of every world are alike (dark sky, dark land);
//! twilights stand apart from them and from the days.

use super::hour::SunAt;
use crate::render::base::colour::{Rgb, mix, smoothstep};
use crate::settings::World;
use crate::settings::worlds::COAST;

/// How many of a world's varied nights in 256 are twilight instead: most
/// of them (full nights sit close together whatever the world).
const TWILIGHTS_IN_256: u64 = 192;

/// Degrees below the horizon a twilight's sun stands, least and most:
/// from the first of it (`hour.rs` still grazes the land with the sun's
/// last light from a degree up, out of the frame to the side) to where
/// the afterglow still shows ([`glowing`]).
pub(super) const DEPTHS: (f32, f32) = (3.0, 9.0);

/// Mixed into a mountain's identity for its twilight, so it is not
/// another draw's again.
const DUSK_KEY: u64 = 0x6475_736b_2064_7261;

/// The sun of the twilight the mountain `identity` in `world` is lit by
/// where its varied draw made night, or None for a night under the moon
/// (and always for the temperate world). Evening or morning, the sun
/// gone down to the viewer's right or left: its last light's disc (which
/// `hour.rs` keeps a degree up) stays out of the frame.
pub(super) fn twilight(world: World, identity: u64) -> Option<SunAt> {
    if matches!(world, World::Temperate | COAST) {
        return None;
    }
    let draw = crate::terrain::splitmix::mix(identity ^ DUSK_KEY);
    if draw & 0xff >= TWILIGHTS_IN_256 {
        return None;
    }
    let unit = |shift: u32| ((draw >> shift) & 0xffff) as f32 / 65535.0;
    let afternoon = (draw >> 63) == 1;
    Some(SunAt {
        elevation: -(DEPTHS.0 + (DEPTHS.1 - DEPTHS.0) * unit(8)),
        azimuth: match afternoon {
            true => 135.0 + 40.0 * unit(24),
            false => 5.0 + 40.0 * unit(24),
        },
        afternoon,
    })
}

/// The afterglow along the horizon of a twilight in `world`, with the
/// mountain's draw of its air `v` (`cover::air_draw`): each world's
/// own, from its deepest to its palest (the desert's orange, winter's
/// rose and lilac over the snow, the tropics' coral, autumn's amber,
/// the mountains' alpenglow).
pub(super) fn afterglow(world: World, v: f32) -> Rgb {
    let [deep, pale]: [Rgb; 2] = match world {
        World::Desert => [[0.86, 0.42, 0.22], [0.90, 0.66, 0.40]],
        World::Winter => [[0.72, 0.50, 0.60], [0.84, 0.70, 0.72]],
        World::Tropical => [[0.86, 0.40, 0.38], [0.92, 0.62, 0.44]],
        World::Autumn => [[0.84, 0.50, 0.26], [0.88, 0.70, 0.44]],
        World::Alpine => [[0.80, 0.46, 0.44], [0.88, 0.66, 0.54]],
        COAST | World::Temperate => return [0.0; 3],
    };
    mix(deep, pale, (v * 11.0).fract())
}

/// How much of the horizon the afterglow takes `night` (0..=1) into
/// the night's look: none by day or under the moon, all of
/// [`AFTERGLOW`] through the first of the blue hour, fading as the
/// night's look grows whole.
pub(super) fn glowing(night: f32) -> f32 {
    AFTERGLOW * smoothstep(0.0, 0.4, night) * (1.0 - smoothstep(0.75, 1.0, night))
}

/// The most of the horizon's colour the afterglow takes.
const AFTERGLOW: f32 = 0.75;

#[cfg(test)]
mod tests {
    use super::*;
    use crate::settings::worlds::OWN_LOOKS;

    /// Three in four of a world's nights are twilight, each sun within its
    /// depths and over most of them, and to the side, never ahead within
    /// the view (`cover::sun`'s 75-105 degrees); the temperate world has
    /// none.
    #[test]
    fn a_worlds_twilights_lie_within_their_depths() {
        for world in OWN_LOOKS {
            let suns: Vec<SunAt> = (0..2000).filter_map(|i| twilight(world, i)).collect();
            let share = suns.len() as f32 / 2000.0;
            let meant = TWILIGHTS_IN_256 as f32 / 256.0;
            assert!((share - meant).abs() < 0.05, "{world:?}: {share}");
            let (least, most) = suns.iter().fold((f32::MAX, f32::MIN), |(a, b), s| {
                (a.min(-s.elevation), b.max(-s.elevation))
            });
            assert!(least >= DEPTHS.0 && most <= DEPTHS.1, "{least}..{most}");
            for s in &suns {
                assert!(!(50.0..=130.0).contains(&s.azimuth), "{world:?}: {s:?}");
            }
            assert!(
                most - least >= 0.9 * (DEPTHS.1 - DEPTHS.0),
                "{least}..{most}"
            );
        }
        assert!((0..200).all(|i| twilight(World::Temperate, i).is_none()));
    }

    /// A twilight's horizon (the sun seven degrees down) glows: warmer
    /// and lighter than the same world's full night's, in every world at
    /// either end of its draw; and two worlds' afterglows at one draw
    /// are apart.
    #[test]
    fn a_twilight_glows_where_a_night_does_not() {
        use super::super::cover::air;
        use super::super::light::Lighting;
        use crate::render::base::colour::luminance;
        let sky = |world, v, elevation| {
            let at = SunAt {
                elevation,
                azimuth: 90.0,
                afternoon: true,
            };
            let l = Lighting::at_hour(at);
            air(world, [l.zenith, l.horizon], v, l.night)[1]
        };
        for world in OWN_LOOKS {
            for v in [0.0, 0.5, 0.99] {
                let (dusk, night) = (sky(world, v, -7.0), sky(world, v, -20.0));
                let warmth = |c: Rgb| c[0] - c[2];
                assert!(
                    warmth(dusk) > warmth(night) + 0.15,
                    "{world:?} {v}: {dusk:?} {night:?}"
                );
                assert!(luminance(dusk) > luminance(night) + 0.1, "{world:?} {v}");
            }
        }
        for (i, &a) in OWN_LOOKS.iter().enumerate() {
            for &b in &OWN_LOOKS[i + 1..] {
                for v in [0.0, 0.3, 0.6, 0.9] {
                    let (x, y) = (afterglow(a, v), afterglow(b, v));
                    let apart = (0..3).map(|k| (x[k] - y[k]).abs()).fold(0.0, f32::max);
                    assert!(apart >= 0.04, "{a:?} {b:?} {v}: {x:?} {y:?}");
                }
            }
        }
    }
}
