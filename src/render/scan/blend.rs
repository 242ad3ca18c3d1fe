//! Colours blended across a screen triangle from its corners' (Gouraud
//! shading): each channel is a plane over the screen through the three
//! corners' colours, read at pixel centres.

use glam::Vec4;

use super::gradient::Gradient;
use crate::render::base::colour::{lanes, packed_lanes};
use crate::render::base::fixed::Fixed2;

/// The colour planes of one triangle, each channel (blue, green, red,
/// 0..=255: a packed colour's bytes in memory order) a lane of a vector: a
/// pixel's channels are worked out together.
pub(crate) struct Blend {
    /// The channels at the first corner.
    at0: Vec4,
    /// The first corner's position in pixels.
    origin: [f32; 2],
    /// Change of each channel per pixel to the right and per row down.
    dx: Vec4,
    dy: Vec4,
    /// Each channel's least and greatest corner value: a pixel centre lies
    /// inside the triangle, so its colour does too, but a sliver's planes
    /// are steep enough for rounding to carry it past its corners.
    lo: Vec4,
    hi: Vec4,
}

/// One row's channels where the row crosses the first corner's column.
/// Every pixel's colour is worked out from it and the pixel's own column
/// alone, so a span cut at a band's edge gets the same colours as whole.
pub(crate) type RowStart = Vec4;

impl Blend {
    /// Planes through packed `colours` at the corners `v` (24.8 fixed point).
    #[inline]
    pub(crate) fn new(v: [Fixed2; 3], colours: [u32; 3]) -> Self {
        Self::over(&Gradient::new(v), colours)
    }

    /// Planes through packed `colours` at the corners of the triangle of
    /// `gradient`.
    #[inline]
    pub(crate) fn over(gradient: &Gradient, colours: [u32; 3]) -> Self {
        let [c0, c1, c2] = colours.map(lanes);
        let (dx, dy) = gradient.slopes(c1 - c0, c2 - c0);
        Blend {
            at0: c0,
            origin: gradient.origin,
            dx,
            dy,
            lo: c0.min(c1).min(c2),
            hi: c0.max(c1).max(c2),
        }
    }

    /// The channels of row `y` where it crosses the first corner, for
    /// [`Blend::at`].
    #[inline]
    pub(crate) fn row(&self, y: u32) -> RowStart {
        self.at0 + self.dy * (y as f32 + 0.5 - self.origin[1])
    }

    /// The packed colour at the centre of pixel `x` of a row.
    #[inline(always)]
    pub(crate) fn at(&self, row: &RowStart, x: u32) -> u32 {
        // +0.5 rounds.
        packed_lanes(self.lanes_at(row, x) + 0.5)
    }

    /// The channels (0.0..=255.0, unrounded) at the centre of pixel `x`
    /// of a row.
    #[inline(always)]
    pub(crate) fn lanes_at(&self, row: &RowStart, x: u32) -> Vec4 {
        let ox = x as f32 + 0.5 - self.origin[0];
        (*row + self.dx * ox).max(self.lo).min(self.hi)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::base::fixed::to_fixed;

    #[test]
    fn corners_get_their_own_colours_and_the_middle_the_mean() {
        let v = [to_fixed(0.5, 0.5), to_fixed(10.5, 0.5), to_fixed(0.5, 10.5)];
        let b = Blend::new(v, [0x000000, 0x0a1400, 0x00000a]);
        assert_eq!(b.at(&b.row(0), 0), 0x000000);
        assert_eq!(b.at(&b.row(0), 10), 0x0a1400);
        assert_eq!(b.at(&b.row(10), 0), 0x00000a);
        // Half way along the long edge: half of each.
        assert_eq!(b.at(&b.row(5), 5), 0x050a05);
    }

    #[test]
    fn a_sliver_stays_within_its_corners_colours() {
        let v = [
            to_fixed(0.0, 0.0),
            to_fixed(100.0, 0.01),
            to_fixed(50.0, 0.02),
        ];
        let b = Blend::new(v, [0x102030, 0x203040, 0x304050]);
        for x in 0..100 {
            let c = b.at(&b.row(0), x);
            let ch = lanes(c);
            assert!((16.0..=48.0).contains(&ch.z), "{c:06x}");
            assert!((48.0..=80.0).contains(&ch.x), "{c:06x}");
        }
    }
}
