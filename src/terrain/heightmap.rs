//! Data sets on disk: 16-bit grayscale PNG heightmaps with our metadata.
//!
//! STUB with the final signatures; the data-set work replaces the bodies.

use std::fmt;
use std::path::{Path, PathBuf};

use super::Heightfield;
use crate::settings::Settings;

/// A heightfield loaded from disk, with what its file said about it.
#[derive(Debug, Clone)]
pub struct DataSet {
    /// The heights, fitted to a `2^n + 1` grid, sea level at 0.
    pub field: Heightfield,
    /// The seed that generated it, when the file says.
    pub seed: Option<u64>,
}

/// Why a heightmap could not be read or written.
#[derive(Debug)]
pub struct HeightmapError {
    /// The file concerned.
    pub path: PathBuf,
    /// What was wrong, for a person.
    pub problem: String,
}

impl fmt::Display for HeightmapError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.path.display(), self.problem)
    }
}

impl std::error::Error for HeightmapError {}

/// Saves `field` as a 16-bit grayscale PNG with the seed and settings in text chunks.
pub fn save(
    path: &Path,
    _field: &Heightfield,
    _seed: Option<u64>,
    _settings: &Settings,
) -> Result<(), HeightmapError> {
    Err(HeightmapError {
        path: path.to_path_buf(),
        problem: "saving is not written yet".into(),
    })
}

/// Loads an 8- or 16-bit grayscale PNG heightmap, ours or a terrain tool's.
pub fn load(path: &Path) -> Result<DataSet, HeightmapError> {
    Err(HeightmapError {
        path: path.to_path_buf(),
        problem: "loading is not written yet".into(),
    })
}
