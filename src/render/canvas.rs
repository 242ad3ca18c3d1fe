//! A rectangle of frame pixels to draw into, with the damage it collects.
//!
//! The parallel full frame gives each thread its own band of columns;
//! stepping uses one canvas that is the whole frame. Either way a pixel only
//! ever receives the writes of one canvas, in painter's order, so the results
//! are identical.

use super::frame::Rect;
use super::raster::Clip;

/// Columns `x0..x0 + width` of rows `y0..` of a frame, stored row by row.
pub(crate) struct Canvas<'a> {
    pixels: &'a mut [u32],
    width: u32,
    x0: u32,
    y0: u32,
    clip: Clip,
    damage: Rect,
}

impl<'a> Canvas<'a> {
    /// `pixels` holds rows `y0..` of the frame, whole rows.
    pub(crate) fn new(pixels: &'a mut [u32], width: u32, y0: u32) -> Self {
        Self::window(pixels, 0, width, y0)
    }

    /// `pixels` holds columns `x0..x0 + width` of rows `y0..` of the frame.
    pub(crate) fn window(pixels: &'a mut [u32], x0: u32, width: u32, y0: u32) -> Self {
        let rows = pixels.len() as u32 / width.max(1);
        Canvas {
            pixels,
            width,
            x0,
            y0,
            clip: Clip {
                x0: x0 as i64,
                x1: (x0 + width) as i64,
                y0: y0 as i64,
                y1: (y0 + rows) as i64,
            },
            damage: Rect::default(),
        }
    }

    /// The pixels this canvas may change.
    #[inline]
    pub(crate) fn clip(&self) -> &Clip {
        &self.clip
    }

    /// What has been drawn so far, in frame coordinates.
    pub(crate) fn damage(&self) -> Rect {
        self.damage
    }

    /// Adds a rectangle to the damage.
    #[inline]
    pub(crate) fn touch(&mut self, x0: u32, y0: u32, x1: u32, y1: u32) {
        let d = &mut self.damage;
        if d.is_empty() {
            *d = Rect { x0, y0, x1, y1 };
        } else {
            d.x0 = d.x0.min(x0);
            d.y0 = d.y0.min(y0);
            d.x1 = d.x1.max(x1);
            d.y1 = d.y1.max(y1);
        }
    }

    /// Row `y`, columns `x0..x1` (frame coordinates, already clipped).
    #[inline]
    pub(crate) fn span_mut(&mut self, y: u32, x0: u32, x1: u32) -> &mut [u32] {
        self.touch(x0, y, x1, y + 1);
        let row = ((y - self.y0) * self.width) as usize;
        let (a, b) = ((x0 - self.x0) as usize, (x1 - self.x0) as usize);
        &mut self.pixels[row + a..row + b]
    }

    /// Adds the pixels of the fixed-point box `lo..=hi` (the pixels holding
    /// those points and all between), clipped, to the damage.
    #[inline]
    pub(crate) fn touch_box(&mut self, lo: [i64; 2], hi: [i64; 2]) {
        let c = self.clip;
        let (x0, y0) = ((lo[0] >> 8).max(c.x0), (lo[1] >> 8).max(c.y0));
        let (x1, y1) = (((hi[0] >> 8) + 1).min(c.x1), ((hi[1] >> 8) + 1).min(c.y1));
        if x0 < x1 && y0 < y1 {
            self.touch(x0 as u32, y0 as u32, x1 as u32, y1 as u32);
        }
    }

    /// Sets one pixel (frame coordinates, already clipped) without adding it
    /// to the damage: the caller has covered it with `touch_box`.
    #[inline]
    pub(crate) fn plot(&mut self, x: u32, y: u32, color: u32) {
        let i = ((y - self.y0) * self.width + (x - self.x0)) as usize;
        self.pixels[i] = color;
    }
}
