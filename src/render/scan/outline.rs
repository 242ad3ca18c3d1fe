//! Where a line runs across a screen triangle: a plane through a value at
//! each corner (the mirror's margin, see `shade::mirror::Look`), its 0 the
//! line, read at pixel centres as how much of a pixel lies on each side.
//! Between two corners' values the line is found to a fraction of a pixel,
//! so it runs straight across a face however large the face is.

use super::gradient::Gradient;
use crate::render::base::fixed::{Fixed2, SUBPIXEL};

/// The signed distance, in pixels, of a pixel centre from the line where a
/// triangle's corner values cross 0.
pub(crate) struct Crossing {
    /// The distance at the first corner.
    at0: f32,
    /// The first corner's position in pixels.
    origin: [f32; 2],
    /// Change of the distance per pixel to the right and per row down.
    dx: f32,
    dy: f32,
}

/// Which side of its line a whole triangle lies on, if it does.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Whole {
    /// Every pixel on the side where the values are above 0.
    Above,
    /// Every pixel on the side where they are at most 0.
    Below,
}

impl Crossing {
    /// The line through `values` at the corners `v` (24.8 fixed point).
    pub(crate) fn new(v: [Fixed2; 3], values: [f32; 3]) -> Self {
        let gradient = Gradient::new(v);
        let (dx, dy) = gradient.slopes(values[1] - values[0], values[2] - values[0]);
        // Values per pixel across the line: dividing by it makes them
        // pixels. A plane of one value has no line in it: its side is its
        // sign's, far from the line.
        let slope = (dx * dx + dy * dy).sqrt();
        let scale = if slope > f32::MIN_POSITIVE {
            1.0 / slope
        } else {
            1e6
        };
        Crossing {
            at0: values[0] * scale,
            origin: gradient.origin,
            dx: dx * scale,
            dy: dy * scale,
        }
    }

    /// The side the whole triangle of corners `v` lies on, if no pixel of
    /// it is within half a pixel of the line.
    pub(crate) fn whole(&self, v: [Fixed2; 3]) -> Option<Whole> {
        let to_px = 1.0 / SUBPIXEL as f32;
        let at = |p: Fixed2| {
            self.at0
                + self.dx * (p[0] as f32 * to_px - self.origin[0])
                + self.dy * (p[1] as f32 * to_px - self.origin[1])
        };
        let d = v.map(at);
        if d.iter().all(|&d| d >= 0.5) {
            Some(Whole::Above)
        } else if d.iter().all(|&d| d <= -0.5) {
            Some(Whole::Below)
        } else {
            None
        }
    }

    /// The distance of row `y` where it crosses the first corner's column,
    /// for [`Crossing::above`].
    #[inline]
    pub(crate) fn row(&self, y: u32) -> f32 {
        self.at0 + self.dy * (y as f32 + 0.5 - self.origin[1])
    }

    /// How much (of 256) of pixel `x` of a row lies on the side above 0:
    /// its centre's distance from the line, as a box a pixel wide would be
    /// covered.
    #[inline(always)]
    pub(crate) fn above(&self, row: f32, x: u32) -> u32 {
        let d = row + self.dx * (x as f32 + 0.5 - self.origin[0]);
        ((d + 0.5).clamp(0.0, 1.0) * 256.0) as u32
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::base::fixed::to_fixed;

    #[test]
    fn the_line_lies_where_the_corner_values_cross_0() {
        // Values -1 at x = 0 and 3 at x = 8: 0 at x = 2.
        let v = [to_fixed(0.0, 0.0), to_fixed(8.0, 0.0), to_fixed(0.0, 8.0)];
        let c = Crossing::new(v, [-1.0, 3.0, -1.0]);
        let row = c.row(4);
        assert_eq!(c.above(row, 0), 0);
        // Pixel 1's centre (1.5) is half a pixel short of the line: none.
        assert_eq!(c.above(row, 1), 0);
        // Pixel 2's (2.5) half a pixel past it: all.
        assert_eq!(c.above(row, 2), 256);
        assert_eq!(c.above(row, 6), 256);
        assert_eq!(c.whole(v), None);
    }

    #[test]
    fn a_line_between_pixel_centres_shares_the_pixel() {
        let v = [to_fixed(0.0, 0.0), to_fixed(8.0, 0.0), to_fixed(0.0, 8.0)];
        // 0 at x = 2.25: pixel 2's centre lies a quarter pixel past it.
        let c = Crossing::new(v, [-2.25, 5.75, -2.25]);
        assert_eq!(c.above(c.row(0), 2), 192);
    }

    #[test]
    fn a_triangle_far_from_the_line_lies_on_one_side() {
        let v = [to_fixed(0.0, 0.0), to_fixed(8.0, 0.0), to_fixed(0.0, 8.0)];
        let steep = Crossing::new(v, [1.0, 9.0, 1.0]);
        assert_eq!(steep.whole(v), Some(Whole::Above));
        let flat = Crossing::new(v, [-0.01, -0.01, -0.01]);
        assert_eq!(flat.whole(v), Some(Whole::Below));
        assert_eq!(flat.above(flat.row(3), 3), 0);
    }
}
