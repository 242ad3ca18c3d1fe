//! The vista camera: low in front of the land, looking across it towards
//! the horizon, as xmountains frames its landscapes.
//!
//! It is fitted to each frame, in grid widths (the camera stands centred,
//! [`STANDOFF`] grid widths in front of the near edge, level sideways):
//! - the back edge at sea level spans exactly the frame's width; the grid's
//!   side edges splay outwards towards the camera, so they never show;
//! - the middle of the back edge at sea level sits [`SKYLINE`] of the
//!   height from the top, leaving the sky above for the peaks to rise into;
//! - the near edge at sea level falls just below the bottom.
//!
//! The width fixes the focal length for a given pitch and camera height;
//! the two vertical conditions then fix the pitch and the height, found by
//! nested bisection (each condition is monotonic in its unknown).

use glam::Vec3;

use super::view::Camera;

/// The camera's horizontal distance in front of the near edge, in grid
/// widths: closer magnifies the foreground more.
const STANDOFF: f32 = 0.6;
/// Where the back edge at sea level sits, as a fraction of the height from
/// the top: peaks behind it rise into the sky above.
const SKYLINE: f32 = 0.4;
/// How far below the bottom row the near edge falls, in pixels.
const BELOW_PX: f32 = 2.0;
/// Camera heights tried, in grid widths. Above the upper end a higher camera
/// no longer widens the angle between the near and back edges.
const HEIGHTS: (f32, f32) = (1e-3, 0.97);
/// Bisection steps: far below a pixel at any frame size.
const STEPS: usize = 48;

/// A camera and its focal length in pixels.
pub(crate) struct Shot {
    /// Where the camera stands and looks.
    pub camera: Camera,
    /// Pixels per unit of `x / depth`.
    pub focal: f32,
}

/// The vista for a grid `extent` units wide in a `width` x `height` frame.
pub(crate) fn frame(extent: f32, width: f32, height: f32) -> Shot {
    let (w, h) = (width.max(1.0), height.max(1.0));
    let near = |eye_h: f32| {
        let pitch = pitch_for(eye_h, w, h);
        let f = focal(eye_h, pitch, w);
        f * (angle_below(eye_h, STANDOFF) - pitch).tan() - (0.5 * h + BELOW_PX)
    };
    let eye_h = bisect(HEIGHTS.0, HEIGHTS.1, near);
    let pitch = pitch_for(eye_h, w, h);
    let eye = Vec3::new(0.5, 1.0 + STANDOFF, eye_h) * extent;
    Shot {
        camera: Camera::looking_back(eye, pitch, extent),
        focal: focal(eye_h, pitch, w),
    }
}

/// The pitch that puts the back edge at [`SKYLINE`] for a camera `eye_h`
/// grid widths high.
fn pitch_for(eye_h: f32, w: f32, h: f32) -> f32 {
    let back = angle_below(eye_h, 1.0 + STANDOFF);
    let above_centre = (0.5 - SKYLINE) * h;
    // At pitch `back` the edge is at the centre; pitching down raises it.
    let rise = |pitch: f32| focal(eye_h, pitch, w) * (back - pitch).tan() + above_centre;
    bisect(back, back + 1.4, |p| -rise(p))
}

/// Focal length (pixels per unit of x / depth, grid width 1) that makes
/// the back edge span `w` pixels.
fn focal(eye_h: f32, pitch: f32, w: f32) -> f32 {
    let (sin, cos) = pitch.sin_cos();
    let back_depth = (1.0 + STANDOFF) * cos + eye_h * sin;
    w * back_depth
}

/// Angle below the horizontal of a sea-level point `dist` ahead.
fn angle_below(eye_h: f32, dist: f32) -> f32 {
    (eye_h / dist).atan()
}

/// The root of an increasing `f` in `lo..=hi` (an end if it has none).
fn bisect(mut lo: f32, mut hi: f32, f: impl Fn(f32) -> f32) -> f32 {
    if f(lo) >= 0.0 {
        return lo;
    }
    if f(hi) <= 0.0 {
        return hi;
    }
    for _ in 0..STEPS {
        let mid = 0.5 * (lo + hi);
        if f(mid) < 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}
