//! Mono mode's 17 black-and-white shades (seed 000's `bwPat`), as a 4x4
//! ordered (Bayer) dither.
//!
//! Level k turns on exactly k of the 16 pixels of every 4x4 tile, and the
//! pixels of level k are among those of level k + 1, so brightness never
//! goes down as the level goes up and neighbouring shades blend. The Bayer
//! order spreads the on pixels evenly, where seed 000's hand-drawn patterns
//! are not nested.

/// Number of shades above black: levels run `0..=LEVELS`.
pub const LEVELS: u8 = 16;

/// The order in which the pixels of a 4x4 tile turn on, row-major.
const BAYER: [[u8; 4]; 4] = [[0, 8, 2, 10], [12, 4, 14, 6], [3, 11, 1, 9], [15, 7, 13, 5]];

/// The dither level (0 black ..= 16 white) for a grey `0x00RRGGBB`; a colour
/// that is not grey counts by its luminance. A value of at most 255 (no red
/// or green) is taken as a grey level 0..=255 itself, so callers that have
/// already reduced a colour to one byte get the same answer; Mono's palette
/// only makes greys, so no pure blue is ever misread.
#[inline]
pub fn level(gray: u32) -> u8 {
    let y = if gray <= 0xff {
        gray
    } else {
        let r = (gray >> 16) & 0xff;
        let g = (gray >> 8) & 0xff;
        let b = gray & 0xff;
        // Rec. 709 weights in 1/256ths: 54 + 183 + 19 = 256.
        (54 * r + 183 * g + 19 * b) >> 8
    };
    ((y * LEVELS as u32 + 127) / 255) as u8
}

/// True when the pixel at (`x`, `y`) is white in dither level `level`
/// (levels above 16 count as 16).
#[inline]
pub fn is_on(level: u8, x: u32, y: u32) -> bool {
    BAYER[(y & 3) as usize][(x & 3) as usize] < level
}
