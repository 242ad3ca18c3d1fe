//! The vista camera: low in front of the land, looking across it towards
//! the horizon, as xmountains frames its landscapes.
//!
//! It is fitted to each frame, in grid widths (the camera stands centred,
//! [`Aim::standoff`] grid widths in front of the near edge, or nearer where
//! that does not fit, level sideways):
//! - the back edge at sea level spans exactly the frame's width; the grid's
//!   side edges splay outwards towards the camera, so they never show;
//! - the middle of the back edge at sea level sits [`Aim::skyline`] of the
//!   height from the top, leaving the sky above for the peaks to rise into
//!   (lower, down to [`SKYLINE_LOWEST`], when the land is so tall it would
//!   fill the sky: exactly as low as keeps [`Aim::room`] clear, see [`fitted`]);
//! - the near edge at sea level falls just below the bottom;
//! - a frame wider than [`ORDINARY`] whose land would still fill the sky
//!   with the back edge at [`SKYLINE_LOWEST`] (the land's height on screen
//!   grows with the width the back edge spans: three 16:9 monitors side by
//!   side see it three times as tall as one does) is framed as a narrower
//!   frame of its height, exactly as narrow as keeps [`Aim::room`] clear
//!   (at most down to [`ORDINARY`]), and stretched sideways to its width:
//!   like xmountains, whose land is as tall on a wide screen as on a
//!   narrow one, it shows the land wider rather than taller.
//!
//! A world other than the temperate aims its vista otherwise ([`Aim::of`]):
//! its back edge higher or lower in the frame and a share of the land's
//! depth below the bottom instead of the near edge, which raises the
//! camera and pitches it down (the alpine world's looks down into its
//! valleys); more or less sky kept above its tallest land than today's
//! vista keeps; and its camera nearer the land than the first of
//! [`STANDOFFS`], so near ridges loom against the far range.
//!
//! The width fixes the focal length for a given pitch and camera height;
//! the two vertical conditions then fix the pitch and the height, found by
//! nested bisection (each condition is monotonic in its unknown).
//!
//! Every condition is a fraction of the frame, none a number of pixels, and
//! each is solved to the end rather than to a tolerance: a frame k times
//! larger is the same framing, k times finer.

use glam::{Vec2, Vec3};

use super::aim::{Aim, STANDOFFS};
use super::camera::Camera;

/// The lowest the back edge goes, for land so tall it would fill the sky.
pub(crate) const SKYLINE_LOWEST: f32 = 0.72;
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
/// How far the land may rise out of the top of the frame, as a share of
/// its height, and the shot not count as cut off there ([`Shot::cut`]): a
/// peak's tip over the top is a near range looming; land that rises a
/// tenth of the frame over it and more was, on the worlds' slides, one
/// near face from edge to edge (seeds 70, 188, 253, 315, 345 and 353 rose
/// 0.15-0.84 of the frame over it; the slides a peak's tip left, 0-0.08).
pub(crate) const OVER_TOP: f32 = 0.1;
/// Camera heights tried, in grid widths. Above the upper end a higher camera
/// no longer widens the angle between the near and back edges.
const HEIGHTS: (f32, f32) = (1e-3, 0.97);
/// Bisection steps for the camera: far below a pixel at any frame size.
const STEPS: usize = 48;
/// Bisection steps for the skyline: its range (at most 0.56 of the frame)
/// down to f32's precision.
const SKYLINE_STEPS: usize = 24;

/// A camera and its focal length in pixels.
pub(crate) struct Shot {
    /// Where the camera stands and looks.
    pub camera: Camera,
    /// Pixels per unit of `x / depth` up the frame.
    pub focal: f32,
    /// How many times wider than high a unit is drawn across the frame
    /// (1 but in frames wider than [`ORDINARY`] whose land needs it).
    pub stretch: f32,
    /// Whether the land still rises out of the top of the frame by more
    /// than [`OVER_TOP`] (the vista accepts it, see [`fitted`]).
    pub cut: bool,
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
/// row's highest point), aimed as `aim` says: the back edge at
/// [`Aim::skyline`], or, where the land would rise within [`Aim::room`] of
/// the top, exactly as much lower as keeps that strip of sky (at most down to [`SKYLINE_LOWEST`]); a frame
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
        top / height.max(1.0) - aim.room
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
    let fits = clear(&lowered) >= -aim.room || tallest <= VISTA_TALLEST * extent;
    let cut = clear(&lowered) + aim.room < -OVER_TOP;
    fits.then_some(Shot { cut, ..lowered })
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
    let standoff = std::iter::once(aim.standoff)
        .chain(STANDOFFS.into_iter().filter(|&s| s < aim.standoff))
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
        cut: false,
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

    /// A world's slide keeps the sky and the camera distance drawn for its
    /// mountain, and is framed alike at two sizes: its highest land sits
    /// the drawn room below the top (where the land is tall enough that
    /// the fit lowers the back edge), and its camera stands no further off
    /// than drawn (a nearer one only where the frame needs it).
    #[test]
    fn a_worlds_slide_keeps_its_drawn_sky_and_distance_at_every_size() {
        let extent = 256.0;
        // A ridge a tenth of the width high across the middle of the land.
        let tops: Vec<Vec3> = (0..=16)
            .map(|i| {
                let y = i as f32 / 16.0;
                let z = 0.1 * (y * std::f32::consts::PI).sin();
                Vec3::new(0.5, y, z) * extent
            })
            .collect();
        let (mut at_room, mut at_standoff) = (0, 0);
        for world in crate::settings::worlds::OWN_LOOKS {
            for identity in 0..40 {
                let aim = Aim::of(world, identity);
                let framed = [(320.0, 180.0), (1920.0, 1080.0)].map(|(w, h)| {
                    let shot = fitted(aim, extent, (w, h), &tops, f32::NAN).expect("framed");
                    let top = (tops.iter())
                        .map(|&p| shot.project(p, w, h).y / h)
                        .fold(f32::INFINITY, f32::min);
                    (top, shot.camera.eye() / extent)
                });
                let [(top, eye), (big_top, big_eye)] = framed;
                let what = format!("{world:?} {identity}: {aim:?}");
                assert!(
                    (top - big_top).abs() < 1e-3,
                    "{what}: {top} against {big_top}"
                );
                assert!(
                    eye.distance(big_eye) < 1e-3,
                    "{what}: {eye} against {big_eye}"
                );
                assert!(top > aim.room - 1e-3, "{what}: the land's top at {top}");
                assert!(eye.y - 1.0 <= aim.standoff + 1e-4, "{what}: eye {eye}");
                at_room += usize::from((top - aim.room).abs() < 1e-3);
                at_standoff += usize::from((eye.y - 1.0 - aim.standoff).abs() < 1e-4);
            }
        }
        // The drawn room and distance, not fixed ones, are what the fit
        // keeps.
        assert!(at_room >= 50, "{at_room} of 200 slides at their room");
        assert!(
            at_standoff >= 150,
            "{at_standoff} of 200 slides at their distance"
        );
    }
}
