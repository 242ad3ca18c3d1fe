//! Data sets on disk: 16-bit grayscale PNG heightmaps with our metadata.
//!
//! **Saving** spreads the field's lowest..highest heights over the whole
//! 16-bit range and records in `mountains:` text chunks how to undo it
//! (`scale`, `offset`, `sea_level`, `extent`), plus the seed and generator
//! parameters. Terrain tools (Blender, Unity, Unreal, World Machine) read the
//! image as an ordinary heightmap; we read it back as the same mountain. After
//! the first quantisation the round trip is exact (see [`quantise`]).
//!
//! **Loading** takes any 8- or 16-bit grayscale PNG, ours or a terrain
//! tool's, or raw 16-bit samples (see [`raw`]), fits it to a `2^n + 1`
//! grid (see [`fit`] for the exact method: central square crop, `2^n`
//! sides extended by one, others resampled to the nearest `2^n + 1` up to
//! 4097) and fills in what its metadata lacks:
//! - no `mountains:scale`: the relief (highest - lowest sample) becomes
//!   [`DEFAULT_RELIEF`] of the width, a natural mountain aspect;
//! - no `mountains:offset`: sample 0 is elevation 0;
//! - no `mountains:sea_level`: the water line is the [`SEA_PERCENTILE`]th
//!   percentile of the heights, and at least half a step above the lowest
//!   sample, so some water shows and the lowest ground is always under it;
//! - no `mountains:extent`: the width is [`DEFAULT_EXTENT`].
//!
//! Land and sea spanning more than [`MAX_DRAWN_RELIEF`] widths are drawn
//! squashed to that (see [`Heightfield::drawn`]); the heights are kept, and
//! a note says so.
//!
//! 8-bit images are softened (see [`soften`]) so their 256 levels do not
//! show as terraces. Each assumption is listed in [`DataSet::notes`]. Bad
//! metadata: see [`meta`].

mod decode;
mod encode;
mod error;
pub mod fit;
pub mod meta;
pub mod quantise;
mod raw;
pub mod soften;

use std::io::Read;
use std::path::Path;

pub use decode::{MAX_SOURCE_SIDE, MIN_SOURCE_SIDE};
pub use encode::encode;
pub use error::{ErrorKind, HeightmapError};
pub use fit::{Fit, FitMethod};
pub use meta::GeneratorParams;
pub use raw::RAW_EXTENSIONS;

use super::Heightfield;
use super::heightfield::MAX_DRAWN_RELIEF;
use crate::settings::Settings;
use decode::RawGrid;
use fit::Resampler;
use meta::Metadata;

/// Width given to a heightmap whose file does not say (`mountains:extent`).
pub const DEFAULT_EXTENT: f32 = 400.0;
/// Relief (highest - lowest) as a fraction of the width, when no scale is given.
pub const DEFAULT_RELIEF: f32 = 0.2;
/// Percentile of the heights put at sea level when the file does not say.
pub const SEA_PERCENTILE: f64 = 10.0;

/// A heightfield loaded from disk, with what its file said about it.
#[derive(Debug, Clone)]
pub struct DataSet {
    /// The heights, fitted to a `2^n + 1` grid, sea level at 0.
    pub field: Heightfield,
    /// The seed that generated it, when the file says.
    pub seed: Option<u64>,
    /// The generator parameters that made it, when the file says.
    pub params: Option<GeneratorParams>,
    /// How the image was fitted to the grid.
    pub fit: Fit,
    /// Bits per sample in the file (8 or 16).
    pub bit_depth: u8,
    /// Height units per sample step, as read or chosen.
    pub scale: f64,
    /// Elevation of sample 0, as read or chosen.
    pub offset: f32,
    /// Elevation of the water line, as read or chosen (heights are relative to it).
    pub sea_level: f32,
    /// What was assumed or ignored while loading, one sentence each, for the log.
    pub notes: Vec<String>,
}

/// The field as raw 16-bit little-endian samples, row by row from the back,
/// spread over the whole range (what terrain tools import as `.r16`), and
/// the heights the samples stand for.
pub fn raw16(field: &Heightfield) -> (Vec<u8>, quantise::Quantisation) {
    let (min, max) = quantise::min_max(field.heights());
    let q = quantise::Quantisation::spanning(min, max);
    let bytes = field
        .heights()
        .iter()
        .flat_map(|&h| q.sample(h).to_le_bytes())
        .collect();
    (bytes, q)
}

/// Saves `field` as a 16-bit grayscale PNG with the seed and settings in text chunks.
///
/// Writes atomically: on any failure an existing file at `path` is untouched.
/// Generator parameters are written only with a seed (see [`meta::to_pairs`]).
pub fn save(
    path: &Path,
    field: &Heightfield,
    seed: Option<u64>,
    settings: &Settings,
) -> Result<(), HeightmapError> {
    let bytes = encode(field, seed, settings, path)?;
    crate::fsutil::write_output_with(path, |w| w.write_all(&bytes))
        .map_err(|e| HeightmapError::new(path, ErrorKind::Io, crate::fsutil::cannot_write(&e)))
}

/// The largest data set file read: a 4097x4097 16-bit PNG stored without
/// compression is 32 MiB; anything far larger is not one of ours or a
/// terrain tool's.
pub const MAX_FILE_BYTES: u64 = 256 << 20;

/// Whether `path`'s name is a data set's, as [`load`] reads them: a PNG,
/// or raw samples (any case).
pub fn named_as_data_set(path: &Path) -> bool {
    path.extension().is_some_and(|e| {
        DATA_SET_EXTENSIONS
            .iter()
            .any(|d| e.eq_ignore_ascii_case(d))
    })
}

/// The extensions of data sets [`load`] reads: PNG, then the raw ones.
pub const DATA_SET_EXTENSIONS: [&str; 3] = ["png", RAW_EXTENSIONS[0], RAW_EXTENSIONS[1]];

/// [`DATA_SET_EXTENSIONS`] as a message lists them: `.png, .r16, .raw`.
pub fn data_set_extensions() -> String {
    let dotted: Vec<String> = DATA_SET_EXTENSIONS
        .iter()
        .map(|e| format!(".{e}"))
        .collect();
    dotted.join(", ")
}

/// Loads an 8- or 16-bit grayscale PNG heightmap, ours or a terrain tool's,
/// or raw 16-bit samples (a `.r16` or `.raw` file that is not a PNG).
///
/// Only a regular file is read (a FIFO would block): see `fsutil::open_regular`.
/// The file is streamed: memory is the fitted grid, never the whole image.
/// `-` is standard input (`heightmap -o - | mountains --open -`), read
/// whole, at most [`MAX_FILE_BYTES`]: a PNG, or else raw samples.
pub fn load(path: &Path) -> Result<DataSet, HeightmapError> {
    let io = |e: std::io::Error| {
        HeightmapError::new(path, ErrorKind::Io, crate::fsutil::cannot_read(&e))
    };
    if path == Path::new("-") {
        use std::io::IsTerminal;
        if std::io::stdin().is_terminal() {
            let problem = "is standard input, a terminal: pipe a data set in \
                           (mountains heightmap -o - | mountains --open -)";
            return Err(HeightmapError::new(path, ErrorKind::Io, problem));
        }
        let mut bytes = Vec::new();
        let stdin = std::io::stdin().lock();
        stdin
            .take(MAX_FILE_BYTES + 1)
            .read_to_end(&mut bytes)
            .map_err(io)?;
        return load_bytes(&bytes, path);
    }
    let file = crate::fsutil::open_regular(path, MAX_FILE_BYTES).map_err(io)?;
    let len = file.metadata().map_err(io)?.len();
    let mut input = std::io::BufReader::new(file);
    if raw::is_raw(path) && !decode::starts_as_png(&mut input).map_err(io)? {
        return raw_data_set(raw::read(input, len, path)?, path);
    }
    let raw = decode::read(input, len, path)?;
    finish(raw, path)
}

/// A data set from `bytes` (a PNG, or else raw samples) that `path`
/// names in messages.
fn load_bytes(bytes: &[u8], path: &Path) -> Result<DataSet, HeightmapError> {
    let len = bytes.len() as u64;
    if len > MAX_FILE_BYTES {
        let problem = format!(
            "holds over {} MiB; a data set is smaller",
            MAX_FILE_BYTES >> 20
        );
        return Err(HeightmapError::new(path, ErrorKind::TooLarge, problem));
    }
    if len == 0 {
        let problem = "is empty: nothing was piped in";
        return Err(HeightmapError::new(path, ErrorKind::NotPng, problem));
    }
    if decode::starts_as_png(&mut std::io::Cursor::new(bytes)).unwrap_or(false) {
        return decode(bytes, path);
    }
    // Not a PNG: say so beside what the raw reading found wrong.
    let grid = raw::read(bytes, len, path).map_err(|mut e| {
        if e.kind == ErrorKind::NotRaw {
            e.problem = e
                .problem
                .replacen("not a raw", "neither a PNG nor a raw", 1);
        }
        e
    })?;
    raw_data_set(grid, path)
}

/// The data set of the raw samples in `grid`, read from `path`, with a
/// note of how they were read.
fn raw_data_set(grid: RawGrid, path: &Path) -> Result<DataSet, HeightmapError> {
    let side = grid.fit.source_width;
    let mut data = finish(grid, path)?;
    data.notes.insert(0, raw::note(side));
    Ok(data)
}

/// Decodes PNG `bytes`; `path` only names the file in messages.
pub fn decode(bytes: &[u8], path: &Path) -> Result<DataSet, HeightmapError> {
    let raw = decode::read(std::io::Cursor::new(bytes), bytes.len() as u64, path)?;
    finish(raw, path)
}

fn finish(raw: RawGrid, path: &Path) -> Result<DataSet, HeightmapError> {
    let meta = meta::parse(&raw.text, path)?;
    to_dataset(raw, meta, path)
}

/// Turns samples into heights relative to sea level, filling in missing keys.
fn to_dataset(raw: RawGrid, mut meta: Metadata, path: &Path) -> Result<DataSet, HeightmapError> {
    let RawGrid {
        fit,
        bit_depth,
        mut samples,
        ..
    } = raw;
    let mut notes = std::mem::take(&mut meta.notes);
    if fit.method != FitMethod::Exact || fit.cropped() {
        notes.push(format!("fitted: {fit}"));
    }
    if bit_depth == 8 {
        soften::soften_steps(&mut samples, fit.size);
        notes.push("8-bit: steps between levels softened into slopes".into());
    }
    let v = Vertical::choose(&samples, &meta, &mut notes);
    let (lo, hi) = quantise::min_max(&samples);
    if !(v.height(lo).is_finite() && v.height(hi).is_finite()) {
        return Err(HeightmapError::metadata(
            path,
            meta::KEY_SCALE,
            "with mountains:offset and mountains:sea_level, gives heights too large to hold",
        ));
    }
    samples.iter_mut().for_each(|s| *s = v.height(*s));
    quantise::snap_to_grid(&mut samples);
    let mut field = Heightfield::from_heights(fit.size, v.extent, samples)
        .ok_or_else(|| HeightmapError::new(path, ErrorKind::Damaged, "fits no grid size"))?;
    // A saved mountain keeps its seed's scene (light, sea) when opened.
    field.set_seed(meta.seed);
    let drawn = field.drawn_scale();
    if drawn < 1.0 {
        notes.push(format!(
            "land and sea span {:.3} times the width: drawn {MAX_DRAWN_RELIEF} times as tall \
             (see mountains:scale, mountains:sea_level, mountains:extent)",
            MAX_DRAWN_RELIEF / drawn
        ));
    }
    Ok(DataSet {
        field,
        seed: meta.seed,
        params: meta.params,
        fit,
        bit_depth,
        scale: v.scale,
        offset: v.offset,
        sea_level: v.sea_level,
        notes,
    })
}

/// How samples become heights: the file's keys, or the documented defaults.
struct Vertical {
    extent: f32,
    scale: f64,
    offset: f32,
    sea_level: f32,
}

impl Vertical {
    /// Takes each key from `meta` or, noting it, from the defaults.
    fn choose(samples: &[f32], meta: &Metadata, notes: &mut Vec<String>) -> Vertical {
        let (lo, hi) = quantise::min_max(samples);
        let extent = meta.extent.unwrap_or_else(|| {
            notes.push(format!(
                "no mountains:extent: width {DEFAULT_EXTENT} assumed"
            ));
            DEFAULT_EXTENT
        });
        let scale = meta.scale.unwrap_or_else(|| {
            notes.push(format!(
                "no mountains:scale: relief set to {DEFAULT_RELIEF} of the width"
            ));
            natural_scale(lo, hi, extent)
        });
        let offset = meta.offset.unwrap_or(0.0);
        let sea_level = meta.sea_level.unwrap_or_else(|| {
            notes.push(format!(
                "no mountains:sea_level: water line at the {SEA_PERCENTILE}th percentile \
                 of the heights"
            ));
            (f64::from(offset) + scale * sea_sample(samples, lo)) as f32
        });
        Vertical {
            extent,
            scale,
            offset,
            sea_level,
        }
    }

    /// Height above sea level of sample value `s`.
    fn height(&self, s: f32) -> f32 {
        let elevation = f64::from(self.offset) + self.scale * f64::from(s);
        (elevation - f64::from(self.sea_level)) as f32
    }
}

/// Scale that makes the relief `DEFAULT_RELIEF` of `extent`.
fn natural_scale(lo: f32, hi: f32, extent: f32) -> f64 {
    if hi > lo {
        f64::from(DEFAULT_RELIEF * extent) / f64::from(hi - lo)
    } else {
        1.0
    }
}

/// The sample value at the sea percentile, at least half a step above `lo`.
fn sea_sample(samples: &[f32], lo: f32) -> f64 {
    let top = quantise::MAX_SAMPLE;
    let mut histogram = vec![0u32; usize::from(top) + 1];
    for &s in samples {
        histogram[s.floor().clamp(0.0, f32::from(top)) as usize] += 1;
    }
    let wanted = (samples.len() as f64 * SEA_PERCENTILE / 100.0).ceil() as u64;
    let mut seen = 0u64;
    let mut level = 0usize;
    for (value, &count) in histogram.iter().enumerate() {
        seen += u64::from(count);
        if seen >= wanted {
            level = value;
            break;
        }
    }
    (level as f64).max(f64::from(lo) + 0.5)
}

/// Resamples `field` to `2^exponent + 1` points a side with the same linear
/// filter loading uses (e.g. to show a big data set at the detail setting).
///
/// Panics if `exponent` is outside the range `Heightfield::flat` accepts.
pub fn refit(field: &Heightfield, exponent: u32) -> Heightfield {
    let side = field.size();
    let mut out = Heightfield::flat(exponent, field.extent());
    out.set_seed(field.seed());
    if out.size() == side {
        return field.clone();
    }
    let plan = Fit {
        source_width: side as u32,
        source_height: side as u32,
        crop_x: 0,
        crop_y: 0,
        crop_side: side as u32,
        size: out.size(),
        method: FitMethod::Resampled,
    };
    let mut grid = Resampler::new(plan);
    for y in 0..side {
        grid.push_row(y as u32, field.row(y).iter().copied());
    }
    out.heights_mut().copy_from_slice(&grid.finish());
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn problem(bytes: &[u8]) -> String {
        let e = load_bytes(bytes, Path::new("-")).expect_err("refused");
        e.problem
    }

    #[test]
    fn piped_bytes_are_a_png_or_else_raw_samples() {
        let mut field = Heightfield::flat(4, 100.0);
        field.set(3, 3, 9.0);
        let (raw, _) = raw16(&field);
        let from_raw = load_bytes(&raw, Path::new("-")).unwrap();
        assert_eq!(from_raw.field.size(), 17);
        assert!(from_raw.notes[0].starts_with("raw 16-bit samples"));
        let png = encode(&field, Some(5), &Settings::default(), Path::new("x.png")).unwrap();
        assert_eq!(load_bytes(&png, Path::new("-")).unwrap().seed, Some(5));
    }

    #[test]
    fn piped_bytes_of_neither_kind_say_so() {
        assert!(problem(b"").contains("nothing was piped in"));
        let short = problem(b"abc");
        assert!(
            short.contains("is 3 bytes, neither a PNG nor a raw"),
            "{short}"
        );
        // A square of bytes keeps the raw reading's 8-bit hint.
        let square = problem(&[7; 9]);
        assert!(square.contains("neither a PNG nor a raw"), "{square}");
        assert!(square.contains("3x3 8-bit samples"), "{square}");
    }
}
