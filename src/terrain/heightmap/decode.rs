//! Reading a grayscale PNG into a fitted grid of raw samples, safely.
//!
//! Everything is checked before it costs memory: the signature first, then
//! the IHDR (colour type, bit depth, at most 16384x16384 pixels) before any
//! image data is read. Rows are streamed into the fitted grid, so memory is
//! the output grid plus a row. The png crate's own buffers (chunks, text) are
//! capped at 32 MiB, and compressed text is only inflated for our own keys,
//! to at most 4 KiB.

use std::io::{self, BufRead, Read, Seek, SeekFrom};
use std::path::Path;

use png::{BitDepth, ColorType, Decoder, DecodingError, Limits, Transformations};

use super::error::{ErrorKind, HeightmapError};
use super::fit::{Fit, Resampler};
use crate::fsutil::PNG_SIGNATURE as SIGNATURE;

/// Largest width or height of a PNG we open.
pub const MAX_SOURCE_SIDE: u32 = 16384;
/// Smallest width or height of a PNG we open.
pub const MIN_SOURCE_SIDE: u32 = 2;
/// What the png crate may allocate for chunks and row buffers.
const DECODER_BYTE_LIMIT: usize = 32 << 20;
/// Largest interlaced image, which cannot be streamed row by row.
const INTERLACED_BYTE_LIMIT: usize = 64 << 20;
/// Largest inflated value of one of our compressed text chunks.
const TEXT_LIMIT: usize = 4096;
/// Prefix of our keys; other text chunks are skipped (never inflated).
const OUR_PREFIX: &str = "mountains:";
/// Most bytes one byte of deflate data can expand to (with a safety margin).
const MAX_DEFLATE_RATIO: u64 = 1100;

/// A decoded image: the fitted grid in sample units and its text chunks.
pub struct RawGrid {
    /// How the image was fitted.
    pub fit: Fit,
    /// 8 or 16.
    pub bit_depth: u8,
    /// `fit.size` squared samples (0..=255 or 0..=65535, filtered), row-major.
    pub samples: Vec<f32>,
    /// Text chunks with our prefix (tEXt, zTXt or iTXt).
    pub text: Vec<(String, String)>,
}

/// Reads a PNG of `len` bytes from `input` (the contents of `path`) into a
/// fitted grid.
pub fn read<R: BufRead + Seek>(
    mut input: R,
    len: u64,
    path: &Path,
) -> Result<RawGrid, HeightmapError> {
    check_signature(&mut input, path)?;
    let err = |e: DecodingError| png_error(path, e);
    let mut decoder = Decoder::new_with_limits(
        input,
        Limits {
            bytes: DECODER_BYTE_LIMIT,
        },
    );
    decoder.set_transformations(Transformations::IDENTITY);
    let header = decoder.read_header_info().map_err(err)?;
    let (width, height, interlaced) = (header.width, header.height, header.interlaced);
    let bit_depth = check_header(header.color_type, header.bit_depth, width, height, path)?;
    check_length(len, width, height, bit_depth, path)?;
    let mut reader = decoder.read_info().map_err(err)?;
    let fit = Fit::plan(width, height);
    let mut grid = Resampler::new(fit);
    if interlaced {
        read_whole(&mut reader, &mut grid, bit_depth, path)?;
    } else {
        let mut y = 0;
        while let Some(row) = reader.next_row().map_err(err)? {
            grid.push_row(y, samples(row.data(), bit_depth));
            y += 1;
        }
    }
    reader.finish().map_err(err)?;
    let text = text_chunks(reader.info(), path)?;
    Ok(RawGrid {
        fit,
        bit_depth,
        samples: grid.finish(),
        text,
    })
}

/// Whether `input` starts with the PNG signature; rewinds.
pub(super) fn starts_as_png<R: Read + Seek>(input: &mut R) -> io::Result<bool> {
    Ok(head(input)? == SIGNATURE)
}

/// The first bytes of `input`, as many as the signature's (fewer if it is
/// shorter); rewinds.
fn head<R: Read + Seek>(input: &mut R) -> io::Result<Vec<u8>> {
    let mut head = Vec::with_capacity(SIGNATURE.len());
    input
        .by_ref()
        .take(SIGNATURE.len() as u64)
        .read_to_end(&mut head)?;
    input.seek(SeekFrom::Start(0))?;
    Ok(head)
}

/// Reads the first 8 bytes, names what is not a PNG, and rewinds.
fn check_signature<R: Read + Seek>(input: &mut R, path: &Path) -> Result<(), HeightmapError> {
    let io =
        |e: io::Error| HeightmapError::new(path, ErrorKind::Io, crate::fsutil::cannot_read(&e));
    let head = head(input).map_err(io)?;
    if head == SIGNATURE {
        return Ok(());
    }
    let (kind, problem) = if head.is_empty() {
        (ErrorKind::NotPng, "is empty, not a PNG file")
    } else if SIGNATURE.starts_with(&head) {
        (
            ErrorKind::Truncated,
            "is truncated: it ends inside the PNG signature",
        )
    } else {
        (ErrorKind::NotPng, "is not a PNG file")
    };
    Err(HeightmapError::new(path, kind, problem))
}

/// Rejects what is not an 8/16-bit grayscale image of a sane size.
fn check_header(
    color: ColorType,
    depth: BitDepth,
    width: u32,
    height: u32,
    path: &Path,
) -> Result<u8, HeightmapError> {
    let gray_only = "a heightmap must be 8- or 16-bit grayscale";
    let not_gray = |what: &str| {
        HeightmapError::new(
            path,
            ErrorKind::NotGrayscale,
            format!("is {what}; {gray_only}"),
        )
    };
    match color {
        ColorType::Grayscale => {}
        ColorType::Rgb => return Err(not_gray("an RGB colour image")),
        ColorType::Rgba => return Err(not_gray("an RGBA colour image")),
        ColorType::Indexed => return Err(not_gray("a palette (indexed colour) image")),
        ColorType::GrayscaleAlpha => return Err(not_gray("grayscale with an alpha channel")),
    }
    let bits = match depth {
        BitDepth::Eight => 8,
        BitDepth::Sixteen => 16,
        other => {
            let n = other as u8;
            return Err(HeightmapError::new(
                path,
                ErrorKind::BitDepth,
                format!("is {n}-bit grayscale, too few levels for heights; {gray_only}"),
            ));
        }
    };
    if width > MAX_SOURCE_SIDE || height > MAX_SOURCE_SIDE {
        return Err(HeightmapError::new(
            path,
            ErrorKind::TooLarge,
            format!(
                "is {width}x{height} pixels; a heightmap may be at most \
                 {MAX_SOURCE_SIDE}x{MAX_SOURCE_SIDE}"
            ),
        ));
    }
    if width < MIN_SOURCE_SIDE || height < MIN_SOURCE_SIDE {
        return Err(HeightmapError::new(
            path,
            ErrorKind::TooSmall,
            format!(
                "is {width}x{height} pixels; a heightmap needs at least \
                 {MIN_SOURCE_SIDE}x{MIN_SOURCE_SIDE}"
            ),
        ));
    }
    Ok(bits)
}

/// Deflate expands at most 1032:1, so a file too short to hold its image
/// even at that ratio is truncated: say so before allocating the grid.
fn check_length(
    len: u64,
    width: u32,
    height: u32,
    bit_depth: u8,
    path: &Path,
) -> Result<(), HeightmapError> {
    let row = 1 + u64::from(width) * u64::from(bit_depth / 8);
    let raw = row * u64::from(height);
    if raw > len.saturating_mul(MAX_DEFLATE_RATIO) {
        return Err(HeightmapError::new(
            path,
            ErrorKind::Truncated,
            format!("is truncated: {len} bytes cannot hold a {width}x{height} image"),
        ));
    }
    Ok(())
}

/// The samples of one row of raw 8- or 16-bit (big-endian) gray.
fn samples(row: &[u8], bit_depth: u8) -> Box<dyn Iterator<Item = f32> + '_> {
    if bit_depth == 16 {
        Box::new(
            row.chunks_exact(2)
                .map(|b| f32::from(u16::from_be_bytes([b[0], b[1]]))),
        )
    } else {
        Box::new(row.iter().map(|&b| f32::from(b)))
    }
}

/// Interlaced images come in passes: decode the whole frame (bounded) first.
fn read_whole<R: BufRead + Seek>(
    reader: &mut png::Reader<R>,
    grid: &mut Resampler,
    bit_depth: u8,
    path: &Path,
) -> Result<(), HeightmapError> {
    let size = reader.output_buffer_size().unwrap_or(usize::MAX);
    if size > INTERLACED_BYTE_LIMIT {
        return Err(HeightmapError::new(
            path,
            ErrorKind::TooLarge,
            format!(
                "is interlaced and needs {} MiB to decode, over the {} MiB allowed; \
                 save it without interlacing",
                size >> 20,
                INTERLACED_BYTE_LIMIT >> 20
            ),
        ));
    }
    let mut buf = vec![0u8; size];
    let info = reader
        .next_frame(&mut buf)
        .map_err(|e| png_error(path, e))?;
    for (y, row) in buf.chunks_exact(info.line_size).enumerate() {
        grid.push_row(y as u32, samples(row, bit_depth));
    }
    Ok(())
}

/// Our keys from the text chunks; compressed ones inflated within bounds.
fn text_chunks(info: &png::Info, path: &Path) -> Result<Vec<(String, String)>, HeightmapError> {
    let mut text: Vec<(String, String)> = info
        .uncompressed_latin1_text
        .iter()
        .filter(|c| c.keyword.starts_with(OUR_PREFIX))
        .map(|c| (c.keyword.clone(), c.text.clone()))
        .collect();
    // The cause in words: a value over our cap is no damage.
    let unreadable = |key: &str, e: DecodingError| {
        // png says "out of decompression space" when our limit is hit.
        let over = matches!(e, DecodingError::LimitsExceeded)
            || e.to_string().to_lowercase().contains("decompression space");
        let why = if over {
            format!(
                "compressed text longer than the {} KiB a value may have",
                TEXT_LIMIT / 1024
            )
        } else {
            "compressed text that cannot be inflated (damaged)".to_string()
        };
        HeightmapError::metadata(path, key, why)
    };
    // zTXt and iTXt chunks have the same methods but no common trait.
    macro_rules! read_ours {
        ($chunks:expr) => {
            for chunk in $chunks.iter().filter(|c| c.keyword.starts_with(OUR_PREFIX)) {
                let mut c = chunk.clone();
                c.decompress_text_with_limit(TEXT_LIMIT)
                    .map_err(|e| unreadable(&c.keyword, e))?;
                let value = c.get_text().map_err(|e| unreadable(&c.keyword, e))?;
                text.push((c.keyword, value));
            }
        };
    }
    read_ours!(info.compressed_latin1_text);
    read_ours!(info.utf8_text);
    Ok(text)
}

/// A png crate error in words, with its kind.
fn png_error(path: &Path, e: DecodingError) -> HeightmapError {
    match e {
        DecodingError::IoError(io) if io.kind() == io::ErrorKind::UnexpectedEof => {
            HeightmapError::new(
                path,
                ErrorKind::Truncated,
                "is truncated: the file ends before the image is complete",
            )
        }
        DecodingError::IoError(io) => {
            HeightmapError::new(path, ErrorKind::Io, crate::fsutil::cannot_read(&io))
        }
        DecodingError::LimitsExceeded => HeightmapError::new(
            path,
            ErrorKind::TooLarge,
            // The limit is on all the memory the chunks take together (a
            // 16 MiB comment can reach it), not on one chunk.
            format!(
                "needs more than the {} MiB of memory a heightmap may use for its chunks \
                 (pixels, text and others together)",
                DECODER_BYTE_LIMIT >> 20
            ),
        ),
        other => HeightmapError::new(
            path,
            ErrorKind::Damaged,
            format!("is a damaged PNG: {}", plain(&other.to_string())),
        ),
    }
}

/// The png crate's message in a person's words: chunk types by their four
/// letters (not `ChunkType { type: IHDR, critical: true, ... }`), a bad
/// filter byte said as such.
fn plain(message: &str) -> String {
    let mut out = String::new();
    let mut rest = message;
    while let Some(i) = rest.find("ChunkType { type: ") {
        out.push_str(&rest[..i]);
        let after = &rest[i + "ChunkType { type: ".len()..];
        let name_end = after.find([',', ' ', '}']).unwrap_or(after.len());
        out.push_str(&after[..name_end]);
        rest = after.find('}').map_or("", |j| &after[j + 1..]);
    }
    out.push_str(rest);
    if out == "Invalid image dimensions" {
        // The png crate says this of a header's zero width or height only.
        return "its header says the image is 0 pixels wide or 0 tall".to_string();
    }
    if let Some(n) = out.strip_prefix("Unknown filter method ") {
        let n = n.trim_end_matches('.');
        return format!(
            "filter type {n}, which PNG does not have (0 to 4 for a row, 0 in the header)"
        );
    }
    out
}

#[cfg(test)]
mod plain_tests {
    use super::plain;

    #[test]
    fn png_messages_in_plain_words() {
        assert_eq!(
            plain(
                "Chunk ChunkType { type: IHDR, critical: true, private: false, reserved: false, safecopy: false } must appear at most once."
            ),
            "Chunk IHDR must appear at most once."
        );
        assert_eq!(
            plain("Unknown filter method 9."),
            "filter type 9, which PNG does not have (0 to 4 for a row, 0 in the header)"
        );
        assert_eq!(plain("CRC error"), "CRC error");
        assert_eq!(
            plain("Invalid image dimensions"),
            "its header says the image is 0 pixels wide or 0 tall"
        );
    }
}
