//! Where each slide's mountain comes from: a fresh generation, or now and
//! then a heightmap from the user's `heightmaps_dir`.

use std::path::Path;

use crate::mountain::Mountain;
use crate::settings::Settings;

/// True when slide number `slide` shows a heightmap from the folder:
/// every other slide, so generated and saved mountains alternate.
pub fn slide_uses_folder(slide: u64) -> bool {
    slide % 2 == 1
}

/// The mountain for slide number `slide`: from the heightmap folder on
/// alternate slides when one is set and holds a readable data set, else generated.
pub fn next_mountain(settings: &Settings, slide: u64) -> Mountain {
    let folder = crate::settings::paths::heightmaps_folder(settings.heightmaps_dir.as_deref());
    if let Some(dir) = folder.filter(|_| slide_uses_folder(slide))
        && let Some(mountain) = random_heightmap(&dir)
    {
        return mountain;
    }
    let mountain = Mountain::generate(settings);
    // The making's working copies are gone; the hold keeps only the heights.
    crate::memory::give_back_free_pages();
    mountain
}

/// Distinct warnings remembered at most, so the list stays bounded.
const MAX_WARNINGS: usize = 10_000;

/// Warns about each problem once: the slide show meets the same bad file
/// or empty folder again and again, and the log must not grow without end.
fn warn_once(message: String) {
    static SEEN: std::sync::Mutex<Vec<String>> = std::sync::Mutex::new(Vec::new());
    let mut seen = SEEN.lock().unwrap_or_else(|e| e.into_inner());
    if seen.contains(&message) || seen.len() >= MAX_WARNINGS {
        return;
    }
    crate::log::warn(&message);
    seen.push(message);
}

fn random_heightmap(dir: &Path) -> Option<Mountain> {
    let files = crate::saved::list_data_sets(&[dir.to_path_buf()]);
    if files.is_empty() {
        warn_once(format!(
            "{}: no heightmaps ({}) to show; generating instead",
            dir.display(),
            crate::terrain::heightmap::data_set_extensions()
        ));
        return None;
    }
    let pick = &files[rand::random_range(0..files.len())];
    match Mountain::open(pick) {
        Ok((mountain, _notes)) => Some(mountain),
        Err(e) => {
            warn_once(format!("{e}; generating instead"));
            None
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::settings::Detail;
    use crate::terrain::{Heightfield, heightmap};
    use std::path::PathBuf;

    fn folder(name: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("mountains-src-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        dir
    }

    #[test]
    fn lists_only_data_sets_sorted() {
        let dir = folder("list");
        for name in ["b.png", "a.PNG", "notes.txt", "c.png.tmp", "e.r16", "f.RAW"] {
            std::fs::write(dir.join(name), b"x").unwrap();
        }
        std::fs::create_dir(dir.join("d.png")).unwrap();
        let names: Vec<_> = crate::saved::list_data_sets(std::slice::from_ref(&dir))
            .iter()
            .map(|p| p.file_name().unwrap().to_string_lossy().into_owned())
            .collect();
        assert_eq!(names, ["a.PNG", "b.png", "e.r16", "f.RAW"]);
        assert!(crate::saved::list_data_sets(&[dir.join("missing")]).is_empty());
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn alternate_slides_come_from_the_folder() {
        let dir = folder("alternate");
        let mut field = Heightfield::flat(4, 100.0);
        field.set(5, 5, 33.0);
        let settings = Settings {
            detail: Detail::Level(5),
            heightmaps_dir: Some(dir.to_string_lossy().into_owned()),
            ..Settings::default()
        };
        heightmap::save(&dir.join("saved.png"), &field, Some(99), &settings).unwrap();
        let loaded = next_mountain(&settings, 1);
        assert_eq!(loaded.seed, Some(99));
        assert_eq!(loaded.field.size(), 17);
        let generated = next_mountain(&settings, 2);
        assert_eq!(generated.field.size(), 33);
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn a_raw_heightmap_in_the_folder_is_shown_too() {
        let dir = folder("raw");
        let mut field = Heightfield::flat(4, 100.0);
        field.set(5, 5, 33.0);
        std::fs::write(dir.join("tool.r16"), heightmap::raw16(&field).0).unwrap();
        let settings = Settings {
            detail: Detail::Level(5),
            heightmaps_dir: Some(dir.to_string_lossy().into_owned()),
            ..Settings::default()
        };
        let loaded = next_mountain(&settings, 1);
        // The tool's 17x17 grid, its one peak where it was.
        assert_eq!(loaded.field.size(), 17);
        let peak = loaded.field.get(5, 5);
        assert!(peak > loaded.field.get(4, 5) && peak > loaded.field.get(5, 4));
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn a_broken_file_or_empty_folder_falls_back_to_generating() {
        let dir = folder("broken");
        let settings = Settings {
            detail: Detail::Level(5),
            heightmaps_dir: Some(dir.to_string_lossy().into_owned()),
            ..Settings::default()
        };
        assert_eq!(next_mountain(&settings, 1).field.size(), 33);
        std::fs::write(dir.join("junk.png"), b"not a png").unwrap();
        assert_eq!(next_mountain(&settings, 1).field.size(), 33);
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
