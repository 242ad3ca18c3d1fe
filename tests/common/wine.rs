//! Test helpers for running the Windows build under Wine: find Wine, mingw
//! and the cross-built exe, build the test-only DLL shim and preview host
//! (tests/wine/) next to a copy of the exe, and keep one WINEPREFIX under
//! target/.
//!
//! One wineserver serves a prefix, and it remembers windows and the display
//! of the processes it ran, so the tests take turns (`Session`) and each one
//! starts and ends with no Wine process left in the prefix.
#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::sync::{Mutex, MutexGuard, OnceLock};
use std::time::{Instant, SystemTime};

#[cfg(unix)]
use super::xvfb::{Saver, Xvfb};

/// The command that makes the exe these tests run.
pub const CROSS_BUILD: &str = "cargo build --release --target x86_64-pc-windows-gnu";

/// Debian's `wine64` package puts the loader here, not on PATH.
const LOADERS: [&str; 2] = ["/usr/lib/wine/wine64", "wine64"];
const SERVERS: [&str; 2] = ["/usr/lib/wine/wineserver", "wineserver"];
const MINGW: &str = "x86_64-w64-mingw32-gcc";

/// Wine and the Windows programs the tests run, ready to start.
pub struct Wine {
    /// The `wine64` loader: `loader program.exe ARGS` runs a Windows program.
    pub loader: PathBuf,
    server: PathBuf,
    prefix: PathBuf,
    /// The folder with mountains.exe, bcryptprimitives.dll and preview_host.exe.
    pub bin: PathBuf,
}

impl Wine {
    /// The environment every Wine process of the tests gets.
    pub fn env(&self) -> Vec<(&'static str, String)> {
        vec![
            ("WINEPREFIX", self.prefix.display().to_string()),
            ("WINEDEBUG", "-all".into()),
            // No prompts to install Mono or Gecko, which nothing here needs.
            ("WINEDLLOVERRIDES", "mscoree,mshtml=".into()),
            ("MOUNTAINS_TRACE", "1".into()),
        ]
    }

    /// The Unix path of a program in `bin`, as the loader takes it.
    pub fn program(&self, name: &str) -> String {
        self.bin.join(name).display().to_string()
    }

    /// The Windows path (`Z:\...`) of a program in `bin`, as Win32 takes it.
    pub fn windows_path(&self, name: &str) -> String {
        format!("Z:{}", self.program(name).replace('/', "\\"))
    }

    /// Ends every Wine process of the prefix, and waits for that.
    fn stop_all(&self) {
        self.server("-k");
        self.server("-w");
    }

    /// Runs Wine's `reg ARGS` in the prefix, which must succeed. It is tried
    /// again after the prefix's Wine processes end: a `reg` started while a
    /// killed program's wineserver is going down can lose its server.
    fn reg(&self, args: &[&str]) {
        let mut failures = Vec::new();
        for _ in 0..3 {
            match self.try_reg(args) {
                Ok(()) => return,
                Err(why) => failures.push(why),
            }
            self.stop_all();
        }
        panic!("wine reg {args:?} failed: {}", failures.join("; "));
    }

    /// One run of Wine's `reg ARGS`; the error holds its status and output.
    fn try_reg(&self, args: &[&str]) -> Result<(), String> {
        let out = Command::new(&self.loader)
            .arg("reg")
            .args(args)
            .envs(self.env())
            .env_remove("DISPLAY")
            .stdin(Stdio::null())
            .output()
            .expect("run Wine's reg");
        if out.status.success() {
            return Ok(());
        }
        Err(format!(
            "{} (stdout {:?}, stderr {:?})",
            out.status,
            String::from_utf8_lossy(&out.stdout).trim(),
            String::from_utf8_lossy(&out.stderr).trim()
        ))
    }

    /// Runs `wineserver FLAG` for the prefix (`-w` waits until it ends).
    fn server(&self, flag: &str) {
        let _ = Command::new(&self.server)
            .arg(flag)
            .env("WINEPREFIX", &self.prefix)
            .stderr(Stdio::null())
            .status();
    }
}

/// One test's turn with Wine: no other Wine test runs until it is dropped,
/// and then no Wine process of the test is left.
pub struct Session {
    /// Wine, set up once for all tests.
    pub wine: &'static Wine,
    _turn: MutexGuard<'static, ()>,
}

impl Session {
    /// Waits for this test's turn. `None` (the test skips) when Wine, mingw
    /// or the exe is missing, unless `MOUNTAINS_REQUIRE_WINE=1`.
    pub fn begin() -> Option<Session> {
        static TURN: Mutex<()> = Mutex::new(());
        static READY: OnceLock<Option<Wine>> = OnceLock::new();
        // A failed test poisons the lock; the next one still needs its turn.
        let turn = TURN.lock().unwrap_or_else(|e| e.into_inner());
        let wine = READY.get_or_init(set_up).as_ref()?;
        wine.stop_all();
        Some(Session { wine, _turn: turn })
    }
}

impl Session {
    /// Runs `PROGRAM ARGS` (a program in `bin`) under Wine on `x`.
    #[cfg(unix)]
    pub fn start(&self, x: &Xvfb, name: &str, program: &str, args: &[&str]) -> Saver {
        let exe = self.wine.program(program);
        let mut all = vec![exe.as_str()];
        all.extend_from_slice(args);
        let env = self.wine.env();
        let env: Vec<(&str, &str)> = env.iter().map(|(k, v)| (*k, v.as_str())).collect();
        Saver::start_program(x, name, &self.wine.loader, &all, &env)
    }

    /// Until the guard is dropped, Wine takes the monitors from Xinerama,
    /// not RandR (its X11 driver's `UseXRandR`): the heads of
    /// `Xvfb::start_xinerama` are Xinerama's alone.
    pub fn monitors_from_xinerama(&self) -> XineramaMonitors<'_> {
        self.wine
            .reg(&["add", X11_DRIVER, "/v", "UseXRandR", "/d", "N", "/f"]);
        // The monitors are read when Wine's desktop starts: the next
        // program must find none running.
        self.wine.server("-w");
        XineramaMonitors(self.wine)
    }
}

/// The Wine registry key of the X11 driver's options.
const X11_DRIVER: &str = r"HKCU\Software\Wine\X11 Driver";

/// Wine's monitors come from Xinerama while this lives; the prefix is
/// given back to RandR when it is dropped (see `monitors_from_xinerama`).
pub struct XineramaMonitors<'a>(&'a Wine);

impl Drop for XineramaMonitors<'_> {
    fn drop(&mut self) {
        // The test's programs end first, so that `reg` finds a settled
        // wineserver; `Y` is Wine's own default, and unlike deleting the
        // value, setting it cannot fail for want of it.
        self.0.stop_all();
        self.0
            .reg(&["add", X11_DRIVER, "/v", "UseXRandR", "/d", "Y", "/f"]);
    }
}

impl Drop for Session {
    fn drop(&mut self) {
        self.wine.stop_all();
    }
}

/// The cross-built mountains.exe, if it is there and at least as new as its
/// sources. `None` (the test skips) otherwise, unless `MOUNTAINS_REQUIRE_WINE=1`.
pub fn cross_built_exe() -> Option<PathBuf> {
    let exe = target_dir().join("x86_64-pc-windows-gnu/release/mountains.exe");
    if !exe.exists() {
        return skip(&format!(
            "{} is missing: run `{CROSS_BUILD}`",
            exe.display()
        ));
    }
    if let Some(newer) = newer_source(&exe) {
        return skip(&format!(
            "{} is older than {} (it would test old code): run `{CROSS_BUILD}`",
            exe.display(),
            newer.display()
        ));
    }
    Some(exe)
}

fn set_up() -> Option<Wine> {
    let target = target_dir();
    let loader = find(&LOADERS, "Wine (apt-get install wine64)")?;
    let server = find(&SERVERS, "wineserver (apt-get install wine64)")?;
    find(&[MINGW], "mingw (apt-get install gcc-mingw-w64-x86-64)")?;
    let exe = cross_built_exe()?;
    let wine = Wine {
        loader,
        server,
        prefix: target.join("wine/prefix"),
        bin: target.join("wine/bin"),
    };
    build_bin(&wine, &exe);
    make_prefix(&wine);
    Some(wine)
}

/// `target/`, found from this test's own build of the Linux binary.
fn target_dir() -> PathBuf {
    let bin = Path::new(env!("CARGO_BIN_EXE_mountains"));
    bin.ancestors().nth(2).expect("target dir").to_path_buf()
}

/// The first of `candidates` that runs with `--version`.
fn find(candidates: &[&str], what: &str) -> Option<PathBuf> {
    let runs = |c: &&&str| {
        Command::new(**c)
            .arg("--version")
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .status()
            .is_ok_and(|s| s.success())
    };
    match candidates.iter().find(runs) {
        Some(c) => Some(PathBuf::from(c)),
        None => skip(&format!("{what} is not available")),
    }
}

fn skip<T>(why: &str) -> Option<T> {
    if std::env::var("MOUNTAINS_REQUIRE_WINE").is_ok_and(|v| v == "1") {
        panic!("MOUNTAINS_REQUIRE_WINE=1 but {why}");
    }
    eprintln!("skipped: {why}");
    None
}

/// A source file newer than the exe, if any: everything that goes into it
/// (src/, config/ through include_str!, Cargo.toml, Cargo.lock, and the
/// resources build.rs makes from assets/).
fn newer_source(exe: &Path) -> Option<PathBuf> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut newest = (SystemTime::UNIX_EPOCH, root.join("Cargo.toml"));
    for file in ["Cargo.toml", "Cargo.lock", "build.rs"] {
        let path = root.join(file);
        if modified(&path) > newest.0 {
            newest = (modified(&path), path);
        }
    }
    newest_under(&root.join("src"), &mut newest);
    newest_under(&root.join("config"), &mut newest);
    newest_under(&root.join("assets"), &mut newest);
    (modified(exe) < newest.0).then_some(newest.1)
}

fn modified(path: &Path) -> SystemTime {
    let meta = std::fs::metadata(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    meta.modified().expect("modification time")
}

fn newest_under(dir: &Path, newest: &mut (SystemTime, PathBuf)) {
    for entry in std::fs::read_dir(dir).unwrap_or_else(|e| panic!("{}: {e}", dir.display())) {
        let path = entry.expect("dir entry").path();
        if path.is_dir() {
            newest_under(&path, newest);
        } else if modified(&path) > newest.0 {
            *newest = (modified(&path), path);
        }
    }
}

/// A fresh `bin`: a copy of the exe, the shim DLL beside it (Windows loads
/// DLLs from the exe's folder first) and the preview host.
fn build_bin(wine: &Wine, exe: &Path) {
    let _ = std::fs::remove_dir_all(&wine.bin);
    std::fs::create_dir_all(&wine.bin).expect("create target/wine/bin");
    std::fs::copy(exe, wine.bin.join("mountains.exe")).expect("copy mountains.exe");
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/wine");
    let shim = ["-shared", "-o", "bcryptprimitives.dll"];
    let shim_src = ["bcryptprimitives.c", "bcryptprimitives.def"].map(|f| src.join(f));
    mingw(wine, &shim, &shim_src, "-ladvapi32");
    let host = ["-o", "preview_host.exe"];
    mingw(wine, &host, &[src.join("preview_host.c")], "-lgdi32");
}

fn mingw(wine: &Wine, args: &[&str], sources: &[PathBuf], lib: &str) {
    // The compiler's words go with the failure, not onto the test's stderr.
    let out = Command::new(MINGW)
        .current_dir(&wine.bin)
        .args(["-O2", "-Wall"])
        .args(args)
        .args(sources)
        .arg(lib)
        .output()
        .expect("run mingw");
    assert!(
        out.status.success(),
        "mingw {args:?} failed: {}: {}",
        out.status,
        String::from_utf8_lossy(&out.stderr)
    );
}

/// Creates the prefix the first time (some seconds), with no display.
fn make_prefix(wine: &Wine) {
    if wine.prefix.join("system.reg").exists() {
        return;
    }
    let started = Instant::now();
    let _ = std::fs::remove_dir_all(&wine.prefix);
    let status = Command::new(&wine.loader)
        .args(["wineboot", "-i"])
        .envs(wine.env())
        .env_remove("DISPLAY")
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .status()
        .expect("run wineboot");
    assert!(status.success(), "wineboot -i failed: {status}");
    // wineboot returns before the prefix is written; its wineserver saves it.
    wine.server("-w");
    assert!(
        wine.prefix.join("system.reg").exists(),
        "no Wine prefix made"
    );
    eprintln!("wine: prefix made in {:?}", started.elapsed());
}
