//! Frames to picture files: `mountains render` (PNG or JPEG, by the
//! extension), and the P key's screenshots (PNG).

mod deflate;
mod huffman;
mod png_parts;

use std::io::{self, Write};
use std::path::Path;

use crate::cli::output::Format;
use crate::fsutil::{write_atomic_with, write_output_with};
use crate::render::Frame;

/// Encodes `frame` as an 8-bit RGB PNG into `out`, its pixels packed
/// on every core (the same file whatever their number).
pub fn encode_png(frame: &Frame, out: &mut dyn Write) -> io::Result<()> {
    png_parts::encode(frame, out, crate::cores::cores()).map_err(png_error)
}

/// The png crate's error as an I/O error, keeping a real I/O error as it is.
fn png_error(e: png::EncodingError) -> io::Error {
    match e {
        png::EncodingError::IoError(e) => e,
        other => io::Error::other(EncodeError(other.to_string())),
    }
}

/// A picture that could not be encoded (as opposed to written).
#[derive(Debug)]
struct EncodeError(String);

impl std::fmt::Display for EncodeError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for EncodeError {}

/// JPEG's quality: fine gradients in the sky without visible blocks.
const JPEG_QUALITY: u8 = 90;

/// Encodes `frame` as a JPEG into `out` (at most 65535 pixels a side,
/// JPEG's limit), reading the frame's pixels as they are (no RGB copy).
pub fn encode_jpeg(frame: &Frame, out: &mut dyn Write) -> io::Result<()> {
    let (Ok(w), Ok(h)) = (u16::try_from(frame.width()), u16::try_from(frame.height())) else {
        return Err(io::Error::other(EncodeError(
            "JPEG allows at most 65535 pixels a side".into(),
        )));
    };
    jpeg_encoder::Encoder::new(out, JPEG_QUALITY)
        .encode_image(FrameImage { frame, w, h })
        .map_err(|e| match e {
            jpeg_encoder::EncodingError::IoError(e) => e,
            other => io::Error::other(EncodeError(other.to_string())),
        })
}

/// A frame as jpeg-encoder reads an image: a row at a time, in YCbCr.
struct FrameImage<'a> {
    frame: &'a Frame,
    w: u16,
    h: u16,
}

impl jpeg_encoder::ImageBuffer for FrameImage<'_> {
    fn get_jpeg_color_type(&self) -> jpeg_encoder::JpegColorType {
        jpeg_encoder::JpegColorType::Ycbcr
    }

    fn width(&self) -> u16 {
        self.w
    }

    fn height(&self) -> u16 {
        self.h
    }

    fn fill_buffers(&self, y: u16, buffers: &mut [Vec<u8>; 4]) {
        let w = usize::from(self.w);
        let start = usize::from(y) * w;
        for &p in &self.frame.pixels()[start..start + w] {
            let (y, cb, cr) = jpeg_encoder::rgb_to_ycbcr((p >> 16) as u8, (p >> 8) as u8, p as u8);
            buffers[0].push(y);
            buffers[1].push(cb);
            buffers[2].push(cr);
        }
    }
}

/// Writes `frame` to `path` as `format` says (PNG or JPEG), atomically.
/// The message names the flag and the file.
pub fn write_picture(path: &Path, frame: &Frame, format: Format) -> Result<(), String> {
    write_output_with(path, |out| match format {
        Format::Jpeg => encode_jpeg(frame, out),
        _ => encode_png(frame, out),
    })
    .map_err(|e| format!("-o {}: {}", path.display(), failure(&e)))
}

/// Writes `frame` to `path` as a PNG, atomically (an existing file is
/// replaced whole or not at all). The message names the file.
pub fn write_png(path: &Path, frame: &Frame) -> Result<(), String> {
    write_atomic_with(path, |out| encode_png(frame, out))
        .map_err(|e| format!("{}: {}", path.display(), failure(&e)))
}

/// "cannot encode" or "cannot write", and why.
fn failure(e: &io::Error) -> String {
    match e.get_ref().and_then(|r| r.downcast_ref::<EncodeError>()) {
        Some(EncodeError(why)) => format!("cannot encode: {why}"),
        None => crate::fsutil::cannot_write(e),
    }
}
