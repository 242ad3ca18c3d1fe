//! Hostile inputs are refused quickly with a message that names them: a FIFO
//! or a device where a file belongs, a preferences file far too large. Each
//! run has a generous time bound (a hang is the defect, not slowness).
#![cfg(unix)]

use crate::common::signals;

use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};
use std::time::{Duration, Instant};

/// Far more than any of these takes; only a hang reaches it. (An 8000x8000
/// `render` in the debug build, beside the other tests on two cores, once
/// took over 20 s to start writing.)
const BOUND: Duration = Duration::from_secs(120);

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("mountains-hostile-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// Runs the binary, killing it (and failing) if it outlives `BOUND`.
fn run(args: &[&str], home: &Path) -> Output {
    let mut child = Command::new(env!("CARGO_BIN_EXE_mountains"))
        .args(args)
        .env("HOME", home)
        .env("XDG_CONFIG_HOME", home.join("config"))
        .env("XDG_DATA_HOME", home.join("data"))
        .env_remove("DISPLAY")
        .env_remove("WAYLAND_DISPLAY")
        .env_remove("WAYLAND_SOCKET")
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("run mountains");
    let start = Instant::now();
    while child.try_wait().expect("wait").is_none() {
        if start.elapsed() > BOUND {
            let _ = child.kill();
            panic!("mountains {args:?} still running after {BOUND:?}");
        }
        std::thread::sleep(Duration::from_millis(10));
    }
    child.wait_with_output().expect("output")
}

fn mkfifo(path: &Path) {
    let status = Command::new("mkfifo").arg(path).status().expect("mkfifo");
    assert!(status.success());
}

#[test]
fn a_fifo_is_refused_not_waited_on() {
    let dir = scratch("fifo");
    let fifo = dir.join("f.png");
    mkfifo(&fifo);
    let f = fifo.to_str().unwrap();
    let out = dir.join("o.png");
    let o = out.to_str().unwrap();
    for args in [
        vec!["render", "--open", f, "-o", o],
        vec!["render", "--config", f, "-o", o],
        vec!["--check-config", f],
        vec!["heightmap", "--open", f, "-o", o],
    ] {
        let got = run(&args, &dir);
        let err = String::from_utf8_lossy(&got.stderr);
        assert!(!got.status.success(), "{args:?}");
        assert!(
            err.contains(f) && err.contains("a FIFO (named pipe), not a regular file"),
            "{args:?}: {err}"
        );
        assert!(!out.exists());
    }
}

#[test]
fn a_device_or_a_huge_file_is_not_read_into_memory() {
    let dir = scratch("huge");
    let got = run(&["render", "--config", "/dev/zero", "-o", "x.png"], &dir);
    let err = String::from_utf8_lossy(&got.stderr);
    assert!(
        err.contains("/dev/zero: cannot read: is a device, not a regular file"),
        "{err}"
    );
    let big = dir.join("big.toml");
    std::fs::write(&big, "# padding\n".repeat(500_000)).unwrap();
    let got = run(&["--check-config", big.to_str().unwrap()], &dir);
    let err = String::from_utf8_lossy(&got.stderr);
    assert_eq!(got.status.code(), Some(1));
    assert!(
        err.contains("big.toml: cannot read: is 4883 KiB; at most 4096 KiB is read"),
        "{err}"
    );
}

/// A screensaver always starts: a preferences file that cannot be read (a
/// FIFO, a device, one over 4 MiB) means the defaults, with the reason on
/// stderr and in mountains.log, and `/dev/null` means the defaults with no
/// word. Without a display each mode then gets as far as looking for one
/// (exit 1, "no display" or "no X display"), past the preferences (which
/// `render` refuses).
#[test]
fn the_saver_starts_on_its_defaults_when_its_preferences_cannot_be_read() {
    let dir = scratch("saver-unreadable");
    let fifo = dir.join("fifo.toml");
    mkfifo(&fifo);
    let big = dir.join("big.toml");
    std::fs::write(&big, "# padding\n".repeat(500_000)).unwrap();
    let why = [
        (
            fifo.to_str().unwrap(),
            "a FIFO (named pipe), not a regular file",
        ),
        ("/dev/zero", "is a device, not a regular file"),
        (
            big.to_str().unwrap(),
            "is 4883 KiB; at most 4096 KiB is read",
        ),
        ("/dev/null", ""),
    ];
    for mode in ["/s", "--root"] {
        for (i, (file, reason)) in why.into_iter().enumerate() {
            let home = dir.join(format!("home-{}-{i}", mode.len()));
            std::fs::create_dir_all(&home).unwrap();
            let got = run(&[mode, "--config", file], &home);
            let err = String::from_utf8_lossy(&got.stderr);
            assert_eq!(got.status.code(), Some(1), "{mode} {file}: {err}");
            let no_display = match mode {
                "/s" => "no display: set WAYLAND_DISPLAY (Wayland) or DISPLAY (X11)",
                _ => "no X display: set DISPLAY",
            };
            assert!(err.contains(no_display), "{mode} {file}: {err}");
            let log = std::fs::read_to_string(home.join("data/mountains/mountains.log"))
                .expect("mountains.log");
            if reason.is_empty() {
                assert!(!err.contains("warning"), "{mode} {file}: {err}");
                assert!(!log.contains("warning"), "{mode} {file}: {log}");
                continue;
            }
            // Named by its flag, as render names it.
            let said = format!("warning: --config {file}: cannot read: ");
            for text in [&*err, &log] {
                assert!(
                    text.contains(&said)
                        && text.contains(reason)
                        && text.contains("using the defaults"),
                    "{mode} {file}: {text}"
                );
            }
        }
    }
}

/// A value is echoed at most ~80 characters long, with its length: a flood
/// in does not become a flood out.
#[test]
fn a_huge_value_is_quoted_short() {
    let dir = scratch("flood");
    let huge = "p".repeat(100_000);
    let set = format!("color={huge}");
    let got = run(&["render", "-o", "x.png", "--set", &set], &dir);
    let err = String::from_utf8_lossy(&got.stderr);
    assert_eq!(got.status.code(), Some(2));
    assert!(err.len() < 2000, "{} bytes of message", err.len());
    assert!(
        err.contains("... (100000 characters) is not allowed"),
        "{err}"
    );
    let config = dir.join("flood.toml");
    std::fs::write(&config, format!("color = \"{}\"\n", "q".repeat(1_000_000))).unwrap();
    let got = run(&["--check-config", config.to_str().unwrap()], &dir);
    let err = String::from_utf8_lossy(&got.stderr);
    assert!(
        err.len() < 2000 && err.contains("(1000000 characters)"),
        "{} bytes",
        err.len()
    );
    let got = run(&[&format!("--{}", "z".repeat(50_000))], &dir);
    let err = String::from_utf8_lossy(&got.stderr);
    assert!(
        err.contains("(50002 characters)") && err.len() < 4000,
        "{} bytes",
        err.len()
    );
}

/// A 33x33 16-bit heightmap with one iTXt chunk `key` = `value`.
fn map_with_itxt(key: &str, value: &str) -> Vec<u8> {
    let n = 33;
    let samples: Vec<u8> = (0..n * n)
        .flat_map(|i: u32| ((i % n) * 1500 + (i / n) * 300).to_be_bytes()[2..].to_vec())
        .collect();
    let mut bytes = Vec::new();
    let mut enc = png::Encoder::new(&mut bytes, n, n);
    enc.set_color(png::ColorType::Grayscale);
    enc.set_depth(png::BitDepth::Sixteen);
    enc.add_itxt_chunk(key.into(), value.into()).unwrap();
    let mut w = enc.write_header().unwrap();
    w.write_image_data(&samples).unwrap();
    w.finish().unwrap();
    bytes
}

/// A text chunk's value is quoted short wherever it is echoed: 1 MiB in
/// an iTXt chunk (issue 22: a `mountains:seed` was echoed whole, 1.0 MB of
/// stderr) is named in a line. An origin key's bad value is a note and the
/// picture is drawn; a height key's is an error.
#[test]
fn a_huge_text_chunk_in_a_data_set_is_quoted_short() {
    let dir = scratch("itxt");
    let flood = format!("x{}", "7".repeat(1 << 20));
    for (key, code) in [
        ("mountains:seed", 0),
        ("mountains:generator", 0),
        ("mountains:scale", 1),
    ] {
        let map = dir.join("flood.png");
        std::fs::write(&map, map_with_itxt(key, &flood)).unwrap();
        let out = dir.join("o.png");
        let _ = std::fs::remove_file(&out);
        let got = run(
            &[
                "render",
                "--open",
                map.to_str().unwrap(),
                "--size",
                "64x36",
                "-o",
                out.to_str().unwrap(),
            ],
            &dir,
        );
        let err = String::from_utf8_lossy(&got.stderr);
        assert!(err.len() < 2000, "{key}: {} bytes of message", err.len());
        assert_eq!(got.status.code(), Some(code), "{key}: {err}");
        assert!(
            err.contains("\"x777") && err.contains("(1048577 characters)"),
            "{key}: {err}"
        );
        assert_eq!(out.exists(), code == 0, "{key}");
    }
}

/// Checking a file with 100,000 unknown keys is linear (it took 49 s when a
/// position was counted from the top for each key) and reports the first
/// 20 problems and a count, not 100,000 lines.
#[test]
fn many_problems_are_checked_in_one_pass_and_counted() {
    let dir = scratch("many");
    let config = dir.join("many.toml");
    let text: String = (0..100_000).map(|i| format!("k{i} = 1\n")).collect();
    std::fs::write(&config, text).unwrap();
    let got = run(&["--check-config", config.to_str().unwrap()], &dir);
    assert_eq!(got.status.code(), Some(1));
    let err = String::from_utf8_lossy(&got.stderr);
    let lines: Vec<&str> = err.lines().collect();
    assert_eq!(lines.len(), 21, "{err}");
    assert!(
        lines[0]
            .ends_with("many.toml:1:1: key `k0`: unknown key (`mountains --help` lists every key)"),
        "{}",
        lines[0]
    );
    assert!(
        lines[19].contains("many.toml:20:1: key `k19`"),
        "{}",
        lines[19]
    );
    assert_eq!(lines[20], "... and 99980 more problems");
}

/// `-o` through a symbolic link replaces the link's target (the link stays
/// a link); into a FIFO it writes into the FIFO (nothing is renamed over
/// it); `-o -` writes to standard output; a folder is refused.
#[test]
fn writes_go_through_links_and_into_pipes() {
    let dir = scratch("writes");
    let real = dir.join("real.png");
    std::fs::write(&real, "old").unwrap();
    let link = dir.join("link.png");
    std::os::unix::fs::symlink(&real, &link).unwrap();
    let got = run(
        &["render", "--size", "64x36", "-o", link.to_str().unwrap()],
        &dir,
    );
    assert!(
        got.status.success(),
        "{}",
        String::from_utf8_lossy(&got.stderr)
    );
    assert!(
        std::fs::symlink_metadata(&link)
            .unwrap()
            .file_type()
            .is_symlink()
    );
    assert!(std::fs::read(&real).unwrap().starts_with(b"\x89PNG"));

    let fifo = dir.join("pipe.png");
    mkfifo(&fifo);
    let copy = dir.join("copied.png");
    let reader = Command::new("sh")
        .args([
            "-c",
            &format!("cat '{}' > '{}'", fifo.display(), copy.display()),
        ])
        .spawn()
        .expect("a reader for the FIFO");
    let got = run(
        &["render", "--size", "64x36", "-o", fifo.to_str().unwrap()],
        &dir,
    );
    assert!(
        got.status.success(),
        "{}",
        String::from_utf8_lossy(&got.stderr)
    );
    let _ = reader.wait_with_output();
    use std::os::unix::fs::FileTypeExt;
    assert!(
        std::fs::symlink_metadata(&fifo)
            .unwrap()
            .file_type()
            .is_fifo()
    );
    assert!(std::fs::read(&copy).unwrap().starts_with(b"\x89PNG"));

    let got = run(&["render", "--size", "64x36", "-o", "-"], &dir);
    assert!(got.status.success());
    assert!(got.stdout.starts_with(b"\x89PNG"), "stdout is not the PNG");
    assert!(String::from_utf8_lossy(&got.stderr).contains("-> -"));

    let got = run(
        &["render", "--size", "64x36", "-o", dir.to_str().unwrap()],
        &dir,
    );
    let err = String::from_utf8_lossy(&got.stderr);
    assert_eq!(got.status.code(), Some(1));
    assert!(
        err.contains("cannot write: is a folder, not a file"),
        "{err}"
    );
}

/// Messages name what the user typed and what is allowed.
#[test]
fn messages_name_what_was_typed() {
    let dir = scratch("messages");
    let check = |text: &str| -> String {
        let config = dir.join("m.toml");
        std::fs::write(&config, text).unwrap();
        let got = run(&["--check-config", config.to_str().unwrap()], &dir);
        assert_eq!(got.status.code(), Some(1), "{text}");
        String::from_utf8_lossy(&got.stderr).into_owned()
    };
    assert!(check("detail = 8.0\n").contains("key `detail`: 8.0 is not allowed"));
    assert!(check("seed = 1e3\n").contains("key `seed`: 1000.0 is not allowed"));
    // A choice typed another way is offered as meant; one far from all is not.
    for (typed, meant) in [
        ("Desert", "desert"),
        ("DESERT", "desert"),
        ("Desret", "desert"),
        ("desret", "desert"),
        ("SONAR", "sonar"),
    ] {
        let key = if meant == "sonar" { "color" } else { "world" };
        let err = check(&format!("{key} = \"{typed}\"\n"));
        assert!(err.contains(&format!("; did you mean `{meant}`?")), "{err}");
    }
    assert!(!check("world = \"zzzzzz\"\n").contains("did you mean"));
    let err = check("detail =\n");
    assert!(
        err.contains("1:9: key `detail`: not valid TOML: nothing after `=`"),
        "{err}"
    );
    let err = check("color = \"gray\"\ncolor = \"red\"\n");
    assert!(
        err.contains("2:1: key `color`: not valid TOML: the key is given twice"),
        "{err}"
    );
    let err = check("seed = 2026-11-24T10:00:00\n");
    assert!(err.contains("found a date and time"), "{err}");
    let err = check("seed = 18446744073709551615\n");
    assert!(
        err.contains("is written in quotes, e.g. seed = \"18446744073709551615\""),
        "{err}"
    );
    // Another key's number too large for TOML is named, with no seed's hint.
    let err = check("cragginess = 99999999999999999999\n");
    assert!(
        err.contains("1:14: key `cragginess`: not valid TOML")
            && err.contains("no key takes a number this large")
            && !err.contains("seed ="),
        "{err}"
    );
    let (a, b) = (dir.join("loop-a.toml"), dir.join("loop-b.toml"));
    std::os::unix::fs::symlink(&b, &a).unwrap();
    std::os::unix::fs::symlink(&a, &b).unwrap();
    let got = run(&["--check-config", a.to_str().unwrap()], &dir);
    let err = String::from_utf8_lossy(&got.stderr);
    assert!(err.contains("Too many levels of symbolic links"), "{err}");
    assert!(!err.contains("no such file"), "{err}");
    let usage = |args: &[&str]| -> String {
        let got = run(args, &dir);
        assert_eq!(got.status.code(), Some(2), "{args:?}");
        String::from_utf8_lossy(&got.stderr).into_owned()
    };
    assert!(usage(&["render", "--output"]).contains("--output needs a value"));
    assert!(usage(&["--config", ""]).contains("--config: an empty value"));
    assert!(usage(&["render", "-o", ""]).contains("-o: an empty value"));
    assert!(usage(&["--open", "", "render", "-o", "x.png"]).contains("--open: an empty value"));
    assert!(usage(&["render", "--set", ""]).contains("--set: an empty value; give key=value"));
    assert!(usage(&["--check-config="]).contains("--check-config=: an empty value"));
    assert!(usage(&["--check-config", ""]).contains("--check-config: an empty value"));
    let err = usage(&["render", "-shadows", "false", "-o", "x.png"]);
    assert!(
        err.contains("`false`: an on/off flag takes no value"),
        "{err}"
    );
    assert!(usage(&["render", "--size", ""]).contains("--size: an empty value; give WIDTHxHEIGHT"));
    // `--set` is typed for the run under `--check-config` too: exit 2.
    let good = dir.join("good.toml");
    std::fs::write(&good, "seed = 5\n").unwrap();
    let err = usage(&[
        "--check-config",
        good.to_str().unwrap(),
        "--set",
        "cragginess=500",
    ]);
    assert!(
        err.contains("--set: key `cragginess`: 500 is not allowed"),
        "{err}"
    );
    assert!(usage(&["/p", "abc"]).contains("`abc` is not a window handle"));
    let err = usage(&["--window-id", "0x100000000"]);
    assert!(
        err.contains("--window-id 0x100000000: X window ids have 32 bits"),
        "{err}"
    );
}

/// `-o -` on a terminal would fill it with a PNG's bytes: refused, as
/// `--open -` from a terminal is. (A pseudo-terminal stands in for one.)
#[cfg(target_os = "linux")]
#[test]
fn a_picture_is_not_written_into_a_terminal() {
    use std::os::fd::FromRawFd;
    let dir = scratch("terminal");
    let (mut leader, mut follower) = (0, 0);
    // SAFETY: openpty writes the two descriptors; no name, settings or size.
    let made = unsafe {
        libc::openpty(
            &mut leader,
            &mut follower,
            std::ptr::null_mut(),
            std::ptr::null(),
            std::ptr::null(),
        )
    };
    assert_eq!(made, 0, "openpty: {}", std::io::Error::last_os_error());
    // SAFETY: both descriptors are open and owned by nothing else.
    let (_leader, tty) = unsafe {
        (
            std::fs::File::from_raw_fd(leader),
            std::fs::File::from_raw_fd(follower),
        )
    };
    for args in [&["render", "--size", "16x9"][..], &["heightmap"][..]] {
        let mode = args[0];
        let got = Command::new(env!("CARGO_BIN_EXE_mountains"))
            .args(args)
            .args(["--set", "detail=4", "-o", "-"])
            .env("HOME", &dir)
            .env("XDG_CONFIG_HOME", dir.join("config"))
            .stdout(tty.try_clone().unwrap())
            .stderr(Stdio::piped())
            .output()
            .expect("run mountains");
        let err = String::from_utf8_lossy(&got.stderr);
        assert_eq!(got.status.code(), Some(2), "{mode}: {err}");
        assert!(
            err.contains("-o -: standard output is a terminal"),
            "{mode}: {err}"
        );
    }
}

/// `render --open X -o X` would put the picture in place of its data set:
/// refused, the data set kept (also through a link to it).
#[test]
fn a_picture_never_replaces_the_data_set_it_is_drawn_from() {
    let dir = scratch("same-file");
    let map = dir.join("map.png");
    let made = run(
        &[
            "heightmap",
            "--set",
            "detail=4",
            "-o",
            map.to_str().unwrap(),
        ],
        &dir,
    );
    assert!(made.status.success());
    let bytes = std::fs::read(&map).unwrap();
    let link = dir.join("link.png");
    std::os::unix::fs::symlink(&map, &link).unwrap();
    for out in [&map, &link] {
        let got = run(
            &[
                "render",
                "--open",
                map.to_str().unwrap(),
                "--size",
                "16x9",
                "-o",
                out.to_str().unwrap(),
            ],
            &dir,
        );
        let err = String::from_utf8_lossy(&got.stderr);
        assert_eq!(got.status.code(), Some(2), "{err}");
        assert!(err.contains("is the data set --open reads"), "{err}");
        assert_eq!(std::fs::read(&map).unwrap(), bytes);
    }
    // Nor a data set over the one it opens: a terrain tool's file of
    // another size would be replaced by our fitted copy of it.
    let got = run(
        &[
            "heightmap",
            "--open",
            map.to_str().unwrap(),
            "-o",
            link.to_str().unwrap(),
        ],
        &dir,
    );
    let err = String::from_utf8_lossy(&got.stderr);
    assert_eq!(got.status.code(), Some(2), "{err}");
    assert!(err.contains("give the data set another name"), "{err}");
    assert_eq!(std::fs::read(&map).unwrap(), bytes);
}

/// A preferences file that is a link to nowhere is a file that cannot be
/// read, and said to be (it was passed over as no file at all).
#[test]
fn a_preferences_link_to_nowhere_is_reported() {
    let dir = scratch("dangling");
    let prefs = dir.join("config").join("mountains");
    std::fs::create_dir_all(&prefs).unwrap();
    std::os::unix::fs::symlink(dir.join("gone.toml"), prefs.join("mountains.toml")).unwrap();
    let out = dir.join("x.png");
    let got = run(
        &["render", "--size", "16x9", "-o", out.to_str().unwrap()],
        &dir,
    );
    let err = String::from_utf8_lossy(&got.stderr);
    assert!(got.status.success(), "{err}");
    assert!(
        err.contains("mountains.toml: cannot read") && err.contains("using the defaults"),
        "{err}"
    );
    // Said as what it is, where the link points too.
    assert!(err.contains("a link to nowhere (to "), "{err}");
    let got = run(
        &[
            "--check-config",
            "--config",
            prefs.join("mountains.toml").to_str().unwrap(),
        ],
        &dir,
    );
    let err = String::from_utf8_lossy(&got.stderr);
    assert_eq!(got.status.code(), Some(1), "{err}");
    assert!(err.contains("cannot read: a link to nowhere"), "{err}");
    // Nor does a picture written through one put a file in its place.
    let link = dir.join("picture.png");
    std::os::unix::fs::symlink(dir.join("gone").join("p.png"), &link).unwrap();
    let got = run(
        &["render", "--size", "16x9", "-o", link.to_str().unwrap()],
        &dir,
    );
    let err = String::from_utf8_lossy(&got.stderr);
    assert_eq!(got.status.code(), Some(1), "{err}");
    assert!(err.contains("a link to nowhere"), "{err}");
    assert!(std::fs::symlink_metadata(&link).unwrap().is_symlink());
}

/// Starts `render` of a large picture into `dir` with the signals set up
/// by `setup`, and waits until it is writing its temporary file.
fn render_until_writing(
    dir: &Path,
    setup: impl FnOnce(&mut Command) -> &mut Command,
) -> std::process::Child {
    let out = dir.join("out.png");
    let mut command = Command::new(env!("CARGO_BIN_EXE_mountains"));
    command
        .args(["render", "--size", "8000x8000", "-o", out.to_str().unwrap()])
        .env("HOME", dir)
        .stdout(Stdio::null())
        .stderr(Stdio::null());
    let mut child = setup(&mut command).spawn().expect("run mountains");
    let tmp = dir.join(format!(".out.png.{}.tmp", child.id()));
    let start = Instant::now();
    while !tmp.exists() {
        assert!(start.elapsed() < BOUND, "no temporary file appeared");
        assert!(child.try_wait().unwrap().is_none(), "ended before writing");
        std::thread::sleep(Duration::from_millis(1));
    }
    child
}

/// Sends SIG`name` to `child` with kill(1).
fn kill(child: &std::process::Child, name: &str) {
    let sent = Command::new("kill")
        .args([format!("-{name}"), child.id().to_string()])
        .status()
        .expect("kill");
    assert!(sent.success());
}

/// SIGTERM, SIGINT or SIGHUP while `render` writes its file: the half-made
/// temporary file is removed, no output appears, and the command ends by
/// the signal (a script must not take it for a success). It used to leave
/// `.NAME.PID.tmp` beside the output. The child starts with each signal at
/// its default action, as from a terminal, however the test was started.
#[test]
fn a_signal_during_the_write_leaves_no_file() {
    use std::os::unix::process::ExitStatusExt;
    for (signal, number) in signals::ENDING {
        let dir = scratch(&format!("signal-{signal}"));
        let mut child = render_until_writing(&dir, signals::as_from_a_terminal);
        kill(&child, signal);
        let status = child.wait().unwrap();
        assert_eq!(status.signal(), Some(number), "SIG{signal}: {status}");
        let left: Vec<_> = std::fs::read_dir(&dir)
            .unwrap()
            .map(|e| e.unwrap().file_name())
            .collect();
        assert!(left.is_empty(), "SIG{signal} left {left:?}");
    }
}

/// A signal ignored when `render` was started stays ignored: a shell starts
/// a background job with SIGINT ignored so that Ctrl+C at the terminal
/// does not end it, and `nohup` ignores SIGHUP; the picture is still made.
/// SIGTERM (what xscreensaver and `kill` send) is never ignored that way.
#[cfg(target_os = "linux")]
#[test]
fn a_signal_ignored_when_started_stays_ignored() {
    for (signal, number) in [("INT", 2), ("HUP", 1)] {
        let dir = scratch(&format!("ignored-{signal}"));
        let mut child = render_until_writing(&dir, |c| signals::ignoring(c, number));
        kill(&child, signal);
        let status = child.wait().unwrap();
        assert!(status.success(), "SIG{signal} ignored: {status}");
        assert!(dir.join("out.png").exists(), "SIG{signal}: no picture");
    }
}
