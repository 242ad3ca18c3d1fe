//! Reading raw 16-bit heightmaps (`.r16`, `.raw`): what `heightmap -o
//! NAME.r16` writes for terrain tools, and what those that write their
//! rows from the back in little-endian order export.
//!
//! Such a file is its samples alone: a square grid, little-endian, row by
//! row from the back. Its side is the square root of half its length; its
//! heights are chosen as a PNG's without our text chunks are (see the
//! module above), and a note says how it was read. The rows are streamed
//! into the fitted grid, as a PNG's are.

use std::io::Read;
use std::path::Path;

use super::decode::{MAX_SOURCE_SIDE, MIN_SOURCE_SIDE, RawGrid};
use super::error::{ErrorKind, HeightmapError};
use super::fit::{Fit, Resampler};

/// The extensions of raw 16-bit heightmaps, which have no signature to
/// know them by.
pub const RAW_EXTENSIONS: [&str; 2] = ["r16", "raw"];

/// Whether `path`'s extension names a raw heightmap (any case).
pub fn is_raw(path: &Path) -> bool {
    path.extension()
        .is_some_and(|e| RAW_EXTENSIONS.iter().any(|r| e.eq_ignore_ascii_case(r)))
}

/// Reads the `len` bytes of a raw heightmap from `input` (the contents of
/// `path`) into a fitted grid.
pub fn read(mut input: impl Read, len: u64, path: &Path) -> Result<RawGrid, HeightmapError> {
    let side = side_of(len, path)?;
    let fit = Fit::plan(side, side);
    let mut grid = Resampler::new(fit);
    let mut row = vec![0u8; 2 * side as usize];
    let mut text = Text::default();
    for y in 0..side {
        input.read_exact(&mut row).map_err(|e| {
            let why = crate::fsutil::cannot_read(&e);
            let problem = format!("{why} (row {y} of {side})");
            HeightmapError::new(path, ErrorKind::Truncated, problem)
        })?;
        text.take(&row);
        let samples = row
            .chunks_exact(2)
            .map(|b| f32::from(u16::from_le_bytes([b[0], b[1]])));
        grid.push_row(y, samples);
    }
    if text.is_text() {
        // `printf 'garbage\n' | mountains --open -`: 8 bytes, a square of 4
        // samples.
        let problem = "holds lines of text, not a raw heightmap of 16-bit samples";
        return Err(HeightmapError::new(path, ErrorKind::NotRaw, problem));
    }
    Ok(RawGrid {
        fit,
        bit_depth: 16,
        samples: grid.finish(),
        text: Vec::new(),
    })
}

/// Whether the bytes seen are lines of text (printable ASCII, tabs and
/// line ends, with a line end among them): what a text piped or named by
/// mistake is, and what no terrain's samples are, whose low bytes run
/// through all 256 values.
#[derive(Default)]
struct Text {
    other: bool,
    line_end: bool,
}

impl Text {
    fn take(&mut self, bytes: &[u8]) {
        let texty = |b: &u8| matches!(b, b'\t' | b'\n' | b'\r' | 0x20..=0x7e);
        self.other |= !bytes.iter().all(texty);
        self.line_end |= bytes.contains(&b'\n');
    }

    fn is_text(&self) -> bool {
        self.line_end && !self.other
    }
}

/// What [`read`] assumed, for the data set's notes.
pub fn note(side: u32) -> String {
    format!("raw 16-bit samples: a {side}x{side} square, little-endian, the first row at the back")
}

/// The side of the square grid of 16-bit samples `len` bytes hold, or
/// what is wrong with that length.
fn side_of(len: u64, path: &Path) -> Result<u32, HeightmapError> {
    let side = (len / 2).isqrt();
    if len == 0 {
        return Err(HeightmapError::new(
            path,
            ErrorKind::NotRaw,
            "is empty, not a raw heightmap",
        ));
    }
    if side * side * 2 != len {
        let mut problem = format!(
            "is {len} bytes, not a raw heightmap: raw 16-bit samples of a square take \
             2 x side x side bytes (1025x1025: 2101250)"
        );
        // Twice a square is never a square: a square of bytes is 8-bit.
        let bytes_side = len.isqrt();
        if bytes_side * bytes_side == len {
            problem += &format!(
                "; if it holds {bytes_side}x{bytes_side} 8-bit samples, save it as a grayscale PNG"
            );
        }
        return Err(HeightmapError::new(path, ErrorKind::NotRaw, problem));
    }
    let too = |kind, what: &str, bound: u32| {
        let problem =
            format!("is a {side}x{side} raw heightmap; a heightmap {what} {bound}x{bound}");
        Err(HeightmapError::new(path, kind, problem))
    };
    if side > u64::from(MAX_SOURCE_SIDE) {
        return too(ErrorKind::TooLarge, "may be at most", MAX_SOURCE_SIDE);
    }
    if side < u64::from(MIN_SOURCE_SIDE) {
        return too(ErrorKind::TooSmall, "needs at least", MIN_SOURCE_SIDE);
    }
    Ok(side as u32)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A raw file of `side` squared samples, sample `i` worth `f(i)`.
    fn raw(side: usize, f: impl Fn(usize) -> u16) -> Vec<u8> {
        (0..side * side).flat_map(|i| f(i).to_le_bytes()).collect()
    }

    fn read_bytes(bytes: &[u8]) -> Result<RawGrid, HeightmapError> {
        read(bytes, bytes.len() as u64, Path::new("t.r16"))
    }

    #[test]
    fn a_square_of_samples_is_read_little_endian_from_the_back() {
        // 17x17, a grid size already: read as it is.
        let bytes = raw(17, |i| 200 * i as u16 + 1);
        let grid = read_bytes(&bytes).unwrap();
        assert_eq!(grid.fit.size, 17);
        assert_eq!(grid.bit_depth, 16);
        let want: Vec<f32> = (0..17 * 17).map(|i| (200 * i + 1) as f32).collect();
        assert_eq!(grid.samples, want);
        // A byte order the other way would read 1 as 256.
        assert_eq!(grid.samples[0], 1.0);
    }

    #[test]
    fn other_sides_are_fitted_as_a_png_is() {
        let bytes = raw(100, |_| 40000);
        let grid = read_bytes(&bytes).unwrap();
        assert_eq!(grid.fit, Fit::plan(100, 100));
        assert!(grid.samples.iter().all(|&s| s == 40000.0));
    }

    #[test]
    fn a_length_that_is_no_square_of_samples_is_named() {
        for (len, kind, says) in [
            (0, ErrorKind::NotRaw, "is empty"),
            (17, ErrorKind::NotRaw, "is 17 bytes"),
            (2 * 3 * 4, ErrorKind::NotRaw, "is 24 bytes"),
            (
                9,
                ErrorKind::NotRaw,
                "if it holds 3x3 8-bit samples, save it as a grayscale PNG",
            ),
            (2, ErrorKind::TooSmall, "1x1"),
        ] {
            let e = read_bytes(&vec![0; len]).err().expect("refused");
            assert_eq!(e.kind, kind, "{len} bytes");
            assert!(e.problem.contains(says), "{len} bytes: {}", e.problem);
        }
        let side = u64::from(MAX_SOURCE_SIDE) + 1;
        let e = side_of(2 * side * side, Path::new("big.raw")).unwrap_err();
        assert_eq!(e.kind, ErrorKind::TooLarge, "{}", e.problem);
    }

    /// Lines of text of a square's length (`echo garbage | mountains
    /// --open -`) are no samples; samples with a line end's byte are.
    #[test]
    fn lines_of_text_are_no_samples() {
        let e = read_bytes(b"garbage\n").err().expect("refused");
        assert_eq!(e.kind, ErrorKind::NotRaw, "{}", e.problem);
        assert!(e.problem.contains("holds lines of text"), "{}", e.problem);
        let e = read_bytes(&b"seed = 5\n".repeat(32)[..288])
            .err()
            .expect("refused");
        assert_eq!(e.kind, ErrorKind::NotRaw, "{}", e.problem);
        let samples = raw(12, |i| 0x0a00 + i as u16);
        assert!(read_bytes(&samples).is_ok());
    }

    #[test]
    fn a_file_shorter_than_it_said_is_truncated() {
        let bytes = raw(5, |_| 7);
        let e = read(&bytes[..30], bytes.len() as u64, Path::new("t.r16"))
            .err()
            .expect("refused");
        assert_eq!(e.kind, ErrorKind::Truncated, "{}", e.problem);
    }

    #[test]
    fn raw_extensions_are_known_in_any_case() {
        assert!(is_raw(Path::new("a/h.r16")) && is_raw(Path::new("H.RAW")));
        assert!(!is_raw(Path::new("h.png")) && !is_raw(Path::new("r16")));
    }
}
