//! Finding data sets to open. No file dialog toolkit: Open lists the PNG
//! files of the data directory and of `heightmaps_dir`. (Saving and its
//! file names are `crate::saved`'s, shared with the window mode.)

use std::path::{Path, PathBuf};

/// At most this many files are listed from one folder.
const MAX_LISTED: usize = 500;

/// The folders Open looks in: the data directory, then `heightmaps_dir`.
pub fn folders(data_dir: Option<&Path>, heightmaps_dir: Option<&str>) -> Vec<PathBuf> {
    let mut out: Vec<PathBuf> = data_dir.map(Path::to_path_buf).into_iter().collect();
    if let Some(d) = heightmaps_dir.filter(|d| !d.is_empty()) {
        let d = PathBuf::from(d);
        if !out.contains(&d) {
            out.push(d);
        }
    }
    out
}

/// The `.png` files directly in `folders`, sorted by name within each
/// folder. Folders that cannot be read are skipped.
pub fn list_pngs(folders: &[PathBuf]) -> Vec<PathBuf> {
    let mut all = Vec::new();
    for dir in folders {
        let Ok(entries) = std::fs::read_dir(dir) else {
            continue;
        };
        let mut found: Vec<PathBuf> = entries
            .filter_map(Result::ok)
            .map(|e| e.path())
            .filter(|p| p.is_file() && is_png(p))
            .take(MAX_LISTED)
            .collect();
        found.sort();
        all.extend(found);
    }
    all
}

fn is_png(p: &Path) -> bool {
    p.extension()
        .and_then(|e| e.to_str())
        .is_some_and(|e| e.eq_ignore_ascii_case("png"))
}
