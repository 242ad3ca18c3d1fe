//! A mountain to show: heights, and the seed that made them. The one way
//! from a data set on disk, or from a seed, to something drawn: the slide
//! show, the settings screen's preview and the one-shot commands all use it.

use std::path::Path;
use std::sync::Arc;

use crate::settings::keys::{self, Key};
use crate::settings::{Detail, Settings};
use crate::terrain::heightmap::{self, DataSet, GeneratorParams};
use crate::terrain::{self, Heightfield};

/// The keys that only shape the heights a generator makes. A data set
/// opened from a file has its heights already, so `render --open` and
/// `heightmap --open` draw and save it the same whatever these say (the
/// saver's N key, which makes a new mountain after `--open`, still uses
/// them). The others are drawn under: the look, the world, the height's
/// treeline, the cliffs' strata, low detail's wireframe.
pub const HEIGHTS_ONLY: [&Key; 12] = [
    &keys::SEED,
    &keys::GENERATOR,
    &keys::CRAGGINESS,
    &keys::ELEVATION,
    &keys::ROUGHNESS,
    &keys::CONTOUR,
    &keys::PROFILE,
    &keys::HURST,
    &keys::EROSION,
    &keys::DETAIL,
    &keys::SEA_LEVEL,
    &keys::WATER_LINE,
];

/// A mountain ready to draw and the seed that made it (none for a foreign heightmap).
#[derive(Debug, Clone)]
pub struct Mountain {
    /// The heights.
    pub field: Arc<Heightfield>,
    /// The seed that generated them, when known.
    pub seed: Option<u64>,
    /// Made here from `seed` (not read from a file), so it can be made
    /// again, e.g. at another detail.
    pub generated: bool,
    /// The keys a data set's file recorded (its look and generator
    /// parameters), drawn under the person's preferences: see
    /// [`Mountain::drawn_with`]. `None` when generated here, or for a file
    /// that records none (a terrain tool's).
    pub recorded: Option<GeneratorParams>,
}

impl Mountain {
    /// A data set read from a file: shown as it is, never made again.
    pub fn loaded(data: DataSet) -> Self {
        Mountain {
            field: Arc::new(data.field),
            seed: data.seed,
            generated: false,
            recorded: data.params,
        }
    }

    /// Generates a mountain from `settings`, with its seed or a fresh random one.
    pub fn generate(settings: &Settings) -> Self {
        Mountain::from_seed(settings, settings.next_seed())
    }

    /// The mountain of `seed` under `settings`.
    pub fn from_seed(settings: &Settings, seed: u64) -> Self {
        Mountain {
            field: Arc::new(terrain::generate(settings, seed)),
            seed: Some(seed),
            generated: true,
            recorded: None,
        }
    }

    /// The settings this mountain is drawn with under the preferences
    /// `prefs`: for a data set, the keys its file recorded where `prefs`
    /// leaves them at their defaults, so a set saved under a look (or a
    /// height) comes back as the picture it was
    /// ([`GeneratorParams::drawn_under`]); `prefs` themselves otherwise.
    pub fn drawn_with(&self, prefs: &Settings) -> Settings {
        Mountain::drawn_under(self.recorded.as_ref(), prefs)
    }

    /// The settings this mountain is saved with under `prefs` (what a data
    /// set records): as [`Mountain::drawn_with`], but a data set read from
    /// a file keeps its file's record of how its heights were made
    /// ([`HEIGHTS_ONLY`]), which `prefs` made nothing of here, and the
    /// detail is always the grid's own (`--set detail=5` recorded on a grid
    /// of another size would be false).
    pub fn saved_with(&self, prefs: &Settings) -> Settings {
        let mut saved = match self.generated {
            true => prefs.clone(),
            false => {
                let mut made = prefs.clone();
                let defaults = Settings::default();
                for key in HEIGHTS_ONLY {
                    keys::copy(key, &defaults, &mut made);
                }
                Mountain::drawn_under(self.recorded.as_ref(), &made)
            }
        };
        // The grid may not be the one the settings say: a 9x9 set is read
        // fitted to 17x17, "auto" fits a window, a preview is smaller.
        // `low_detail` is kept as it is: it draws the wireframe's cells.
        let exponent = self.field.exponent();
        if saved.grid_exponent() != exponent {
            saved.detail = Detail::Level(saved.detail_for_grid(exponent));
        }
        saved
    }

    /// The settings a mountain whose file recorded `recorded` is drawn with
    /// under `prefs` (see [`Mountain::drawn_with`]), for those that keep
    /// only what the file recorded.
    pub fn drawn_under(recorded: Option<&GeneratorParams>, prefs: &Settings) -> Settings {
        match recorded {
            Some(recorded) => recorded.drawn_under(prefs),
            None => prefs.clone(),
        }
    }

    /// The data set at `path`, and the notes its reading left (values it
    /// set aside), for the caller to pass on; the message names the file.
    pub fn open(path: &Path) -> Result<(Self, Vec<String>), String> {
        let mut data = heightmap::load(path).map_err(|e| e.to_string())?;
        let notes = std::mem::take(&mut data.notes);
        Ok((Mountain::loaded(data), notes))
    }

    /// `--open`'s data set if given, else a generated mountain.
    pub fn open_or_generate(
        settings: &Settings,
        open: Option<&Path>,
    ) -> Result<(Self, Vec<String>), String> {
        match open {
            Some(path) => Mountain::open(path),
            None => Ok((Mountain::generate(settings), Vec::new())),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::settings::Detail;

    /// The heights-only keys and the key table's keys that shape the next
    /// mountain say one thing twice: each key that shapes only the next
    /// mountain is heights-only (height and cliffs shape it and are drawn
    /// under too: the treeline, the strata), and a heights-only key changes
    /// the mountain on screen only by making it again.
    #[test]
    fn the_heights_only_keys_are_the_tables_next_mountain_keys() {
        use crate::settings::keys::{Change, KEYS};
        let drawn_under_too = [keys::HEIGHT.name, keys::CLIFFS.name];
        for key in KEYS {
            let heights_only = HEIGHTS_ONLY.iter().any(|k| k.name == key.name);
            if key.change == Change::Next && !drawn_under_too.contains(&key.name) {
                assert!(heights_only, "`{}` shapes only the next mountain", key.name);
            }
            if heights_only {
                let remade = matches!(key.change, Change::Next | Change::Remake);
                assert!(
                    remade,
                    "`{}` is heights-only but {:?}",
                    key.name, key.change
                );
            }
        }
    }

    /// A data set remembers every key that shaped its heights, so that
    /// opened again it is drawn as it was made: in its generator record,
    /// but the seed (recorded apart, `mountains:seed`) and the water line
    /// (recorded by what it made: the sea level itself).
    #[test]
    fn a_data_set_records_every_key_that_shaped_its_heights() {
        let recorded: Vec<&str> = heightmap::meta::recorded_keys().collect();
        let apart = [keys::SEED.name, keys::WATER_LINE.name];
        for key in HEIGHTS_ONLY.iter().filter(|k| !apart.contains(&k.name)) {
            assert!(
                recorded.contains(&key.name),
                "`{}` is not recorded",
                key.name
            );
        }
    }

    fn small() -> Settings {
        Settings {
            detail: Detail::Level(5),
            seed: Some(11),
            ..Settings::default()
        }
    }

    /// A data set records the detail of its own grid, whatever the
    /// preferences say: "auto" (fitted to a window) or another level.
    #[test]
    fn a_saved_set_records_its_own_grid() {
        let made = Mountain::from_seed(&small(), 11);
        let auto = Settings {
            detail: Detail::Auto,
            ..small()
        };
        assert_eq!(made.saved_with(&auto).detail, Detail::Level(5));
        let low = Settings {
            low_detail: true,
            ..auto.clone()
        };
        assert_eq!(made.saved_with(&low).grid_exponent(), 5);
        let opened = Mountain {
            generated: false,
            ..made.clone()
        };
        let eight = Settings {
            detail: Detail::Level(8),
            ..small()
        };
        assert_eq!(opened.saved_with(&eight).detail, Detail::Level(5));
    }

    #[test]
    fn the_detail_for_a_grid_gives_that_grid_back() {
        for low_detail in [false, true] {
            for exponent in crate::settings::MIN_GRID_EXPONENT..crate::settings::MAX_GRID_EXPONENT {
                let prefs = Settings {
                    low_detail,
                    ..small()
                };
                let detail = Detail::Level(prefs.detail_for_grid(exponent));
                let back = Settings { detail, ..prefs };
                assert_eq!(back.grid_exponent(), exponent, "low_detail {low_detail}");
            }
        }
    }

    #[test]
    fn a_low_detail_set_of_the_finest_grid_keeps_its_low_detail() {
        // low_detail draws the wireframe's cells: dropped from the record,
        // the set saved again drew twice as many lines.
        let field = Heightfield::flat(crate::settings::MAX_GRID_EXPONENT, 100.0);
        let low = Settings {
            low_detail: true,
            ..small()
        };
        // A data set read from a file that records no keys.
        let opened = Mountain {
            field: Arc::new(field),
            seed: None,
            generated: false,
            recorded: None,
        };
        let saved = opened.saved_with(&low);
        assert!(saved.low_detail);
        assert_eq!(
            saved.detail,
            Detail::Level(crate::settings::MAX_GRID_EXPONENT)
        );
    }

    #[test]
    fn a_seed_or_a_file_gives_the_same_heights_and_says_which() {
        let made = Mountain::from_seed(&small(), 11);
        assert_eq!(*made.field, terrain::generate(&small(), 11));
        assert!(made.generated);
        let dir = std::env::temp_dir().join(format!("mountains-mountain-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("m.png");
        heightmap::save(&path, &made.field, made.seed, &small()).unwrap();
        let (opened, _) = Mountain::open_or_generate(&small(), Some(&path)).unwrap();
        assert_eq!((opened.seed, opened.generated), (Some(11), false));
        assert_eq!(opened.field.size(), made.field.size());
        let (generated, notes) = Mountain::open_or_generate(&small(), None).unwrap();
        assert_eq!((generated.seed, generated.generated), (Some(11), true));
        assert!(notes.is_empty());
        let missing = Mountain::open(&dir.join("none.png")).unwrap_err();
        assert!(missing.contains("none.png"), "{missing}");
        let _ = std::fs::remove_dir_all(&dir);
    }
}
