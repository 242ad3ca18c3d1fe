//! Screen positions in 24.8 fixed point and the pixels a rasteriser may
//! touch: what the scene projects its points to, and what the rasteriser,
//! the lines and the canvas read.

/// Fixed-point steps per pixel (8 bits of sub-pixel precision).
pub const SUBPIXEL: i64 = 1 << 8;

/// A screen position in 24.8 fixed point.
pub type Fixed2 = [i64; 2];

/// The pixels a rasteriser may touch: columns `x0..x1`, rows `y0..y1`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Clip {
    /// First column.
    pub x0: i64,
    /// Column past the last.
    pub x1: i64,
    /// First row.
    pub y0: i64,
    /// Row past the last.
    pub y1: i64,
}

impl Clip {
    /// A `width` x `height` frame, whole.
    pub fn frame(width: u32, height: u32) -> Self {
        Clip {
            x0: 0,
            x1: width as i64,
            y0: 0,
            y1: height as i64,
        }
    }
}

/// Converts a position in pixels to fixed point (non-finite values become 0).
#[inline]
pub fn to_fixed(x: f32, y: f32) -> Fixed2 {
    [round(x * SUBPIXEL as f32), round(y * SUBPIXEL as f32)]
}

/// Nearest integer, halves up; without a libm call (`f32::round` is one on
/// baseline x86-64). `as` saturates and maps NaN to 0, so wild input cannot
/// overflow here.
#[inline]
fn round(v: f32) -> i64 {
    let t = (v + 0.5).clamp(-1e15, 1e15);
    let i = t as i64;
    // `as` truncates towards zero: step down for negative non-integers.
    if (i as f32) > t { i - 1 } else { i }
}
