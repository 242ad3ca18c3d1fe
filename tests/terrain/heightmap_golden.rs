//! Files saved by format 1 must keep loading as the same mountain.
//!
//! `tests/data/heightmap_v1.png` was written by `regenerate_golden_file`
//! (run it with `cargo test --test terrain heightmap_golden -- --ignored` only when
//! the format deliberately changes, and bump `meta::FORMAT_VERSION` then).

use crate::common::heightmaps;

use std::path::{Path, PathBuf};

use mountains::settings::Detail;
use mountains::settings::{Generator, Profile, Settings};
use mountains::terrain::heightmap::{self, GeneratorParams, decode, encode};

fn golden_path() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/heightmap_v1.png")
}

fn golden_settings() -> Settings {
    Settings {
        generator: Generator::Square,
        cragginess: 96,
        profile: Profile::Peak,
        detail: Detail::Level(5),
        // The golden file was written before erosion existed: it has no
        // erosion key, which reads as none.
        erosion: 0.0,
        // Written when the contour default was 1.0 (now seed 000's 1.5).
        contour: 1.0,
        ..crate::common::terrain_setup::temperate()
    }
}

const GOLDEN_SEED: u64 = 0xdead_beef_0123_4567;

#[test]
#[ignore = "writes the golden file; run only on a deliberate format change"]
fn regenerate_golden_file() {
    let f = heightmaps::field(5, 321.5);
    heightmap::save(&golden_path(), &f, Some(GOLDEN_SEED), &golden_settings()).unwrap();
}

#[test]
fn format_1_file_loads_as_the_same_mountain() {
    let d = heightmap::load(&golden_path()).unwrap();
    assert_eq!(d.seed, Some(GOLDEN_SEED));
    assert_eq!(
        d.params,
        Some(GeneratorParams::from_settings(&golden_settings()))
    );
    assert_eq!(d.field.extent(), 321.5);
    assert!(d.notes.is_empty(), "{:?}", d.notes);
    // The same field saved today decodes to the same heights.
    let f = heightmaps::field(5, 321.5);
    let today = encode(
        &f,
        Some(GOLDEN_SEED),
        &golden_settings(),
        Path::new("t.png"),
    )
    .unwrap();
    assert_eq!(decode(&today, Path::new("t.png")).unwrap().field, d.field);
}
