//! Mono mode's 17 black-and-white shades: seed 000's `bwPat`, the listing's
//! own 8x8 QuickDraw patterns, from black (0) to white (16).
//!
//! A pattern's bit is 1 where the pen (black) paints; each of the eight
//! bytes is a row, its top bit the leftmost pixel, and the patterns line up
//! with the frame's origin, as QuickDraw aligns them with the port's. The
//! listing draws level 16 only above its treeline; here a face is as bright
//! as its grey says (Mono's palette keeps green land below 15).

/// Number of shades above black: levels run `0..=LEVELS`.
pub const LEVELS: u8 = 16;

/// The darkest shade Mono paints a face in, but for seed 000's own look:
/// the listing's first pattern is solid black, the colour of its window,
/// so land turned from the light (or a data set seen only from its dark
/// side) vanished into the background and could leave a frame all black.
/// The levels are spread over `FACE_FLOOR..=LEVELS` instead (see
/// [`lifted`]): shade keeps its texture, a few dots above black. Level 1,
/// one column of dots a tile, would comb large shadows with vertical lines.
pub const FACE_FLOOR: u8 = 2;

/// `level` (0..=16) spread over `floor..=LEVELS`, order kept, rounded.
pub fn lifted(level: u8, floor: u8) -> u8 {
    let (l, f, top) = (
        u32::from(level.min(LEVELS)),
        u32::from(floor.min(LEVELS)),
        u32::from(LEVELS),
    );
    (f + (l * (top - f) + top / 2) / top) as u8
}

/// `bwPat[17][2]` of seed 000's listing, each pair of longs as eight rows.
const BW_PAT: [[u8; 8]; 17] = [
    rows(0xFFFF_FFFF),
    rows(0xFFBF_BFBF),
    rows(0xFFEE_FFBB),
    rows(0xFFEE_FFAA),
    rows(0xBBEE_BBEE),
    rows(0xAA77_AAFF),
    rows(0xAA77_AADD),
    rows(0xAA77_AA55),
    rows(0xAA55_AA55),
    rows(0xAA55_AA11),
    rows(0xAA44_AA11),
    rows(0xAA44_AA00),
    rows(0x2288_2288),
    rows(0x2200_AA00),
    rows(0x2200_8800),
    rows(0x8000_0800),
    rows(0x0000_0000),
];

/// The eight rows of a pattern whose two longs are both `long` (so they
/// are in every pattern of the listing).
const fn rows(long: u32) -> [u8; 8] {
    let b = long.to_be_bytes();
    [b[0], b[1], b[2], b[3], b[0], b[1], b[2], b[3]]
}

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

/// The grey (`0x00RRGGBB`) that [`level`] reads as `level`: how a colour
/// that is already one of the patterns (seed 000's own choice) is handed
/// to the painter.
pub fn grey(level: u8) -> u32 {
    let v = u32::from(level.min(LEVELS)) * 255 / u32::from(LEVELS);
    v << 16 | v << 8 | v
}

/// True when the pixel at (`x`, `y`) is white in dither level `level`
/// (levels above 16 count as 16).
#[inline]
pub fn is_on(level: u8, x: u32, y: u32) -> bool {
    let row = BW_PAT[level.min(LEVELS) as usize][(y & 7) as usize];
    row & (0x80 >> (x & 7)) == 0
}
