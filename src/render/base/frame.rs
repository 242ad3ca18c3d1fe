//! The CPU framebuffer every mode draws into.

use super::size::Size;

/// A rectangle of pixels, `x0..x1` by `y0..y1` (exclusive ends).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Rect {
    /// Left column (inclusive).
    pub x0: u32,
    /// Top row (inclusive).
    pub y0: u32,
    /// Right column (exclusive).
    pub x1: u32,
    /// Bottom row (exclusive).
    pub y1: u32,
}

impl Rect {
    /// The `w` x `h` rectangle whose top left corner is (`x0`, `y0`).
    pub fn sized(x0: u32, y0: u32, w: u32, h: u32) -> Rect {
        Rect {
            x0,
            y0,
            x1: x0 + w,
            y1: y0 + h,
        }
    }

    /// The part of `self` inside `other` (empty if they do not meet).
    pub fn intersect(&self, other: &Rect) -> Rect {
        Rect {
            x0: self.x0.max(other.x0),
            y0: self.y0.max(other.y0),
            x1: self.x1.min(other.x1),
            y1: self.y1.min(other.y1),
        }
    }

    /// True when the rectangle covers no pixel.
    pub fn is_empty(&self) -> bool {
        self.x0 >= self.x1 || self.y0 >= self.y1
    }

    /// The smallest rectangle holding both.
    pub fn union(&self, other: &Rect) -> Rect {
        if self.is_empty() {
            return *other;
        }
        if other.is_empty() {
            return *self;
        }
        Rect {
            x0: self.x0.min(other.x0),
            y0: self.y0.min(other.y0),
            x1: self.x1.max(other.x1),
            y1: self.y1.max(other.y1),
        }
    }
}

/// Pixels as `0x00RRGGBB`, row-major, what softbuffer presents.
#[derive(Debug, Clone, PartialEq)]
pub struct Frame {
    width: u32,
    height: u32,
    pixels: Vec<u32>,
}

/// `count` zero pixels, or `None` if the allocator refuses. Zeroed memory
/// from the allocator, like `vec![0; count]`: the kernel hands out zero pages
/// lazily, so a fresh frame costs nothing until it is drawn.
fn zeroed_pixels(count: usize) -> Option<Vec<u32>> {
    let layout = std::alloc::Layout::array::<u32>(count).ok()?;
    // SAFETY: `layout` has a non-zero size (count > 0, checked by the
    // caller); a non-null result is an allocation of exactly that layout,
    // all zero bytes, which are valid u32s. Vec::from_raw_parts takes it
    // with the same element type, length and capacity, and will free it
    // with the same layout.
    unsafe {
        let ptr = std::alloc::alloc_zeroed(layout).cast::<u32>();
        if ptr.is_null() {
            return None;
        }
        Some(Vec::from_raw_parts(ptr, count, count))
    }
}

/// Largest frame accepted: 16384x16384 (1 GiB of pixels) would be absurd for
/// a screensaver; 2^28 pixels (1 GiB of u32) is the hard cap.
pub const MAX_PIXELS: u64 = 1 << 28;

impl Frame {
    /// A black frame, or `None` if either side is zero, it exceeds
    /// `MAX_PIXELS`, or the memory for it cannot be had (a large frame under
    /// a memory limit is a message, not an abort).
    pub fn new(width: u32, height: u32) -> Option<Self> {
        let count = width as u64 * height as u64;
        if count == 0 || count > MAX_PIXELS {
            return None;
        }
        Some(Frame {
            width,
            height,
            pixels: zeroed_pixels(count as usize)?,
        })
    }

    /// Width in pixels.
    pub fn width(&self) -> u32 {
        self.width
    }

    /// Height in pixels.
    pub fn height(&self) -> u32 {
        self.height
    }

    /// Width and height.
    pub fn size(&self) -> Size {
        Size::new(self.width, self.height)
    }

    /// All pixels, row-major.
    pub fn pixels(&self) -> &[u32] {
        &self.pixels
    }

    /// All pixels, row-major, writable.
    pub fn pixels_mut(&mut self) -> &mut [u32] {
        &mut self.pixels
    }

    /// The whole frame as a rectangle.
    pub fn bounds(&self) -> Rect {
        Rect {
            x0: 0,
            y0: 0,
            x1: self.width,
            y1: self.height,
        }
    }

    /// Fills every pixel with one colour.
    pub fn clear(&mut self, color: u32) {
        self.pixels.fill(color);
    }

    /// The pixel at column `x`, row `y` (inside the frame).
    #[inline]
    pub fn get(&self, x: u32, y: u32) -> u32 {
        self.pixels[y as usize * self.width as usize + x as usize]
    }

    /// Sets the pixel at column `x`, row `y` (inside the frame).
    #[inline]
    pub fn set(&mut self, x: u32, y: u32, color: u32) {
        self.pixels[y as usize * self.width as usize + x as usize] = color;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sized_rectangles_end_past_their_last_pixel() {
        assert_eq!(
            Rect::sized(2, 3, 4, 5),
            Rect {
                x0: 2,
                y0: 3,
                x1: 6,
                y1: 8
            }
        );
        assert!(Rect::sized(7, 7, 0, 9).is_empty());
    }

    #[test]
    fn intersect_keeps_the_common_part_or_nothing() {
        let a = Rect::sized(0, 0, 10, 10);
        assert_eq!(
            a.intersect(&Rect::sized(5, 2, 20, 3)),
            Rect::sized(5, 2, 5, 3)
        );
        assert_eq!(a.intersect(&a), a);
        assert!(a.intersect(&Rect::sized(20, 0, 5, 5)).is_empty());
        assert!(a.intersect(&Rect::sized(0, 10, 5, 5)).is_empty());
    }
}
