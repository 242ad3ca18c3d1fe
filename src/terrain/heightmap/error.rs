//! The one error type of data-set reading and writing.

use std::fmt;
use std::path::{Path, PathBuf};

/// Which kind of problem a [`HeightmapError`] reports, for callers that react
/// differently (e.g. a slide show skips a foreign file but reports a bug).
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum ErrorKind {
    /// The file could not be read or written.
    Io,
    /// The bytes do not start with the PNG signature.
    NotPng,
    /// A raw heightmap (`.r16`, `.raw`) whose length is no square of
    /// 16-bit samples.
    NotRaw,
    /// The file ends before the image is complete.
    Truncated,
    /// The PNG structure is broken (bad CRC, bad chunk, bad compressed data).
    Damaged,
    /// Colour, palette or gray+alpha where plain grayscale is expected.
    NotGrayscale,
    /// Grayscale of 1, 2 or 4 bits: too few levels to be a heightmap.
    BitDepth,
    /// More pixels than we are willing to hold.
    TooLarge,
    /// Too few pixels to be a heightmap.
    TooSmall,
    /// A `mountains:` text chunk holds a value we cannot use; names the key.
    Metadata(String),
    /// The heightfield given to `save` cannot be stored (NaN, bad extent).
    BadField,
}

/// Why a heightmap could not be read or written.
#[derive(Debug)]
pub struct HeightmapError {
    /// The file concerned.
    pub path: PathBuf,
    /// What was wrong, for a person.
    pub problem: String,
    /// What was wrong, for a program.
    pub kind: ErrorKind,
}

impl HeightmapError {
    /// An error about `path`.
    pub(crate) fn new(path: &Path, kind: ErrorKind, problem: impl Into<String>) -> Self {
        HeightmapError {
            path: path.to_path_buf(),
            problem: problem.into(),
            kind,
        }
    }

    /// An error about the value of one metadata key.
    pub(crate) fn metadata(path: &Path, key: &str, problem: impl fmt::Display) -> Self {
        HeightmapError::new(
            path,
            ErrorKind::Metadata(key.to_string()),
            format!("{key}: {problem}"),
        )
    }
}

impl fmt::Display for HeightmapError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.path.display(), self.problem)
    }
}

impl std::error::Error for HeightmapError {}
