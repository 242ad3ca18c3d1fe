//! The binary's one-shot commands, run as a user would run them.

use crate::common::headless;

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn mountains(args: &[&str]) -> Output {
    command(args).output().expect("run mountains")
}

/// The binary with `args`, its preferences and data in a scratch home.
fn command(args: &[&str]) -> Command {
    let mut command = Command::new(env!("CARGO_BIN_EXE_mountains"));
    command
        .args(args)
        .env("HOME", scratch("home"))
        .env("XDG_CONFIG_HOME", scratch("home").join("config"))
        .env("XDG_DATA_HOME", scratch("home").join("data"));
    command
}

/// A folder of this test process's own, emptied the first time one is
/// asked for: a process number comes round again, and what an earlier
/// run's test left (`no-maps`, made once its warning was seen) turned a
/// later run's warning off, one run in a dozen.
fn scratch(name: &str) -> PathBuf {
    static EMPTIED: std::sync::Once = std::sync::Once::new();
    let root = std::env::temp_dir().join(format!("mountains-commands-{}", std::process::id()));
    EMPTIED.call_once(|| {
        let _ = std::fs::remove_dir_all(&root);
    });
    let dir = root.join(name);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// `mountains args`, which must succeed.
fn run(args: &[&str]) -> Output {
    let o = mountains(args);
    assert!(o.status.success(), "{args:?}: {}", stderr(&o));
    o
}

/// `heightmap -o to` of seed 3's 33x33 grid, which must succeed.
fn small_data_set(to: &Path) -> Output {
    run(&[
        "heightmap",
        "--set",
        "detail=5",
        "--set",
        "seed=3",
        "-o",
        &arg(to),
    ])
}

/// `p` as an argument.
fn arg(p: &Path) -> String {
    p.to_str().unwrap().to_string()
}

fn png_size(path: &Path) -> (u32, u32) {
    let decoder = png::Decoder::new(std::io::BufReader::new(std::fs::File::open(path).unwrap()));
    let reader = decoder.read_info().unwrap();
    (reader.info().width, reader.info().height)
}

#[test]
fn render_writes_a_png_of_the_asked_size_and_prints_the_seed() {
    let out = scratch("render").join("m.png");
    let o = mountains(&[
        "render",
        "--size",
        "160x90",
        "--set",
        "seed=42",
        "--set",
        "detail=5",
        "-o",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(png_size(&out), (160, 90));
    assert!(String::from_utf8_lossy(&o.stdout).contains("seed 42"));
}

#[test]
fn render_prints_a_random_seed_that_reproduces_the_picture() {
    let dir = scratch("reproduce");
    let (a, b) = (dir.join("a.png"), dir.join("b.png"));
    let o = mountains(&[
        "render",
        "--size",
        "64x48",
        "--set",
        "detail=5",
        "-o",
        a.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let stdout = String::from_utf8_lossy(&o.stdout).into_owned();
    let seed = stdout.split_whitespace().nth(1).expect("seed printed");
    let set = format!("seed={seed}");
    let o = mountains(&[
        "render",
        "--size",
        "64x48",
        "--set",
        "detail=5",
        "--set",
        &set,
        "-o",
        b.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(std::fs::read(&a).unwrap(), std::fs::read(&b).unwrap());
}

#[test]
fn bad_arguments_exit_2_and_name_the_flag() {
    for (args, needle) in [
        (vec!["--bogus"], "--bogus"),
        (vec!["render", "-o", "x.png", "--size", "wide"], "--size"),
        (
            vec!["render", "-o", "x.png", "--set", "detail=99"],
            "detail",
        ),
        (
            vec!["render", "-o", "x.png", "--set", "colour=red"],
            "did you mean `color`",
        ),
        (
            vec!["render", "-o", "x.png", "--size", "100000x100000"],
            "too large",
        ),
    ] {
        let o = mountains(&args);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
        assert!(stderr(&o).contains(needle), "{args:?}: {}", stderr(&o));
    }
}

/// Every error begins the same way and names the flag it is about (or the
/// argument nothing takes): they began `mountains: -o x.bmp:` or
/// `mountains: error: --set:`, and `/p:` said only "`` is not a window
/// handle".
#[test]
fn every_error_says_error_and_names_its_flag() {
    let dir = scratch("errors");
    let missing = dir.join("none/m.toml").display().to_string();
    let no_dir = dir.join("none/x.png").display().to_string();
    let missing = missing.as_str();
    fn render<'a>(more: &[&'a str]) -> Vec<&'a str> {
        [&["render", "-o", "x.png"], more].concat()
    }
    let cases: Vec<(Vec<&str>, &str)> = vec![
        (vec!["--bogus"], "--bogus"),
        (vec!["render", "-o", "x.bmp"], "-o x.bmp"),
        (vec!["heightmap", "-o", "x.jpg"], "-o x.jpg"),
        (vec!["render"], "-o"),
        (vec!["/p:"], "/p"),
        (vec!["/p", "junk"], "/p"),
        (vec!["/P:junk"], "/P"),
        (vec!["-c:0"], "-c"),
        (vec!["--window-id", "junk"], "--window-id"),
        (vec!["--window-id", "0x100000000"], "--window-id"),
        (vec!["--layer", "wallpaper"], "--layer"),
        (vec!["-delay", "soon"], "-delay"),
        (vec!["-cragginess"], "-cragginess"),
        (vec!["--window", "--root"], "--root"),
        (vec!["--size", "64x36"], "--size"),
        (render(&["--size", "wide"]), "--size"),
        (render(&["--size", "0x5"]), "--size"),
        (render(&["--size", "40000x2"]), "--size"),
        (render(&["--set", "cragginess=999"]), "--set"),
        (render(&["-cragginess", "999"]), "-cragginess"),
        (render(&["--sea-level", "7"]), "--sea-level"),
        (render(&["-color", "pink"]), "-color"),
        (render(&["--set", "nokey=1"]), "--set"),
        (render(&["--set", "novalue"]), "--set"),
        (render(&["--config", ""]), "--config"),
        (render(&["--config", missing]), "--config"),
        (render(&["--open", "/nonexistent/h.png"]), "--open"),
        (vec!["--check-config", missing], "--check-config"),
        (vec!["--config", missing, "--check-config"], "--config"),
        (
            vec![
                "render", "--size", "8x8", "--set", "detail=4", "-o", &no_dir,
            ],
            "-o",
        ),
        (vec!["heightmap", "--set", "detail=4", "-o", &no_dir], "-o"),
    ];
    for (args, flag) in cases {
        let o = mountains(&args);
        let err = stderr(&o);
        assert!(!o.status.success(), "{args:?}: {err}");
        let first = err.lines().next().unwrap_or_default();
        assert!(first.starts_with("mountains: error: "), "{args:?}: {err}");
        assert!(first.contains(flag), "{args:?}: no {flag} in {first}");
    }
}

/// A mistake on the command line is said in a line that stays on the
/// screen: the message with the nearest flag, and where to read the rest,
/// not the whole usage after it.
#[test]
fn a_mistyped_flag_is_answered_in_two_lines() {
    let o = mountains(&["--colour", "sonar"]);
    assert_eq!(o.status.code(), Some(2));
    let err = stderr(&o);
    assert_eq!(
        err.lines().collect::<Vec<_>>(),
        [
            "mountains: error: unknown argument `--colour`; did you mean `--color`?",
            "`mountains --help` lists every mode, flag and key."
        ],
        "{err}"
    );
}

/// One rule for a preferences file everywhere: a bad value is a warning
/// naming file:line:key, its key keeps the default and the picture is
/// made; the file is left as it was.
#[test]
fn render_warns_about_a_broken_config_value_and_draws_on_the_default() {
    let dir = scratch("broken");
    let config = dir.join("m.toml");
    let text = "# mine\ncragginess = 999\n";
    std::fs::write(&config, text).unwrap();
    let out = dir.join("x.png");
    let o = mountains(&[
        "render",
        "--config",
        config.to_str().unwrap(),
        "--size",
        "64x36",
        "-o",
        out.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let err = stderr(&o);
    assert!(
        err.contains("mountains: warning: ")
            && err.contains("m.toml:2:14: key `cragginess`")
            && err.contains("using the default"),
        "{err}"
    );
    assert!(!err.contains("error:"), "{err}");
    assert_eq!(png_size(&out), (64, 36));
    assert_eq!(std::fs::read_to_string(&config).unwrap(), text);
}

/// A file that is not TOML, or not text, is used not at all (a syntax
/// error stops the reading): the warning says so, where a bad value's says
/// that its key keeps the default.
#[test]
fn render_says_when_nothing_in_a_broken_file_was_used() {
    let dir = scratch("unused");
    let warning = |name: &str, bytes: &[u8]| {
        let config = dir.join(name);
        std::fs::write(&config, bytes).unwrap();
        let out = dir.join("x.png");
        let o = mountains(&[
            "render",
            "--config",
            &arg(&config),
            "--size",
            "16x9",
            "-o",
            &arg(&out),
        ]);
        assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
        assert_eq!(std::fs::read(&config).unwrap(), bytes);
        stderr(&o)
    };
    for (name, bytes) in [
        ("syntax.toml", &b"seed = 5\ncragginess = \n"[..]),
        ("latin1.toml", &b"seed = 5\n# caf\xe9\n"[..]),
    ] {
        let err = warning(name, bytes);
        assert!(
            err.contains("nothing in the file was used: using the defaults"),
            "{name}: {err}"
        );
    }
    let err = warning("value.toml", b"seed = 5\ncragginess = 500\n");
    assert!(
        err.contains("using the default") && !err.contains("nothing in the file"),
        "{err}"
    );
}

/// A key's flag takes its value after `=` as every other flag does, and a
/// flag that is a value of its own (`--no-shadows`) takes none.
#[test]
fn a_key_flag_takes_its_value_after_an_equals_sign() {
    let dir = scratch("equals");
    let (a, b) = (dir.join("a.png"), dir.join("b.png"));
    let o = mountains(&[
        "render",
        "--seed=5",
        "--color=sonar",
        "--size",
        "32x18",
        "-o",
        &arg(&a),
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(String::from_utf8_lossy(&o.stdout).starts_with("seed 5 -> "));
    let o = mountains(&[
        "render",
        "--set",
        "seed=5",
        "--set",
        "color=sonar",
        "--size",
        "32x18",
        "-o",
        &arg(&b),
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert_eq!(std::fs::read(&a).unwrap(), std::fs::read(&b).unwrap());
    for typed in ["--no-shadows=true", "--shadows=false"] {
        let o = mountains(&["render", typed, "-o", &arg(&a)]);
        assert_eq!(o.status.code(), Some(2));
        let flag = typed.split('=').next().unwrap();
        assert!(
            stderr(&o).contains(&format!(
                "{flag} takes no value: -shadows turns it on, -no-shadows off"
            )),
            "{}",
            stderr(&o)
        );
    }
}

/// `--set` is typed for this one run: a bad value is an error, said as one,
/// and nothing is drawn.
#[test]
fn a_bad_set_value_is_an_error_that_says_so() {
    let out = scratch("bad-set").join("x.png");
    let o = mountains(&[
        "render",
        "--set",
        "cragginess=999",
        "--size",
        "64x36",
        "-o",
        out.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("mountains: error: --set: key `cragginess`"),
        "{}",
        stderr(&o)
    );
    assert!(!out.exists());
}

/// `--config /dev/null` is the usual way to say "no preferences": the
/// defaults, with no word about it, for `render` and `--check-config`.
#[cfg(unix)]
#[test]
fn config_dev_null_means_the_defaults() {
    let out = scratch("dev-null").join("x.png");
    let o = mountains(&[
        "render",
        "--config",
        "/dev/null",
        "--size",
        "64x36",
        "-o",
        out.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert_eq!(stderr(&o), "");
    assert_eq!(png_size(&out), (64, 36));
    for args in [
        &["--check-config", "/dev/null"][..],
        &["--config", "/dev/null", "--check-config"],
    ] {
        let o = mountains(args);
        assert_eq!(o.status.code(), Some(0), "{args:?}: {}", stderr(&o));
        let said = String::from_utf8_lossy(&o.stdout);
        assert!(said.contains("the defaults are in use"), "{args:?}: {said}");
    }
}

#[test]
fn check_config_exits_0_for_good_and_1_for_bad() {
    let dir = scratch("check");
    let good = dir.join("good.toml");
    std::fs::write(&good, "color = \"sonar\"\n").unwrap();
    let o = mountains(&["--check-config", good.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let bad = dir.join("bad.toml");
    std::fs::write(&bad, "color = \"pink\"\n").unwrap();
    let o = mountains(&["--check-config", bad.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(1));
    assert!(
        stderr(&o).contains("bad.toml:1:9: key `color`"),
        "{}",
        stderr(&o)
    );
    let shipped = concat!(env!("CARGO_MANIFEST_DIR"), "/config/default.toml");
    assert_eq!(
        mountains(&["--check-config", shipped]).status.code(),
        Some(0)
    );
}

#[test]
fn help_lists_every_key() {
    let o = mountains(&["--help"]);
    assert!(o.status.success());
    let text = String::from_utf8_lossy(&o.stdout);
    for key in mountains::settings::keys::KEYS {
        assert!(text.contains(key.name), "--help lacks {}", key.name);
    }
    for binding in mountains::saver::input::WINDOW_KEYS {
        let line = format!("  {:<15} {}", binding.label, binding.doc);
        assert!(text.contains(&line), "--help lacks the window key {line:?}");
    }
}

#[test]
fn heightmap_saves_a_data_set_that_loads_back_with_its_seed() {
    let out = scratch("heightmap").join("h.png");
    let o = mountains(&[
        "heightmap",
        "--set",
        "seed=7",
        "--set",
        "detail=5",
        "-o",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(String::from_utf8_lossy(&o.stdout).contains("seed 7"));
    let data = mountains::terrain::heightmap::load(&out).unwrap();
    assert_eq!((data.seed, data.field.size()), (Some(7), 33));
    let expected = mountains::terrain::generate(&settings_with(7, 5), 7);
    let step = (expected.max() - expected.min()) / 65535.0;
    for (a, b) in data.field.heights().iter().zip(expected.heights()) {
        assert!((a - b).abs() <= step, "{a} vs {b}");
    }
}

#[test]
fn render_open_draws_a_saved_data_set() {
    let dir = scratch("open");
    let (h, a, b) = (dir.join("h.png"), dir.join("a.png"), dir.join("b.png"));
    run(&[
        "heightmap",
        "--set",
        "detail=5",
        "--set",
        "seed=9",
        "-o",
        &arg(&h),
    ]);
    run(&[
        "render",
        "--size",
        "80x60",
        "--open",
        &arg(&h),
        "-o",
        &arg(&a),
    ]);
    run(&[
        "render",
        "--size",
        "80x60",
        "--open",
        &arg(&h),
        "--set",
        "color=sonar",
        "-o",
        &arg(&b),
    ]);
    assert_ne!(
        std::fs::read(&a).unwrap(),
        std::fs::read(&b).unwrap(),
        "sonar looks like natural"
    );
    let o = mountains(&[
        "render",
        "-o",
        &arg(&a),
        "--open",
        &arg(&dir.join("missing.png")),
    ]);
    assert_eq!(o.status.code(), Some(1));
    assert!(stderr(&o).contains("missing.png"), "{}", stderr(&o));
}

/// A raw data set (`-o NAME.r16`, as terrain tools import and export)
/// opens again: saved raw once more it gives the same bytes (the same
/// samples, rows and byte order), and it draws. A raw file whose length
/// is no square of samples is refused, naming the file and its length.
#[test]
fn a_raw_data_set_opens_and_saves_back_the_same() {
    let dir = scratch("open-raw");
    let [a, b, picture, bad] = ["a.r16", "b.RAW", "p.png", "bad.r16"].map(|f| dir.join(f));
    small_data_set(&a);
    let o = run(&["heightmap", "--open", &arg(&a), "-o", &arg(&b)]);
    assert!(
        stderr(&o).contains("a 33x33 square, little-endian"),
        "{}",
        stderr(&o)
    );
    let (saved, again) = (std::fs::read(&a).unwrap(), std::fs::read(&b).unwrap());
    assert_eq!(saved.len(), 33 * 33 * 2);
    assert!(saved == again, "the raw data set came back changed");
    run(&[
        "render",
        "--size",
        "80x60",
        "--open",
        &arg(&a),
        "-o",
        &arg(&picture),
    ]);
    assert_eq!(png_size(&picture), (80, 60));
    // A PNG data set named as raw is read as the PNG it is.
    let png = dir.join("h.png");
    small_data_set(&png);
    std::fs::copy(&png, &bad).unwrap();
    run(&["heightmap", "--open", &arg(&bad), "-o", &arg(&b)]);
    assert!(
        std::fs::read(&b).unwrap() == saved,
        "a PNG named .r16 read as raw"
    );
    std::fs::write(&bad, &saved[..1000]).unwrap();
    let o = mountains(&["render", "--open", &arg(&bad), "-o", &arg(&picture)]);
    assert_eq!(o.status.code(), Some(1));
    let err = stderr(&o);
    assert!(
        err.contains("bad.r16") && err.contains("is 1000 bytes"),
        "{err}"
    );
}

/// `--open -` reads a data set from standard input, a PNG or raw
/// samples: `heightmap -o - | mountains render --open -` draws what the
/// file does, and raw samples piped in save back the same.
#[test]
fn a_data_set_opens_from_standard_input() {
    use std::io::Write;
    let dir = scratch("open-stdin");
    let [png, raw, from_file, piped, raw_again] =
        ["h.png", "h.r16", "file.png", "piped.png", "again.r16"].map(|f| dir.join(f));
    small_data_set(&png);
    small_data_set(&raw);
    let piping = |input: &Path, args: &[&str]| {
        let mut child = command(args)
            .stdin(std::process::Stdio::piped())
            .stdout(std::process::Stdio::piped())
            .stderr(std::process::Stdio::piped())
            .spawn()
            .expect("run mountains");
        let bytes = std::fs::read(input).unwrap();
        child.stdin.take().unwrap().write_all(&bytes).unwrap();
        let o = child.wait_with_output().unwrap();
        assert!(o.status.success(), "{args:?}: {}", stderr(&o));
    };
    let size = ["render", "--size", "80x60"];
    run(&[&size[..], &["--open", &arg(&png), "-o", &arg(&from_file)]].concat());
    piping(
        &png,
        &[&size[..], &["--open", "-", "-o", &arg(&piped)]].concat(),
    );
    assert!(
        std::fs::read(&from_file).unwrap() == std::fs::read(&piped).unwrap(),
        "the piped data set drew another picture"
    );
    piping(&raw, &["heightmap", "--open", "-", "-o", &arg(&raw_again)]);
    assert!(std::fs::read(&raw).unwrap() == std::fs::read(&raw_again).unwrap());
}

/// `--open` draws a data set under the look its file recorded (and the
/// height): the picture the same file makes with those keys given on the
/// command line, and, but for the 16-bit heights' rounding, the picture
/// `render` made of the mountain before it was saved; a look given on the
/// command line wins over the file's.
#[test]
fn render_open_draws_a_data_set_under_its_recorded_look() {
    let dir = scratch("open-look");
    let files = ["h.png", "made.png", "opened.png", "told.png", "theirs.png"].map(|f| dir.join(f));
    let [h, made, opened, told, theirs] = files.each_ref().map(|p| p.to_str().unwrap());
    let recorded = ["--set", "look=essay", "--set", "height=7"];
    let sets = [&recorded[..], &["--set", "detail=5", "--set", "seed=9"]].concat();
    run(&[&["heightmap", "-o", h][..], &sets].concat());
    run(&[&["render", "--size", "80x60", "-o", made][..], &sets].concat());
    run(&["render", "--size", "80x60", "--open", h, "-o", opened]);
    run(&[
        &["render", "--size", "80x60", "--open", h, "-o", told][..],
        &recorded,
    ]
    .concat());
    let look = "look=mountain-terrain";
    run(&[
        "render", "--size", "80x60", "--open", h, "--set", look, "-o", theirs,
    ]);
    let read = |p: &str| std::fs::read(p).unwrap();
    assert_eq!(
        read(opened),
        read(told),
        "not drawn under the keys its file recorded"
    );
    // Saving rounds the heights to 16 bits: an edge may cross a pixel
    // centre, no more (the essay's camera keeps its place exactly).
    let pixels = |p: &str| headless::read_rgb_png(Path::new(p));
    let (a, b) = (pixels(made), pixels(opened));
    let moved = a.iter().zip(&b).filter(|(x, y)| x != y).count();
    assert!(
        moved * 100 <= a.len(),
        "{moved} of {} pixels differ from the picture it was saved from",
        a.len()
    );
    assert_ne!(read(theirs), read(opened), "the command line's look lost");
}

fn settings_with(seed: u64, detail: u32) -> mountains::settings::Settings {
    mountains::settings::Settings {
        seed: Some(seed),
        detail: mountains::settings::Detail::Level(detail),
        ..Default::default()
    }
}

/// No preferences file is no mistake: the defaults are in use. A file named
/// with `--config` is checked, and so is every `--set`.
#[test]
fn check_config_without_a_file_is_fine_and_honours_config_and_set() {
    let o = mountains(&["--check-config"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let out = String::from_utf8_lossy(&o.stdout);
    assert!(out.contains("the defaults are in use"), "{out}");
    let dir = scratch("check-config-flags");
    let bad = dir.join("bad.toml");
    std::fs::write(&bad, "cragginess = 500\n").unwrap();
    let o = mountains(&["--config", bad.to_str().unwrap(), "--check-config"]);
    assert_eq!(o.status.code(), Some(1));
    assert!(
        stderr(&o).contains("bad.toml:1:14: key `cragginess`"),
        "{}",
        stderr(&o)
    );
    // A `--set` is typed for the run: a usage error (docs/refusals.md).
    let o = mountains(&["--check-config", "--set", "color=pink"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("--set: key `color`"), "{}", stderr(&o));
    let missing = dir.join("missing.toml");
    let o = mountains(&["--check-config", missing.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(1));
    assert!(
        stderr(&o).contains("missing.toml: no such file"),
        "{}",
        stderr(&o)
    );
}

/// A bad `--set` is exit 2 under `--check-config` whatever the file, and
/// is never hidden: not behind a named file that is missing, nor in the
/// "... and N more" of a file with many problems.
#[test]
fn check_config_always_says_a_bad_set() {
    let dir = scratch("check-config-sets");
    let missing = dir.join("missing.toml");
    let o = mountains(&["--check-config", &arg(&missing), "--set", "color=pink"]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    let err = stderr(&o);
    assert!(
        err.contains("--set: key `color`") && err.contains("no such file"),
        "{err}"
    );
    let many = dir.join("many.toml");
    let lines: String = (0..30).map(|n| format!("nonsense{n} = 1\n")).collect();
    std::fs::write(&many, lines).unwrap();
    let o = mountains(&["--check-config", &arg(&many), "--set", "color=pink"]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    let err = stderr(&o);
    assert!(err.contains("... and 10 more"), "{err}");
    assert!(err.contains("--set: key `color`"), "{err}");
}

/// `--config` and `--check-config` naming one file in two ways (through
/// `..`, a link) name one file to check, not two.
#[test]
fn check_config_and_config_naming_one_file_check_it() {
    let dir = scratch("check-config-one-file");
    let file = dir.join("p.toml");
    std::fs::write(&file, "seed = 5\n").unwrap();
    std::fs::create_dir_all(dir.join("sub")).unwrap();
    let other = dir.join("sub").join("..").join("p.toml");
    let o = mountains(&["--config", &arg(&file), "--check-config", &arg(&other)]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let two = dir.join("q.toml");
    std::fs::write(&two, "seed = 6\n").unwrap();
    let o = mountains(&["--config", &arg(&file), "--check-config", &arg(&two)]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
}

/// A `heightmaps_dir` that names no folder is well formed, but the slide
/// show would show none of it: `--check-config` warns, and the file is ok.
#[test]
fn check_config_warns_of_a_heightmaps_folder_that_is_not_there() {
    let dir = scratch("check-config-folder");
    let file = dir.join("p.toml");
    let missing = dir.join("no-maps");
    std::fs::write(&file, format!("heightmaps_dir = {:?}\n", arg(&missing))).unwrap();
    let o = mountains(&["--check-config", &arg(&file)]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let err = stderr(&o);
    assert!(
        err.contains("heightmaps_dir") && err.contains("no such folder"),
        "{err}"
    );
    std::fs::create_dir_all(&missing).unwrap();
    let o = mountains(&["--check-config", &arg(&file)]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(!stderr(&o).contains("no such folder"), "{}", stderr(&o));
}

/// The warning of a `heightmaps_dir` that names no folder names the file,
/// line and key, as a problem in the file is named (it named only the
/// key), and a file where the folder should be as not a folder (it said
/// "no such folder" of a file that is there).
#[test]
fn check_config_names_the_line_of_a_heightmaps_folder_that_is_not_there() {
    let dir = scratch("check-config-folder-line");
    let file = dir.join("p.toml");
    let in_the_way = dir.join("a-file");
    std::fs::write(&in_the_way, "").unwrap();
    for (target, what) in [
        (dir.join("no-maps"), "no such folder"),
        (in_the_way, "not a folder"),
    ] {
        let value = arg(&target);
        std::fs::write(&file, format!("seed = 5\nheightmaps_dir = {value:?}\n")).unwrap();
        let o = mountains(&["--check-config", &arg(&file)]);
        assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
        let said = format!(
            "mountains: warning: {}:2:18: key `heightmaps_dir`: {value:?}: {what} ({value}); \
             every slide is generated\n",
            file.display()
        );
        assert_eq!(stderr(&o), said);
    }
}

/// A relative `heightmaps_dir` in a preferences file is the file's
/// neighbour, from whatever folder the program starts: it was looked for
/// in the current folder, so `--check-config` run elsewhere, and the
/// saver started by xscreensaver in the home folder, looked elsewhere.
#[test]
fn a_relative_heightmaps_folder_is_beside_its_preferences_file() {
    let dir = scratch("relative-maps");
    let (home, elsewhere) = (dir.join("prefs"), dir.join("elsewhere"));
    std::fs::create_dir_all(home.join("maps")).unwrap();
    std::fs::create_dir_all(elsewhere.join("other")).unwrap();
    let file = home.join("p.toml");
    for (written, warned) in [("maps", false), ("./maps", false), ("other", true)] {
        std::fs::write(&file, format!("heightmaps_dir = {written:?}\n")).unwrap();
        let o = command(&["--check-config", &arg(&file)])
            .current_dir(&elsewhere)
            .output()
            .expect("run mountains");
        assert_eq!(o.status.code(), Some(0), "{written}: {}", stderr(&o));
        let err = stderr(&o);
        assert_eq!(err.contains("no such folder"), warned, "{written}: {err}");
        let meant = format!("no such folder ({})", arg(&home.join(written)));
        assert!(!warned || err.contains(&meant), "{written}: {err}");
    }
}

/// A `heightmaps_dir` typed for the run (`--heightmaps-dir DIR`, `--set
/// heightmaps_dir=DIR`) that names no folder is warned of beside
/// `--check-config` as the file's is, named as typed: it was "ok" alone.
#[test]
fn check_config_warns_of_a_heightmaps_folder_typed_that_is_not_there() {
    let dir = scratch("check-config-folder-typed");
    let file = dir.join("p.toml");
    std::fs::write(&file, "seed = 5\n").unwrap();
    let file = arg(&file);
    let missing = arg(&dir.join("no-maps"));
    let set = format!("heightmaps_dir={missing}");
    for (args, typed) in [
        (
            vec!["--heightmaps-dir", &missing],
            format!("--heightmaps-dir {missing}"),
        ),
        (vec!["--set", &set], format!("--set {set}")),
    ] {
        let args = [&["--check-config", &file][..], &args].concat();
        let o = mountains(&args);
        assert_eq!(o.status.code(), Some(0), "{args:?}: {}", stderr(&o));
        let said = format!(
            "mountains: warning: {typed}: no such folder ({missing}); every slide is generated\n"
        );
        assert_eq!(stderr(&o), said, "{args:?}");
    }
    let o = mountains(&["--check-config", &file, "--heightmaps-dir", &arg(&dir)]);
    assert!(stderr(&o).is_empty(), "{}", stderr(&o));
}

/// A key this version does not know (the settings screen keeps it) is a
/// warning with a suggestion for `render`, and still a failure for
/// `--check-config`.
#[test]
fn an_unknown_key_is_a_warning_for_render_and_an_error_for_check_config() {
    let dir = scratch("unknown-key");
    let config = dir.join("newer.toml");
    std::fs::write(&config, "colour = \"sonar\"\nfuture_key = 3\n").unwrap();
    let out = dir.join("m.png");
    let o = mountains(&[
        "render",
        "--config",
        config.to_str().unwrap(),
        "--size",
        "64x36",
        "-o",
        out.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(out.exists());
    let err = stderr(&o);
    assert!(
        err.contains("warning: ") && err.contains("did you mean `color`?"),
        "{err}"
    );
    assert!(err.contains("key `future_key`"), "{err}");
    let o = mountains(&["--check-config", config.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(1));
    assert!(stderr(&o).contains("error: "), "{}", stderr(&o));
}

/// `-o` writes what its extension says, or refuses before any work.
#[test]
fn the_output_extension_chooses_the_format() {
    let dir = scratch("formats");
    let jpg = dir.join("m.JPG");
    let o = mountains(&[
        "render",
        "--size",
        "96x54",
        "--set",
        "seed=3",
        "-o",
        jpg.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let bytes = std::fs::read(&jpg).unwrap();
    assert_eq!(&bytes[..3], &[0xff, 0xd8, 0xff], "not a JPEG");
    let raw = dir.join("h.r16");
    let o = small_data_set(&raw);
    assert_eq!(std::fs::read(&raw).unwrap().len(), 33 * 33 * 2);
    assert!(String::from_utf8_lossy(&o.stdout).contains("33x33 16-bit little-endian"));
    for (args, allowed) in [
        (&["render", "-o"][..], ".png, .jpg, .jpeg"),
        (&["heightmap", "-o"][..], ".png, .r16, .raw"),
    ] {
        let bad = dir.join("out.gif");
        let mut all = args.to_vec();
        all.push(bad.to_str().unwrap());
        let o = mountains(&all);
        assert_eq!(o.status.code(), Some(2));
        let err = stderr(&o);
        assert!(
            err.contains("-o ") && err.contains("cannot be written as .gif"),
            "{err}"
        );
        assert!(err.contains(allowed), "{err}");
        assert!(!bad.exists());
    }
}

/// Which standard stream [`unread`] leaves with no reader.
#[derive(Clone, Copy, Debug)]
enum Stream {
    Stdout,
    Stderr,
}

/// Runs the binary with `stream` a pipe whose read end is closed before the
/// program starts (as `mountains --help | true` ends up when `true` is
/// quick): every write to it fails with EPIPE. The other stream is kept.
/// There is no display, so a window mode ends at once with its messages.
fn unread(args: &[&str], stream: Stream) -> Output {
    let (reader, writer) = std::io::pipe().expect("a pipe");
    drop(reader);
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_mountains"));
    cmd.args(args)
        .env_remove("DISPLAY")
        .env_remove("WAYLAND_DISPLAY")
        .env("HOME", scratch("home"))
        .env("XDG_CONFIG_HOME", scratch("home").join("config"))
        .env("XDG_DATA_HOME", scratch("home").join("data"));
    match stream {
        Stream::Stdout => cmd.stdout(writer),
        Stream::Stderr => cmd.stderr(writer),
    };
    cmd.output().expect("run mountains")
}

/// A closed stdout is a reader that left (`| head -1`, `| true`): every
/// printing command drops what it had to say there, without a panic (exit
/// 101) or a word on stderr, and ends with the status it would have had: a
/// file written is still a success, a check's verdict still its verdict.
/// The product itself not delivered (`-o -`) stays a failure.
#[test]
fn a_closed_stdout_loses_only_the_printed_lines() {
    let dir = scratch("closed-stdout");
    let (png, data, raw) = (dir.join("m.png"), dir.join("h.png"), dir.join("h.r16"));
    let good = dir.join("good.toml");
    std::fs::write(&good, "color = \"sonar\"\n").unwrap();
    let bad = dir.join("bad.toml");
    std::fs::write(&bad, "color = \"pink\"\n").unwrap();
    let render = ["render", "--size", "32x24", "--set", "detail=4", "-o"];
    let heightmap = ["heightmap", "--set", "detail=4", "-o"];
    let cases: Vec<(Vec<&str>, i32)> = vec![
        (vec!["--help"], 0),
        (vec!["--version"], 0),
        (vec!["--xscreensaver-xml"], 0),
        (vec!["--man-page"], 0),
        (vec!["/a"], 0),
        ([&render[..], &[png.to_str().unwrap()]].concat(), 0),
        ([&heightmap[..], &[data.to_str().unwrap()]].concat(), 0),
        ([&heightmap[..], &[raw.to_str().unwrap()]].concat(), 0),
        (vec!["--check-config"], 0),
        (vec!["--check-config", good.to_str().unwrap()], 0),
        (vec!["--check-config", "--set", "seed=4"], 0),
        (vec!["--check-config", bad.to_str().unwrap()], 1),
        ([&render[..], &["-"]].concat(), 1),
    ];
    for (args, code) in cases {
        let o = unread(&args, Stream::Stdout);
        let err = stderr(&o);
        assert_eq!(o.status.code(), Some(code), "{args:?}: {err}");
        assert!(!err.contains("panicked"), "{args:?}: {err}");
        if code == 0 {
            assert!(err.is_empty(), "{args:?} said: {err}");
        }
    }
    for file in [&png, &data, &raw] {
        assert!(file.exists(), "{} was not written", file.display());
    }
    let o = unread(&[&render[..], &["-"]].concat(), Stream::Stdout);
    assert!(stderr(&o).contains("-o -: cannot write"), "{}", stderr(&o));
}

/// A closed stderr (`2>&1 | head -1`) does not turn a message into a panic:
/// a usage error is still exit 2, a warning still lets the work finish, and
/// a window mode (here `--root` with no display, warned about a bad value
/// first) still ends by its own failure, exit 1.
#[test]
fn a_closed_stderr_keeps_the_exit_status() {
    let dir = scratch("closed-stderr");
    let config = dir.join("m.toml");
    std::fs::write(&config, "no_such_key = 1\n").unwrap();
    let out = dir.join("m.png");
    let warned = [
        "render",
        "--size",
        "32x24",
        "--set",
        "detail=4",
        "--config",
        config.to_str().unwrap(),
        "-o",
        out.to_str().unwrap(),
    ];
    let bad = dir.join("bad.toml");
    std::fs::write(&bad, "color = \"pink\"\n").unwrap();
    for (args, code) in [
        (&["/x"][..], 2),
        (&["render", "-o", "x.png", "--set", "colour=red"][..], 2),
        (&warned[..], 0),
        (&["--check-config", bad.to_str().unwrap()][..], 1),
        (&["--root", "--config", bad.to_str().unwrap()][..], 1),
    ] {
        let o = unread(args, Stream::Stderr);
        assert_eq!(o.status.code(), Some(code), "{args:?}");
    }
    assert!(out.exists());
}

/// `heightmap --open` saves the grid it read: the detail and generator
/// its file recorded, not the ones typed for the run (a 33x33 grid said
/// to be detail 7). A `--set` that only shapes generated heights, which
/// `--open` leaves without effect, is named in a warning, in `render` too.
#[test]
fn open_keeps_the_data_sets_record_and_warns_of_a_set_it_ignores() {
    let dir = scratch("open-record");
    let files = ["h.png", "again.png", "r.png"].map(|f| dir.join(f));
    let [h, again, picture] = files.each_ref().map(|p| p.to_str().unwrap());
    small_data_set(&files[0]);
    let o = run(&[
        "heightmap",
        "--open",
        h,
        "--set",
        "detail=7",
        "-seed",
        "9",
        "-o",
        again,
    ]);
    let err = stderr(&o);
    // Each named as typed: `-seed 9` was named `--set seed=9`.
    for set in ["--set detail=7", "-seed 9"] {
        assert!(
            err.contains(&format!("warning: {set}: no effect with --open")),
            "{err}"
        );
    }
    let data = mountains::terrain::heightmap::load(&files[1]).unwrap();
    let recorded = mountains::mountain::Mountain::drawn_under(
        data.params.as_ref(),
        &mountains::settings::Settings::default(),
    );
    assert_eq!(data.field.size(), 33);
    assert_eq!(recorded.detail, mountains::settings::Detail::Level(5));
    assert_eq!(data.seed, Some(3));
    // A 9x9 set is read fitted to 17x17, and saved again as what it is.
    run(&["heightmap", "--set", "detail=3", "--set", "seed=3", "-o", h]);
    run(&["heightmap", "--open", h, "-o", again]);
    let data = mountains::terrain::heightmap::load(&files[1]).unwrap();
    let recorded = mountains::mountain::Mountain::drawn_under(
        data.params.as_ref(),
        &mountains::settings::Settings::default(),
    );
    assert_eq!(
        (data.field.size(), recorded.detail),
        (17, mountains::settings::Detail::Level(4))
    );
    let o = run(&[
        "render", "--size", "40x30", "--open", h, "--set", "seed=9", "-o", picture,
    ]);
    assert!(
        stderr(&o).contains("warning: --set seed=9: no effect with --open"),
        "{}",
        stderr(&o)
    );
    // A key the picture is drawn under is no mistake.
    let o = run(&[
        "render",
        "--size",
        "40x30",
        "--open",
        h,
        "--set",
        "color=sonar",
        "-o",
        picture,
    ]);
    assert!(!stderr(&o).contains("warning"), "{}", stderr(&o));
}

/// A data set given as the preferences file (`--config h.png`, meant for
/// `--open`) is named as a PNG, with the flag that reads one.
#[test]
fn a_png_given_as_preferences_is_named_as_one() {
    let dir = scratch("png-config");
    let h = dir.join("h.png");
    small_data_set(&h);
    let o = mountains(&["--check-config", &arg(&h)]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    assert!(
        stderr(&o)
            .contains("h.png:1:1: a PNG image, not text (a data set is opened with --open FILE)"),
        "{}",
        stderr(&o)
    );
    let out = dir.join("x.png");
    let o = run(&[
        "render",
        "--config",
        &arg(&h),
        "--size",
        "8x8",
        "-o",
        &arg(&out),
    ]);
    let err = stderr(&o);
    assert!(err.contains("a PNG image, not text"), "{err}");
    assert!(err.contains("nothing in the file was used"), "{err}");
}

/// A file flag given twice is a usage error (exit 2) said before any
/// work: no picture is written to either name.
#[test]
fn a_file_flag_given_twice_exits_2_and_writes_nothing() {
    let dir = scratch("file-flag-twice");
    let (a, b) = (dir.join("a.png"), dir.join("b.png"));
    let o = mountains(&[
        "render",
        "--size",
        "8x8",
        "--set",
        "detail=4",
        "-o",
        &arg(&a),
        "--output",
        &arg(&b),
    ]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    let first = stderr(&o).lines().next().unwrap_or_default().to_string();
    let want = format!(
        "mountains: error: `--output {}` given after `-o {}`: give one output file",
        arg(&b),
        arg(&a)
    );
    assert_eq!(first, want);
    assert!(!a.exists() && !b.exists());
}

/// The warning of a key `--open` leaves without effect names it as it was
/// typed: `-seed 9` was named `--set seed=9`, a flag the person never gave.
#[test]
fn open_names_a_set_it_ignores_as_typed() {
    let dir = scratch("open-as-typed");
    let files = ["h.png", "again.png", "r.png"].map(|f| dir.join(f));
    let [h, again, picture] = files.each_ref().map(|p| p.to_str().unwrap());
    small_data_set(&files[0]);
    let o = run(&[
        "heightmap",
        "--open",
        h,
        "-seed",
        "9",
        "--cragginess=40",
        "--set=detail=6",
        "-set",
        "erosion=0",
        "-o",
        again,
    ]);
    let err = stderr(&o);
    for typed in [
        "-seed 9",
        "--cragginess=40",
        "--set=detail=6",
        "-set erosion=0",
    ] {
        let warning = format!("mountains: warning: {typed}: no effect with --open {h}");
        assert!(err.lines().any(|l| l.starts_with(&warning)), "{err}");
    }
    assert!(!err.contains("--set seed=9"), "{err}");
    let o = run(&[
        "render", "--size", "40x30", "--open", h, "--seed", "9", "-o", picture,
    ]);
    let err = stderr(&o);
    assert!(
        err.contains("warning: --seed 9: no effect with --open"),
        "{err}"
    );
    assert!(!err.contains("--set seed=9"), "{err}");
}

/// A good file checked with a bad `--set` is exit 2, and what stdout says
/// does not contradict it: it printed "good.toml: ok" as if all were
/// well. It says the file is fine and the `--set` is not.
#[test]
fn check_config_with_a_bad_set_says_no_bare_ok() {
    let dir = scratch("check-config-ok-but");
    let good = dir.join("good.toml");
    std::fs::write(&good, "seed = 5\n").unwrap();
    for args in [
        vec![
            "--check-config",
            good.to_str().unwrap(),
            "--set",
            "color=pink",
        ],
        vec![
            "--config",
            good.to_str().unwrap(),
            "--check-config",
            "--set",
            "color=pink",
        ],
    ] {
        let o = mountains(&args);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
        assert!(stderr(&o).contains("key `color`"), "{}", stderr(&o));
        let out = String::from_utf8_lossy(&o.stdout);
        let said = format!("{}: the file is ok; a --set is not\n", good.display());
        assert_eq!(out, said, "{args:?}");
    }
    let o = run(&[
        "--check-config",
        good.to_str().unwrap(),
        "--set",
        "color=sonar",
    ]);
    let out = String::from_utf8_lossy(&o.stdout);
    assert_eq!(out, format!("{}: ok\n--set: ok\n", good.display()));
}

/// A key flag with a bad value beside `--check-config` (`-color pink`)
/// is said as a bad `--set` is: named as typed, after it the file's own
/// verdict, exit 2. It was refused while the arguments were read, and
/// the file went unchecked: the user was not told whether it was ok.
#[test]
fn check_config_with_a_bad_key_flag_still_checks_the_file() {
    let dir = scratch("check-config-key-flag");
    let good = dir.join("good.toml");
    std::fs::write(&good, "seed = 5\n").unwrap();
    let good = arg(&good);
    for (args, typed) in [
        (
            vec!["--check-config", &good, "-color", "pink"],
            "-color pink",
        ),
        (
            vec!["--check-config", &good, "--color=pink"],
            "--color=pink",
        ),
        (
            vec!["--config", &good, "--check-config", "-cragginess", "500"],
            "-cragginess 500",
        ),
    ] {
        let o = mountains(&args);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
        let flag = typed.split([' ', '=']).next().unwrap();
        let err = stderr(&o);
        assert!(
            err.starts_with(&format!("mountains: error: {flag}: "))
                && err.contains("is not allowed"),
            "{args:?}: {err}"
        );
        let out = String::from_utf8_lossy(&o.stdout);
        assert_eq!(
            out,
            format!("{good}: the file is ok; {typed} is not\n"),
            "{args:?}"
        );
    }
    // A bad file beside it: both are said, the flag first.
    let bad = dir.join("bad.toml");
    std::fs::write(&bad, "cragginess = 500\n").unwrap();
    let o = mountains(&["--check-config", &arg(&bad), "-color", "pink"]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    let err = stderr(&o);
    let (flag, file) = (
        err.find("-color: "),
        err.find("bad.toml:1:14: key `cragginess`"),
    );
    assert!(flag.is_some() && file.is_some() && flag < file, "{err}");
    // A good flag is named as typed, not as a `--set` no one typed.
    let o = run(&["--check-config", &good, "-color", "sonar"]);
    let out = String::from_utf8_lossy(&o.stdout);
    assert_eq!(out, format!("{good}: ok\n-color sonar: ok\n"));
    // Every other mode still refuses it before any work, as typed.
    let o = mountains(&["render", "-o", &arg(&dir.join("x.png")), "-color", "pink"]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(
        stderr(&o).starts_with("mountains: error: -color: "),
        "{}",
        stderr(&o)
    );
    assert!(!dir.join("x.png").exists());
}

/// A file that cannot be read fails the work, exit 1, whichever flag
/// names it: `render --config missing.toml` exited 2, as a mistyped flag
/// does, where `render --open missing.png` and `--check-config
/// missing.toml` exit 1 (docs/refusals.md: 2 is a mistake in what was
/// typed).
#[test]
fn a_file_that_cannot_be_read_exits_1_whichever_flag_names_it() {
    let dir = scratch("unreadable-exit");
    let out = arg(&dir.join("x.png"));
    let folder = dir.join("a-folder");
    std::fs::create_dir_all(&folder).unwrap();
    let (missing_toml, missing_png) = (arg(&dir.join("m.toml")), arg(&dir.join("m.png")));
    for mode in [&["render", "--size", "8x8"][..], &["heightmap"]] {
        for (flag, file) in [
            ("--config", &missing_toml),
            ("--config", &arg(&folder)),
            ("--open", &missing_png),
            ("--open", &arg(&folder)),
        ] {
            let args = [mode, &["--set", "detail=3", flag, file, "-o", &out]].concat();
            let o = mountains(&args);
            assert_eq!(o.status.code(), Some(1), "{args:?}: {}", stderr(&o));
            assert!(
                stderr(&o).contains("cannot read"),
                "{args:?}: {}",
                stderr(&o)
            );
        }
    }
    let o = mountains(&["--check-config", &missing_toml]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
}

/// A data set and a preferences file that cannot be read are said in
/// one wording, the flag and the file first: `--open` said "cannot be
/// read" where `--config` said "cannot read", which read as two faults.
#[test]
fn a_failed_read_is_said_alike_for_data_sets_and_preferences() {
    let dir = scratch("read-alike");
    let out = arg(&dir.join("x.png"));
    for (flag, name) in [("--open", "missing.png"), ("--config", "missing.toml")] {
        let missing = arg(&dir.join(name));
        let o = mountains(&["render", "--size", "8x8", flag, &missing, "-o", &out]);
        assert_ne!(o.status.code(), Some(0));
        let err = stderr(&o);
        let said = format!("mountains: error: {flag} {missing}: cannot read: ");
        assert!(err.starts_with(&said), "{err}");
    }
    let folder = dir.join("a-folder.png");
    std::fs::create_dir_all(&folder).unwrap();
    let o = mountains(&["render", "--open", &arg(&folder), "-o", &out]);
    let said = format!("--open {}: cannot read: is a folder", folder.display());
    assert!(stderr(&o).contains(&said), "{}", stderr(&o));
}

/// A file its owner made read-only is not replaced by `-o`: the rename
/// that replaces a file asks leave of its folder, not of the file, so
/// `render -o kept.png` replaced a `chmod a-w` file that a shell's `>`
/// would have refused. It is refused before any work, exit 1, the file
/// left as it was (also for root, who may write anything: the file's own
/// bits say it is to be kept).
#[test]
fn a_read_only_file_is_not_replaced() {
    let dir = scratch("read-only-output");
    for (mode, name) in [
        (&["render", "--size", "8x8"][..], "kept.png"),
        (&["heightmap", "--set", "detail=3"], "kept.r16"),
    ] {
        let kept = dir.join(name);
        std::fs::write(&kept, b"precious").unwrap();
        let mut permissions = std::fs::metadata(&kept).unwrap().permissions();
        permissions.set_readonly(true);
        std::fs::set_permissions(&kept, permissions).unwrap();
        let out = arg(&kept);
        let args = [mode, &["-o", &out]].concat();
        let o = mountains(&args);
        assert_eq!(o.status.code(), Some(1), "{args:?}: {}", stderr(&o));
        let said = format!(
            "mountains: error: -o {}: cannot write: is read-only",
            kept.display()
        );
        assert!(stderr(&o).starts_with(&said), "{}", stderr(&o));
        assert!(o.stdout.is_empty(), "{args:?}");
        assert_eq!(std::fs::read(&kept).unwrap(), b"precious");
    }
}

/// `-o` over a file keeps its leave to read it (a private picture stays
/// private): the new file was made with the defaults.
#[cfg(unix)]
#[test]
fn a_replaced_output_keeps_its_permissions() {
    use std::os::unix::fs::PermissionsExt;
    let dir = scratch("private-output");
    let private = dir.join("private.png");
    std::fs::write(&private, b"old").unwrap();
    std::fs::set_permissions(&private, std::fs::Permissions::from_mode(0o600)).unwrap();
    run(&["render", "--size", "8x8", "-o", &arg(&private)]);
    assert_eq!(png_size(&private), (8, 8));
    let mode = std::fs::metadata(&private).unwrap().permissions().mode();
    assert_eq!(mode & 0o777, 0o600, "{mode:o}");
}

/// A command refused before its work says only why: no warning about
/// the preferences or the flags comes before the refusal (a warning of
/// `-seed 9` beside `--open`, then a refusal of the `-o`, told of work
/// it never did). The same warnings are said when the work is done.
#[test]
fn a_refused_command_says_no_warnings_first() {
    let dir = scratch("refused-first");
    let h = dir.join("h.png");
    small_data_set(&h);
    let config = dir.join("prefs.toml");
    std::fs::write(&config, "nonsense = 1\n").unwrap();
    let broken = dir.join("broken.png");
    std::fs::write(&broken, b"\x89PNG\r\n\x1a\nnot a png at all").unwrap();
    let (h, config) = (arg(&h), arg(&config));
    let missing_folder = arg(&dir.join("no-such-folder").join("x.png"));
    let common = ["--config", &config, "-seed", "9"];
    for (mode, open, output, code) in [
        (
            &["render", "--size", "40x30"][..],
            h.as_str(),
            missing_folder.as_str(),
            1,
        ),
        (&["heightmap"], h.as_str(), missing_folder.as_str(), 1),
        (&["render", "--size", "40x30"], h.as_str(), h.as_str(), 2),
        (&["heightmap"], h.as_str(), h.as_str(), 2),
        (
            &["render", "--size", "32768x32768"],
            h.as_str(),
            &arg(&dir.join("big.png")),
            2,
        ),
        (
            &["render", "--size", "40x30"],
            &arg(&broken),
            &arg(&dir.join("r.png")),
            1,
        ),
        (&["heightmap"], &arg(&broken), &arg(&dir.join("d.png")), 1),
    ] {
        let args: Vec<&str> = [mode, &common, &["--open", open, "-o", output]].concat();
        let o = mountains(&args);
        let err = stderr(&o);
        assert_eq!(o.status.code(), Some(code), "{args:?}: {err}");
        assert!(!err.contains("warning:"), "{args:?}: {err}");
        assert!(err.starts_with("mountains: error: "), "{args:?}: {err}");
    }
    // Done, the work is warned of as before.
    let done = arg(&dir.join("done.png"));
    let args = [
        &["render", "--size", "40x30"][..],
        &common,
        &["--open", &h, "-o", &done],
    ]
    .concat();
    let err = stderr(&run(&args));
    assert!(
        err.contains("warning: -seed 9: no effect with --open"),
        "{err}"
    );
    assert!(err.contains("prefs.toml:1:1: key `nonsense`"), "{err}");
}

/// An `-o` the write would refuse, a folder that is not there or a
/// folder named as the file, is refused before any work, as the write
/// refuses it (exit 1): it was said only once the picture was drawn or
/// the data set made. With an `--open` that cannot be read, the `-o` is
/// still what is said; nothing is left behind.
#[test]
fn an_output_the_write_would_refuse_is_refused_before_any_work() {
    let dir = scratch("unwritable-output");
    let missing = arg(&dir.join("missing.png"));
    let folder = dir.join("a-folder.png");
    std::fs::create_dir_all(&folder).unwrap();
    let nowhere = dir.join("no-such-folder").join("x.png");
    for mode in [&["render", "--size", "8x8"][..], &["heightmap"]] {
        for (out, why) in [(&nowhere, None), (&folder, Some("is a folder, not a file"))] {
            let out_arg = arg(out);
            for heights in [&["--set", "detail=4"][..], &["--open", &missing]] {
                let args = [mode, heights, &["-o", &out_arg]].concat();
                let o = mountains(&args);
                assert_eq!(o.status.code(), Some(1), "{args:?}: {}", stderr(&o));
                let said = format!("mountains: error: -o {out_arg}: cannot write: ");
                assert!(stderr(&o).starts_with(&said), "{args:?}: {}", stderr(&o));
                if let Some(why) = why {
                    assert_eq!(stderr(&o), format!("{said}{why}\n"), "{args:?}");
                }
            }
        }
    }
    assert!(folder.is_dir() && !nowhere.parent().unwrap().exists());
    no_temporary_file_in(&dir);
}

/// No temporary file (a dot file: fsutil writes `.NAME.PID.tmp` and renames
/// it) is left in `dir` after a refused or failed write.
fn no_temporary_file_in(dir: &std::path::Path) {
    let left: Vec<_> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .filter(|n| n.to_string_lossy().starts_with('.'))
        .collect();
    assert!(left.is_empty(), "left behind: {left:?}");
}

/// An `-o` that ends in `/` and is no folder (`-o new/`, `-o x.png/`)
/// names a folder, never a file: it is refused before any work, saying
/// so. It passed the check before the work, and once the picture was
/// drawn or the data set made its rename failed with "Not a directory",
/// of a folder that was never there. With an `--open` that cannot be
/// read, the `-o` is still what is said; a file so named is untouched.
#[test]
fn an_output_that_ends_in_a_slash_is_refused_before_any_work() {
    let dir = scratch("output-ends-in-a-slash");
    let missing = arg(&dir.join("missing.png"));
    let file = dir.join("kept.png");
    std::fs::write(&file, "kept").unwrap();
    let (new, kept) = (
        format!("{}/", arg(&dir.join("new"))),
        format!("{}/", arg(&file)),
    );
    for mode in [&["render", "--size", "8x8"][..], &["heightmap"]] {
        for out in [&new, &kept] {
            for heights in [&["--set", "detail=4"][..], &["--open", &missing]] {
                let args = [mode, heights, &["-o", out]].concat();
                let o = mountains(&args);
                assert_eq!(o.status.code(), Some(1), "{args:?}: {}", stderr(&o));
                let said = format!(
                    "mountains: error: -o {out}: cannot write: names a folder (it ends in /), not a file\n"
                );
                assert_eq!(stderr(&o), said, "{args:?}");
            }
        }
    }
    assert_eq!(std::fs::read_to_string(&file).unwrap(), "kept");
    assert!(!dir.join("new").exists());
    no_temporary_file_in(&dir);
}

/// `-o` naming the file `--config` reads (`heightmap --config h.png -o
/// h.png`, a data set typed after `--config` for `--open`) is refused
/// before any work, exit 2, as `--open X -o X` is: the file was replaced
/// by a new picture or data set, with only a warning that it was no
/// text. `--config /dev/null -o /dev/null` writes to the device, as before.
#[test]
fn an_output_over_the_preferences_file_is_refused() {
    let dir = scratch("output-over-config");
    let mine = dir.join("mine.png");
    small_data_set(&mine);
    let bytes = std::fs::read(&mine).unwrap();
    let (mine, again) = (arg(&mine), arg(&dir.join(".").join("mine.png")));
    for (mode, made) in [
        (&["render", "--size", "8x8"][..], "picture"),
        (&["heightmap"], "data set"),
    ] {
        for out in [&mine, &again] {
            let args = [mode, &["--config", &mine, "-o", out]].concat();
            let o = mountains(&args);
            assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
            let said = format!(
                "mountains: error: -o {out}: is the preferences file --config reads; \
                 give the {made} another name\n"
            );
            assert!(stderr(&o).starts_with(&said), "{args:?}: {}", stderr(&o));
            assert_eq!(
                std::fs::read(dir.join("mine.png")).unwrap(),
                bytes,
                "{args:?}"
            );
        }
    }
    #[cfg(unix)]
    run(&[
        "render",
        "--size",
        "8x8",
        "--config",
        "/dev/null",
        "-o",
        "/dev/null",
    ]);
}

/// `-o` through a link to nowhere is refused (a file renamed in its place
/// would replace someone's link), and before any work: it was refused only
/// once the whole picture was drawn or the data set made. With an
/// `--open` that cannot be read, the link is still what is said: the work
/// that would fail on the data set is not begun.
#[cfg(unix)]
#[test]
fn a_link_to_nowhere_at_o_is_refused_before_any_work() {
    let dir = scratch("link-to-nowhere");
    let missing = arg(&dir.join("missing.png"));
    for (mode, name) in [
        (&["render", "--size", "8x8"][..], "p.png"),
        (&["render", "--size", "8x8"], "p.jpg"),
        (&["heightmap"], "h.png"),
        (&["heightmap"], "h.r16"),
    ] {
        let (link, target) = (dir.join(name), dir.join("gone").join(name));
        let _ = std::fs::remove_file(&link);
        std::os::unix::fs::symlink(&target, &link).unwrap();
        let link_arg = arg(&link);
        let want = format!(
            "mountains: error: -o {link_arg}: cannot write: a link to nowhere (to {})\n",
            target.display()
        );
        for heights in [&["--set", "detail=4"][..], &["--open", &missing]] {
            let args = [mode, heights, &["-o", &link_arg]].concat();
            let o = mountains(&args);
            assert_eq!(o.status.code(), Some(1), "{args:?}: {}", stderr(&o));
            assert_eq!(stderr(&o), want, "{args:?}");
            let still = std::fs::symlink_metadata(&link).unwrap();
            assert!(still.file_type().is_symlink(), "{args:?}");
        }
    }
}

/// A bad `--set` is a mistake typed for the run, as a bad key flag is,
/// and is answered alike: the message, then where to read the rest. It
/// ended at the message (a bad value pointed nowhere), and an unknown key
/// pointed at the help inside it.
#[test]
fn a_bad_set_is_answered_as_a_bad_key_flag_is() {
    let out = arg(&scratch("set-alike").join("x.png"));
    for (args, first) in [
        (
            vec!["render", "--set", "colr=pink", "-o", &out],
            "mountains: error: --set: key `colr`: unknown key; did you mean `color`?",
        ),
        (
            vec!["render", "--set", "color=pink", "-o", &out],
            "mountains: error: --set: key `color`: \"pink\" is not allowed; expected one of ",
        ),
        (
            vec!["render", "-color", "pink", "-o", &out],
            "mountains: error: -color: \"pink\" is not allowed; expected one of ",
        ),
    ] {
        let o = mountains(&args);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
        let err = stderr(&o);
        let lines: Vec<&str> = err.lines().collect();
        assert_eq!(lines.len(), 2, "{args:?}: {err}");
        assert!(lines[0].starts_with(first), "{args:?}: {err}");
        assert!(!lines[0].contains("--help"), "{args:?}: {err}");
        assert_eq!(
            lines[1], "`mountains --help` lists every mode, flag and key.",
            "{args:?}"
        );
    }
    assert!(!Path::new(&out).exists());
}

/// A key set beside a mode that prints a file, or `/a`, is refused as
/// `--open` is there: it can have no effect, and it passed with exit 0
/// and no word, its key and value not even checked
/// (`--xscreensaver-xml --set nope=1`). A bad one is refused in the words
/// every other mode says it in; a good one naming it as typed, and why.
#[test]
fn a_key_set_is_refused_where_nothing_is_drawn() {
    let out = arg(&scratch("printed-sets").join("x.png"));
    let modes = ["--xscreensaver-xml", "--man-page", "/a"];
    for bad in [
        &["--set", "nope=1"][..],
        &["--set", "seed=abc"],
        &["-seed", "abc"],
    ] {
        let elsewhere = stderr(&mountains(&[&["render", "-o", &out][..], bad].concat()));
        for mode in modes {
            let args = [&[mode][..], bad].concat();
            let o = mountains(&args);
            assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
            assert!(o.stdout.is_empty(), "{args:?}");
            assert_eq!(stderr(&o), elsewhere, "{args:?}");
        }
    }
    for (args, typed, why) in [
        (
            &["--xscreensaver-xml", "--set", "seed=3"][..],
            "--set seed=3",
            "it prints a file and shows no mountain",
        ),
        (&["--man-page", "-seed", "3"], "-seed 3", "prints a file"),
        (
            &["-no-shadows", "--man-page"],
            "-no-shadows",
            "prints a file",
        ),
        (
            &["/a", "--color=sonar"],
            "--color=sonar",
            "/a changes no password",
        ),
    ] {
        let o = mountains(args);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
        assert!(o.stdout.is_empty(), "{args:?}");
        let err = stderr(&o);
        let said = format!("mountains: error: {typed}: no key is set here: ");
        assert!(
            err.starts_with(&said) && err.contains(why),
            "{args:?}: {err}"
        );
    }
    assert!(!Path::new(&out).exists());
}

/// A key's flag typed last without its value beside `--check-config`
/// (`-seed`) is said as one with a bad value is: named, the file checked
/// and its verdict said, exit 2. It was refused while the arguments were
/// read, and the file went unchecked.
#[test]
fn check_config_with_a_key_flag_missing_its_value_still_checks_the_file() {
    let dir = scratch("check-config-no-value");
    let good = dir.join("good.toml");
    std::fs::write(&good, "seed = 5\n").unwrap();
    let good = arg(&good);
    for (args, flag) in [
        (vec!["--check-config", &good, "-seed"], "-seed"),
        (
            vec!["--config", &good, "--check-config", "--color"],
            "--color",
        ),
    ] {
        let o = mountains(&args);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
        let err = stderr(&o);
        let named = format!("mountains: error: `{flag}` needs a value: ");
        assert!(err.starts_with(&named), "{args:?}: {err}");
        let out = String::from_utf8_lossy(&o.stdout);
        let verdict = format!("{good}: the file is ok; {flag} needs a value\n");
        assert_eq!(out, verdict, "{args:?}");
    }
    // A bad file beside it: both are said, the flag first.
    let bad = dir.join("bad.toml");
    std::fs::write(&bad, "cragginess = 500\n").unwrap();
    let o = mountains(&["--check-config", &arg(&bad), "-seed"]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    let err = stderr(&o);
    let (flag, file) = (
        err.find("`-seed` needs a value"),
        err.find("bad.toml:1:14: key `cragginess`"),
    );
    assert!(flag.is_some() && file.is_some() && flag < file, "{err}");
    // Every other mode still refuses it before any work.
    let out = arg(&dir.join("x.png"));
    let o = mountains(&["render", "-o", &out, "-seed"]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    let err = stderr(&o);
    assert!(
        err.starts_with("mountains: error: `-seed` needs a value: "),
        "{err}"
    );
    assert!(!Path::new(&out).exists());
}

/// A malformed `--set` beside `--check-config` (typed last without its
/// value, or giving no key=value) is said as a key's flag missing its
/// value is: named in the words every mode says it in, the file checked
/// and its verdict said, exit 2. It was refused while the arguments were
/// read, and the file went unchecked.
#[test]
fn check_config_with_a_malformed_set_still_checks_the_file() {
    let dir = scratch("check-config-malformed-set");
    let good = dir.join("good.toml");
    std::fs::write(&good, "seed = 5\n").unwrap();
    let good = arg(&good);
    for (args, said, verdict) in [
        (
            vec!["--check-config", &good, "--set"],
            "--set needs a value",
            "--set needs a value",
        ),
        (
            vec!["--check-config", &good, "--set", "nokey"],
            "--set nokey: expected key=value",
            "a --set is not",
        ),
        (
            vec!["--set", "nokey", "--check-config", &good],
            "--set nokey: expected key=value",
            "a --set is not",
        ),
        (
            vec!["--check-config", &good, "--set="],
            "--set=: an empty value; give key=value",
            "a --set is not",
        ),
    ] {
        let o = mountains(&args);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
        let err = stderr(&o);
        let named = format!("mountains: error: {said}\n");
        assert!(err.starts_with(&named), "{args:?}: {err}");
        let out = String::from_utf8_lossy(&o.stdout);
        assert_eq!(
            out,
            format!("{good}: the file is ok; {verdict}\n"),
            "{args:?}"
        );
    }
    // A bad file beside it: both are said, the --set first.
    let bad = dir.join("bad.toml");
    std::fs::write(&bad, "cragginess = 500\n").unwrap();
    let o = mountains(&["--check-config", &arg(&bad), "--set", "nokey"]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    let err = stderr(&o);
    let (set, file) = (
        err.find("--set nokey: expected key=value"),
        err.find("bad.toml:1:14: key `cragginess`"),
    );
    assert!(set.is_some() && file.is_some() && set < file, "{err}");
    // Every other mode still refuses it before any work, in the same words.
    let out = arg(&dir.join("x.png"));
    for (args, said) in [
        (vec!["render", "-o", &out, "--set"], "--set needs a value"),
        (
            vec!["render", "--set", "nokey", "-o", &out],
            "--set nokey: expected key=value",
        ),
    ] {
        let o = mountains(&args);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
        let err = stderr(&o);
        let named = format!("mountains: error: {said}\n");
        assert!(err.starts_with(&named), "{args:?}: {err}");
    }
    assert!(!Path::new(&out).exists());
}

/// Mistakes typed beside `--check-config` are said in the order they
/// were typed, whatever their kind, and the verdict names the first: a
/// `--set nokey` typed before `-color pink` was said after it, and the
/// verdict named `-color pink` alone.
#[test]
fn check_config_says_mistakes_in_the_order_typed() {
    let dir = scratch("check-config-mistakes-in-order");
    let good = dir.join("good.toml");
    std::fs::write(&good, "seed = 5\n").unwrap();
    let good = arg(&good);
    let (nokey, pink) = ("--set nokey: expected key=value", "-color: \"pink\" is not");
    for (args, said, verdict) in [
        (
            vec!["--check-config", &good, "--set", "nokey", "-color", "pink"],
            vec![nokey, pink],
            "a --set is not",
        ),
        (
            vec!["--check-config", &good, "-color", "pink", "--set", "nokey"],
            vec![pink, nokey],
            "-color pink is not",
        ),
        (
            vec!["--set=", "-color", "pink", "--check-config", &good, "-seed"],
            vec!["--set=: an empty value", pink, "`-seed` needs a value"],
            "a --set is not",
        ),
    ] {
        let o = mountains(&args);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
        let err = stderr(&o);
        let line_of = |text: &str| {
            let start = format!("mountains: error: {text}");
            err.lines().position(|l| l.starts_with(&start))
        };
        let lines: Vec<Option<usize>> = said.iter().map(|text| line_of(text)).collect();
        let in_order = (0..lines.len()).map(Some).collect::<Vec<_>>();
        assert_eq!(lines, in_order, "{args:?}: {err}");
        let out = String::from_utf8_lossy(&o.stdout);
        assert_eq!(
            out,
            format!("{good}: the file is ok; {verdict}\n"),
            "{args:?}"
        );
    }
}

/// A line that gives a key another format's way (`seed: 5`, `seed 5`)
/// names its key and how TOML writes it: it said only "key with no
/// value, expected `=`", about no key. A first word that is no key is
/// named as no key.
#[test]
fn a_key_written_without_equals_is_named() {
    let dir = scratch("key-without-equals");
    for (text, at) in [("seed: 5\n", "1:7"), ("color = \"sonar\"\nseed 5\n", "2:6")] {
        let file = dir.join("p.toml");
        std::fs::write(&file, text).unwrap();
        let o = mountains(&["--check-config", &arg(&file)]);
        assert_eq!(o.status.code(), Some(1), "{text:?}");
        let said = format!(
            "mountains: error: {}:{at}: key `seed`: not valid TOML: ",
            file.display()
        );
        let err = stderr(&o);
        assert!(err.starts_with(&said), "{text:?}: {err}");
        assert!(
            err.contains("; write it as `seed = VALUE`"),
            "{text:?}: {err}"
        );
    }
    let file = dir.join("q.toml");
    std::fs::write(&file, "mystery: 5\n").unwrap();
    let err = stderr(&mountains(&["--check-config", &arg(&file)]));
    assert!(!err.contains("key `"), "{err}");
}

/// A data set the slide show cannot open is a warning named by its flag,
/// as a preferences file's problems are and as `render --open` names it:
/// it was `mountains: h.png: is truncated ...`, neither. The show goes on
/// without it (here it stops for want of a display, after saying so).
#[test]
fn a_data_set_the_slide_show_cannot_open_is_a_warning_naming_its_flag() {
    let dir = scratch("slide-show-open");
    let missing = arg(&dir.join("missing.png"));
    let o = command(&["--window", "--open", &missing])
        .env_remove("DISPLAY")
        .env_remove("WAYLAND_DISPLAY")
        .output()
        .unwrap();
    let err = stderr(&o);
    let said = format!("mountains: warning: --open {missing}: cannot read: ");
    assert!(err.starts_with(&said), "{err}");
    assert!(
        err.lines()
            .next()
            .unwrap()
            .ends_with("; showing generated mountains instead"),
        "{err}"
    );
}

/// A file whose lines end in a lone carriage return (old Mac line
/// endings) is said to be so, naming no key: the whole file was one line,
/// and its error was put to the first key, with what that key takes.
#[test]
fn a_file_of_lone_carriage_returns_is_said_to_be_one() {
    let dir = scratch("lone-carriage-returns");
    let file = dir.join("p.toml");
    std::fs::write(&file, "seed = 5\rcolor = \"sonar\"\r").unwrap();
    let o = mountains(&["--check-config", &arg(&file)]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    let said = format!(
        "mountains: error: {}:1:10: not valid TOML: a carriage return without a newline \
         after it: lines end in \\n or \\r\\n (old Mac line endings are not read)\n",
        file.display()
    );
    assert_eq!(stderr(&o), said);
}

/// A table of our keys (`[mountains]` over `seed = 5`, another format's
/// habit) says that its keys are read only at the top of the file: it was
/// "key `mountains`: unknown key", and the keys in it passed over as if read.
#[test]
fn a_table_of_our_keys_says_where_they_belong() {
    let dir = scratch("table-of-our-keys");
    let file = dir.join("p.toml");
    std::fs::write(&file, "[mountains]\nseed = 5\ncolor = \"sonar\"\n").unwrap();
    let o = mountains(&["--check-config", &arg(&file)]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    let said = format!(
        "mountains: error: {}:1:2: key `mountains`: unknown key; the keys in it \
         (`seed`, `color`) are read only at the top of the file, before any [table] \
         (`mountains --help` lists every key)\n",
        file.display()
    );
    assert_eq!(stderr(&o), said);
    std::fs::write(&file, "[other]\nname = 5\n").unwrap();
    let err = stderr(&mountains(&["--check-config", &arg(&file)]));
    assert!(!err.contains("the keys in it"), "{err}");
}

/// A file `--check-config` cannot read (a folder) is named with the flag
/// that named it, as `--config` and `--open` name theirs: it was named
/// by the file alone.
#[test]
fn check_config_names_its_flag_for_a_file_it_cannot_read() {
    let dir = scratch("check-config-folder");
    let folder = dir.join("folder.toml");
    std::fs::create_dir_all(&folder).unwrap();
    let folder = arg(&folder);
    let out = arg(&dir.join("x.png"));
    let inline = format!("--check-config={folder}");
    for (args, flag) in [
        (vec!["--check-config", &folder], "--check-config"),
        (vec![inline.as_str()], "--check-config"),
        (vec!["--config", &folder, "--check-config"], "--config"),
        (vec!["render", "--config", &folder, "-o", &out], "--config"),
        (vec!["render", "--open", &folder, "-o", &out], "--open"),
    ] {
        let o = mountains(&args);
        assert!(!o.status.success(), "{args:?}");
        let err = stderr(&o);
        let said = format!("mountains: error: {flag} {folder}: cannot read: ");
        assert!(
            err.starts_with(&said) && err.contains("folder"),
            "{args:?}: {err}"
        );
    }
}

/// A preferences file beside a mode that only prints (`--man-page
/// --config p.toml`) is refused naming it and why, as a key set there
/// is: nothing reads it, and it was passed over with exit 0. Where a
/// file is read, it is taken.
#[test]
fn a_preferences_file_is_refused_where_nothing_is_drawn() {
    let dir = scratch("printed-config");
    let good = dir.join("good.toml");
    std::fs::write(&good, "seed = 5\n").unwrap();
    let good = arg(&good);
    let inline = format!("--config={good}");
    for (args, why) in [
        (vec!["--man-page", "--config", &good], "prints a file"),
        (vec![&inline, "--xscreensaver-xml"], "prints a file"),
        (vec!["/a", "--config", &good], "/a changes no password"),
    ] {
        let o = mountains(&args);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
        assert!(o.stdout.is_empty(), "{args:?}");
        let err = stderr(&o);
        let said = format!("mountains: error: --config {good}: no preferences are read here: ");
        assert!(
            err.starts_with(&said) && err.contains(why),
            "{args:?}: {err}"
        );
    }
    run(&["--config", &good, "--check-config"]);
}
