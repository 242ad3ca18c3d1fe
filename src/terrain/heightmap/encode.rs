//! Writing a heightfield as a 16-bit grayscale PNG with our text chunks.

use std::path::Path;

use png::{BitDepth, ColorType, Compression, Encoder};

use super::error::{ErrorKind, HeightmapError};
use super::meta;
use super::quantise::{Quantisation, min_max};
use crate::settings::Settings;
use crate::terrain::Heightfield;

/// The PNG bytes of `field`; `path` only names the file in messages.
pub fn encode(
    field: &Heightfield,
    seed: Option<u64>,
    settings: &Settings,
    path: &Path,
) -> Result<Vec<u8>, HeightmapError> {
    let bad = |problem: &str| HeightmapError::new(path, ErrorKind::BadField, problem);
    if field.heights().iter().any(|h| !h.is_finite()) {
        return Err(bad("the heightfield holds NaN or infinite heights"));
    }
    let extent = field.extent();
    if !(extent.is_finite() && extent > 0.0) {
        return Err(bad("the heightfield's extent is not a positive number"));
    }
    let (min, max) = min_max(field.heights());
    let q = Quantisation::spanning(min, max);
    if let Err((key, why)) = meta::check_storable(&q, extent) {
        return Err(bad(&format!(
            "the heightfield cannot be stored so that it loads again: {key}: {why}"
        )));
    }
    let pixels: Vec<u8> = field
        .heights()
        .iter()
        .flat_map(|&h| q.sample(h).to_be_bytes())
        .collect();
    let text = meta::to_pairs(&q, extent, seed, settings);
    write_png(field.size() as u32, &pixels, &text)
        .map_err(|e| HeightmapError::new(path, ErrorKind::Io, format!("cannot encode: {e}")))
}

fn write_png(
    side: u32,
    pixels: &[u8],
    text: &[(&'static str, String)],
) -> Result<Vec<u8>, png::EncodingError> {
    let mut out = Vec::with_capacity(pixels.len() / 2);
    let mut enc = Encoder::new(&mut out, side, side);
    enc.set_color(ColorType::Grayscale);
    enc.set_depth(BitDepth::Sixteen);
    enc.set_compression(Compression::Fast);
    enc.add_text_chunk(
        "Software".into(),
        format!("mountains {}", env!("CARGO_PKG_VERSION")),
    )?;
    enc.add_text_chunk(
        "Description".into(),
        "Heightmap: elevation = mountains:offset + mountains:scale * sample; \
         water below mountains:sea_level; mountains:extent = grid width in the same units"
            .into(),
    )?;
    for (key, value) in text {
        enc.add_text_chunk((*key).into(), value.clone())?;
    }
    let mut writer = enc.write_header()?;
    writer.write_image_data(pixels)?;
    writer.finish()?;
    Ok(out)
}
