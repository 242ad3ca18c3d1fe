//! The essay's camera (seed 002's `camera = [500,100,0]`, `screen = 600`
//! and `center = [500,850,2400]`, on its 1000x600 canvas): the eye level
//! (no tilt), 750 units above the square's base and 2400 in front of its
//! centre, for a square `2^N = 2048` units wide, projecting onto a screen
//! 600 units away whose centre is the canvas point (500, 100), a sixth of
//! the way down. Its canvas is fitted inside the frame, centred: scaled
//! to the frame's width or height, whichever is the tighter, the rest of
//! the frame the essay's white page.

use glam::{Vec2, Vec3};

use super::camera::Camera;
use super::view::View;
use crate::render::base::size::Size;
use crate::terrain::Heightfield;
use crate::terrain::heightmap::quantise::Quantisation;

/// The essay's canvas, in its pixels (`<canvas width="1000" height="600">`).
pub const CANVAS: Vec2 = Vec2::new(1000.0, 600.0);
/// `camera`: the eye, in the canvas's units (x right, y down, z away).
const EYE: Vec3 = Vec3::new(500.0, 100.0, 0.0);
/// `screen`: the distance to the picture plane, in canvas pixels.
const SCREEN: f32 = 600.0;
/// `center`: the square's centre, its base at y = 850.
const CENTRE: Vec3 = Vec3::new(500.0, 850.0, 2400.0);
/// The square's side, `Math.pow(2, N)` with `N = 11`.
const SIDE: f32 = 2048.0;

/// The essay's square as it stands in the field: its side and the height
/// of its base (its corners, which the essay keeps at its `center`'s
/// height), in the field's units.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Square {
    pub(crate) side: f32,
    pub(crate) base: f32,
}

impl Square {
    /// The square `field` holds, not yet turned: its width, and its
    /// corners' mean height for its base, on the 16-bit grid a data set
    /// saves it on (`snap_to_grid`'s, spanning the field's lowest to
    /// highest point, which a save keeps exactly): a set saved and opened
    /// again has its heights on that grid, so its eye stands where it stood
    /// and the picture comes back pixel for pixel.
    pub(crate) fn of(field: &Heightfield) -> Self {
        let last = field.size().saturating_sub(1);
        let corners = [(0, 0), (last, 0), (0, last), (last, last)];
        let sum: f32 = corners.iter().map(|&(x, y)| field.get(x, y)).sum();
        let (lo, hi) = field.min_max();
        let grid = Quantisation::spanning(lo, hi);
        let base = grid.height(grid.sample(0.25 * sum));
        Square {
            side: field.extent(),
            base: if base.is_finite() { base } else { 0.0 },
        }
    }

    /// The same square with its heights drawn `f` times their own.
    pub(crate) fn scaled(self, f: f32) -> Self {
        Square {
            base: self.base * f,
            ..self
        }
    }
}

/// The view the essay's camera has of a `size` x `size` grid `extent`
/// units wide centred on `square` (the square turned inside it), in a
/// frame of `frame` size.
pub(crate) fn view(square: Square, size: usize, extent: f32, frame: Size) -> View {
    // The essay's units per field unit.
    let k = SIDE / square.side;
    let centre = 0.5 * extent;
    let eye = Vec3::new(
        centre + (EYE.x - CENTRE.x) / k,
        centre + (CENTRE.z - EYE.z) / k,
        square.base + (CENTRE.y - EYE.y) / k,
    );
    let camera = Camera::looking_back(eye, 0.0, extent);
    // The canvas fitted inside the frame, centred.
    let frame = Vec2::new(frame.width as f32, frame.height as f32);
    let fit = (frame / CANVAS).min_element();
    let corner = 0.5 * (frame - fit * CANVAS);
    let principal = Vec2::new(EYE.x, EYE.y);
    View::through(camera, size, extent, fit * SCREEN, corner + fit * principal)
}
