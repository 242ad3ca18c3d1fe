//! The coast drawn clean: along the shore line of a face that crosses the
//! water line, land and water pixels are mixed by how much of each pixel
//! lies on the other side, so the coast is a smooth line, not a staircase.
//!
//! Each pixel is still written once, by the part of the face that covers
//! its centre; that part mixes in the colour across the line, from none
//! half a pixel away to half on the line (the share of a pixel a straight
//! edge cuts off, to first order).

use crate::render::base::colour::mix_packed;
use crate::render::base::fixed::SUBPIXEL;

/// The shore line through one face, on screen.
pub(crate) struct ShoreLine {
    /// One end, in pixels.
    from: [f32; 2],
    /// Unit vector along the line and the line's length in pixels.
    along: [f32; 2],
    length: f32,
    /// The land's colours at the two ends.
    colours: [u32; 2],
}

/// A corner of a face as the shore line needs it: where it is on screen
/// (24.8 fixed point) and the land's colour there.
pub(crate) trait ShorePoint {
    /// Screen position, 24.8 fixed point.
    fn screen(&self) -> [i64; 2];
    /// The land's colour here (smooth shading).
    fn land(&self) -> u32;
}

impl ShoreLine {
    /// The line from `a` to `b`; `None` when they meet on screen.
    pub(crate) fn new(a: &impl ShorePoint, b: &impl ShorePoint) -> Option<Self> {
        let px = |p: [i64; 2]| p.map(|v| v as f32 / SUBPIXEL as f32);
        let (from, to) = (px(a.screen()), px(b.screen()));
        let d = [to[0] - from[0], to[1] - from[1]];
        let length = (d[0] * d[0] + d[1] * d[1]).sqrt();
        (length > 1e-3).then(|| ShoreLine {
            from,
            along: [d[0] / length, d[1] / length],
            length,
            colours: [a.land(), b.land()],
        })
    }

    /// How much of the colour across the line pixel (`x`, `y`) takes, in
    /// 1/256ths: 128 on the line, none from half a pixel away.
    #[inline]
    pub(crate) fn weight(&self, x: u32, y: u32) -> u32 {
        let (dx, dy) = self.offset(x, y);
        let across = (dx * self.along[1] - dy * self.along[0]).abs();
        ((0.5 - across).clamp(0.0, 0.5) * 256.0) as u32
    }

    /// The land's colour on the line beside pixel (`x`, `y`).
    #[inline]
    pub(crate) fn land_at(&self, x: u32, y: u32) -> u32 {
        let (dx, dy) = self.offset(x, y);
        let t = ((dx * self.along[0] + dy * self.along[1]) / self.length).clamp(0.0, 1.0);
        mix_packed(self.colours[0], self.colours[1], t)
    }

    /// Pixel (`x`, `y`)'s centre from the line's first end.
    #[inline]
    fn offset(&self, x: u32, y: u32) -> (f32, f32) {
        (x as f32 + 0.5 - self.from[0], y as f32 + 0.5 - self.from[1])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    struct P([i64; 2], u32);

    impl ShorePoint for P {
        fn screen(&self) -> [i64; 2] {
            self.0
        }
        fn land(&self) -> u32 {
            self.1
        }
    }

    fn at(x: f32, y: f32, c: u32) -> P {
        P(crate::render::base::fixed::to_fixed(x, y), c)
    }

    #[test]
    fn half_on_the_line_none_half_a_pixel_away() {
        // A level line through row 10's centres.
        let line = ShoreLine::new(&at(0.0, 10.5, 0), &at(20.0, 10.5, 0)).unwrap();
        assert_eq!(line.weight(5, 10), 128);
        assert_eq!(line.weight(5, 11), 0);
        assert_eq!(line.weight(5, 9), 0);
        // A quarter pixel off: a quarter of the colour across.
        let line = ShoreLine::new(&at(0.0, 10.25, 0), &at(20.0, 10.25, 0)).unwrap();
        assert_eq!(line.weight(5, 10), 64);
    }

    #[test]
    fn the_land_colour_runs_along_the_line() {
        let line = ShoreLine::new(&at(0.5, 0.5, 0x000000), &at(10.5, 0.5, 0x0a0a0a)).unwrap();
        assert_eq!(line.land_at(5, 3), 0x050505);
        assert_eq!(line.land_at(20, 0), 0x0a0a0a);
        assert!(ShoreLine::new(&at(1.0, 1.0, 0), &at(1.0, 1.0, 0)).is_none());
    }
}
