//! A data set saved under a look comes back as the same picture: its file
//! records the look (`mountains:look`) beside the other keys, each exact,
//! and opening it draws it under that look. Files from before the looks
//! load as ours.

use std::path::{Path, PathBuf};

use mountains::mountain::Mountain;
use mountains::render::{Frame, render_full};
use mountains::settings::load::apply_set;
use mountains::settings::{ColorMode, Look, Settings};
use mountains::terrain::{self, heightmap};

const SEED: u64 = 4242;
const SIZE: (u32, u32) = (96, 64);

/// Default settings with `sets` applied as `--set` would.
fn with(sets: &[(&str, &str)]) -> Settings {
    let mut s = crate::common::terrain_setup::temperate();
    for (k, v) in sets {
        apply_set(&mut s, k, v).unwrap_or_else(|p| panic!("{p}"));
    }
    s
}

/// A folder of this test's own, empty.
fn folder(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!(
        "mountains-heightmap-looks-{name}-{}",
        std::process::id()
    ));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn picture(field: &terrain::Heightfield, s: &Settings) -> Frame {
    let mut frame = Frame::new(SIZE.0, SIZE.1).unwrap();
    render_full(field, s, &mut frame);
    frame
}

/// The mountain of `made` saved at `path` and opened again.
fn saved_and_opened(made: &Settings, path: &Path) -> Mountain {
    let field = terrain::generate(made, SEED);
    heightmap::save(path, &field, Some(SEED), made).unwrap();
    let (opened, notes) = Mountain::open(path).unwrap();
    assert!(notes.is_empty(), "{notes:?}");
    opened
}

/// Each look's set under default preferences: the settings it is drawn
/// with are the ones it was saved under, key for key, so the picture is too.
fn comes_back_as_saved(made: &Settings, name: &str) {
    let dir = folder(name);
    let opened = saved_and_opened(made, &dir.join("set.png"));
    let recorded = opened.recorded.clone().expect("our file records its keys");
    assert_eq!(recorded, heightmap::GeneratorParams::from_settings(made));
    let drawn = opened.drawn_with(&crate::common::terrain_setup::temperate());
    assert_eq!(drawn, *made, "{name}");
    // The picture of the mountain as it was made, before saving: saving
    // rounds its heights to 16 bits, which may move an edge across a pixel
    // centre (look = ours, seeds 1-8 at 80x60: 8 to 74 of 4,800 pixels),
    // no more.
    let original = picture(&terrain::generate(made, SEED), made);
    let again = picture(&opened.field, &drawn);
    let moved = (again.pixels().iter().zip(original.pixels()))
        .filter(|(a, b)| a != b)
        .count();
    assert!(
        moved * 100 <= again.pixels().len(),
        "{name}: {moved} pixels moved"
    );
    // Ignoring what the file says would show another picture: the test
    // can fail.
    let ours = picture(&opened.field, &crate::common::terrain_setup::temperate());
    assert_ne!(again.pixels(), ours.pixels(), "{name}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_set_saved_under_fl3_comes_back_with_its_look_and_height() {
    let made = with(&[("look", "fl3"), ("height", "7"), ("detail", "5")]);
    assert_eq!(made.look, Look::Fl3);
    comes_back_as_saved(&made, "fl3");
}

#[test]
fn a_set_saved_under_the_essay_comes_back_with_its_look_and_height() {
    let made = with(&[("look", "essay"), ("height", "7"), ("detail", "5")]);
    assert_eq!(made.look, Look::Essay);
    comes_back_as_saved(&made, "essay");
}

/// A key recorded at its own default under a look that gives another
/// value (height 5 under the essay, whose height is 10) comes back as 5:
/// the look read back does not replace the keys read before it.
#[test]
fn a_key_at_its_default_under_a_look_comes_back_exact() {
    let mut made = with(&[("look", "essay"), ("detail", "5")]);
    made.height = crate::common::terrain_setup::temperate().height;
    assert_ne!(with(&[("look", "essay")]).height, made.height);
    comes_back_as_saved(&made, "essay-default-height");
}

/// The recorded keys lie under the person's preferences, as a look lies
/// under the keys: a look or a key they set to anything but its default
/// wins over the file's.
#[test]
fn a_look_or_key_the_person_chose_wins_over_the_files() {
    let dir = folder("prefs");
    let made = with(&[("look", "fl3"), ("height", "7"), ("detail", "5")]);
    let opened = saved_and_opened(&made, &dir.join("set.png"));
    let theirs = with(&[("look", "mountain-terrain")]);
    let drawn = opened.drawn_with(&theirs);
    assert_eq!(drawn.look, Look::MountainTerrain);
    assert_eq!(drawn.color, theirs.color);
    assert_eq!(
        drawn.height, 7,
        "a key they left at its default: the file's"
    );
    let sonar = with(&[("color", "sonar"), ("height", "3")]);
    let drawn = opened.drawn_with(&sonar);
    assert_eq!(drawn.look, Look::Fl3);
    assert_eq!((drawn.color, drawn.height), (ColorMode::Sonar, 3));
    assert_eq!(drawn.view, made.view, "the look's keys no file records");
    let _ = std::fs::remove_dir_all(&dir);
}

/// A file from before the looks (the format 1 golden file) has no
/// `mountains:look`: it loads as ours, without a note, and is drawn so.
#[test]
fn an_old_file_without_a_look_loads_as_ours() {
    let golden = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/heightmap_v1.png");
    let text = std::fs::read(&golden).unwrap();
    assert!(
        !text.windows(14).any(|w| w == b"mountains:look"),
        "the golden file predates the look"
    );
    let (opened, notes) = Mountain::open(&golden).unwrap();
    assert!(notes.is_empty(), "{notes:?}");
    let drawn = opened.drawn_with(&crate::common::terrain_setup::temperate());
    assert_eq!(drawn.look, Look::Ours);
    assert_eq!(drawn.view, crate::common::terrain_setup::temperate().view);
}

/// A look this version does not know (a newer version's) drops the
/// recorded keys with a note naming the key, as any bad origin key does;
/// the heights still load.
#[test]
fn an_unknown_recorded_look_is_a_note_naming_the_key() {
    let made = with(&[("detail", "5")]);
    let field = terrain::generate(&made, SEED);
    let bytes = heightmap::encode(&field, Some(SEED), &made, Path::new("x.png")).unwrap();
    // Same length, so the PNG's chunk lengths stay right; the CRC is
    // recomputed by `rewrite_text`.
    let bytes = rewrite_text(&bytes, b"mountains:look\0ours", b"mountains:look\0xyzw");
    let d = heightmap::decode(&bytes, Path::new("x.png")).unwrap();
    assert_eq!(d.params, None);
    assert!(
        d.notes.iter().any(|n| n.contains("mountains:look")),
        "{:?}",
        d.notes
    );
}

/// `bytes` (a PNG) with the tEXt chunk holding `from` holding `to` (the
/// same length), its CRC made again.
fn rewrite_text(bytes: &[u8], from: &[u8], to: &[u8]) -> Vec<u8> {
    assert_eq!(from.len(), to.len());
    let mut out = bytes.to_vec();
    let at = out
        .windows(from.len())
        .position(|w| w == from)
        .expect("the chunk is there");
    out[at..at + to.len()].copy_from_slice(to);
    // The chunk's type starts 4 bytes before its data; its length 8 before.
    let start = at - 4;
    let len = u32::from_be_bytes(out[start - 4..start].try_into().unwrap()) as usize;
    let crc = crc32(&out[start..start + 4 + len]);
    out[start + 4 + len..start + 8 + len].copy_from_slice(&crc.to_be_bytes());
    out
}

/// PNG's CRC-32 (ISO 3309), bit by bit: a few chunks in a test.
fn crc32(data: &[u8]) -> u32 {
    let mut crc = !0u32;
    for &b in data {
        crc ^= u32::from(b);
        for _ in 0..8 {
            crc = if crc & 1 == 1 {
                (crc >> 1) ^ 0xedb8_8320
            } else {
                crc >> 1
            };
        }
    }
    !crc
}
