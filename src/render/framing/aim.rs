//! Where a vista aims ([`Aim`]): today's vista, and each world's drawn per
//! mountain within the world's ranges. The vista's camera is fitted to
//! the aim in `vista.rs`.

use crate::settings::World;
use crate::settings::worlds::COAST;

/// The camera's horizontal distance in front of the near edge, in grid
/// widths: closer magnifies the foreground more. Tall frames (portrait)
/// need a closer camera to see from the back edge down to the near edge;
/// the vista's fit takes the first distance that can (after a world's
/// own, [`Aim::standoff`]). The first is today's vista's.
pub(super) const STANDOFFS: [f32; 6] = [0.6, 0.45, 0.32, 0.22, 0.14, 0.08];
/// Where the back edge at sea level sits, as a fraction of the height from
/// the top: peaks behind it rise into the sky above.
pub(super) const SKYLINE: f32 = 0.4;
/// Sky kept above the highest land, as a fraction of the height, in
/// today's vista.
pub(super) const SKY_ROOM: f32 = 0.12;

/// Where a vista aims: where the back edge sits, how much of the grid's
/// depth lies in front of the frame's bottom, how much sky stays above the
/// land and how far off the camera stands. Today's vista
/// ([`Aim::ACROSS`]) sees the whole grid from low in front of it; a higher
/// camera that looks down into the valleys (the alpine world's) leaves the
/// nearest land below the frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Aim {
    /// Where the back edge at sea level sits, as a fraction of the height
    /// from the top (before tall land lowers it).
    pub skyline: f32,
    /// The share of the grid's depth, from its near edge, that falls
    /// below the bottom of the frame: 0 shows the near edge.
    pub cropped: f32,
    /// Sky kept above the highest land where tall land lowers the back
    /// edge, as a fraction of the height ([`SKY_ROOM`] for today's vista).
    pub room: f32,
    /// The camera's horizontal distance in front of the near edge, in grid
    /// widths, where the frame lets it see from the back edge down to the
    /// bottom (a nearer one of [`STANDOFFS`] where not).
    pub standoff: f32,
}

/// The shares of the land's depth, from its near edge, that a world's
/// vista whose land it sees only cut off at the top crops below the frame
/// instead, tried in turn ([`Aim::looking_down`]): a camera above the near
/// land, looking down over it as the alpine world's does, rather than one
/// near face from edge to edge (6 of seeds 1-480 were such walls: tall
/// land near the front, whichever side is the front).
pub(super) const DOWN_CROPS: [f32; 3] = [0.5, 0.65, 0.8];
/// Where the back edge of a vista looking down sits ([`Aim::looking_down`]):
/// high in the frame, over the land below it.
const DOWN_SKYLINE: f32 = 0.2;

impl Aim {
    /// This aim from above its near land, looking down over it: `cropped`
    /// of the land's depth below the frame, the back edge high
    /// ([`DOWN_SKYLINE`]).
    pub(super) fn looking_down(self, cropped: f32) -> Aim {
        Aim {
            cropped,
            skyline: DOWN_SKYLINE,
            ..self
        }
    }

    /// Low in front of the land, looking across it: the near edge at the
    /// bottom, the back edge at [`SKYLINE`] (the temperate world's vista).
    pub const ACROSS: Aim = Aim {
        skyline: SKYLINE,
        cropped: 0.0,
        room: SKY_ROOM,
        standoff: STANDOFFS[0],
    };

    /// The aim of the vista of the mountain `identity` in `world`, drawn
    /// from the identity within the world's ranges (the same at every
    /// size), so two slides of one world are framed apart. The alpine
    /// world's camera stands high and looks down into its valleys, where
    /// its lakes lie: the back edge high in the frame and the near half of
    /// the land below it. Each part is drawn from bits of its own. The
    /// temperate world named keeps today's vista (`worlds::COAST`, the
    /// temperate coast of the varied draw, draws its own).
    pub fn of(world: World, identity: u64) -> Aim {
        let Some(ranges) = aims(world) else {
            return Aim::ACROSS;
        };
        let draw = crate::terrain::splitmix::mix(identity ^ AIM_KEY);
        // A second draw for the room and the distance (the first's bits
        // are spent), so the back edge and the crop keep their draws.
        let more = crate::terrain::splitmix::mix(draw);
        let unit = |bits: u64, shift: u32| ((bits >> shift) & 0xffff) as f32 / 65535.0;
        let within = |(lo, hi): Range, t: f32| lo + (hi - lo) * t;
        Aim {
            skyline: within(ranges.skyline, unit(draw, 16)),
            cropped: within(ranges.cropped, unit(draw, 40)),
            room: within(ranges.room, unit(more, 0)),
            standoff: within(ranges.standoff, unit(more, 16)),
        }
    }
}

/// The ranges [`Aim::of`] draws a world's aim from, each (least, most),
/// each wide, so the slides of one world are framed apart: from looking
/// across the land with much sky to looking down with little, and from a
/// near ridge looming against a far range to the whole land laid out.
struct Ranges {
    /// Where the back edge sits ([`Aim::skyline`]).
    skyline: Range,
    /// How much of the land's depth falls below the frame ([`Aim::cropped`]).
    cropped: Range,
    /// Sky kept above the highest land ([`Aim::room`]).
    room: Range,
    /// The camera's distance in front of the land ([`Aim::standoff`]).
    standoff: Range,
}

/// A range a vista's aim is drawn from: (least, most).
type Range = (f32, f32);

/// The sky a world's slide keeps above its highest land: from a strip
/// over a range that fills the frame to a wide sky over a low horizon
/// (about half the frame). Below 0.08 the tallest land meets the top;
/// more than 0.4 and the sky becomes most of the picture.
const ROOMS: Range = (0.08, 0.4);

/// A world's camera distances, nearer than the temperate vista's (the
/// first of [`STANDOFFS`]): a camera near the land sees the near ridges
/// loom large, often in shade, against the far range; from further back
/// the land lies flatter, as the temperate coast's does. (A range out to
/// a whole grid width, further than today's, made the slides more alike.)
const NEARER: Range = (0.15, 0.45);

/// The desert's camera distances: its mesas stand tall at the near
/// edge, and from much nearer than the temperate vista a camera sees a
/// single wall of rock.
const DESERT_NEARER: Range = (0.3, STANDOFFS[0]);

/// The ranges of the vista of `world`; none for the temperate world
/// named ([`Aim::ACROSS`]), which keeps the picture from before the
/// worlds (`worlds::COAST` here is the temperate coast the varied draw
/// gave, `worlds::drawn_world`).
fn aims(world: World) -> Option<Ranges> {
    let (skyline, cropped, standoff) = match world {
        World::Temperate => return None,
        // The temperate coast of the varied draw: low over its sea, as the
        // tropics', and now and then a near ridge cropped.
        COAST => ((0.3, 0.55), (0.0, 0.3), NEARER),
        World::Alpine => ((0.16, 0.34), (0.35, 0.65), NEARER),
        World::Winter => ((0.22, 0.5), (0.0, 0.5), NEARER),
        World::Autumn => ((0.25, 0.5), (0.0, 0.45), NEARER),
        World::Desert => ((0.25, 0.55), (0.0, 0.4), DESERT_NEARER),
        // Low over the sea, as the temperate coast: from higher, the
        // water below the sun or the moon mirrors the sky above it and
        // no longer glitters.
        World::Tropical => ((0.34, 0.55), (0.0, 0.0), NEARER),
    };
    Some(Ranges {
        skyline,
        cropped,
        room: ROOMS,
        standoff,
    })
}

/// Mixed into a mountain's identity for its vista's aim, so the aim is
/// not another draw's again.
const AIM_KEY: u64 = 0x6169_6d20_6f66_2076;

#[cfg(test)]
mod tests {
    use super::*;

    /// Each world's aims lie within its ranges and reach across most of
    /// them, the temperate coast of the varied draw's (`worlds::COAST`)
    /// too; the temperate world named keeps today's vista.
    #[test]
    fn each_world_aims_within_its_ranges() {
        let worlds = crate::settings::worlds::OWN_LOOKS;
        for world in worlds.into_iter().chain([COAST]) {
            let ranges = aims(world).expect("a world's ranges");
            let drawn: Vec<Aim> = (0..500).map(|i| Aim::of(world, i)).collect();
            for (range, get) in [
                (ranges.skyline, (|a: &Aim| a.skyline) as fn(&Aim) -> f32),
                (ranges.cropped, |a: &Aim| a.cropped),
                (ranges.room, |a: &Aim| a.room),
                (ranges.standoff, |a: &Aim| a.standoff),
            ] {
                let values: Vec<f32> = drawn.iter().map(get).collect();
                let (lo, hi) = values
                    .iter()
                    .fold((f32::MAX, f32::MIN), |(lo, hi), &v| (lo.min(v), hi.max(v)));
                assert!(
                    lo >= range.0 && hi <= range.1,
                    "{world:?}: {lo}..{hi} in {range:?}"
                );
                assert!(
                    hi - lo >= 0.9 * (range.1 - range.0),
                    "{world:?}: {lo}..{hi}"
                );
            }
        }
        assert_eq!(Aim::of(World::Temperate, 7), Aim::ACROSS);
    }
}
