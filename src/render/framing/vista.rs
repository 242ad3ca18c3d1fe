//! The vista camera: low in front of the land, looking across it towards
//! the horizon, as xmountains frames its landscapes.
//!
//! It is fitted to each frame, in grid widths (the camera stands centred,
//! one of [`STANDOFFS`] grid widths in front of the near edge, level sideways):
//! - the back edge at sea level spans exactly the frame's width; the grid's
//!   side edges splay outwards towards the camera, so they never show;
//! - the middle of the back edge at sea level sits [`SKYLINE`] of the
//!   height from the top, leaving the sky above for the peaks to rise into
//!   (lower, down to [`SKYLINE_LOWEST`], when the land is so tall it would
//!   fill the sky: exactly as low as keeps [`SKY_ROOM`] clear, see [`fitted`]);
//! - the near edge at sea level falls just below the bottom;
//! - a frame wider than [`ORDINARY`] whose land would still fill the sky
//!   with the back edge at [`SKYLINE_LOWEST`] (the land's height on screen
//!   grows with the width the back edge spans: three 16:9 monitors side by
//!   side see it three times as tall as one does) is framed as a narrower
//!   frame of its height, exactly as narrow as keeps [`SKY_ROOM`] clear
//!   (at most down to [`ORDINARY`]), and stretched sideways to its width:
//!   like xmountains, whose land is as tall on a wide screen as on a
//!   narrow one, it shows the land wider rather than taller.
//!
//! A world other than the temperate aims its vista otherwise ([`Aim::of`]):
//! its back edge higher or lower in the frame and a share of the land's
//! depth below the bottom instead of the near edge, which raises the
//! camera and pitches it down (the alpine world's looks down into its
//! valleys).
//!
//! The width fixes the focal length for a given pitch and camera height;
//! the two vertical conditions then fix the pitch and the height, found by
//! nested bisection (each condition is monotonic in its unknown).
//!
//! Every condition is a fraction of the frame, none a number of pixels, and
//! each is solved to the end rather than to a tolerance: a frame k times
//! larger is the same framing, k times finer.

use glam::{Vec2, Vec3};

use super::camera::Camera;
use crate::settings::World;

/// The camera's horizontal distance in front of the near edge, in grid
/// widths: closer magnifies the foreground more. Tall frames (portrait)
/// need a closer camera to see from the back edge down to the near edge;
/// the first distance that can is taken.
const STANDOFFS: [f32; 6] = [0.6, 0.45, 0.32, 0.22, 0.14, 0.08];
/// Where the back edge at sea level sits, as a fraction of the height from
/// the top: peaks behind it rise into the sky above.
pub(crate) const SKYLINE: f32 = 0.4;
/// The lowest the back edge goes, for land so tall it would fill the sky.
pub(crate) const SKYLINE_LOWEST: f32 = 0.72;
/// Sky kept above the highest land, as a fraction of the height.
const SKY_ROOM: f32 = 0.12;
/// The widest aspect framed only as itself (16:9, one monitor); wider
/// frames are stretched sideways when their land would fill the sky.
const ORDINARY: f32 = 16.0 / 9.0;
/// How much wider than [`ORDINARY`] a frame may be and still count as
/// 16:9: a 1366x768 laptop's screen is a 16:9 monitor too.
const ORDINARY_SLACK: f32 = 1.01;
/// The tallest land the vista frames when it would rise out of the top of
/// the frame, in grid widths above sea level. Its camera stands about a
/// tenth of a width high: from there, land half a width tall is its near
/// slope alone, one colour from edge to edge (a data set 33 samples wide
/// with `mountains:scale` 0.01 rose 0.86 widths; the settings' tallest
/// mountains rise 2.4). Generated land at the default settings rises 0.2.
const VISTA_TALLEST: f32 = 0.5;
/// How far below the bottom the near edge falls, as a fraction of the
/// height (two pixels at 1080 rows), so no row of sky shows under the sea.
const BELOW: f32 = 2.0 / 1080.0;
/// Camera heights tried, in grid widths. Above the upper end a higher camera
/// no longer widens the angle between the near and back edges.
const HEIGHTS: (f32, f32) = (1e-3, 0.97);
/// Bisection steps for the camera: far below a pixel at any frame size.
const STEPS: usize = 48;
/// Bisection steps for the skyline: its 0.32 range down to f32's precision.
const SKYLINE_STEPS: usize = 24;

/// Where a vista aims: where the back edge sits and how much of the
/// grid's depth lies in front of the frame's bottom. Today's vista
/// ([`Aim::ACROSS`]) sees the whole grid from low in front of it; a higher
/// camera that looks down into the valleys ([`Aim::DOWN`]) leaves the
/// nearest land below the frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Aim {
    /// Where the back edge at sea level sits, as a fraction of the height
    /// from the top (before tall land lowers it).
    pub skyline: f32,
    /// The share of the grid's depth, from its near edge, that falls
    /// below the bottom of the frame: 0 shows the near edge.
    pub cropped: f32,
}

impl Aim {
    /// Low in front of the land, looking across it: the near edge at the
    /// bottom, the back edge at [`SKYLINE`] (the temperate world's vista).
    pub const ACROSS: Aim = Aim {
        skyline: SKYLINE,
        cropped: 0.0,
    };

    /// The aim of the vista of the mountain `identity` in `world`, drawn
    /// from the identity within the world's ranges (the same at every
    /// size), so two slides of one world are framed apart. The alpine
    /// world's camera stands high and looks down into its valleys, where
    /// its lakes lie: the back edge high in the frame and the near half of
    /// the land below it. The temperate world keeps today's vista.
    pub fn of(world: World, identity: u64) -> Aim {
        let Some((skyline, cropped)) = aims(world) else {
            return Aim::ACROSS;
        };
        let draw = crate::terrain::splitmix::mix(identity ^ AIM_KEY);
        let unit = |shift: u32| ((draw >> shift) & 0xffff) as f32 / 65535.0;
        let within = |(lo, hi): (f32, f32), t: f32| lo + (hi - lo) * t;
        Aim {
            skyline: within(skyline, unit(16)),
            cropped: within(cropped, unit(40)),
        }
    }
}

/// The ranges [`Aim::of`] draws a world's aim from: where its back edge
/// sits (least, most) and how much of the land's depth falls below the
/// frame (least, most); each wide, so the slides of one world are framed
/// from looking across the land with much sky to looking down with
/// little. None for the temperate world ([`Aim::ACROSS`]).
fn aims(world: World) -> Option<((f32, f32), (f32, f32))> {
    match world {
        World::Temperate | World::Varied => None,
        World::Alpine => Some(((0.16, 0.34), (0.35, 0.65))),
        World::Winter => Some(((0.22, 0.5), (0.0, 0.5))),
        World::Autumn => Some(((0.25, 0.5), (0.0, 0.45))),
        World::Desert => Some(((0.25, 0.55), (0.0, 0.4))),
        // Low over the sea, as the temperate coast: from higher, the
        // water below the sun or the moon mirrors the sky above it and
        // no longer glitters.
        World::Tropical => Some(((0.34, 0.55), (0.0, 0.0))),
    }
}

/// Mixed into a mountain's identity for its vista's aim, so the aim is
/// not another draw's again.
const AIM_KEY: u64 = 0x6169_6d20_6f66_2076;

/// A camera and its focal length in pixels.
pub(crate) struct Shot {
    /// Where the camera stands and looks.
    pub camera: Camera,
    /// Pixels per unit of `x / depth` up the frame.
    pub focal: f32,
    /// How many times wider than high a unit is drawn across the frame
    /// (1 but in frames wider than [`ORDINARY`] whose land needs it).
    pub stretch: f32,
}

impl Shot {
    /// Frame position of world point `p` in a `width` x `height` frame.
    fn project(&self, p: Vec3, width: f32, height: f32) -> Vec2 {
        let scale = Vec2::new(self.focal * self.stretch, self.focal);
        Vec2::new(width, height) * 0.5 + scale * self.camera.project(p)
    }
}

/// The vista for a grid `extent` units wide in a `width` x `height` frame,
/// over land whose highest points are `tops` (world positions, e.g. each
/// row's highest point): the back edge at [`SKYLINE`], or, where the land
/// would rise within [`SKY_ROOM`] of the top, exactly as much lower as
/// keeps that strip of sky (at most down to [`SKYLINE_LOWEST`]); a frame
/// wider than [`ORDINARY`] whose land needs more is then drawn as a
/// narrower one stretched sideways ([`Shot::stretch`]).
///
/// `None` for land so tall (over [`VISTA_TALLEST`]) that even then it
/// rises out of the top of the frame: a camera this low in front of it
/// sees only the near slope (a data set's relief can be many times its
/// width), so the caller frames it another way. `None` too when
/// the near edge's lowest point (`near_floor`) stands above the camera: it
/// would look up at the edge's face and see only that wall, one colour
/// (a raised plateau, land lifted over a sea far below, a wall along the
/// near edge).
pub(crate) fn fitted(
    aim: Aim,
    extent: f32,
    (width, height): (f32, f32),
    tops: &[Vec3],
    near_floor: f32,
) -> Option<Shot> {
    let shot = fitted_to_tops(aim, extent, width, height, tops)?;
    (near_floor.is_nan() || near_floor < shot.camera.eye_height()).then_some(shot)
}

/// [`fitted`] without the look at the near edge.
fn fitted_to_tops(aim: Aim, extent: f32, width: f32, height: f32, tops: &[Vec3]) -> Option<Shot> {
    let shot = |skyline: f32| frame(Aim { skyline, ..aim }, extent, width, height);
    // The highest land's distance below the strip of sky, in heights: it
    // grows as the back edge goes down.
    let clear = |s: &Shot| {
        let top = (tops.iter())
            .map(|&p| s.project(p, width, height).y)
            .fold(f32::INFINITY, f32::min);
        top / height.max(1.0) - SKY_ROOM
    };
    let first = shot(aim.skyline);
    // Not below zero (or not a number: no land to fit): the sky is clear.
    let short = clear(&first);
    if short >= 0.0 || short.is_nan() {
        return Some(first);
    }
    let skyline = bisect_steps(aim.skyline, SKYLINE_LOWEST, SKYLINE_STEPS, |s| {
        clear(&shot(s))
    });
    let mut lowered = shot(skyline);
    let widest = width / (ORDINARY * height.max(1.0));
    if clear(&lowered) < 0.0 && widest > ORDINARY_SLACK {
        let narrowed = |k: f32| stretched(aim, extent, width, height, k);
        let k = bisect_steps(1.0, widest, SKYLINE_STEPS, |k| clear(&narrowed(k)));
        lowered = narrowed(k);
    }
    let tallest = tops.iter().map(|p| p.z).fold(0.0, f32::max);
    // Land that still rises out of the top of the frame is cut off, which
    // the vista accepts (its near slope is not yet all there is to see) up
    // to a height of `VISTA_TALLEST`.
    let fits = clear(&lowered) >= -SKY_ROOM || tallest <= VISTA_TALLEST * extent;
    fits.then_some(lowered)
}

/// The vista for a grid `extent` units wide in a `width` x `height` frame,
/// aimed as `aim` says.
fn frame(aim: Aim, extent: f32, width: f32, height: f32) -> Shot {
    let (w, h) = (width.max(1.0), height.max(1.0));
    let skyline = aim.skyline;
    let last = STANDOFFS[STANDOFFS.len() - 1];
    // The sea-level point that falls just below the bottom, its distance
    // in front of the near edge.
    let near_of = |s: f32| s + aim.cropped;
    let standoff = STANDOFFS
        .into_iter()
        .find(|&s| near_below_bottom((s, near_of(s)), HEIGHTS.1, w, h, skyline) >= 0.0)
        .unwrap_or(last);
    let eye_h = bisect(HEIGHTS.0, HEIGHTS.1, |e| {
        near_below_bottom((standoff, near_of(standoff)), e, w, h, skyline)
    });
    let pitch = pitch_for(standoff, eye_h, w, h, skyline);
    let eye = Vec3::new(0.5, 1.0 + standoff, eye_h) * extent;
    Shot {
        camera: Camera::looking_back(eye, pitch, extent),
        focal: focal(standoff, eye_h, pitch, w),
        stretch: 1.0,
    }
}

/// The vista of a `width` x `height` frame drawn as that of a frame
/// `stretch` times narrower, widened to it, the back edge at
/// [`SKYLINE_LOWEST`].
fn stretched(aim: Aim, extent: f32, width: f32, height: f32, stretch: f32) -> Shot {
    let aim = Aim {
        skyline: SKYLINE_LOWEST,
        ..aim
    };
    let narrow = frame(aim, extent, width / stretch, height);
    Shot { stretch, ..narrow }
}

/// How far below the wanted row (just below the bottom) the sea-level
/// point `near` grid widths ahead of the camera falls, in pixels, for a
/// camera `standoff` in front of the near edge and `eye_h` high, pitched
/// to put the back edge `skyline` of the height from the top.
fn near_below_bottom(
    (standoff, near): (f32, f32),
    eye_h: f32,
    w: f32,
    h: f32,
    skyline: f32,
) -> f32 {
    let pitch = pitch_for(standoff, eye_h, w, h, skyline);
    let f = focal(standoff, eye_h, pitch, w);
    f * (angle_below(eye_h, near) - pitch).tan() - (0.5 + BELOW) * h
}

/// The pitch that puts the back edge at `skyline` for a camera `eye_h`
/// grid widths high and `standoff` in front (`skyline` of the height from the top).
fn pitch_for(standoff: f32, eye_h: f32, w: f32, h: f32, skyline: f32) -> f32 {
    let back = angle_below(eye_h, 1.0 + standoff);
    let above_centre = (0.5 - skyline) * h;
    // At pitch `back` the edge is at the centre; pitching down raises it,
    // pitching up (a skyline below the centre) lowers it.
    let rise = |pitch: f32| focal(standoff, eye_h, pitch, w) * (back - pitch).tan() + above_centre;
    bisect(back - 1.4, back + 1.4, |p| -rise(p))
}

/// Focal length (pixels per unit of x / depth, grid width 1) that makes
/// the back edge span `w` pixels.
fn focal(standoff: f32, eye_h: f32, pitch: f32, w: f32) -> f32 {
    let (sin, cos) = pitch.sin_cos();
    let back_depth = (1.0 + standoff) * cos + eye_h * sin;
    w * back_depth
}

/// Angle below the horizontal of a sea-level point `dist` ahead.
fn angle_below(eye_h: f32, dist: f32) -> f32 {
    (eye_h / dist).atan()
}

/// The root of an increasing `f` in `lo..=hi` (an end if it has none).
fn bisect(lo: f32, hi: f32, f: impl Fn(f32) -> f32) -> f32 {
    bisect_steps(lo, hi, STEPS, f)
}

/// [`bisect`] in `steps` halvings.
fn bisect_steps(mut lo: f32, mut hi: f32, steps: usize, f: impl Fn(f32) -> f32) -> f32 {
    if f(lo) >= 0.0 {
        return lo;
    }
    if f(hi) <= 0.0 {
        return hi;
    }
    for _ in 0..steps {
        let mid = 0.5 * (lo + hi);
        // `lo` and `hi` are neighbouring floats: every later step keeps
        // the answer at `mid`. The nested fits (pitch inside height inside
        // skyline) reach this in about half their steps, and the vista's
        // fit was a third of a 1080p frame's start.
        if mid == lo || mid == hi {
            return mid;
        }
        if f(mid) < 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each world's aims lie within its ranges and reach across most of
    /// them; the temperate world keeps today's vista.
    #[test]
    fn each_world_aims_within_its_ranges() {
        for world in crate::settings::worlds::OWN_LOOKS {
            let (skyline, cropped) = aims(world).expect("a world's ranges");
            let drawn: Vec<Aim> = (0..500).map(|i| Aim::of(world, i)).collect();
            for (range, get) in [
                (skyline, (|a: &Aim| a.skyline) as fn(&Aim) -> f32),
                (cropped, |a: &Aim| a.cropped),
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
