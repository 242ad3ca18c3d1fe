//! `look = ...`: a seed program's keys as a layer of defaults under the
//! keys a person sets, whatever order they come in, in a file, on the
//! command line and on saving.

use mountains::settings::keys::{self, KEYS};
use mountains::settings::load::{self, DEFAULT_TOML};
use mountains::settings::looks;
use mountains::settings::save::merge;
use mountains::settings::{Detail, Generator, Look, Settings, Shading, Sun, ViewKind};

const LOOKS: [Look; 5] = [
    Look::Ours,
    Look::FractalMountainClimbing,
    Look::MountainTerrain,
    Look::Fl3,
    Look::Essay,
];

fn load_text(text: &str) -> Settings {
    let mut s = Settings::default();
    let problems = load::apply_toml(&mut s, text, "test.toml");
    assert!(problems.is_empty(), "{problems:?}");
    s
}

/// The shipped file with its `look` line changed: what a person who
/// copied it and chose a look has.
fn shipped_with(look: &str) -> String {
    assert!(
        DEFAULT_TOML.contains("\nlook = \"ours\"\n"),
        "config/default.toml has no `look = \"ours\"` line"
    );
    DEFAULT_TOML.replace("\nlook = \"ours\"\n", &format!("\nlook = \"{look}\"\n"))
}

#[test]
fn every_looks_presets_are_keys_and_values_the_table_allows() {
    for look in LOOKS {
        for &(name, _) in looks::presets(look) {
            let key = keys::find(name).unwrap_or_else(|| panic!("{look:?}: `{name}` is no key"));
            let value = keys::look_value(look, key).expect("a preset");
            let mut s = Settings::default();
            keys::apply(&mut s, key, &value)
                .unwrap_or_else(|e| panic!("{look:?}: `{name}` = {value}: {e}"));
            assert_eq!(keys::get(&s, key), value, "{look:?}: `{name}`");
        }
    }
    assert!(looks::presets(Look::Ours).is_empty());
}

#[test]
fn fractal_mountain_climbing_is_seed_000s_menus_and_view() {
    let s = load_text("look = \"fractal-mountain-climbing\"\n");
    assert_eq!(s.look, Look::FractalMountainClimbing);
    assert_eq!(s.generator, Generator::Triangle);
    // menuCk = {3,6,5,5,1}: Iterations 5, Contour 1.50, Smoothness 2.00,
    // Height 5.
    assert_eq!(s.detail, Detail::Level(5));
    assert_eq!((s.contour, s.roughness, s.height), (1.5, 2.0, 5));
    assert_eq!(
        (s.view, s.sun, s.shading),
        (ViewKind::Oblique, Sun::Classic, Shading::Flat)
    );
    assert!(!s.shadows && !s.lakes && !s.relative_depth);
    assert_eq!(s.erosion, 0.0);
}

#[test]
fn a_key_set_to_something_else_overrides_the_look_before_or_after_it() {
    let before = load_text("view = \"perspective\"\nlook = \"fractal-mountain-climbing\"\n");
    let after = load_text("look = \"fractal-mountain-climbing\"\nview = \"perspective\"\n");
    for s in [&before, &after] {
        assert_eq!(s.view, ViewKind::Perspective);
        // The rest of the look still holds.
        assert_eq!((s.sun, s.generator), (Sun::Classic, Generator::Triangle));
    }
    assert_eq!(before, after);
}

#[test]
fn the_shipped_file_copied_with_a_look_chosen_draws_that_look() {
    for look in LOOKS {
        let name = keys::get(
            &Settings {
                look,
                ..Settings::default()
            },
            keys::find("look").unwrap(),
        );
        let keys::Value::Str(name) = name else {
            unreachable!()
        };
        let s = load_text(&shipped_with(&name));
        assert_eq!(s.look, look);
        for &(key, _) in looks::presets(look) {
            let key = keys::find(key).unwrap();
            assert_eq!(
                Some(keys::get(&s, key)),
                keys::look_value(look, key),
                "{look:?}: `{}`",
                key.name
            );
        }
    }
}

#[test]
fn set_flags_layer_a_look_over_the_file_and_back() {
    let mut s = load_text("cragginess = 40\n");
    load::apply_set(&mut s, "look", "mountain-terrain").unwrap();
    assert_eq!(
        (s.generator, s.view),
        (Generator::Square, ViewKind::Oblique)
    );
    // A key the file sets stays the file's.
    assert_eq!(s.cragginess, 40);
    // Back to ours: every key the look moved returns to its default.
    load::apply_set(&mut s, "look", "ours").unwrap();
    let want = Settings {
        cragginess: 40,
        ..Settings::default()
    };
    assert_eq!(s, want);
    // From one look to another: nothing of the first is left.
    let mut a = Settings::default();
    load::apply_set(&mut a, "look", "fractal-mountain-climbing").unwrap();
    load::apply_set(&mut a, "look", "essay").unwrap();
    let mut b = Settings::default();
    load::apply_set(&mut b, "look", "essay").unwrap();
    assert_eq!(a, b);
}

#[test]
fn saving_under_a_look_leaves_the_files_defaults_alone() {
    for look in LOOKS {
        let text = shipped_with(match look {
            Look::Ours => "ours",
            Look::FractalMountainClimbing => "fractal-mountain-climbing",
            Look::MountainTerrain => "mountain-terrain",
            Look::Fl3 => "fl3",
            Look::Essay => "essay",
        });
        let s = load_text(&text);
        assert_eq!(merge(&text, &s).unwrap(), text, "{look:?}");
        // A file without the look's keys gains none of them either.
        let short = "look = \"fractal-mountain-climbing\"\n";
        let s = load_text(short);
        assert_eq!(merge(short, &s).unwrap(), short);
    }
    // A key changed away from the look is written.
    let short = "look = \"fractal-mountain-climbing\"\n";
    let mut s = load_text(short);
    s.view = ViewKind::Perspective;
    let out = merge(short, &s).unwrap();
    assert!(out.contains("view = \"perspective\""), "{out}");
    assert_eq!(load_text(&out), s);
    assert_eq!(KEYS.iter().filter(|k| k.name == "look").count(), 1);
}

/// The settings screen choosing a look: every key the look moved counts as
/// changed there, and saving them into a copy of the shipped file changes
/// its `look` line and nothing else; the file read back is the screen's.
#[test]
fn choosing_a_look_on_the_screen_saves_one_line() {
    use mountains::settings::save::save_changes;
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("looks-save");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("mountains.toml");
    std::fs::write(&file, DEFAULT_TOML).unwrap();
    let before = load_text(DEFAULT_TOML);
    let mut edited = before.clone();
    load::apply_set(&mut edited, "look", "mountain-terrain").unwrap();
    let changed: Vec<_> = KEYS
        .iter()
        .filter(|k| keys::get(&edited, k) != keys::get(&before, k))
        .collect();
    assert!(changed.len() > 5, "{} keys moved", changed.len());
    save_changes(&file, &edited, &changed).unwrap();
    let text = std::fs::read_to_string(&file).unwrap();
    let differ: Vec<(&str, &str)> = DEFAULT_TOML
        .lines()
        .zip(text.lines())
        .filter(|(a, b)| a != b)
        .collect();
    assert_eq!(differ, [("look = \"ours\"", "look = \"mountain-terrain\"")]);
    assert_eq!(text.lines().count(), DEFAULT_TOML.lines().count());
    assert_eq!(load_text(&text), edited);
}
