//! Saved data sets and screenshots: where they go, what they are called, and
//! finding them again. One scheme for the window mode (S, P, O keys), the
//! settings screen (Save, Open) and the slide show's `heightmaps_dir`.

use std::path::{Path, PathBuf};

use crate::render::Frame;
use crate::settings::Settings;
use crate::terrain::{Heightfield, heightmap};

/// A readable file stem in local time: `mountain-2026-11-22-023512-seed-42`.
pub fn file_stem(unix_seconds: u64, seed: Option<u64>) -> String {
    stem_at(&crate::clock::local_plain(unix_seconds), seed)
}

/// The stem for a `YYYY-MM-DD HH:MM:SS` time.
fn stem_at(when: &str, seed: Option<u64>) -> String {
    let (date, time) = when.split_once(' ').unwrap_or((when, ""));
    let time: String = time.chars().filter(char::is_ascii_digit).collect();
    match seed {
        Some(seed) => format!("mountain-{date}-{time}-seed-{seed}"),
        None => format!("mountain-{date}-{time}"),
    }
}

/// A path in `dir` for `stem` + `suffix` (e.g. `.png`) that names
/// nothing there, a link to nowhere included (`fsutil::taken`: a save
/// refuses to write through one): `stem.png`, else `stem-2.png`,
/// `stem-3.png` ...
pub fn free_path(dir: &Path, stem: &str, suffix: &str) -> Option<PathBuf> {
    (1..100)
        .map(|n| match n {
            1 => dir.join(format!("{stem}{suffix}")),
            n => dir.join(format!("{stem}-{n}{suffix}")),
        })
        .find(|p| !crate::fsutil::taken(p))
}

/// A new file name in `dir` (created if missing) for something saved now.
pub fn new_path(dir: &Path, suffix: &str, seed: Option<u64>) -> Result<PathBuf, String> {
    if dir.is_file() {
        return Err(format!(
            "{}: is a file, so nothing can be saved in it (move it, or choose another folder)",
            dir.display()
        ));
    }
    std::fs::create_dir_all(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    free_path(dir, &file_stem(crate::clock::now(), seed), suffix)
        .ok_or_else(|| format!("{}: too many files with the same name", dir.display()))
}

/// Saves `field` as a data set (16-bit PNG with our metadata) in `dir`; returns where.
pub fn save_data_set(
    dir: &Path,
    field: &Heightfield,
    seed: Option<u64>,
    settings: &Settings,
) -> Result<PathBuf, String> {
    let path = new_path(dir, ".png", seed)?;
    heightmap::save(&path, field, seed, settings).map_err(|e| e.to_string())?;
    Ok(path)
}

/// Saves `frame` as a PNG screenshot in the `screenshots` folder of `dir`
/// (kept apart so Open, which lists `dir`, offers only data sets); returns where.
pub fn save_screenshot(dir: &Path, frame: &Frame, seed: Option<u64>) -> Result<PathBuf, String> {
    let path = new_path(&dir.join("screenshots"), "-screenshot.png", seed)?;
    crate::snapshot::write_png(&path, frame)?;
    Ok(path)
}

/// At most this many folder entries are looked at: a huge folder must not
/// stall the slide show or the settings screen.
const MAX_ENTRIES: usize = 10_000;

/// The folders saved data sets are looked for in: the data directory, then
/// `heightmaps_dir` (empty = none; `~` is the home folder), without repeats.
pub fn folders(data_dir: Option<&Path>, heightmaps_dir: Option<&str>) -> Vec<PathBuf> {
    let mut out: Vec<PathBuf> = data_dir.map(Path::to_path_buf).into_iter().collect();
    if let Some(d) = crate::settings::paths::heightmaps_folder(heightmaps_dir)
        && !out.contains(&d)
    {
        out.push(d);
    }
    out
}

/// The data sets (`.png`, and raw `.r16` and `.raw`) directly in
/// `folders`, sorted by name within each folder. Folders that cannot be
/// read are skipped.
pub fn list_data_sets(folders: &[PathBuf]) -> Vec<PathBuf> {
    let mut all = Vec::new();
    for dir in folders {
        let Ok(entries) = std::fs::read_dir(dir) else {
            continue;
        };
        let mut found: Vec<PathBuf> = entries
            .take(MAX_ENTRIES)
            .filter_map(Result::ok)
            .map(|e| e.path())
            .filter(|p| p.is_file() && heightmap::named_as_data_set(p))
            .collect();
        found.sort();
        all.extend(found);
    }
    all
}

/// The data set after `current` in `files` (the first if `current` is not
/// among them), wrapping round: what Open shows next.
pub fn next_after<'a>(files: &'a [PathBuf], current: Option<&Path>) -> Option<&'a PathBuf> {
    let at = current.and_then(|c| files.iter().position(|f| f == c));
    match at {
        Some(i) => files.get((i + 1) % files.len()),
        None => files.first(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `heightmaps_dir = "~/maps"` is the maps in the home folder, as a
    /// shell would read it; a `~` inside a name is a `~`.
    #[test]
    fn a_leading_tilde_is_the_home_folder() {
        let Some(home) = directories::BaseDirs::new().map(|b| b.home_dir().to_path_buf()) else {
            return;
        };
        assert_eq!(folders(None, Some("~")), [home.join("")]);
        assert_eq!(folders(None, Some("~/maps")), [home.join("maps")]);
        assert_eq!(folders(None, Some("a~/b")), [PathBuf::from("a~/b")]);
        assert_eq!(folders(None, Some("~user/b")), [PathBuf::from("~user/b")]);
    }

    #[test]
    fn a_link_to_nowhere_is_no_free_name() {
        let dir = std::env::temp_dir().join(format!("mountains-free-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let link = dir.join("m.png");
        let _ = std::fs::remove_file(&link);
        #[cfg(unix)]
        std::os::unix::fs::symlink(dir.join("gone").join("m.png"), &link).unwrap();
        #[cfg(not(unix))]
        std::fs::write(&link, b"").unwrap();
        assert_eq!(free_path(&dir, "m", ".png"), Some(dir.join("m-2.png")));
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    fn file_names_hold_local_date_time_and_seed() {
        assert_eq!(
            stem_at("1970-01-01 00:00:00", Some(7)),
            "mountain-1970-01-01-000000-seed-7"
        );
        assert_eq!(
            stem_at("2026-11-22 02:35:12", None),
            "mountain-2026-11-22-023512"
        );
        // The stem of a moment is its local time.
        let t = 1_795_314_912;
        let local = crate::clock::local_plain(t)
            .replace(' ', "-")
            .replace(':', "");
        assert_eq!(file_stem(t, None), format!("mountain-{local}"));
    }

    #[test]
    fn a_data_folder_that_is_a_file_is_named_as_such() {
        let file =
            std::env::temp_dir().join(format!("mountains-not-a-folder-{}", std::process::id()));
        std::fs::write(&file, "x").unwrap();
        let e = new_path(&file, ".png", Some(1)).unwrap_err();
        assert!(
            e.ends_with(
                "is a file, so nothing can be saved in it (move it, or choose another folder)"
            ),
            "{e}"
        );
        let _ = std::fs::remove_file(&file);
    }

    #[test]
    fn free_path_never_names_an_existing_file() {
        let dir = std::env::temp_dir().join(format!("mountains-free-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::write(dir.join("a.png"), b"x").unwrap();
        let p = free_path(&dir, "a", ".png").unwrap();
        assert_eq!(p, dir.join("a-2.png"));
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn next_after_cycles_and_starts_at_the_first() {
        let files: Vec<PathBuf> = ["a.png", "b.png"].iter().map(PathBuf::from).collect();
        assert_eq!(next_after(&files, None), Some(&files[0]));
        assert_eq!(
            next_after(&files, Some(Path::new("a.png"))),
            Some(&files[1])
        );
        assert_eq!(
            next_after(&files, Some(Path::new("b.png"))),
            Some(&files[0])
        );
        assert_eq!(
            next_after(&files, Some(Path::new("gone.png"))),
            Some(&files[0])
        );
        assert_eq!(next_after(&[], None), None);
    }
}
