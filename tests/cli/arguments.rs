//! The command line: both screensaver protocols and our own flags.

use std::ffi::OsString;
use std::path::{Path, PathBuf};

use mountains::cli::{self, Mode};
use mountains::render::Size;

fn parse(args: &[&str]) -> Result<cli::Invocation, cli::UsageError> {
    let args: Vec<OsString> = args.iter().map(OsString::from).collect();
    cli::parse(&args)
}

fn mode(args: &[&str]) -> Mode {
    parse(args).unwrap_or_else(|e| panic!("{args:?}: {e}")).mode
}

#[test]
fn windows_letters_any_case_slash_or_dash() {
    for a in ["/s", "/S", "-s", "-S"] {
        assert_eq!(mode(&[a]), Mode::Fullscreen, "{a}");
    }
    assert_eq!(mode(&["/p", "1234"]), Mode::Preview { parent: Some(1234) });
    assert_eq!(mode(&["/P:1234"]), Mode::Preview { parent: Some(1234) });
    assert_eq!(mode(&["-p"]), Mode::Preview { parent: None });
    assert_eq!(mode(&["/c:5678"]), Mode::Settings { parent: Some(5678) });
    assert_eq!(mode(&["/C", "5678"]), Mode::Settings { parent: Some(5678) });
    assert_eq!(mode(&["/c"]), Mode::Settings { parent: None });
    assert_eq!(mode(&["/a", "99"]), Mode::ChangePassword);
}

#[test]
fn xscreensaver_flags_one_or_two_dashes_hex_or_decimal() {
    assert_eq!(mode(&["--root"]), Mode::XRoot);
    assert_eq!(mode(&["-root"]), Mode::XRoot);
    assert_eq!(
        mode(&["--window-id", "0x1a00005"]),
        Mode::XWindowId(0x1a00005)
    );
    assert_eq!(mode(&["-window-id", "27262981"]), Mode::XWindowId(27262981));
    assert_eq!(mode(&["--window-id=0X10"]), Mode::XWindowId(16));
    assert_eq!(mode(&["-window"]), Mode::Window);
}

#[test]
fn no_argument_is_settings_on_windows_and_a_window_elsewhere() {
    let expected = if cfg!(windows) {
        Mode::Settings { parent: None }
    } else {
        Mode::Window
    };
    assert_eq!(mode(&[]), expected);
}

#[test]
fn shared_options_go_with_every_mode() {
    let inv = parse(&[
        "--config",
        "a.toml",
        "/s",
        "--set",
        "color=sonar",
        "--set=detail=6",
        "--open",
        "h.png",
    ])
    .unwrap();
    assert_eq!(inv.mode, Mode::Fullscreen);
    assert_eq!(inv.config, Some(PathBuf::from("a.toml")));
    assert_eq!(inv.open, Some(PathBuf::from("h.png")));
    assert_eq!(
        inv.key_values(),
        vec![
            ("color".into(), "sonar".into()),
            ("detail".into(), "6".into())
        ]
    );
}

#[test]
fn subcommands_take_output_and_size() {
    let m = mode(&["render", "--size", "640x480", "-o", "x.png"]);
    assert_eq!(
        m,
        Mode::Render {
            size: Size::new(640, 480),
            output: "x.png".into()
        }
    );
    assert_eq!(
        mode(&["render", "-o", "x.png"]),
        Mode::Render {
            size: Size::new(1920, 1080),
            output: "x.png".into()
        }
    );
    assert_eq!(
        mode(&["heightmap", "-o", "h.png"]),
        Mode::Heightmap {
            output: "h.png".into()
        }
    );
    assert_eq!(mode(&["--check-config"]), Mode::CheckConfig(None));
    assert_eq!(
        mode(&["--check-config", "f.toml"]),
        Mode::CheckConfig(Some("f.toml".into()))
    );
    // One file is checked: `--config` names it, or `--check-config` does,
    // and two different ones are refused rather than one passed over.
    assert_eq!(
        mode(&["--config", "f.toml", "--check-config", "f.toml"]),
        Mode::CheckConfig(Some("f.toml".into()))
    );
    let e = parse(&["--config", "a.toml", "--check-config", "b.toml"]).unwrap_err();
    assert!(
        e.0.contains("--check-config b.toml and --config a.toml: two files; give one"),
        "{e}"
    );
}

#[test]
fn mistakes_name_the_flag() {
    let cases: &[(&[&str], &str)] = &[
        (&["--bogus"], "--bogus"),
        (&["render"], "-o"),
        (&["render", "-o", "x.png", "--size", "12by4"], "--size"),
        (&["render", "-o", "x.png", "--size", "0x4"], "--size"),
        (&["--window-id"], "--window-id"),
        (&["--window-id", "zz"], "zz"),
        (&["/p:abc"], "abc"),
        (&["--set", "novalue"], "key=value"),
        (&["/s", "/p"], "/p"),
        (&["/s", "-o", "x.png"], "-o"),
    ];
    for (args, needle) in cases {
        let e = parse(args).expect_err(&format!("{args:?} should fail"));
        assert!(e.0.contains(needle), "{args:?}: {e}");
    }
}

/// A mistyped flag or word is answered with the nearest one, as a
/// mistyped key is (`--set colour=sonar`): the keys' own flags, the fixed
/// flags and the subcommands, offered with two dashes however many were
/// typed; nothing is offered when nothing is near.
#[test]
fn a_mistyped_flag_offers_the_nearest() {
    for (args, offered) in [
        (
            &["--colour", "sonar"][..],
            "`--colour`; did you mean `--color`?",
        ),
        (&["-colour", "sonar"][..], "did you mean `--color`?"),
        (&["--craggines", "40"][..], "did you mean `--cragginess`?"),
        (
            &["--draw_second", "3"][..],
            "did you mean `--draw-seconds`?",
        ),
        (&["--no-shadow"][..], "did you mean `--no-shadows`?"),
        (&["--confg", "m.toml"][..], "did you mean `--config`?"),
        (&["--check-confg"][..], "did you mean `--check-config`?"),
        (&["--verison"][..], "did you mean `--version`?"),
        (&["rendr", "-o", "x.png"][..], "did you mean `render`?"),
        // A value after `=` does not hide the flag, and a key=value
        // alone is a `--set` without its flag.
        (&["--colour=sonar"][..], "did you mean `--color`?"),
        (&["-outptu=x.png"][..], "did you mean `--output`?"),
        (&["color=sonar"][..], "did you mean `--set color=sonar`?"),
    ] {
        let e = parse(args).expect_err(&format!("{args:?} should fail"));
        assert!(e.0.contains(offered), "{args:?}: {e}");
    }
    for args in [&["--bogus"][..], &["--zzzzzzzzzz"], &["/x"]] {
        let e = parse(args).expect_err(&format!("{args:?} should fail"));
        assert!(!e.0.contains("did you mean"), "{args:?}: {e}");
    }
}

/// A flag cut short (`--out`) is offered whole (`--output`) when it
/// begins one flag alone: `--out x.png` was offered `--set`, two letters
/// changed. One that begins several is offered by its spelling.
#[test]
fn a_flag_cut_short_offers_the_flag_it_begins() {
    for (args, offered) in [
        (
            &["render", "--out", "x.png"][..],
            "`--out`; did you mean `--output`?",
        ),
        (
            &["render", "-o", "x.png", "-low"],
            "`-low`; did you mean `--low-detail`?",
        ),
        (
            &["--pause", "3"],
            "`--pause`; did you mean `--pause-seconds`?",
        ),
    ] {
        let e = parse(args).expect_err(&format!("{args:?} should fail"));
        assert!(e.0.contains(offered), "{args:?}: {e}");
    }
    // `--win` begins `--window` and `--window-id`: neither is offered
    // for being begun.
    let e = parse(&["--win"]).expect_err("--win should fail");
    assert!(!e.0.contains("--window-id"), "{e}");
}

/// `-` for a preferences file, as `--open -` and `-o -` take it for a
/// pipe, is refused naming the flag and why, exit 2: `--check-config -`
/// was an unknown argument `-`, and `--config -` a file not there. A file
/// named `-` is `./-`.
#[test]
fn a_preferences_file_from_standard_input_is_refused_saying_why() {
    for (args, flag) in [
        (&["--check-config", "-"][..], "--check-config"),
        (&["--check-config=-"], "--check-config"),
        (&["--config", "-", "--check-config"], "--config"),
        (&["render", "--config", "-", "-o", "x.png"], "--config"),
        (&["--config=-", "--window"], "--config"),
        (&["-config", "-"], "--config"),
    ] {
        let e = parse(args).expect_err(&format!("{args:?} should fail"));
        let said = format!("{flag} -: preferences are read from a file, not from standard input");
        assert!(e.0.starts_with(&said), "{args:?}: {e}");
    }
    let dashed = parse(&["--config", "./-", "--check-config", "./-"]).unwrap();
    assert_eq!(dashed.config, Some(PathBuf::from("./-")));
}

/// A mode's value that is refused is named as it was typed, after `=`
/// or after a space: `--layer=foo` was said as `--layer=foo foo`, the
/// value twice, and `-window-id=zz` as `-window-id=zz: `zz``.
#[test]
fn a_mode_value_refused_is_named_as_typed() {
    let layers = "expected one of background, bottom, top, overlay";
    let wide = "X window ids have 32 bits (at most 0xffffffff)";
    let handle = "is not a window handle (a decimal number, or hex with 0x)";
    for (args, said) in [
        (&["--layer=foo"][..], format!("--layer=foo: {layers}")),
        (&["-layer", "foo"], format!("-layer foo: {layers}")),
        (
            &["--window-id=0x100000000"],
            format!("--window-id=0x100000000: {wide}"),
        ),
        (
            &["--window-id", "0x100000000"],
            format!("--window-id 0x100000000: {wide}"),
        ),
        (&["-window-id=zz"], format!("-window-id: `zz` {handle}")),
        (
            &["--window-id", "zz"],
            format!("--window-id: `zz` {handle}"),
        ),
    ] {
        let e = parse(args).expect_err(&format!("{args:?} should fail"));
        assert_eq!(e.0, said, "{args:?}");
    }
}

/// An `-o` that ends in a dot (`x.png.`) says that nothing after it names
/// a type: it said "a picture cannot be written as .".
#[test]
fn an_output_ending_in_a_dot_says_it_names_no_type() {
    for (args, use_) in [
        (&["render", "-o", "x.png."][..], ".png, .jpg, .jpeg"),
        (&["heightmap", "-o", "h."], ".png, .r16, .raw"),
    ] {
        let e = parse(args).expect_err(&format!("{args:?} should fail"));
        let out = args[2];
        let said = format!("-o {out}: nothing after its last dot names a type; use {use_}");
        assert_eq!(e.0, said, "{args:?}");
    }
}

/// A key, flag or mode typed in capitals (caps lock, or a Windows habit:
/// its letters take any case) is offered in the case it takes: `--set
/// COLOR=sonar`, `-COLOR`, `--SET` and `RENDER` were further than any
/// misspelling, and offered nothing.
#[test]
fn a_name_typed_in_capitals_offers_the_name() {
    for (args, offered) in [
        (
            &["render", "-o", "x.png", "--set", "COLOR=sonar"][..],
            "did you mean `color`?",
        ),
        (
            &["render", "-o", "x.png", "-COLOR", "sonar"],
            "did you mean `--color`?",
        ),
        (
            &["render", "-o", "x.png", "--SET", "color=sonar"],
            "did you mean `--set`?",
        ),
        (&["RENDER", "-o", "x.png"], "did you mean `render`?"),
        (&["render", "--OUT", "x.png"], "did you mean `--output`?"),
    ] {
        let e = parse(args).expect_err(&format!("{args:?} should fail"));
        assert!(e.0.contains(offered), "{args:?}: {e}");
    }
}

/// A mode given twice names both as typed, with their values: `--layer
/// background --layer top` was "`--layer` given after `--layer`: choose
/// one mode", naming neither layer, and of one mode given twice.
#[test]
fn a_mode_given_twice_names_both_as_typed() {
    for (args, said) in [
        (
            &["--check-config", "a.toml", "--check-config", "b.toml"][..],
            "`--check-config b.toml` given after `--check-config a.toml`: give it once",
        ),
        (
            &["--layer", "background", "--layer=top"],
            "`--layer=top` given after `--layer background`: give it once",
        ),
        (
            &["/p", "1234", "/s"],
            "`/s` given after `/p 1234`: choose one mode",
        ),
        (
            &["render", "--root"],
            "`--root` given after `render`: choose one mode",
        ),
    ] {
        let e = parse(args).expect_err(&format!("{args:?} should fail"));
        assert_eq!(e.0, said, "{args:?}");
    }
}

/// A file's name that is not valid text (a Latin-1 name on Linux) is
/// taken by `--check-config` as `--config` takes it: it was passed over,
/// then refused as "argument \"\\xFE.toml\" is not valid text".
#[cfg(unix)]
#[test]
fn check_config_takes_a_file_name_that_is_not_text() {
    use std::os::unix::ffi::OsStringExt;
    let name = OsString::from_vec(b"\xfe.toml".to_vec());
    for flag in ["--check-config", "--config"] {
        let args = [OsString::from(flag), name.clone()];
        let inv = cli::parse(&args).unwrap_or_else(|e| panic!("{flag}: {e}"));
        let file = match inv.mode {
            Mode::CheckConfig(file) => file,
            _ => inv.config,
        };
        assert_eq!(file, Some(PathBuf::from(&name)), "{flag}");
    }
}

/// A file's name that is not valid text is taken after `=` as it is
/// after a space: `--config=NAME` (and `--open=`, `-o=`, `--output=`,
/// `--check-config=`, with one dash too) was refused as "argument ... is
/// not valid text", since each argument was read as text before it was
/// split at its `=`. A flag that takes no file still refuses one.
#[cfg(unix)]
#[test]
fn a_file_name_that_is_not_text_is_taken_after_equals() {
    use std::os::unix::ffi::OsStringExt;
    let name = |stem: &[u8], ext: &[u8]| OsString::from_vec([stem, ext].concat());
    let joined = |flag: &str, value: &OsString| {
        let mut a = OsString::from(format!("{flag}="));
        a.push(value);
        a
    };
    let (toml, png) = (name(b"\xfe", b".toml"), name(b"\xe9t\xe9", b".png"));
    for flag in ["--config", "-config"] {
        let inv = cli::parse(&[joined(flag, &toml)]).unwrap_or_else(|e| panic!("{flag}: {e}"));
        assert_eq!(inv.config, Some(PathBuf::from(&toml)), "{flag}");
    }
    let inv = cli::parse(&[joined("--open", &png)]).expect("--open=");
    assert_eq!(inv.open, Some(PathBuf::from(&png)));
    for flag in ["-o", "--output"] {
        let args = [OsString::from("render"), joined(flag, &png)];
        let inv = cli::parse(&args).unwrap_or_else(|e| panic!("{flag}: {e}"));
        match inv.mode {
            Mode::Render { output, .. } => assert_eq!(output, PathBuf::from(&png), "{flag}"),
            other => panic!("{flag}: {other:?}"),
        }
    }
    let inv = cli::parse(&[joined("--check-config", &toml)]).expect("--check-config=");
    assert!(matches!(inv.mode, Mode::CheckConfig(Some(f)) if f.as_os_str() == toml));
    let e = cli::parse(&[joined("--layer", &toml)]).expect_err("--layer= takes a name");
    assert!(e.0.contains("is not valid text"), "{}", e.0);
}

/// A second file after `--check-config`'s (`--check-config *.toml`) is
/// refused saying that it checks one: it was "unknown argument `b.toml`".
#[test]
fn check_config_with_two_files_says_it_checks_one() {
    let one = "--check-config checks one file; run it once for each";
    for (args, said) in [
        (
            &["--check-config", "a.toml", "b.toml"][..],
            format!("`b.toml` given after `--check-config a.toml`: {one}"),
        ),
        (
            &["--check-config=a.toml", "b.toml", "c.toml"],
            format!("`b.toml` given after `--check-config=a.toml`: {one}"),
        ),
        (
            &["--check-config", "/etc/a.toml", "/etc/b.toml"],
            format!("`/etc/b.toml` given after `--check-config /etc/a.toml`: {one}"),
        ),
    ] {
        let e = parse(args).expect_err(&format!("{args:?} should fail"));
        assert_eq!(e.0, said, "{args:?}");
    }
    assert!(parse(&["--check-config", "a.toml", "--set", "seed=1"]).is_ok());
    assert!(parse(&["--check-config", "a.toml", "/s"]).is_err());
}

/// `--size` bounds the pixels in all as it bounds each side, as the
/// arguments are read: `render` said it only after asking about its `-o`.
#[test]
fn size_bounds_the_pixels_in_all() {
    for size in ["32768x32768", "16385x16384"] {
        let e = parse(&["render", "-o", "x.png", "--size", size]).unwrap_err();
        let want = format!("--size {size}: too large (at most 268435456 pixels in all)");
        assert_eq!(e.0, want);
    }
    let inv = parse(&["render", "-o", "x.png", "--size", "16384x16384"]);
    assert!(inv.is_ok(), "{:?}", inv.err());
}

/// `--size` bounds each side (a frame 2^28 pixels wide and one high took
/// 97 s and 3.5 GB though its pixel count is allowed), and says so naming
/// the flag; the bound itself is taken.
#[test]
fn size_bounds_each_side() {
    let side = cli::MAX_SIDE.to_string();
    for size in [format!("{side}x2"), format!("2x{side}")] {
        let inv = parse(&["render", "-o", "x.png", "--size", &size]);
        assert!(inv.is_ok(), "{size}: {:?}", inv.err());
    }
    for size in ["268435456x1", "1x268435456", "32769x2", "2x32769"] {
        let e = parse(&["render", "-o", "x.png", "--size", size]).unwrap_err();
        let want = format!("--size {size}: too large (each side at most 32768 pixels)");
        assert!(e.0.contains(&want), "{e}");
    }
    // A side of none is a size, but too small: said so, not as a misspelling.
    for size in ["0x0", "0x100", "100x0"] {
        let e = parse(&["render", "-o", "x.png", "--size", size]).unwrap_err();
        let want = format!("--size {size}: too small (each side at least 1 pixel)");
        assert!(e.0.contains(&want), "{e}");
    }
}

/// `--size` takes the sizes people name screens by, in any case, and
/// spaces around the `x`.
#[test]
fn size_takes_named_screens() {
    for (text, w, h) in [
        ("4k", 3840, 2160),
        ("4K", 3840, 2160),
        ("1080p", 1920, 1080),
        ("720P", 1280, 720),
        ("80 x 60", 80, 60),
    ] {
        let m = mode(&["render", "--size", text, "-o", "x.png"]);
        let want = Mode::Render {
            size: Size::new(w, h),
            output: "x.png".into(),
        };
        assert_eq!(m, want, "{text}");
    }
    let e = parse(&["render", "-o", "x.png", "--size", "4kk"]).unwrap_err();
    assert!(e.0.contains("or one of 720p, 1080p, 1440p, 4k"), "{e}");
}

#[test]
fn handles_must_be_nonzero() {
    assert!(cli::parse_handle("0").is_err());
    assert_eq!(cli::parse_handle("0xff").unwrap(), 255);
}

/// Every preference key is a flag of its own, as xscreensaver hacks take them.
#[test]
fn every_key_is_a_flag_of_its_own() {
    let inv = parse(&[
        "-root",
        "-cragginess",
        "40",
        "--color",
        "sonar",
        "-no-shadows",
        "-low-detail",
        "--draw_seconds",
        "3",
        "-sea-level",
        "-0.25",
    ])
    .expect("key flags");
    let want = [
        ("cragginess", "40"),
        ("color", "sonar"),
        ("shadows", "false"),
        ("low_detail", "true"),
        ("draw_seconds", "3"),
        ("sea_level", "-0.25"),
    ];
    let got: Vec<(&str, &str)> = inv
        .sets
        .iter()
        .map(|set| (set.key.as_str(), set.value.as_str()))
        .collect();
    assert_eq!(got, want);
    // Each flag with a value it accepts, its key's default: a value out of
    // a key's range is refused as the flag is read.
    let defaults = mountains::settings::Settings::default();
    for key in mountains::settings::keys::KEYS {
        let flag = format!("-{}", key.name.replace('_', "-"));
        let boolean = key.kind == mountains::settings::keys::Kind::Bool;
        let value = match mountains::settings::keys::get(&defaults, key) {
            mountains::settings::keys::Value::Str(s) => s,
            v => v.to_string(),
        };
        let args: &[&str] = if boolean { &[&flag] } else { &[&flag, &value] };
        let inv = parse(args).unwrap_or_else(|e| panic!("{flag}: {e}"));
        assert_eq!(inv.sets[0].key, key.name, "{flag}");
    }
    let e = parse(&["-cragginess"]).unwrap_err().0;
    assert!(
        e.contains("`-cragginess` needs a value: an integer from 1 to 128"),
        "{e}"
    );
    let e = parse(&["-no-color", "x"]).unwrap_err().0;
    assert!(e.contains("unknown argument `-no-color`"), "{e}");
}

/// A value after `=` is taken with one dash as with two, as `-seed 5`
/// is: `-seed=5` as `--seed=5`, `-config=FILE` as `--config=FILE`. In
/// the window, named: with no mode Windows opens the settings screen,
/// which takes no `-delay`.
#[test]
fn one_dash_takes_a_value_after_an_equals_sign() {
    let args = [
        "--window",
        "-seed=5",
        "-color=sonar",
        "-config=f.toml",
        "-delay=20",
    ];
    let inv = parse(&args).unwrap_or_else(|e| panic!("{e}"));
    let sets: Vec<(&str, &str)> = inv
        .sets
        .iter()
        .map(|set| (set.key.as_str(), set.value.as_str()))
        .collect();
    assert_eq!(sets, [("seed", "5"), ("color", "sonar")]);
    assert_eq!(inv.config, Some(PathBuf::from("f.toml")));
    assert_eq!(inv.xss.delay_us, Some(20));
    let e = parse(&["-cragginess=500"]).unwrap_err().0;
    assert!(e.starts_with("-cragginess: "), "{e}");
    let e = parse(&["-fps=1"]).unwrap_err().0;
    assert!(e.contains("-fps takes no value"), "{e}");
}

/// Each set keeps its key, its value and how it was typed together, in
/// the order given: a message about one names it as typed. (They were
/// two vectors side by side, kept in step by hand.)
#[test]
fn each_set_keeps_how_it_was_typed() {
    let inv = parse(&[
        "-seed",
        "9",
        "--set",
        "color=sonar",
        "--cragginess=40",
        "-no-shadows",
        "-set=detail=6",
    ])
    .unwrap_or_else(|e| panic!("{e}"));
    let got: Vec<(&str, &str, &str)> = inv
        .sets
        .iter()
        .map(|set| (set.key.as_str(), set.value.as_str(), set.typed.as_str()))
        .collect();
    assert_eq!(
        got,
        [
            ("seed", "9", "-seed 9"),
            ("color", "sonar", "--set color=sonar"),
            ("cragginess", "40", "--cragginess=40"),
            ("shadows", "false", "-no-shadows"),
            ("detail", "6", "-set=detail=6"),
        ]
    );
}

/// xscreensaver's common options, `--version`, and its dialog's preview
/// command (`-root` and `-window-id` together, in either order).
#[test]
fn xscreensavers_common_options_mean_what_they_mean_there() {
    let inv = parse(&[
        "-root", "-fps", "-delay", "20000", "-install", "-visual", "default",
    ])
    .expect("common options");
    assert_eq!(inv.mode, Mode::XRoot);
    assert!(inv.xss.fps);
    assert_eq!(inv.xss.delay_us, Some(20000));
    let inv = parse(&["-display", ":7", "--window"]).expect("-display");
    assert_eq!(inv.xss.display.as_deref(), Some(":7"));
    // `--flag=VALUE` as the other flags take it (the value was dropped, and
    // the next argument taken: `--display=:1 --root` meant display `--root`).
    let inv = parse(&["--display=:1", "--root", "--delay=300", "--visual=default"]).expect("=");
    assert_eq!(inv.xss.display.as_deref(), Some(":1"));
    assert_eq!((inv.mode, inv.xss.delay_us), (Mode::XRoot, Some(300)));
    let e = parse(&["--fps=false", "--root"]).unwrap_err().0;
    assert!(e.contains("--fps takes no value"), "{e}");
    // An empty display emptied DISPLAY: the run was said to have none set,
    // or went to Wayland though `-display` means X11.
    for typed in [&["-display", ""][..], &["--display="], &["-display", " "]] {
        let e = parse(&[typed, &["/s"]].concat()).unwrap_err().0;
        assert!(
            e.contains("an empty value; give an X display"),
            "{typed:?}: {e}"
        );
    }
    let e = parse(&["--settings", "-display", ""]).unwrap_err().0;
    assert!(e.starts_with("-display: an empty value"), "{e}");
    // A mode's flag takes no value either (`-root=1` dropped its `1`).
    for (typed, said) in [
        ("-root=1", "--root"),
        ("--window=x", "--window"),
        ("-settings=x", "--settings"),
    ] {
        let e = parse(&[typed]).unwrap_err().0;
        assert!(
            e.contains(&format!("{said} takes no value")),
            "{typed}: {e}"
        );
    }
    assert_eq!(mode(&["-help"]), Mode::Help);
    for v in ["--version", "-V", "-version"] {
        assert_eq!(mode(&[v]), Mode::Version, "{v}");
    }
    assert_eq!(
        mode(&["-root", "-window-id", "0x42"]),
        Mode::XWindowId(0x42)
    );
    assert_eq!(mode(&["--window-id", "66", "--root"]), Mode::XWindowId(66));
    let e = parse(&["-delay", "soon"]).unwrap_err().0;
    assert!(e.contains("-delay soon"), "{e}");
    assert!(e.contains("expected microseconds"), "{e}");
    // More digits than any delay: too large, not "not a number".
    let e = parse(&["-root", "-delay", "99999999999999999999"])
        .unwrap_err()
        .0;
    assert!(
        e.contains("-delay 99999999999999999999`: too large: microseconds"),
        "{e}"
    );
    assert!(parse(&["--window", "--root"]).is_err());
}

/// xscreensaver's shared options beside a mode xscreensaver never runs
/// (`render`, `heightmap`, `--check-config`, `--settings`, the printed
/// files, `/a`) are refused, exit 2, named as typed and why, as `--open`
/// and `--set` are where they do nothing: they were taken in silence.
/// The slide show's modes take them all, and the settings screen takes
/// `-display`, the X display its window opens on.
#[test]
fn xscreensavers_options_are_refused_where_no_slide_show_is_drawn() {
    for (args, typed, why) in [
        (&["--man-page", "-fps"][..], "-fps", "it prints a file"),
        (
            &["render", "-delay", "5", "-o", "x.png"],
            "-delay 5",
            "render draws one picture",
        ),
        (
            &["heightmap", "-o", "h.png", "--visual=default"],
            "--visual=default",
            "heightmap writes one data set",
        ),
        (
            &["--check-config", "p.toml", "-install"],
            "-install",
            "--check-config checks a preferences file only",
        ),
        (
            &["--settings", "-display", ":1", "-no-fps"],
            "-no-fps",
            "the settings screen takes -display alone",
        ),
        (
            &["--xscreensaver-xml", "-display", ":1"],
            "-display :1",
            "it prints a file",
        ),
        (&["/a", "-fps"], "-fps", "/a changes no password"),
    ] {
        let e = parse(args).expect_err(&format!("{args:?} should fail")).0;
        let said = format!("{typed}: xscreensaver's option does nothing here: ");
        assert!(e.starts_with(&said) && e.contains(why), "{args:?}: {e}");
    }
    let inv = parse(&["--settings", "-display", ":1"]).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(inv.xss.display.as_deref(), Some(":1"));
    let all = [
        "-fps", "-delay", "9", "-display", ":1", "-install", "-visual", "v",
    ];
    for saver in [
        &["--root"][..],
        &["-window-id", "7"],
        &["--window"],
        &["/s"],
    ] {
        let args = [saver, &all[..]].concat();
        parse(&args).unwrap_or_else(|e| panic!("{args:?}: {e}"));
    }
    // `--layer` draws on Wayland alone: an X display beside it was taken
    // in silence; its other options pace and mark its slide show.
    let e = parse(&["--layer", "background", "-display", ":1"])
        .unwrap_err()
        .0;
    assert_eq!(
        e,
        "-display :1: --layer draws on Wayland, never on an X display"
    );
    let e = parse(&["--display=:1", "--layer=top"]).unwrap_err().0;
    assert!(
        e.starts_with("--display=:1: --layer draws on Wayland"),
        "{e}"
    );
    parse(&["--layer", "top", "-fps", "-delay", "9"]).unwrap_or_else(|e| panic!("{e}"));
    // `--help` and `--version` are answered, whatever else is typed.
    assert_eq!(mode(&["-fps", "--help"]), Mode::Help);
}

/// `--layer NAME`: the four wlr-layer-shell layers by name, one or two
/// dashes, `=` or a separate value; anything else is refused naming them.
#[test]
fn layer_takes_the_four_layer_names() {
    use mountains::cli::Layer;
    assert_eq!(
        mode(&["--layer", "background"]),
        Mode::Layer(Layer::Background)
    );
    assert_eq!(mode(&["-layer", "bottom"]), Mode::Layer(Layer::Bottom));
    assert_eq!(mode(&["--layer=top"]), Mode::Layer(Layer::Top));
    assert_eq!(mode(&["--layer", "Overlay"]), Mode::Layer(Layer::Overlay));
    let e = parse(&["--layer", "wallpaper"]).unwrap_err().0;
    assert!(e.contains("--layer wallpaper"), "{e}");
    assert!(e.contains("background, bottom, top, overlay"), "{e}");
    let e = parse(&["--layer"]).unwrap_err().0;
    assert!(e.contains("--layer needs a value"), "{e}");
    let e = parse(&["/s", "--layer", "top"]).unwrap_err().0;
    assert!(e.contains("choose one mode"), "{e}");
    let e = parse(&["--layr", "top"]).unwrap_err().0;
    assert!(e.contains("--layer"), "{e}");
}

/// `--help` and the man page name every layer `--layer` takes (the names
/// live in `cli::Layer::NAMES`).
#[test]
fn help_and_man_page_name_every_layer() {
    let man = mountains::contrib::man_page::man_page();
    for (name, _) in mountains::cli::Layer::NAMES {
        assert!(mountains::help::USAGE.contains(name), "--help lacks {name}");
        assert!(man.contains(name), "the man page lacks {name}");
    }
}

/// `--help` or `--version` after a mode (`mountains render --help`, as one
/// asks most commands) answers it, even with the mode's own flags given;
/// two modes are still refused.
#[test]
fn help_after_a_mode_is_answered() {
    assert_eq!(mode(&["render", "--help"]), Mode::Help);
    assert_eq!(mode(&["render", "-o", "x.png", "-h"]), Mode::Help);
    assert_eq!(mode(&["heightmap", "--size", "9x9", "--help"]), Mode::Help);
    assert_eq!(mode(&["/s", "--version"]), Mode::Version);
    let e = parse(&["render", "/s"]).unwrap_err().0;
    assert!(e.contains("choose one mode"), "{e}");
}

/// A flag where a file or key=value belongs is refused, naming both: `render
/// -o --help` wrote a picture named `--help`, and `--config --help` read
/// a file of that name. A value that starts with a dash can still be given
/// as `--output=-name` (as the message says) or `./-name`.
#[test]
fn a_flag_is_not_taken_as_a_flags_value() {
    for args in [
        &["render", "-o", "--help"][..],
        &["--config", "--help"],
        &["--open", "-x.png"],
        &["--set", "--seed=3"],
        &["render", "-o", "x.png", "--size", "-1920x1080"],
    ] {
        let e = parse(args).unwrap_err().0;
        assert!(e.contains("needs a value, not the flag"), "{args:?}: {e}");
        assert!(e.contains(args[args.len() - 2]), "{args:?}: {e}");
        assert!(
            e.contains(&format!("={}", args[args.len() - 1])),
            "{args:?}: {e}"
        );
    }
    let inv = parse(&["render", "--output=-x.png"]).expect("an inline value");
    assert_eq!(
        inv.mode,
        Mode::Render {
            size: Size::new(1920, 1080),
            output: "-x.png".into()
        }
    );
    let inv = parse(&["--config", "./--help"]).expect("a dashed name as ./");
    assert_eq!(inv.config.as_deref(), Some(Path::new("./--help")));
}

/// What a newcomer types for a mode, a flag or a file is offered as the
/// program takes it: `--render` as `render`, `help` as `--help`, a lone
/// file name as `-o` (a PNG that is there as `--open`).
#[test]
fn a_mode_flag_or_file_typed_the_other_way_is_offered_as_meant() {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("cli-offers");
    std::fs::create_dir_all(&dir).unwrap();
    let there = dir.join("there.png");
    std::fs::write(&there, b"not read here").unwrap();
    let there = there.to_str().unwrap();
    let missing = dir.join("missing.png");
    let missing = missing.to_str().unwrap();
    let open = format!("`--open {there}`");
    let output = format!("`-o {missing}`");
    let raw = dir.join("there.r16");
    std::fs::write(&raw, b"not read here").unwrap();
    let raw = raw.to_str().unwrap();
    let open_raw = format!("`--open {raw}`");
    for (args, offered) in [
        (&["--render", "-o", "x.png"][..], "`render`"),
        (&["-heightmap"], "`heightmap`"),
        (&["help"], "`--help`"),
        (&["version"], "`--version`"),
        (&["root"], "`--root`"),
        (&["render", "out.jpg"], "`-o out.jpg`"),
        (&["heightmap", "out.r16"], "`-o out.r16`"),
        (&["render", missing], output.as_str()),
        (&["render", there], open.as_str()),
        (&["render", raw], open_raw.as_str()),
        (&["--colour", "red"], "`--color`"),
    ] {
        let e = parse(args).unwrap_err().0;
        assert!(
            e.contains(&format!("did you mean {offered}?")),
            "{args:?}: {e}"
        );
    }
}

/// A file flag given twice (`-o a.png -o b.png`, in any of its spellings)
/// was "last wins": the first file was passed over in silence. It is
/// refused, naming both as typed; no invocation of ours repeats one.
#[test]
fn a_file_flag_given_twice_is_refused_naming_both() {
    for (args, said) in [
        (
            &["render", "-o", "a.png", "-o", "b.png"][..],
            "`-o b.png` given after `-o a.png`: give one output file",
        ),
        (
            &["render", "--output=a.png", "-o", "a.png"],
            "`-o a.png` given after `--output=a.png`: give one output file",
        ),
        (
            &["--config", "a.toml", "-config=b.toml", "/s"],
            "`-config=b.toml` given after `--config a.toml`: give one preferences file",
        ),
        (
            &["--open", "a.png", "--window", "-open", "b.png"],
            "`-open b.png` given after `--open a.png`: give one data set",
        ),
    ] {
        let e = parse(args).expect_err(&format!("{args:?} should fail"));
        assert_eq!(e.0, said, "{args:?}");
    }
}

/// `--size` given twice is refused naming both as typed, as the file
/// flags are: the last one won, and the first was passed over in
/// silence. Nothing we ship repeats it. `-delay` and `-display` keep the
/// last, as X toolkit programs and xscreensaver's hacks do (a command line
/// edited in xscreensaver's settings may repeat `-delay`).
#[test]
fn a_second_size_is_refused_and_delay_and_display_keep_the_last() {
    for (args, said) in [
        (
            &["render", "-o", "x.png", "--size", "640x480", "--size", "4k"][..],
            "`--size 4k` given after `--size 640x480`: give one size",
        ),
        (
            &["render", "--size=1080p", "-o", "x.png", "-size", "1x1"],
            "`-size 1x1` given after `--size=1080p`: give one size",
        ),
    ] {
        let e = parse(args).expect_err(&format!("{args:?} should fail"));
        assert_eq!(e.0, said, "{args:?}");
    }
    let inv = parse(&[
        "-root",
        "-delay",
        "10",
        "-delay=20",
        "-display",
        ":1",
        "--display",
        ":2",
    ])
    .unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(inv.xss.delay_us, Some(20));
    assert_eq!(inv.xss.display.as_deref(), Some(":2"));
}

/// A one-letter flag typed in the other case is offered as ours: `-v`
/// (the version, as many programs spell it) said only "unknown argument".
#[test]
fn a_letter_in_the_other_case_is_offered_as_ours() {
    for (typed, ours) in [("-v", "-V"), ("-O", "-o"), ("-H", "-h")] {
        let e = parse(&[typed]).unwrap_err();
        let want = format!("unknown argument `{typed}`; did you mean `{ours}`?");
        assert_eq!(e.0, want);
    }
}

/// `--set =5` names no key: said as `--set color` is (expected
/// key=value), where it was "key ``: unknown key" once the file was read.
#[test]
fn a_set_without_a_key_is_refused_as_read() {
    for typed in ["=5", " =5", "="] {
        let e = parse(&["--set", typed]).unwrap_err();
        assert_eq!(e.0, format!("--set {typed}: expected key=value"));
    }
}

/// A side of digits too many for a number is a size too large, as 32769
/// is, not a misspelling: `--size 4294967296x1` said "expected
/// WIDTHxHEIGHT".
#[test]
fn a_side_past_any_number_is_too_large() {
    for size in ["4294967296x1", "1x99999999999999999999"] {
        let e = parse(&["render", "-o", "x.png", "--size", size]).unwrap_err();
        let want = format!("--size {size}: too large (each side at most 32768 pixels)");
        assert_eq!(e.0, want);
    }
    let e = parse(&["render", "-o", "x.png", "--size", "1.5x2"]).unwrap_err();
    assert!(e.0.contains("expected WIDTHxHEIGHT"), "{e}");
}

/// `--open` beside a mode that shows no mountain is refused, naming the
/// file and why: `--check-config` said "ok" of a preferences file while
/// the data set went unread, and the settings screen and the printed
/// files passed it over in silence. The modes that show one take it.
#[test]
fn a_data_set_is_refused_where_no_mountain_is_shown() {
    for (args, why) in [
        (
            &["--check-config", "p.toml", "--open", "h.png"][..],
            "--check-config checks a preferences file only",
        ),
        (&["--settings", "--open", "h.png"], "the settings screen"),
        (&["--open=h.png", "--man-page"], "prints a file"),
        (&["--xscreensaver-xml", "--open", "h.png"], "prints a file"),
    ] {
        let e = parse(args).expect_err(&format!("{args:?} should fail"));
        assert!(
            e.0.starts_with("--open h.png: no data set is opened here: "),
            "{}",
            e.0
        );
        assert!(e.0.contains(why), "{args:?}: {}", e.0);
    }
    for args in [
        &["render", "-o", "x.png", "--open", "h.png"][..],
        &["heightmap", "-o", "y.png", "--open", "h.png"],
        &["--root", "--open", "h.png"],
        &["--window", "--open", "h.png"],
    ] {
        let inv = parse(args).unwrap_or_else(|e| panic!("{args:?}: {e}"));
        assert_eq!(inv.open.as_deref(), Some(std::path::Path::new("h.png")));
    }
}

/// A value typed is echoed at most 80 characters long with its length,
/// as a bad key's value is (docs/refusals.md, "Floods"): a `--set`
/// without `=`, a `--size`, a window handle, a `-delay`, a flag where a
/// value belongs and a mode's flag given after another, 100000
/// characters long, were echoed whole (twice, for the flag). A file's
/// name is a path, and is named whole, as every message names one.
#[test]
fn a_huge_value_typed_is_echoed_short() {
    let huge = "k".repeat(100_000);
    let flag = format!("-{huge}");
    let digits = format!("{}x5", "9".repeat(100_000));
    let wide_id = format!("0x{}100000000", "0".repeat(100_000));
    let checked = format!("--check-config={huge}");
    for args in [
        vec!["render", "-o", "x.png", "--set", &huge],
        vec!["render", "-o", "x.png", "--size", &huge],
        vec!["render", "-o", "x.png", "--size", &digits],
        vec!["render", "-o", &flag],
        vec!["/p", &huge],
        vec!["--window-id", &huge],
        vec!["--window-id", &wide_id],
        vec!["--root", "-delay", &huge],
        vec![&checked, "--root"],
    ] {
        let e = parse(&args).expect_err("a huge value is refused");
        assert!(
            e.0.len() < 1000 && e.0.contains(" characters)"),
            "{} bytes: {}",
            e.0.len(),
            &e.0[..e.0.len().min(300)]
        );
    }
}
