//! Where preferences, logs and saved data sets live on this platform.

use std::path::{Path, PathBuf, is_separator};

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

/// A folder named in the preferences file `file` (`text`): a relative
/// one is the file's neighbour. The saver is started wherever its host
/// chooses (xscreensaver in the home folder, Windows in System32), and
/// `--check-config` from any folder: `heightmaps_dir = "maps"` was looked
/// for in each one's own. Empty, `~` and absolute names are kept, and so
/// is a name whose folder cannot be written as text.
pub fn beside(text: &str, file: &Path) -> String {
    let parent = file.parent().filter(|p| !p.as_os_str().is_empty());
    let kept = text.is_empty() || text.starts_with('~') || Path::new(text).is_absolute();
    match parent {
        Some(parent) if !kept => parent.join(text).to_str().unwrap_or(text).to_string(),
        _ => text.to_string(),
    }
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_relative_folder_is_the_preferences_files_neighbour() {
        let file = Path::new("/home/me/.config/mountains/mountains.toml");
        let beside_it = |text| beside(text, file);
        assert_eq!(beside_it("maps"), "/home/me/.config/mountains/maps");
        assert_eq!(beside_it("../maps"), "/home/me/.config/mountains/../maps");
        for kept in ["", "~/maps", "~", "/srv/maps"] {
            assert_eq!(beside_it(kept), kept);
        }
        // A file named without a folder is in the current one, as is its
        // neighbour.
        assert_eq!(beside("maps", Path::new("m.toml")), "maps");
    }
}
