//! The real xscreensaver daemon runs the hack as the README says: it starts
//! `mountains --root` on activation, a mountain appears, and on deactivation
//! our process is gone.
//!
//! xscreensaver refuses to launch hacks as root, so under root (CI) the daemon
//! runs as `nobody` (setpriv), with a home and a copy of the binary in /tmp.
//! Without xscreensaver the test fails, saying how to install it (or skips
//! if asked to: see common/tools.rs).
#![cfg(target_os = "linux")]

use crate::common::tools;
use crate::common::xvfb;

use std::path::Path;
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

use xvfb::{TempDir, Xvfb};

/// The daemon takes a few seconds to start and to launch a hack.
const PATIENCE: Duration = Duration::from_secs(30);

/// Whether xscreensaver is here; a failure instead of a skip under CI.
fn have_xscreensaver() -> bool {
    let found = Command::new("xscreensaver-command")
        .arg("-help")
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .status()
        .is_ok();
    if !found {
        tools::missing(
            "xscreensaver is not installed",
            "apt-get install xscreensaver",
            "MOUNTAINS_REQUIRE_XSCREENSAVER",
        );
    }
    found
}

/// A command run as the daemon's user: `nobody` when we are root.
fn as_user(program: &str, home: &Path, display: &str) -> Command {
    let root = effective_uid() == 0;
    let mut c = if root {
        let mut c = Command::new("setpriv");
        c.args([
            "--reuid=nobody",
            "--regid=nogroup",
            "--clear-groups",
            program,
        ]);
        c
    } else {
        Command::new(program)
    };
    c.env("HOME", home)
        .env("DISPLAY", display)
        .env("XDG_CONFIG_HOME", home.join(".config"))
        .env("XDG_DATA_HOME", home.join(".local/share"))
        .current_dir(home);
    c
}

/// The effective user id, read from /proc (no libc call needed).
fn effective_uid() -> u32 {
    let status = std::fs::read_to_string("/proc/self/status").unwrap_or_default();
    status
        .lines()
        .find_map(|l| l.strip_prefix("Uid:"))
        .and_then(|l| l.split_whitespace().nth(1))
        .and_then(|u| u.parse().ok())
        .unwrap_or(u32::MAX)
}

/// Pids of live (not zombie) processes running `exe`.
fn running(exe: &Path) -> Vec<u32> {
    let Ok(dir) = std::fs::read_dir("/proc") else {
        return Vec::new();
    };
    dir.filter_map(|e| e.ok()?.file_name().to_str()?.parse::<u32>().ok())
        .filter(|pid| {
            let link = std::fs::read_link(format!("/proc/{pid}/exe"));
            let stat = std::fs::read_to_string(format!("/proc/{pid}/stat")).unwrap_or_default();
            let zombie = stat.rsplit(") ").next().is_some_and(|s| s.starts_with('Z'));
            link.is_ok_and(|l| l == exe) && !zombie
        })
        .collect()
}

/// Polls `check` until it holds, or fails naming `what` with the daemon's log.
fn wait_for(what: &str, log: &Path, mut check: impl FnMut() -> bool) -> Duration {
    let start = Instant::now();
    while start.elapsed() < PATIENCE {
        if check() {
            return start.elapsed();
        }
        std::thread::sleep(Duration::from_millis(50));
    }
    let log = std::fs::read_to_string(log).unwrap_or_default();
    panic!("{what} did not happen within {PATIENCE:?}; xscreensaver said:\n{log}");
}

/// A shaded mountain, not the server's two-colour root weave nor the
/// daemon's black: lit, and in many colours.
fn mountain_on(pixels: &[u32]) -> bool {
    let colours: std::collections::HashSet<u32> = pixels.iter().copied().collect();
    xvfb::looks_drawn(pixels) && colours.len() > 200
}

/// The daemon; killed on drop.
struct Daemon(Child);

impl Drop for Daemon {
    fn drop(&mut self) {
        let _ = self.0.kill();
        let _ = self.0.wait();
    }
}

#[test]
fn display_xscreensaver_runs_the_hack_and_ends_it() {
    if !have_xscreensaver() {
        return;
    }
    let Some(x) = Xvfb::start(800, 600, &[]) else {
        return;
    };
    let home = TempDir::new("xscreensaver");
    // A copy in the home: the build folder may be closed to `nobody`.
    let exe = home.0.join("mountains");
    std::fs::copy(env!("CARGO_BIN_EXE_mountains"), &exe).expect("copy the binary");
    // The README's `programs:` line, with the binary's path.
    let prefs = format!(
        "mode: one\nselected: 0\nlock: False\nsplash: False\nfade: False\nunfade: False\n\
         timeout: 0:30:00\nprograms: \"Mountains\" {} --root \\n\n",
        exe.display()
    );
    std::fs::write(home.0.join(".xscreensaver"), prefs).expect("write ~/.xscreensaver");
    if effective_uid() == 0 {
        let owner = Command::new("chown")
            .args(["-R", "nobody:nogroup"])
            .arg(&home.0)
            .status();
        assert!(
            owner.is_ok_and(|s| s.success()),
            "chown the test home to nobody"
        );
    }
    let log = home.0.join("daemon.log");
    let log_file = std::fs::File::create(&log).expect("daemon log");
    let daemon = as_user("xscreensaver", &home.0, x.display())
        .args(["-no-splash", "-verbose"])
        .stdout(log_file.try_clone().expect("log"))
        .stderr(log_file)
        .spawn()
        .expect("start xscreensaver");
    let _daemon = Daemon(daemon);
    let command = |verb: &str| {
        as_user("xscreensaver-command", &home.0, x.display())
            .arg(verb)
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .status()
            .is_ok_and(|s| s.success())
    };
    assert!(
        !mountain_on(&x.grab_screen()),
        "a mountain before activation?"
    );
    // The daemon needs a moment before it answers.
    wait_for("xscreensaver answering -activate", &log, || {
        command("-activate")
    });
    let started = wait_for("our hack starting", &log, || !running(&exe).is_empty());
    let drawn = wait_for("a mountain on screen", &log, || {
        mountain_on(&x.grab_screen())
    });
    eprintln!("hack started {started:?} after -activate; a mountain {drawn:?} later");
    assert!(command("-deactivate"), "xscreensaver-command -deactivate");
    let gone = wait_for("our process gone", &log, || running(&exe).is_empty());
    eprintln!("gone {gone:?} after -deactivate");
}
