//! Where preferences, logs and saved data sets live on this platform.

use std::path::PathBuf;

fn project_dirs() -> Option<directories::ProjectDirs> {
    directories::ProjectDirs::from("", "", "mountains")
}

/// The preferences file, e.g. `~/.config/mountains/mountains.toml`.
pub fn config_file() -> Option<PathBuf> {
    project_dirs().map(|d| d.config_dir().join("mountains.toml"))
}

/// The data directory for the log, saved data sets and screenshots,
/// e.g. `~/.local/share/mountains`.
pub fn data_dir() -> Option<PathBuf> {
    project_dirs().map(|d| d.data_dir().to_path_buf())
}
