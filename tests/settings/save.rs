//! Saving preferences: only edited values change, comments and unknown keys
//! stay, broken files are never overwritten, every value is checked.

use crate::common::files;
use files::replace_keeping_mtime;
use std::path::{Path, PathBuf};

use mountains::settings::Detail;
use mountains::settings::load::{self, DEFAULT_TOML};
use mountains::settings::save::{self, merge};
use mountains::settings::{ColorMode, Settings};

fn data(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/settings")
        .join(name)
}

fn read(path: &Path) -> String {
    std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

fn loaded(text: &str) -> Settings {
    let mut s = Settings::default();
    let problems = load::apply_toml(&mut s, text, "test.toml");
    // The golden file's one unknown key is meant to be there.
    let real: Vec<_> = problems
        .iter()
        .filter(|p| p.key.as_deref() != Some("my_own_note"))
        .collect();
    assert!(real.is_empty(), "{real:?}");
    s
}

/// A fresh, empty folder under the target directory for one test.
fn scratch(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("save-{name}"));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

#[test]
fn edited_values_change_and_everything_else_stays() {
    let input = read(&data("commented.toml"));
    let mut s = loaded(&input);
    s.cragginess = 12;
    s.color = ColorMode::Mono;
    s.shadows = false;
    s.contour = 0.35;
    let out = merge(&input, &s).unwrap();
    let expected = read(&data("commented.expected.toml"));
    assert_eq!(out, expected, "output:\n{out}");
    assert_eq!(
        loaded(&out),
        s,
        "the saved file reads back as the screen's values"
    );
}

#[test]
fn unchanged_settings_leave_the_text_byte_identical() {
    let input = read(&data("commented.toml"));
    let s = loaded(&input);
    assert_eq!(merge(&input, &s).unwrap(), input);
    assert_eq!(
        merge(DEFAULT_TOML, &Settings::default()).unwrap(),
        DEFAULT_TOML
    );
}

#[test]
fn a_value_written_differently_but_equal_is_kept_as_written() {
    let input = "draw_seconds = 8\nelevation = 1e2\n";
    let s = loaded(input);
    assert_eq!(s.elevation, 100.0);
    assert_eq!(merge(input, &s).unwrap(), input);
}

#[test]
fn every_key_round_trips_through_the_shipped_file() {
    use mountains::settings::{
        Clouds, Generator, Look, Monitors, OnBattery, Profile, Shading, Sun, ViewKind, WaterLine,
        World,
    };
    let s = Settings {
        seed: Some(u64::MAX),
        look: Look::Essay,
        world: World::Desert,
        generator: Generator::Triangle,
        cragginess: 128,
        elevation: 999.5,
        roughness: 4.25,
        contour: 0.3,
        profile: Profile::Massif,
        hurst: 0.35,
        height: 10,
        erosion: 0.75,
        cliffs: 0.6,
        detail: Detail::Level(4),
        low_detail: true,
        sea_level: -0.14,
        water_line: WaterLine::Generator,
        lakes: false,
        color: ColorMode::Ridges,
        relative_depth: false,
        shadows: false,
        sun: Sun::Clock,
        latitude: -33.87,
        longitude: 151.21,
        shading: Shading::Flat,
        clouds: Clouds::Amount(0.35),
        fine_relief: false,
        reflections: false,
        view: ViewKind::Perspective,
        rotation: 270,
        auto_redraw: false,
        draw_seconds: 0.0,
        pause_seconds: 3600.0,
        monitors: Monitors::Primary,
        on_battery: OnBattery::Slow,
        heightmaps_dir: Some("C:\\Maps \"quoted\"".into()),
    };
    let out = merge(DEFAULT_TOML, &s).unwrap();
    assert_eq!(loaded(&out), s);
    assert!(out.contains("seed = \"18446744073709551615\""), "{out}");
    assert!(out.contains("sea_level = -0.14\n"), "{out}");
    // Every comment of the shipped file is still there.
    for line in DEFAULT_TOML.lines().filter(|l| l.starts_with('#')) {
        assert!(out.contains(line), "lost comment {line:?}");
    }
}

#[test]
fn a_missing_key_is_added_at_the_end_with_its_doc() {
    let s = Settings {
        height: 9,
        ..Settings::default()
    };
    let out = merge("# mine\ncolor = \"gray\"\n", &s).unwrap();
    assert_eq!(
        out,
        "# mine\ncolor = \"natural\"\n\n\
         # height of the peaks; also raises the treeline and snow\nheight = 9\n"
    );
}

#[test]
fn a_file_that_does_not_parse_is_never_overwritten() {
    let dir = scratch("broken");
    let path = dir.join("mountains.toml");
    let broken = b"# mine\ncolor = \"sonar\"\ncragginess = = 3\n";
    std::fs::write(&path, broken).unwrap();
    let s = Settings {
        cragginess: 5,
        ..Settings::default()
    };
    let err = save::save(&path, &s).unwrap_err();
    assert_eq!(std::fs::read(&path).unwrap(), broken);
    assert_eq!(err.position.map(|p| p.0), Some(3), "{err}");
    let text = err.to_string();
    assert!(text.contains("mountains.toml:3:"), "{text}");
    assert!(text.contains("not saved"), "{text}");
    // In the words the file's loading uses, naming the key.
    let missing = dir.join("missing-value.toml");
    std::fs::write(&missing, b"cragginess = \n").unwrap();
    let text = save::save(&missing, &s).unwrap_err().to_string();
    assert!(
        text.contains(
            "key `cragginess`: not valid TOML: nothing after `=`; give a value; not saved"
        ),
        "{text}"
    );
    std::fs::remove_file(&missing).unwrap();
    let leftovers: Vec<_> = std::fs::read_dir(&dir).unwrap().collect();
    assert_eq!(leftovers.len(), 1, "no temporary file is left behind");
}

#[test]
fn a_file_that_is_not_utf8_is_never_overwritten() {
    let dir = scratch("latin1");
    let path = dir.join("mountains.toml");
    let bytes = b"# caf\xe9\ncolor = \"sonar\"\n";
    std::fs::write(&path, bytes).unwrap();
    assert!(save::save(&path, &Settings::default()).is_err());
    assert_eq!(std::fs::read(&path).unwrap(), bytes);
}

/// A file written on Windows keeps its `\r\n` line endings: saving it
/// unchanged leaves it byte for byte, and an edit changes only its value
/// (the parser had turned every line ending into `\n`); a key added after
/// its blank last line gets one blank line before it, not two.
#[test]
fn windows_line_endings_are_kept() {
    let input = "# mine\r\ncolor = \"sonar\"\r\n\r\n# more\r\nseed = 5\r\n";
    let s = loaded(input);
    assert_eq!(merge(input, &s).unwrap(), input);
    let edited = Settings {
        color: ColorMode::Mono,
        cragginess: 12,
        ..s
    };
    let out = merge(input, &edited).unwrap();
    assert!(
        out.starts_with("# mine\r\ncolor = \"mono\"\r\n\r\n# more\r\nseed = 5\r\n"),
        "{out:?}"
    );
    assert!(!out.replace("\r\n", "").contains('\n'), "{out:?}");
    assert_eq!(loaded(&out), edited);
    // A key added after a file's blank last line: one blank line before it.
    let added = merge("seed = 5\r\n\r\n", &edited).unwrap();
    assert!(added.starts_with("seed = 5\r\n\r\n# "), "{added:?}");
    assert!(!added.ends_with("\r\n\r\n"), "{added:?}");
    let unix = merge("seed = 5\n\n", &edited).unwrap();
    assert_eq!(unix.replace('\n', "\r\n"), added);
    // Mixed endings are no Windows file: the parser's `\n` throughout.
    let mixed = "seed = 5\r\ncolor = \"sonar\"\n";
    assert_eq!(
        merge(mixed, &loaded(mixed)).unwrap(),
        "seed = 5\ncolor = \"sonar\"\n"
    );
}

/// A file in UTF-16 with its mark (Windows PowerShell 5's `>`, Notepad's
/// "Unicode") is read as its text, and a save writes it back in UTF-16:
/// its comments and keys kept, only the edited value changed. Before, the
/// save refused it ("not valid UTF-8 text") and loading ignored it. A
/// UTF-8 file's mark (older Notepad's) is kept too; a save dropped it.
#[test]
fn a_utf16_file_is_read_and_saved_back_in_utf16() {
    use mountains::settings::text::{Form, encode};
    let dir = scratch("utf16");
    let path = dir.join("mountains.toml");
    let text = "# mine \u{2603}\r\ncolor = \"sonar\"\r\nseed = 5\r\n";
    for form in [Form::Utf16Le, Form::Utf16Be, Form::Utf8Bom] {
        std::fs::write(&path, encode(text, form)).unwrap();
        let mut read = Settings::default();
        assert!(load::apply_file(&mut read, &path).is_empty());
        assert_eq!((read.color, read.seed), (ColorMode::Sonar, Some(5)));
        let edited = Settings {
            color: ColorMode::Mono,
            ..read
        };
        save::save(&path, &edited).unwrap();
        let saved = std::fs::read(&path).unwrap();
        let expected = text.replace("\"sonar\"", "\"mono\"");
        assert_eq!(saved, encode(&expected, form), "{form:?}");
    }
}

/// A UTF-16 file whose text breaks is refused where it breaks, and left
/// as it is.
#[test]
fn a_broken_utf16_file_is_never_overwritten() {
    let dir = scratch("utf16-broken");
    let path = dir.join("mountains.toml");
    let mut bytes = vec![0xff, 0xfe];
    for c in "seed = 5\n# ".bytes() {
        bytes.extend([c, 0]);
    }
    bytes.extend(0xdc00u16.to_le_bytes());
    std::fs::write(&path, &bytes).unwrap();
    let err = save::save(&path, &Settings::default()).unwrap_err();
    assert_eq!(err.position, Some((2, 3)), "{err}");
    assert!(err.to_string().contains("not valid UTF-16 text"), "{err}");
    assert_eq!(std::fs::read(&path).unwrap(), bytes);
    let problems = load::apply_file(&mut Settings::default(), &path);
    assert_eq!(problems.len(), 1, "{problems:?}");
    assert_eq!(problems[0].position, Some((2, 3)));
}

#[test]
fn an_invalid_value_is_never_saved() {
    let dir = scratch("invalid");
    let path = dir.join("mountains.toml");
    std::fs::write(&path, "cragginess = 7\n").unwrap();
    for bad in [
        Settings {
            cragginess: 500,
            ..Settings::default()
        },
        Settings {
            sea_level: f32::NAN,
            ..Settings::default()
        },
        Settings {
            rotation: 45,
            ..Settings::default()
        },
    ] {
        let err = save::save(&path, &bad).unwrap_err();
        assert!(err.message.contains("not allowed"), "{err}");
        assert_eq!(read(&path), "cragginess = 7\n");
    }
}

#[test]
fn a_missing_file_starts_from_the_commented_defaults() {
    let dir = scratch("new");
    let path = dir.join("sub").join("mountains.toml");
    let s = Settings {
        color: ColorMode::Sonar,
        ..Settings::default()
    };
    save::save(&path, &s).unwrap();
    let text = read(&path);
    assert!(text.contains("color = \"sonar\"\n"), "{text}");
    assert!(text.starts_with("# mountains: preferences"), "{text}");
    assert_eq!(loaded(&text), s);
}

#[test]
fn saving_twice_changes_nothing_the_second_time() {
    let dir = scratch("twice");
    let path = dir.join("mountains.toml");
    std::fs::copy(data("commented.toml"), &path).unwrap();
    let mut s = loaded(&read(&path));
    s.cragginess = 3;
    save::save(&path, &s).unwrap();
    let first = read(&path);
    save::save(&path, &s).unwrap();
    assert_eq!(read(&path), first);
}

/// The settings screen's advice follows the cause: Edit file mends a
/// broken file, not a full disk or a folder in the way (it advised Edit
/// file for every failure).
#[test]
fn the_advice_after_a_failed_save_follows_its_cause() {
    let dir = scratch("advice");
    let broken = dir.join("broken.toml");
    std::fs::write(&broken, "cragginess = \n").unwrap();
    let e = save::save(&broken, &Settings::default()).unwrap_err();
    assert_eq!(e.io, None);
    assert!(e.advice().contains("Edit file"), "{}", e.advice());

    // A file where the preferences' folder should be.
    std::fs::write(dir.join("in-the-way"), "").unwrap();
    let blocked = dir.join("in-the-way").join("mountains.toml");
    let e = save::save(&blocked, &Settings::default()).unwrap_err();
    assert!(e.io.is_some(), "{e}");
    assert!(!e.advice().contains("Edit file"), "{}", e.advice());

    let full = save::SaveError {
        path: dir.join("mountains.toml"),
        position: None,
        message: "cannot write: No space left on device (os error 28)".into(),
        io: Some(std::io::ErrorKind::StorageFull),
    };
    assert!(full.advice().starts_with("Free some space on the disk"));
    let read_only = save::SaveError {
        io: Some(std::io::ErrorKind::ReadOnlyFilesystem),
        ..full
    };
    assert!(read_only.advice().contains("writable"));
}

/// A preferences file its owner made read-only is not replaced by a save
/// (the rename asks leave of the folder, not of the file): refused, with
/// the advice to make it writable, the file as it was.
#[test]
fn a_read_only_preferences_file_is_not_replaced() {
    let dir = scratch("read-only");
    let file = dir.join("mountains.toml");
    std::fs::write(&file, "seed = 5\n").unwrap();
    let mut permissions = std::fs::metadata(&file).unwrap().permissions();
    permissions.set_readonly(true);
    std::fs::set_permissions(&file, permissions).unwrap();
    let e = save::save(&file, &Settings::default()).unwrap_err();
    assert!(e.message.starts_with("cannot write: is read-only"), "{e}");
    assert!(e.advice().contains("writable"), "{}", e.advice());
    assert_eq!(std::fs::read_to_string(&file).unwrap(), "seed = 5\n");
}

/// A save keeps the file's leave to read it: a private (0600) preferences
/// file, which may hold where its owner lives (`latitude`, `longitude`),
/// came back readable by all (0644) from the new file's defaults.
#[cfg(unix)]
#[test]
fn a_save_keeps_a_private_file_private() {
    use std::os::unix::fs::PermissionsExt;
    let dir = scratch("private");
    let file = dir.join("mountains.toml");
    std::fs::write(&file, "latitude = 51.5\n").unwrap();
    std::fs::set_permissions(&file, std::fs::Permissions::from_mode(0o600)).unwrap();
    let settings = Settings {
        seed: Some(7),
        ..Settings::default()
    };
    save::save(&file, &settings).unwrap();
    assert!(std::fs::read_to_string(&file).unwrap().contains("seed = 7"));
    let mode = std::fs::metadata(&file).unwrap().permissions().mode();
    assert_eq!(mode & 0o777, 0o600, "{mode:o}");
}

/// The new text of a private file is private while it is written: its
/// temporary file was made readable by all (the umask's 0644) and made
/// private only once written, so anyone could open it in between and
/// read on through that open file.
#[cfg(unix)]
#[test]
fn a_private_file_s_new_text_is_never_readable_by_others() {
    use std::os::unix::fs::PermissionsExt;
    let dir = scratch("private-tmp");
    let file = dir.join("mountains.toml");
    std::fs::write(&file, "latitude = 51.5\n").unwrap();
    std::fs::set_permissions(&file, std::fs::Permissions::from_mode(0o600)).unwrap();
    let mut seen = Vec::new();
    mountains::fsutil::write_atomic_with(&file, |w| {
        w.write_all(b"latitude = 48.2\n")?;
        for entry in std::fs::read_dir(&dir)? {
            let entry = entry?;
            let mode = entry.metadata()?.permissions().mode() & 0o777;
            seen.push((entry.file_name(), mode));
        }
        Ok(())
    })
    .unwrap();
    let temporary: Vec<_> = seen.iter().filter(|(n, _)| n != "mountains.toml").collect();
    assert_eq!(temporary.len(), 1, "{seen:?}");
    assert_eq!(temporary[0].1, 0o600, "{seen:?}");
    assert_eq!(std::fs::read_to_string(&file).unwrap(), "latitude = 48.2\n");
}

fn key(name: &str) -> &'static mountains::settings::keys::Key {
    mountains::settings::keys::find(name).unwrap()
}

#[test]
fn saving_changes_keeps_a_key_another_program_changed_since_it_was_read() {
    let path = scratch("concurrent").join("mountains.toml");
    std::fs::write(&path, "# mine\ncragginess = 40 # sharp\n").unwrap();
    let mut edited = loaded(&read(&path));
    edited.cragginess = 12;
    replace_keeping_mtime(
        &path,
        "# mine\ncragginess = 40 # sharp\nzzz = 1\ncolor = \"sonar\"\n",
    );
    save::save_changes(&path, &edited, &[key("cragginess")]).unwrap();
    assert_eq!(
        read(&path),
        "# mine\ncragginess = 12 # sharp\nzzz = 1\ncolor = \"sonar\"\n",
        "the other program's color stays, the edit is written, comments kept"
    );
}

#[test]
fn a_key_changed_both_on_disk_and_in_the_save_takes_the_saved_value() {
    let path = scratch("both").join("mountains.toml");
    std::fs::write(&path, "color = \"gray\"\nheight = 2\n").unwrap();
    let mut edited = loaded(&read(&path));
    edited.color = ColorMode::Natural;
    replace_keeping_mtime(&path, "color = \"sonar\"\nheight = 3\n");
    save::save_changes(&path, &edited, &[key("color")]).unwrap();
    assert_eq!(read(&path), "color = \"natural\"\nheight = 3\n");
}

#[test]
fn saving_no_changes_leaves_a_file_changed_elsewhere_as_it_is() {
    let path = scratch("nochange").join("mountains.toml");
    std::fs::write(&path, "cragginess = 40\n").unwrap();
    let edited = loaded(&read(&path));
    replace_keeping_mtime(&path, "cragginess = 41\ncolor = \"sonar\"\n");
    save::save_changes(&path, &edited, &[]).unwrap();
    assert_eq!(read(&path), "cragginess = 41\ncolor = \"sonar\"\n");
}

/// A preferences file that is a link to nowhere is someone's link (say, to
/// a file on a disk not mounted yet): a save refuses it, naming it, and the
/// link stays a link, never replaced by a file of the defaults.
#[cfg(unix)]
#[test]
fn a_link_to_nowhere_is_never_replaced_by_a_save() {
    let dir = scratch("nowhere");
    let path = dir.join("mountains.toml");
    std::os::unix::fs::symlink(dir.join("gone").join("prefs.toml"), &path).unwrap();
    let e = save::save(&path, &Settings::default()).unwrap_err();
    assert!(
        e.to_string().contains("cannot read: a link to nowhere"),
        "{e}"
    );
    assert!(std::fs::symlink_metadata(&path).unwrap().is_symlink());
    assert!(!dir.join("gone").exists());
}
