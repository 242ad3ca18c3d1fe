//! Where preferences, logs and saved data sets live on this platform.

use std::path::{PathBuf, is_separator};

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

/// The folder `heightmaps_dir` names (`text`; empty or none: no folder),
/// a leading `~` read as the home folder as a shell reads it: the file is
/// written by hand, and no shell ever sees it (`~/maps` was looked for in
/// a folder named `~`).
pub fn heightmaps_folder(text: Option<&str>) -> Option<PathBuf> {
    text.filter(|t| !t.is_empty()).map(folder)
}

/// A folder a person named, `~` read as [`heightmaps_folder`] says.
fn folder(text: &str) -> PathBuf {
    let home = directories::BaseDirs::new().map(|b| b.home_dir().to_path_buf());
    match (text.strip_prefix('~'), home) {
        (Some(rest), Some(home)) if rest.is_empty() || rest.starts_with(is_separator) => {
            home.join(rest.trim_start_matches(is_separator))
        }
        _ => PathBuf::from(text),
    }
}
