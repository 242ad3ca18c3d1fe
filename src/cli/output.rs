//! What `-o FILE` writes, from its extension: pictures as PNG or JPEG, data
//! sets as a 16-bit PNG or as the raw 16-bit samples terrain tools import
//! (`.r16`, `.raw`). Anything else is refused before any work is done.

use std::path::Path;

use super::UsageError;
use crate::terrain::heightmap::RAW_EXTENSIONS;

/// A file type `-o` can write.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Format {
    /// PNG (8-bit RGB pictures, 16-bit gray data sets).
    Png,
    /// JPEG, quality 90 (pictures).
    Jpeg,
    /// Little-endian 16-bit samples, row by row from the back (data sets).
    Raw16,
}

/// Extensions and formats `render -o` writes.
pub const PICTURES: &[(&str, Format)] = &[
    ("png", Format::Png),
    ("jpg", Format::Jpeg),
    ("jpeg", Format::Jpeg),
];

/// Extensions and formats `heightmap -o` writes: every data set `--open`
/// reads (a test holds the two lists alike).
pub const DATA_SETS: &[(&str, Format)] = &[
    ("png", Format::Png),
    (RAW_EXTENSIONS[0], Format::Raw16),
    (RAW_EXTENSIONS[1], Format::Raw16),
];

/// The format `path`'s extension names among `allowed` (no extension: PNG).
pub fn format_of(
    path: &Path,
    allowed: &[(&str, Format)],
    what: &str,
) -> Result<Format, UsageError> {
    let Some(ext) = path.extension() else {
        return Ok(Format::Png);
    };
    let ext = ext.to_string_lossy().to_ascii_lowercase();
    allowed
        .iter()
        .find(|(e, _)| *e == ext)
        .map(|&(_, f)| f)
        .ok_or_else(|| {
            let names: Vec<String> = allowed.iter().map(|(e, _)| format!(".{e}")).collect();
            // `x.png.` has an empty extension: "written as ." said nothing.
            let why = match ext.is_empty() {
                true => "nothing after its last dot names a type".to_string(),
                false => format!("{what} cannot be written as .{ext}"),
            };
            UsageError(format!(
                "-o {}: {why}; use {}",
                path.display(),
                names.join(", ")
            ))
        })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `heightmap -o` writes every kind of data set `--open` reads, and no
    /// other: the two lists are one list.
    #[test]
    fn the_data_sets_written_are_those_read() {
        let written: Vec<&str> = DATA_SETS.iter().map(|(e, _)| *e).collect();
        assert_eq!(written, crate::terrain::heightmap::DATA_SET_EXTENSIONS);
    }
}
