//! Frames to picture files: `mountains render` (PNG or JPEG, by the
//! extension), and the P key's screenshots (PNG).

use std::path::Path;

use crate::cli::output::Format;
use crate::fsutil::{write_atomic, write_output};
use crate::render::Frame;

/// Encodes `frame` as an 8-bit RGB PNG.
pub fn encode_png(frame: &Frame) -> Result<Vec<u8>, png::EncodingError> {
    let mut bytes = Vec::new();
    let mut encoder = png::Encoder::new(&mut bytes, frame.width(), frame.height());
    encoder.set_color(png::ColorType::Rgb);
    encoder.set_depth(png::BitDepth::Eight);
    // fdeflate with the Up filter on every row: a 1080p frame in about a
    // tenth of the default's time, for files some 10-20% larger (2-9% more
    // than choosing each row's filter, which cost 4 ms of a 90 ms `render`);
    // a screensaver's pictures are many and seldom kept.
    encoder.set_compression(png::Compression::Fastest);
    let mut writer = encoder.write_header()?;
    let rgb = rgb(frame).ok_or_else(|| {
        png::EncodingError::from(std::io::Error::new(
            std::io::ErrorKind::OutOfMemory,
            no_memory(),
        ))
    })?;
    writer.write_image_data(&rgb)?;
    writer.finish()?;
    Ok(bytes)
}

/// The frame's pixels as bytes, red, green, blue; `None` if the memory for
/// them cannot be had.
fn rgb(frame: &Frame) -> Option<Vec<u8>> {
    let mut rgb = Vec::new();
    rgb.try_reserve_exact(frame.pixels().len() * 3).ok()?;
    for &p in frame.pixels() {
        rgb.extend_from_slice(&[(p >> 16) as u8, (p >> 8) as u8, p as u8]);
    }
    Some(rgb)
}

fn no_memory() -> String {
    "not enough memory to encode the frame".into()
}

/// JPEG's quality: fine gradients in the sky without visible blocks.
const JPEG_QUALITY: u8 = 90;

/// Encodes `frame` as a JPEG (at most 65535 pixels a side, JPEG's limit).
pub fn encode_jpeg(frame: &Frame) -> Result<Vec<u8>, String> {
    let (Ok(w), Ok(h)) = (u16::try_from(frame.width()), u16::try_from(frame.height())) else {
        return Err("JPEG allows at most 65535 pixels a side".into());
    };
    let mut bytes = Vec::new();
    jpeg_encoder::Encoder::new(&mut bytes, JPEG_QUALITY)
        .encode(
            &rgb(frame).ok_or_else(no_memory)?,
            w,
            h,
            jpeg_encoder::ColorType::Rgb,
        )
        .map_err(|e| e.to_string())?;
    Ok(bytes)
}

/// Writes `frame` to `path` as `format` says (PNG or JPEG), atomically.
/// The message names the file.
pub fn write_picture(path: &Path, frame: &Frame, format: Format) -> Result<(), String> {
    let bytes = match format {
        Format::Jpeg => encode_jpeg(frame),
        _ => encode_png(frame).map_err(|e| e.to_string()),
    }
    .map_err(|e| format!("{}: cannot encode: {e}", path.display()))?;
    write_output(path, &bytes).map_err(|e| format!("-o {}: cannot write: {e}", path.display()))
}

/// Writes `frame` to `path` as a PNG, atomically (an existing file is
/// replaced whole or not at all). The message names the file.
pub fn write_png(path: &Path, frame: &Frame) -> Result<(), String> {
    let bytes =
        encode_png(frame).map_err(|e| format!("{}: cannot encode PNG: {e}", path.display()))?;
    write_atomic(path, &bytes).map_err(|e| format!("{}: cannot write: {e}", path.display()))
}
