//! The size of a frame in pixels: the one way a frame's, a window's, a
//! preview's or a monitor's part's width and height travel together.

use std::fmt;

/// A width and a height in pixels (a Wayland surface's logical size
/// counts the compositor's units). Written `WxH` (`1920x1080`), as the
/// command line takes it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Size {
    /// Columns.
    pub width: u32,
    /// Rows.
    pub height: u32,
}

impl Size {
    /// A `width` x `height` size.
    pub const fn new(width: u32, height: u32) -> Size {
        Size { width, height }
    }

    /// How many pixels a frame of this size holds.
    pub fn pixels(self) -> u64 {
        u64::from(self.width) * u64::from(self.height)
    }

    /// True when either side is zero: nothing to draw.
    pub fn is_empty(self) -> bool {
        self.width == 0 || self.height == 0
    }
}

impl fmt::Display for Size {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}x{}", self.width, self.height)
    }
}
