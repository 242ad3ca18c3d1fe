//! Preferences: the shipped file, the key table, messages for bad input.

use mountains::settings::keys::{self, KEYS};
use mountains::settings::load::{self, DEFAULT_TOML, Problem};
use mountains::settings::{ColorMode, Detail, Settings};

fn load_text(text: &str) -> (Settings, Vec<Problem>) {
    let mut s = Settings::default();
    let problems = load::apply_toml(&mut s, text, "test.toml");
    (s, problems)
}

#[test]
fn shipped_file_is_exactly_the_defaults() {
    // Start from settings that differ in every key, so a key missing from the
    // file would show as a difference.
    let mut s = Settings::default();
    s.seed = Some(7);
    s.cragginess = 3;
    s.elevation = 7.0;
    s.roughness = 4.0;
    s.hurst = 0.3;
    s.lakes = !s.lakes;
    s.cliffs = 0.5;
    s.contour = 3.0;
    s.height = 9;
    s.detail = Detail::Level(5);
    s.low_detail = !s.low_detail;
    s.sea_level = 0.5;
    s.color = ColorMode::Ridges;
    s.relative_depth = !s.relative_depth;
    s.shadows = !s.shadows;
    s.rotation = 270;
    s.auto_redraw = !s.auto_redraw;
    s.draw_seconds = 99.0;
    s.pause_seconds = 99.0;
    s.heightmaps_dir = Some("x".into());
    let problems = load::apply_toml(&mut s, DEFAULT_TOML, "default.toml");
    assert!(problems.is_empty(), "{problems:?}");
    let d = Settings::default();
    assert_eq!(
        (s.generator, s.profile, s.view, s.monitors),
        (d.generator, d.profile, d.view, d.monitors)
    );
    assert_eq!(s, d);
}

#[test]
fn shipped_file_documents_every_key_and_only_those() {
    let doc: toml::Table = DEFAULT_TOML.parse().unwrap();
    for key in KEYS {
        assert!(
            doc.contains_key(key.name),
            "config/default.toml lacks `{}`",
            key.name
        );
    }
    assert_eq!(doc.len(), KEYS.len());
}

#[test]
fn every_key_round_trips_through_get_and_apply() {
    let defaults = Settings::default();
    for key in KEYS {
        let mut s = Settings::default();
        let v = keys::get(&defaults, key);
        keys::apply(&mut s, key, &v).unwrap_or_else(|e| panic!("{}: {e}", key.name));
        assert_eq!(s, defaults, "key {}", key.name);
    }
}

#[test]
fn out_of_range_is_an_error_with_position_and_allowed_values() {
    let (s, problems) = load_text("detail = 8\ncragginess = 999\n");
    assert_eq!(problems.len(), 1);
    let p = &problems[0];
    assert_eq!(p.position, Some((2, 14)));
    assert_eq!(p.key.as_deref(), Some("cragginess"));
    let text = p.to_string();
    assert!(
        text.starts_with("test.toml:2:14: key `cragginess`"),
        "{text}"
    );
    assert!(text.contains("from 1 to 128"), "{text}");
    // Not clamped: the bad key keeps its default, the good one is used.
    assert_eq!(s.cragginess, Settings::default().cragginess);
}

/// Seed 000's menus: Iterations from 3, Smoothness's blank item (0 here),
/// Contour checked at 1.50; one step beyond each is still refused.
#[test]
fn seed_000s_menu_values_are_accepted() {
    assert_eq!(Settings::default().contour, 1.5);
    let (s, problems) = load_text("detail = 3\nroughness = 0\ncontour = 0.25\n");
    assert!(problems.is_empty(), "{problems:?}");
    assert_eq!(
        (s.detail, s.roughness, s.contour),
        (Detail::Level(3), 0.0, 0.25)
    );
    let f = mountains::terrain::generate(&s, 7);
    assert_eq!(f.size(), 9, "detail 3 is seed 000's 9x9 map");
    let (_, problems) = load_text("detail = 2\nroughness = -1\n");
    let keys: Vec<_> = problems.iter().map(|p| p.key.as_deref()).collect();
    assert_eq!(keys, [Some("detail"), Some("roughness")], "{problems:?}");
}

#[test]
fn good_keys_survive_a_bad_neighbour() {
    let (s, problems) = load_text("color = \"sonar\"\nheight = \"tall\"\nlow_detail = true\n");
    assert_eq!(problems.len(), 1);
    assert_eq!(s.color, ColorMode::Sonar);
    assert!(s.low_detail);
    assert_eq!(s.height, Settings::default().height);
}

#[test]
fn unknown_key_is_reported_with_a_suggestion() {
    let (_, problems) = load_text("\n  cragines = 5\n");
    assert_eq!(problems.len(), 1);
    assert_eq!(problems[0].position, Some((2, 3)));
    assert!(
        problems[0].message.contains("did you mean `cragginess`"),
        "{}",
        problems[0].message
    );
}

#[test]
fn syntax_error_names_line_and_column_and_uses_nothing() {
    let (s, problems) = load_text("color = \"sonar\"\ndetail = = 3\n");
    assert_eq!(problems.len(), 1);
    assert_eq!(problems[0].position.map(|p| p.0), Some(2));
    assert!(problems[0].message.starts_with("not valid TOML"));
    assert_eq!(s, Settings::default());
}

/// A value TOML cannot read names its key and what the key takes: `color
/// = sonar` said only "string values must be quoted", about no key. An
/// error in the key itself (before the `=`) names none.
#[test]
fn syntax_error_in_a_value_names_its_key_and_what_it_takes() {
    for (text, key, position, takes) in [
        (
            "seed = 5\ncolor = sonar\n",
            "color",
            (2, 9),
            "one of \"natural\"",
        ),
        ("lakes = yes\n", "lakes", (1, 9), "true or false"),
        (
            "sea_level = .5\n",
            "sea_level",
            (1, 13),
            "a number from -1 to 1",
        ),
    ] {
        let (s, problems) = load_text(text);
        assert_eq!(problems.len(), 1, "{text:?}");
        let p = &problems[0];
        assert_eq!(p.key.as_deref(), Some(key), "{p}");
        assert_eq!(p.position, Some(position), "{p}");
        assert!(p.message.starts_with("not valid TOML: "), "{p}");
        assert!(p.message.contains(&format!("; it takes {takes}")), "{p}");
        assert_eq!(s, Settings::default());
    }
    let (_, problems) = load_text("se ed = 1\n");
    assert_eq!(problems[0].key, None, "{}", problems[0]);
    let (_, problems) = load_text("mystery = yes\n");
    assert_eq!(problems[0].key.as_deref(), Some("mystery"));
    assert!(!problems[0].message.contains("it takes"), "{}", problems[0]);
}

#[test]
fn wrong_type_names_the_expected_values() {
    let (_, problems) = load_text("shadows = 1\ncolor = \"pink\"\n");
    assert_eq!(problems.len(), 2);
    assert!(problems[0].message.contains("true or false"));
    assert!(
        problems[1].message.contains("\"sonar\""),
        "{}",
        problems[1].message
    );
}

#[test]
fn floats_accept_integers_but_not_nan_or_out_of_range() {
    assert_eq!(load_text("elevation = 200\n").0.elevation, 200.0);
    assert_eq!(load_text("elevation = nan\n").1.len(), 1);
    assert_eq!(load_text("sea_level = 1.5\n").1.len(), 1);
}

#[test]
fn seeds_accept_integers_big_strings_and_random() {
    assert_eq!(load_text("seed = 42\n").0.seed, Some(42));
    assert_eq!(
        load_text("seed = \"18446744073709551615\"\n").0.seed,
        Some(u64::MAX)
    );
    assert_eq!(load_text("seed = \"random\"\n").0.seed, None);
    assert_eq!(load_text("seed = -3\n").1.len(), 1);
}

/// A number or a true/false written in quotes in the file is offered
/// without them, when the key takes it so; one out of range is not.
#[test]
fn a_quoted_number_or_boolean_is_offered_without_quotes() {
    for (line, offered) in [
        ("detail = \"8\"\n", "did you mean 8, without quotes?"),
        ("draw_seconds = \"5\"\n", "did you mean 5, without quotes?"),
        (
            "low_detail = \"true\"\n",
            "did you mean true, without quotes?",
        ),
    ] {
        let problems = load_text(line).1;
        assert_eq!(problems.len(), 1, "{line}");
        assert!(
            problems[0].message.contains(offered),
            "{line}: {}",
            problems[0]
        );
    }
    let problems = load_text("detail = \"99\"\n").1;
    assert!(
        !problems[0].message.contains("did you mean"),
        "{}",
        problems[0]
    );
}

#[test]
fn set_accepts_bare_words_and_toml_values() {
    let mut s = Settings::default();
    load::apply_set(&mut s, "color", "mono").unwrap();
    load::apply_set(&mut s, "color", "\"outline\"").unwrap();
    load::apply_set(&mut s, "detail", "10").unwrap();
    load::apply_set(&mut s, "draw_seconds", "0.5").unwrap();
    load::apply_set(&mut s, "rotation", "90").unwrap();
    assert_eq!(
        (s.color, s.detail, s.draw_seconds, s.rotation),
        (ColorMode::Outline, Detail::Level(10), 0.5, 90)
    );
    let e = load::apply_set(&mut s, "rotation", "45").unwrap_err();
    assert!(e.to_string().starts_with("--set: key `rotation`"), "{e}");
    assert!(
        load::apply_set(&mut s, "colour", "red")
            .unwrap_err()
            .message
            .contains("did you mean `color`")
    );
}

#[test]
fn resolve_reports_file_problems_and_refuses_a_missing_explicit_file() {
    let dir = std::env::temp_dir().join(format!("mountains-settings-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("prefs.toml");
    std::fs::write(&file, "detail = 99\ncolor = \"red\"\n").unwrap();
    let sets = vec![("detail".to_string(), "6".to_string())];
    let loaded = load::resolve(Some(&file), &sets, load::Unreadable::Refuse).unwrap();
    assert_eq!(loaded.problems.len(), 1);
    assert_eq!(
        (loaded.settings.color, loaded.settings.detail),
        (ColorMode::Red, Detail::Level(6))
    );
    let missing =
        load::resolve(Some(&dir.join("nope.toml")), &[], load::Unreadable::Refuse).unwrap_err();
    assert!(missing.message.starts_with("cannot read"), "{missing}");
    // The settings screen may start a new file: defaults, no file, no problem.
    let fresh = load::resolve(
        Some(&dir.join("nope.toml")),
        &[],
        load::Unreadable::NewIfMissing,
    )
    .unwrap();
    assert_eq!((fresh.file, fresh.problems.len()), (None, 0));
    assert_eq!(fresh.settings, mountains::settings::Settings::default());
    // A link to nowhere is no new file: it cannot be read, and says why.
    #[cfg(unix)]
    {
        let link = dir.join("link.toml");
        std::os::unix::fs::symlink(dir.join("gone.toml"), &link).unwrap();
        let refused = load::resolve(Some(&link), &[], load::Unreadable::NewIfMissing).unwrap_err();
        assert!(refused.to_string().contains("--config"), "{refused}");
        assert!(
            refused
                .message
                .starts_with("cannot read: a link to nowhere"),
            "{refused}"
        );
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

/// The saver's way of reading preferences starts on the defaults when the
/// file cannot be read, and says why; the null device is no preferences
/// in every mode.
#[cfg(unix)]
#[test]
fn resolve_for_a_saver_uses_the_defaults_when_the_file_cannot_be_read() {
    let dir = std::env::temp_dir().join(format!("mountains-unreadable-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let folder = dir.join("a-folder.toml");
    std::fs::create_dir_all(&folder).unwrap();
    let sets = vec![("detail".to_string(), "6".to_string())];
    let loaded = load::resolve(Some(&folder), &sets, load::Unreadable::Defaults).unwrap();
    assert_eq!(loaded.problems.len(), 1);
    assert!(loaded.problems[0].is_unreadable(), "{}", loaded.problems[0]);
    assert_eq!(loaded.settings.detail, Detail::Level(6));
    assert!(load::resolve(Some(&folder), &[], load::Unreadable::Refuse).is_err());
    for unreadable in [
        load::Unreadable::Refuse,
        load::Unreadable::NewIfMissing,
        load::Unreadable::Defaults,
    ] {
        let none = load::resolve(Some(std::path::Path::new("/dev/null")), &[], unreadable).unwrap();
        assert_eq!((none.file, none.problems.len()), (None, 0));
        assert_eq!(none.settings, mountains::settings::Settings::default());
    }
    // A bad `--set` stays an error for the saver too.
    let bad = vec![("cragginess".to_string(), "999".to_string())];
    assert!(load::resolve(Some(&folder), &bad, load::Unreadable::Defaults).is_err());
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn invalid_utf8_is_a_problem_not_a_panic() {
    let dir = std::env::temp_dir().join(format!("mountains-utf8-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("bad.toml");
    std::fs::write(&file, b"color = \"red\"\ndetail = \xff\n").unwrap();
    let mut s = Settings::default();
    let problems = load::apply_file(&mut s, &file);
    assert_eq!(problems.len(), 1);
    assert_eq!(problems[0].position, Some((2, 10)));
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn next_seed_is_the_set_one_or_a_fresh_one_that_fits_toml() {
    let set = Settings {
        seed: Some(u64::MAX),
        ..Settings::default()
    };
    assert_eq!(set.next_seed(), u64::MAX);
    let random = Settings::default();
    let seeds: Vec<u64> = (0..64).map(|_| random.next_seed()).collect();
    // A fresh seed can be written back as `seed = N` (a TOML integer is an i64).
    for &seed in &seeds {
        let (s, problems) = load_text(&format!("seed = {seed}\n"));
        assert!(problems.is_empty(), "{seed}: {problems:?}");
        assert_eq!(s.seed, Some(seed));
    }
    assert!(
        seeds.windows(2).any(|w| w[0] != w[1]),
        "fresh seeds should differ"
    );
}

/// Each row of the key table reads and writes its own field and no other
/// (`look` also the keys its look sets, and only those):
/// a new value written through a key reads back through it, and every
/// other key still reads its default (each row carries its own accessors,
/// so a row copied from its neighbour would show here).
#[test]
fn every_key_writes_and_reads_only_its_own_field() {
    use mountains::settings::keys::{Kind, Value};
    let defaults = Settings::default();
    for key in KEYS {
        // The row's default is what a default Settings holds.
        assert_eq!(keys::get(&defaults, key), (key.default)(), "{}", key.name);
        let new = match key.kind {
            Kind::Int { max, .. } => Value::Int(max),
            // The least value, or the most where the least is the default
            // (cliffs: 0, none).
            Kind::Float { min, max } if (key.default)() == Value::Float(min) => Value::Float(max),
            Kind::Float { min, .. } => Value::Float(min),
            Kind::IntOrAuto { min, .. } => Value::Int(min),
            Kind::Bool => match keys::get(&defaults, key) {
                Value::Bool(b) => Value::Bool(!b),
                other => panic!("{}: {other:?}", key.name),
            },
            Kind::Choice(names) => {
                let now = keys::get(&defaults, key);
                let other = names.iter().find(|n| Value::Str(n.to_string()) != now);
                Value::Str(other.unwrap().to_string())
            }
            Kind::Seed => Value::Int(4711),
            Kind::Path => Value::Str("/some/folder".into()),
            Kind::QuarterTurn => Value::Int(90),
            Kind::AmountOrVaried => Value::Float(0.5),
        };
        assert_ne!(
            keys::get(&defaults, key),
            new,
            "{}: pick another value",
            key.name
        );
        let mut s = defaults.clone();
        keys::apply(&mut s, key, &new).unwrap_or_else(|e| panic!("{}: {e}", key.name));
        assert_eq!(keys::get(&s, key), new, "{} does not read back", key.name);
        // `look` moves exactly the keys its look gives values to (under
        // "ours", every other key keeps its default).
        for other in KEYS.iter().filter(|o| o.name != key.name) {
            assert_eq!(
                keys::get(&s, other),
                keys::under_look(s.look, other, keys::get(&defaults, other)),
                "writing {} changed {}",
                key.name,
                other.name
            );
        }
    }
}
