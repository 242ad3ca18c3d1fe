//! Colours blended across a screen triangle from its corners' (Gouraud
//! shading): each channel is a plane over the screen through the three
//! corners' colours, read at pixel centres.

use super::raster::{Fixed2, SUBPIXEL};

/// The colour planes of one triangle.
pub(crate) struct Blend {
    /// Each channel (red, green, blue, 0..=255) at the first corner.
    at0: [f32; 3],
    /// The first corner's position in pixels.
    origin: [f32; 2],
    /// Change of each channel per pixel to the right and per row down.
    dx: [f32; 3],
    dy: [f32; 3],
    /// Each channel's least and greatest corner value: a pixel centre lies
    /// inside the triangle, so its colour does too, but a sliver's planes
    /// are steep enough for rounding to carry it past its corners.
    lo: [f32; 3],
    hi: [f32; 3],
}

/// One row's channels where the row crosses the first corner's column.
/// Every pixel's colour is worked out from it and the pixel's own column
/// alone, so a span cut at a band's edge gets the same colours as whole.
pub(crate) type RowStart = [f32; 3];

impl Blend {
    /// Planes through packed `colours` at the corners `v` (24.8 fixed point).
    pub(crate) fn new(v: [Fixed2; 3], colours: [u32; 3]) -> Self {
        let px = v.map(|p| [p[0] as f32, p[1] as f32].map(|c| c / SUBPIXEL as f32));
        let ch = colours.map(channels);
        let (e1, e2) = (
            [px[1][0] - px[0][0], px[1][1] - px[0][1]],
            [px[2][0] - px[0][0], px[2][1] - px[0][1]],
        );
        let det = e1[0] * e2[1] - e2[0] * e1[1];
        let mut dx = [0.0; 3];
        let mut dy = [0.0; 3];
        if det != 0.0 {
            for k in 0..3 {
                let (d1, d2) = (ch[1][k] - ch[0][k], ch[2][k] - ch[0][k]);
                dx[k] = (d1 * e2[1] - d2 * e1[1]) / det;
                dy[k] = (d2 * e1[0] - d1 * e2[0]) / det;
            }
        }
        Blend {
            at0: ch[0],
            origin: px[0],
            dx,
            dy,
            lo: [0, 1, 2].map(|k| ch[0][k].min(ch[1][k]).min(ch[2][k])),
            hi: [0, 1, 2].map(|k| ch[0][k].max(ch[1][k]).max(ch[2][k])),
        }
    }

    /// The channels of row `y` where it crosses the first corner, for
    /// [`Blend::at`].
    #[inline]
    pub(crate) fn row(&self, y: u32) -> RowStart {
        let oy = y as f32 + 0.5 - self.origin[1];
        [0, 1, 2].map(|k| self.at0[k] + self.dy[k] * oy)
    }

    /// The packed colour at the centre of pixel `x` of a row.
    #[inline(always)]
    pub(crate) fn at(&self, row: &RowStart, x: u32) -> u32 {
        let ox = x as f32 + 0.5 - self.origin[0];
        let c = |k: usize| {
            let v = (row[k] + self.dx[k] * ox).clamp(self.lo[k], self.hi[k]);
            // NaN casts to 0; +0.5 rounds.
            (v + 0.5) as u32
        };
        c(0) << 16 | c(1) << 8 | c(2)
    }
}

/// A packed colour's channels, 0..=255.
#[inline]
fn channels(c: u32) -> [f32; 3] {
    [(c >> 16) & 0xff, (c >> 8) & 0xff, c & 0xff].map(|v| v as f32)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::raster::to_fixed;

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
            let ch = channels(c);
            assert!((16.0..=48.0).contains(&ch[0]), "{c:06x}");
            assert!((48.0..=80.0).contains(&ch[2]), "{c:06x}");
        }
    }
}
