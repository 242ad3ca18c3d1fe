//! Test helpers for Wayland tests: a private headless sway (with Xwayland
//! when asked), `mountains` and the sway tools (grim, wtype, swaymsg) run
//! as its clients, and a virtual pointer.
//!
//! sway refuses to run as root: as root, the compositor and its clients
//! run as `nobody` (setpriv), with a runtime folder and a home of their
//! own and a link to (or copy of) the binary, since the build folder may be
//! closed to `nobody`. Everything started here is ended on drop.
#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

use super::running::Running;

pub use super::signals;

/// How long a test waits for something that normally takes a fraction of a second.
pub const PATIENCE: Duration = Duration::from_secs(15);

/// What to install for these tests (Debian's names).
const INSTALL: &str = "apt-get install sway xwayland grim wtype";

/// A headless sway with one output; ended on drop.
pub struct Sway {
    child: Child,
    /// Its `XDG_RUNTIME_DIR` (the clients' too), removed on drop.
    runtime: PathBuf,
    /// The Wayland socket's name in `runtime` (`wayland-1`).
    socket: String,
    /// `mountains`, where the compositor's user can run it.
    exe: PathBuf,
    /// True when we are root and its processes run as `nobody`.
    as_nobody: bool,
    shots: std::cell::Cell<u32>,
}

impl Sway {
    /// Starts sway with one `width` x `height` output at `scale`, with
    /// Xwayland if `xwayland`. Without sway and its tools the test fails,
    /// or skips if asked to (see common/tools.rs); CI sets
    /// `MOUNTAINS_REQUIRE_WAYLAND=1`.
    pub fn start(name: &str, width: u32, height: u32, scale: u32, xwayland: bool) -> Option<Sway> {
        for tool in ["sway", "swaymsg", "grim", "wtype"] {
            if !installed(tool) {
                let what = format!("{tool} is not installed");
                super::tools::missing(&what, INSTALL, "MOUNTAINS_REQUIRE_WAYLAND");
                return None;
            }
        }
        if xwayland && !installed("Xwayland") {
            super::tools::missing(
                "Xwayland is not installed",
                INSTALL,
                "MOUNTAINS_REQUIRE_WAYLAND",
            );
            return None;
        }
        let as_nobody = effective_uid() == 0;
        let runtime =
            std::env::temp_dir().join(format!("mountains-sway-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&runtime);
        std::fs::create_dir_all(runtime.join("home")).unwrap();
        let exe = runtime.join("mountains");
        let built = Path::new(env!("CARGO_BIN_EXE_mountains"));
        if std::fs::hard_link(built, &exe).is_err() {
            std::fs::copy(built, &exe).expect("copy the binary");
        }
        let config = runtime.join("sway.conf");
        let xw = if xwayland { "enable" } else { "disable" };
        let text = format!(
            "xwayland {xw}\noutput HEADLESS-1 resolution {width}x{height} scale {scale}\n\
             default_border none\nexec echo $DISPLAY > {}\n",
            runtime.join("display").display()
        );
        std::fs::write(&config, text).unwrap();
        use std::os::unix::fs::PermissionsExt;
        std::fs::set_permissions(&runtime, std::fs::Permissions::from_mode(0o700)).unwrap();
        if as_nobody {
            let owner = Command::new("chown")
                .args(["-R", "nobody:nogroup"])
                .arg(&runtime)
                .status();
            assert!(
                owner.is_ok_and(|s| s.success()),
                "chown the runtime folder to nobody"
            );
        }
        // Beside the runtime folder, which belongs to the compositor's user.
        let log = std::fs::File::create(runtime.with_extension("log")).unwrap();
        let mut command = user_command("sway", as_nobody, &runtime);
        command
            .args(["-c"])
            .arg(&config)
            .env("WLR_BACKENDS", "headless")
            .env("WLR_RENDERER", "pixman")
            .env("WLR_LIBINPUT_NO_DEVICES", "1")
            .env("WLR_HEADLESS_OUTPUTS", "1")
            .stdin(Stdio::null())
            .stdout(Stdio::null())
            .stderr(log);
        let child = signals::as_from_a_terminal(&mut command)
            .spawn()
            .expect("start sway");
        let mut sway = Sway {
            child,
            runtime,
            socket: String::new(),
            exe,
            as_nobody,
            shots: std::cell::Cell::new(0),
        };
        sway.socket = sway.wait_for_socket();
        Some(sway)
    }

    fn wait_for_socket(&mut self) -> String {
        let start = Instant::now();
        while start.elapsed() < PATIENCE {
            if let Some(status) = self.child.try_wait().unwrap() {
                let log = std::fs::read_to_string(self.runtime.with_extension("log"));
                panic!(
                    "sway ended at start ({status}):\n{}",
                    log.unwrap_or_default()
                );
            }
            let found = std::fs::read_dir(&self.runtime).ok().and_then(|dir| {
                let names: Vec<String> = dir
                    .filter_map(|e| e.ok()?.file_name().into_string().ok())
                    .collect();
                let ipc = names.iter().any(|n| n.starts_with("sway-ipc."));
                let socket = names
                    .iter()
                    .find(|n| n.starts_with("wayland-") && !n.ends_with(".lock"))?;
                ipc.then(|| socket.clone())
            });
            if let Some(socket) = found {
                return socket;
            }
            std::thread::sleep(Duration::from_millis(20));
        }
        panic!("sway made no socket within {PATIENCE:?}");
    }

    /// Where `mountains` saves screenshots (`$XDG_DATA_HOME/mountains/screenshots`).
    pub fn screenshots_dir(&self) -> PathBuf {
        self.runtime.join("home/data/mountains/screenshots")
    }

    /// The path of the compositor's socket.
    pub fn socket_path(&self) -> PathBuf {
        self.runtime.join(&self.socket)
    }

    /// `program` as a client of this compositor (on Wayland; `DISPLAY`
    /// unset), with the compositor's user and a private home.
    pub fn command(&self, program: &str) -> Command {
        let mut c = user_command(program, self.as_nobody, &self.runtime);
        c.env("WAYLAND_DISPLAY", &self.socket);
        if let Some(ipc) = self.ipc_socket() {
            c.env("SWAYSOCK", ipc);
        }
        c
    }

    fn ipc_socket(&self) -> Option<PathBuf> {
        std::fs::read_dir(&self.runtime)
            .ok()?
            .filter_map(|e| e.ok())
            .map(|e| e.path())
            .find(|p| {
                p.file_name()
                    .is_some_and(|n| n.to_string_lossy().starts_with("sway-ipc."))
            })
    }

    /// Xwayland's `DISPLAY` (sway writes it at start, see the config).
    pub fn xwayland_display(&self) -> String {
        let file = self.runtime.join("display");
        let start = Instant::now();
        while start.elapsed() < PATIENCE {
            let text = std::fs::read_to_string(&file).unwrap_or_default();
            if text.trim().starts_with(':') {
                return text.trim().to_string();
            }
            std::thread::sleep(Duration::from_millis(20));
        }
        panic!("sway told no Xwayland DISPLAY within {PATIENCE:?}");
    }

    /// Runs `mountains ARGS` natively on Wayland with quick pacing.
    pub fn mountains(&self, args: &[&str]) -> Client {
        self.spawn_mountains(args, None)
    }

    /// Runs `mountains ARGS` natively on the Wayland socket `socket` of the
    /// runtime folder (a proxy's, see common/wl_proxy.rs) instead of sway's.
    pub fn mountains_via(&self, socket: &str, args: &[&str]) -> Client {
        self.spawn_mountains_with(args, |c| {
            c.env("WAYLAND_DISPLAY", socket);
        })
    }

    /// A path in the runtime folder the clients share.
    pub fn runtime_path(&self, name: &str) -> PathBuf {
        self.runtime.join(name)
    }

    /// Runs `mountains ARGS` through Xwayland (`DISPLAY` set, no `WAYLAND_DISPLAY`).
    pub fn mountains_on_xwayland(&self, args: &[&str]) -> Client {
        let display = self.xwayland_display();
        self.spawn_mountains(args, Some(&display))
    }

    fn spawn_mountains(&self, args: &[&str], x_display: Option<&str>) -> Client {
        self.spawn_mountains_with(args, |c| {
            if let Some(display) = x_display {
                c.env_remove("WAYLAND_DISPLAY").env("DISPLAY", display);
            }
        })
    }

    fn spawn_mountains_with(&self, args: &[&str], adjust: impl FnOnce(&mut Command)) -> Client {
        let n = self.shots.get() + 1;
        self.shots.set(n);
        let stderr = self.runtime.join(format!("mountains-{n}.txt"));
        let mut c = self.command(self.exe.to_str().unwrap());
        c.args(["--set", "draw_seconds=0.5", "--set", "pause_seconds=1"])
            .args(args)
            .env("MOUNTAINS_TRACE", "1")
            .stdin(Stdio::null())
            .stdout(Stdio::null())
            .stderr(std::fs::File::create(&stderr).unwrap());
        adjust(&mut c);
        let child = signals::as_from_a_terminal(&mut c)
            .spawn()
            .expect("start mountains");
        Client(Running::new(child, stderr))
    }

    /// Runs a sway tool to its end; panics with its stderr if it fails.
    pub fn run(&self, program: &str, args: &[&str]) -> String {
        let out = self
            .command(program)
            .args(args)
            .stdin(Stdio::null())
            .output()
            .unwrap_or_else(|e| panic!("run {program}: {e}"));
        assert!(
            out.status.success(),
            "{program} {args:?}: {}\n{}",
            out.status,
            String::from_utf8_lossy(&out.stderr)
        );
        String::from_utf8_lossy(&out.stdout).into_owned()
    }

    /// Presses and releases a key (an xkb name: `Escape`, `q`) with wtype.
    /// wtype adds a keyboard to the seat; the pause lets the focused window
    /// get it before the press (else the key is pressed when it arrives,
    /// and only its release is sent).
    pub fn key(&self, name: &str) {
        self.run("wtype", &["-s", "300", "-k", name]);
    }

    /// The whole output as 0x00RRGGBB pixels, with its size, by grim.
    pub fn screenshot(&self) -> (u32, u32, Vec<u32>) {
        let n = self.shots.get() + 1;
        self.shots.set(n);
        let path = self.runtime.join(format!("shot-{n}.png"));
        self.run("grim", &[path.to_str().unwrap()]);
        let (w, h, _, pixels) = super::headless::read_png(&path);
        let _ = std::fs::remove_file(&path);
        (w, h, pixels)
    }

    /// One output (`HEADLESS-2`) as 0x00RRGGBB pixels, with its size, by grim.
    pub fn screenshot_output(&self, output: &str) -> (u32, u32, Vec<u32>) {
        let n = self.shots.get() + 1;
        self.shots.set(n);
        let path = self.runtime.join(format!("shot-{n}.png"));
        self.run("grim", &["-o", output, path.to_str().unwrap()]);
        let (w, h, _, pixels) = super::headless::read_png(&path);
        let _ = std::fs::remove_file(&path);
        (w, h, pixels)
    }

    /// The names of the outputs sway has now (`HEADLESS-1`, ...).
    pub fn outputs(&self) -> Vec<String> {
        let json = self.run("swaymsg", &["-r", "-t", "get_outputs"]);
        json.split("\"name\": \"")
            .skip(1)
            .filter_map(|rest| rest.split('"').next())
            .map(str::to_string)
            .collect()
    }

    /// sway's tree of outputs and windows, as JSON text.
    pub fn tree(&self) -> String {
        self.run("swaymsg", &["-r", "-t", "get_tree"])
    }
}

impl Drop for Sway {
    fn drop(&mut self) {
        // SIGTERM lets it end Xwayland; then make sure.
        let _ = Command::new("kill")
            .args(["-TERM", &self.child.id().to_string()])
            .status();
        let start = Instant::now();
        while start.elapsed() < Duration::from_secs(3) {
            if self.child.try_wait().ok().flatten().is_some() {
                break;
            }
            std::thread::sleep(Duration::from_millis(20));
        }
        let _ = self.child.kill();
        let _ = self.child.wait();
        let _ = std::fs::remove_dir_all(&self.runtime);
        let _ = std::fs::remove_file(self.runtime.with_extension("log"));
    }
}

/// A `mountains` run on the compositor; killed on drop (see [`Running`]
/// for its stderr, status and end).
pub struct Client(Running);

impl std::ops::Deref for Client {
    type Target = Running;
    fn deref(&self) -> &Running {
        &self.0
    }
}

impl std::ops::DerefMut for Client {
    fn deref_mut(&mut self) -> &mut Running {
        &mut self.0
    }
}

impl Client {
    /// Waits for `what` to end it and checks it ended with status 0.
    pub fn expect_exit(&mut self, what: &str) {
        let status = self.wait(PATIENCE);
        let status =
            status.unwrap_or_else(|| panic!("{what} did not end mountains:\n{}", self.stderr()));
        assert!(status.success(), "{what}: {status}\n{}", self.stderr());
    }

    /// Sends it SIGTERM, as an idle daemon or swaylock-plugin ends it.
    pub fn terminate(&self) {
        let pid = self.pid().to_string();
        let status = Command::new("kill").args(["-TERM", &pid]).status();
        assert!(status.is_ok_and(|s| s.success()), "kill -TERM {pid}");
    }

    /// Polls until its stderr says `words` (while it runs, up to `PATIENCE`).
    pub fn poll_said(&mut self, words: &str) -> Duration {
        let stderr = self.stderr_path().clone();
        let what = format!("saying `{words}`");
        self.poll(&what, || {
            std::fs::read_to_string(&stderr).is_ok_and(|t| t.contains(words))
        })
    }

    /// Polls `check` while it runs until it holds or `PATIENCE` runs out.
    pub fn poll(&mut self, what: &str, mut check: impl FnMut() -> bool) -> Duration {
        let start = Instant::now();
        while start.elapsed() < PATIENCE {
            self.assert_running();
            if check() {
                return start.elapsed();
            }
            std::thread::sleep(Duration::from_millis(50));
        }
        panic!(
            "{what} did not happen within {PATIENCE:?}; stderr:\n{}",
            self.stderr()
        );
    }
}

/// `program` with a clean environment for the compositor's user: PATH,
/// the runtime folder, and a home inside it.
fn user_command(program: &str, as_nobody: bool, runtime: &Path) -> Command {
    let mut c = if as_nobody {
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
    let home = runtime.join("home");
    c.env_clear()
        .env(
            "PATH",
            std::env::var_os("PATH").unwrap_or_else(|| "/usr/bin:/bin".into()),
        )
        .env("HOME", &home)
        .env("XDG_RUNTIME_DIR", runtime)
        .env("XDG_CONFIG_HOME", home.join("config"))
        .env("XDG_DATA_HOME", home.join("data"))
        .current_dir(runtime);
    c
}

/// True when `program` can be started.
fn installed(program: &str) -> bool {
    // Xwayland has no --version that exits at once everywhere: look it up.
    let path = std::env::var_os("PATH").unwrap_or_else(|| "/usr/bin:/bin".into());
    std::env::split_paths(&path).any(|dir| dir.join(program).is_file())
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
