//! Test helpers for display tests: a private Xvfb server, the `mountains`
//! binary run against it, screen reads and fake input over x11rb.
//!
//! Everything started here is killed on drop, so a failing test leaves no
//! process behind.
#![allow(dead_code)]

use std::io::{BufRead, BufReader};
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

use super::running::Running;

// The program a test signals must not inherit an ignored signal.
pub use super::signals;

use x11rb::connection::Connection;
use x11rb::protocol::xproto::{
    ConfigureWindowAux, ConnectionExt as _, CreateWindowAux, ImageFormat, MapState, Window,
    WindowClass,
};
use x11rb::protocol::xtest::ConnectionExt as _;
use x11rb::rust_connection::RustConnection;
use x11rb::wrapper::ConnectionExt as _;

/// How long a test waits for something that normally takes a fraction of
/// a second (a few seconds for a 4K slide in the debug build). Only an
/// upper bound on a wait that ends as soon as its condition holds: 10 s
/// was too short for the first 4K slide while the other tests and a build
/// shared the two cores.
pub const PATIENCE: Duration = Duration::from_secs(30);

/// A private X server; killed on drop.
pub struct Xvfb {
    child: Child,
    /// The Xvfb a nested server (Xephyr) draws into, killed after it.
    host: Option<Box<Xvfb>>,
    display: String,
    /// The connection the test uses to look and to type.
    pub conn: RustConnection,
    /// The root window of screen 0.
    pub root: Window,
    /// Screen size in pixels.
    pub size: (u16, u16),
}

/// A window's or a rectangle's place on the screen: x, y, width, height.
pub type Geometry = (i16, i16, u16, u16);

impl Xvfb {
    /// Starts `Xvfb -noreset -displayfd 1 -screen 0 WxHx24` plus `extra`
    /// arguments (`depth=16` among them changes the screen depth). Without
    /// Xvfb the test fails, or skips if asked to (see common/tools.rs).
    pub fn start(width: u16, height: u16, extra: &[&str]) -> Option<Xvfb> {
        let depth = extra_depth(extra).unwrap_or(24);
        let screen = format!("{width}x{height}x{depth}");
        let mut args = vec!["-screen", "0", &screen];
        args.extend(extra.iter().filter(|a| !a.starts_with("depth=")));
        Xvfb::serve("Xvfb", &args, None, "apt-get install xvfb")
    }

    /// An X server whose monitors are Xinerama heads, one per `(w, h)` of
    /// `heads`, side by side from the left; its one RandR output covers the
    /// first only. A nested Xephyr in an Xvfb of its own: Xvfb cannot
    /// place Xinerama heads side by side, and Wine takes its monitors from
    /// RandR outputs or from Xinerama, never from RandR's monitors.
    pub fn start_xinerama(heads: &[(u16, u16)]) -> Option<Xvfb> {
        let width: u16 = heads.iter().map(|h| h.0).sum();
        let height = heads.iter().map(|h| h.1).max().unwrap_or(1);
        let host = Xvfb::start(width, height, &[])?;
        let screens: Vec<String> = heads.iter().map(|(w, h)| format!("{w}x{h}")).collect();
        let mut args = vec!["+xinerama"];
        for screen in &screens {
            args.extend(["-screen", screen.as_str()]);
        }
        let install = "apt-get install xserver-xephyr";
        Xvfb::serve("Xephyr", &args, Some(host), install)
    }

    /// Starts the X server `program -noreset -nolisten tcp -displayfd 1
    /// ARGS` (on `host`'s display, if any) and connects to it. Without the
    /// program the test fails, or skips if asked to (see common/tools.rs).
    fn serve(program: &str, args: &[&str], host: Option<Xvfb>, install: &str) -> Option<Xvfb> {
        let mut all = vec!["-noreset"];
        all.extend_from_slice(args);
        let (child, display) = launch(program, &all, host.as_ref(), install)?;
        let (conn, screen_num) = RustConnection::connect(Some(&display)).expect("connect to X");
        let screen = &conn.setup().roots[screen_num];
        let (root, size) = (
            screen.root,
            (screen.width_in_pixels, screen.height_in_pixels),
        );
        Some(Xvfb {
            child,
            host: host.map(Box::new),
            display,
            conn,
            root,
            size,
        })
    }

    /// The `DISPLAY` value for this server.
    pub fn display(&self) -> &str {
        &self.display
    }

    /// Pixels (0x00RRGGBB) of a window's `w` x `h` area at its origin.
    pub fn grab(&self, window: Window, w: u16, h: u16) -> Vec<u32> {
        let mut pixels = self.grab_raw(window, w, h);
        for p in &mut pixels {
            *p &= 0x00ff_ffff;
        }
        pixels
    }

    /// Like `grab`, with the top byte as the server holds it (alpha on a
    /// 32-bit window, padding on a 24-bit one).
    pub fn grab_raw(&self, window: Window, w: u16, h: u16) -> Vec<u32> {
        let reply = self
            .conn
            .get_image(ImageFormat::Z_PIXMAP, window, 0, 0, w, h, !0)
            .expect("GetImage request")
            .reply()
            .expect("GetImage reply");
        reply
            .data
            .chunks_exact(4)
            .map(|b| u32::from_le_bytes([b[0], b[1], b[2], b[3]]))
            .collect()
    }

    /// A window's depth in bits (24, or 32 for ARGB visuals).
    pub fn depth(&self, window: Window) -> u8 {
        self.conn
            .get_geometry(window)
            .unwrap()
            .reply()
            .unwrap()
            .depth
    }

    /// The whole screen's pixels.
    pub fn grab_screen(&self) -> Vec<u32> {
        self.grab(self.root, self.size.0, self.size.1)
    }

    /// A mapped top-level window of `w` x `h` made by the test, like a
    /// screensaver daemon's window.
    pub fn create_window(&self, w: u16, h: u16) -> Window {
        let id = self.conn.generate_id().unwrap();
        let aux = CreateWindowAux::new().background_pixel(0);
        self.conn
            .create_window(
                0,
                id,
                self.root,
                10,
                10,
                w,
                h,
                0,
                WindowClass::INPUT_OUTPUT,
                0,
                &aux,
            )
            .unwrap();
        self.conn.map_window(id).unwrap();
        self.conn.flush().unwrap();
        id
    }

    /// Like `create_window`, with a 32-bit TrueColor (ARGB) visual, as
    /// compositing desktops give screensavers. Such a window needs its own
    /// colormap and a border pixel, since it cannot copy the root's.
    pub fn create_argb_window(&self, w: u16, h: u16) -> Window {
        use x11rb::protocol::xproto::{ColormapAlloc, VisualClass};
        let screen = &self.conn.setup().roots[0];
        let visual = screen
            .allowed_depths
            .iter()
            .filter(|d| d.depth == 32)
            .flat_map(|d| &d.visuals)
            .find(|v| v.class == VisualClass::TRUE_COLOR)
            .expect("Xvfb offers a 32-bit TrueColor visual")
            .visual_id;
        let colormap = self.conn.generate_id().unwrap();
        self.conn
            .create_colormap(ColormapAlloc::NONE, colormap, self.root, visual)
            .unwrap();
        let id = self.conn.generate_id().unwrap();
        let aux = CreateWindowAux::new()
            .background_pixel(0)
            .border_pixel(0)
            .colormap(colormap);
        self.conn
            .create_window(
                32,
                id,
                self.root,
                10,
                10,
                w,
                h,
                0,
                WindowClass::INPUT_OUTPUT,
                visual,
                &aux,
            )
            .unwrap()
            .check()
            .expect("create a 32-bit window");
        self.conn.map_window(id).unwrap();
        self.conn.flush().unwrap();
        id
    }

    /// Resizes a window the test owns.
    pub fn resize_window(&self, id: Window, w: u16, h: u16) {
        let aux = ConfigureWindowAux::new()
            .width(u32::from(w))
            .height(u32::from(h));
        self.conn.configure_window(id, &aux).unwrap();
        self.conn.flush().unwrap();
    }

    /// Destroys a window the test owns.
    pub fn destroy_window(&self, id: Window) {
        self.conn.destroy_window(id).unwrap();
        self.conn.flush().unwrap();
    }

    /// Gives a window the keyboard focus (there is no window manager to do it).
    pub fn focus(&self, window: Window) {
        use x11rb::protocol::xproto::InputFocus;
        self.conn
            .set_input_focus(InputFocus::PARENT, window, x11rb::CURRENT_TIME)
            .unwrap();
        self.conn.sync().unwrap();
    }

    /// A window's `_NET_WM_NAME` title.
    pub fn title(&self, window: Window) -> String {
        use x11rb::protocol::xproto::AtomEnum;
        let atom = |name: &[u8]| {
            self.conn
                .intern_atom(false, name)
                .unwrap()
                .reply()
                .unwrap()
                .atom
        };
        let (name, utf8) = (atom(b"_NET_WM_NAME"), atom(b"UTF8_STRING"));
        let _ = AtomEnum::ANY;
        let reply = self
            .conn
            .get_property(false, window, name, utf8, 0, 1024)
            .unwrap();
        String::from_utf8_lossy(&reply.reply().unwrap().value).into_owned()
    }

    /// True when another client holds the keyboard grab (ours is refused).
    pub fn keyboard_grabbed_elsewhere(&self) -> bool {
        use x11rb::protocol::xproto::{GrabMode, GrabStatus};
        let reply = self
            .conn
            .grab_keyboard(
                false,
                self.root,
                x11rb::CURRENT_TIME,
                GrabMode::ASYNC,
                GrabMode::ASYNC,
            )
            .unwrap()
            .reply()
            .unwrap();
        if reply.status == GrabStatus::SUCCESS {
            self.conn.ungrab_keyboard(x11rb::CURRENT_TIME).unwrap();
            self.conn.sync().unwrap();
        }
        reply.status == GrabStatus::ALREADY_GRABBED
    }

    /// True when another client holds the pointer grab.
    pub fn pointer_grabbed_elsewhere(&self) -> bool {
        use x11rb::protocol::xproto::{EventMask, GrabMode, GrabStatus};
        let reply = self
            .conn
            .grab_pointer(
                false,
                self.root,
                EventMask::NO_EVENT,
                GrabMode::ASYNC,
                GrabMode::ASYNC,
                x11rb::NONE,
                x11rb::NONE,
                x11rb::CURRENT_TIME,
            )
            .unwrap()
            .reply()
            .unwrap();
        if reply.status == GrabStatus::SUCCESS {
            self.conn.ungrab_pointer(x11rb::CURRENT_TIME).unwrap();
            self.conn.sync().unwrap();
        }
        reply.status == GrabStatus::ALREADY_GRABBED
    }

    /// Pixels of one rectangle of the screen (x, y, w, h), 0x00RRGGBB.
    pub fn grab_rect(&self, (left, top, w, h): Geometry) -> Vec<u32> {
        use x11rb::protocol::xproto::ImageFormat;
        let reply = self
            .conn
            .get_image(ImageFormat::Z_PIXMAP, self.root, left, top, w, h, !0)
            .unwrap()
            .reply()
            .unwrap();
        reply
            .data
            .chunks_exact(4)
            .map(|b| u32::from_le_bytes([b[0], b[1], b[2], b[3]]) & 0x00ff_ffff)
            .collect()
    }

    /// The places of the mapped children of the root window, in order.
    pub fn mapped_places(&self) -> Vec<Geometry> {
        let mut found: Vec<Geometry> = self.mapped_windows().into_iter().map(|(_, g)| g).collect();
        found.sort();
        found
    }

    /// Mapped children of the root window with their geometry (x, y, w, h).
    pub fn mapped_windows(&self) -> Vec<(Window, Geometry)> {
        let tree = self.conn.query_tree(self.root).unwrap().reply().unwrap();
        tree.children
            .into_iter()
            .filter_map(|w| {
                let attrs = self.conn.get_window_attributes(w).ok()?.reply().ok()?;
                if attrs.map_state != MapState::VIEWABLE {
                    return None;
                }
                let g = self.conn.get_geometry(w).ok()?.reply().ok()?;
                Some((w, (g.x, g.y, g.width, g.height)))
            })
            .collect()
    }

    /// How many pixels of the pointer's current cursor image can be seen
    /// (alpha above 0), by XFixes.
    pub fn visible_cursor_pixels(&self) -> usize {
        use x11rb::protocol::xfixes::ConnectionExt as _;
        self.conn
            .xfixes_query_version(4, 0)
            .unwrap()
            .reply()
            .unwrap();
        let image = self
            .conn
            .xfixes_get_cursor_image()
            .unwrap()
            .reply()
            .unwrap();
        image.cursor_image.iter().filter(|&&p| p >> 24 != 0).count()
    }

    /// Presses and releases a key (keycode 38 is A on Xvfb's keymap).
    pub fn key(&self, keycode: u8) {
        self.fake(2, keycode, 0, 0);
        self.fake(3, keycode, 0, 0);
    }

    /// Presses and releases a mouse button.
    pub fn click(&self, button: u8) {
        self.fake(4, button, 0, 0);
        self.fake(5, button, 0, 0);
    }

    /// Moves the pointer by (dx, dy) pixels.
    pub fn move_by(&self, dx: i16, dy: i16) {
        self.fake(6, 1, dx, dy);
    }

    /// Moves the pointer `px` right and back, five times, slowly: the hand
    /// resting on the mouse, which must not end a screensaver.
    pub fn jitter(&self, px: i16) {
        for _ in 0..5 {
            self.move_by(px, 0);
            std::thread::sleep(Duration::from_millis(50));
            self.move_by(-px, 0);
            std::thread::sleep(Duration::from_millis(50));
        }
    }

    /// Puts the pointer at (x, y).
    pub fn move_to(&self, x: i16, y: i16) {
        self.fake(6, 0, x, y);
    }

    /// Sends the server a signal with kill(1): `STOP` freezes it, so that
    /// every client waiting for a reply waits on; `CONT` lets it go on.
    pub fn signal(&self, name: &str) {
        let status = Command::new("kill")
            .args([format!("-{name}"), self.child.id().to_string()])
            .status()
            .expect("run kill");
        assert!(status.success());
    }

    /// Warps the pointer to (x, y), as `xdotool mousemove` does: the
    /// pointer jumps, and no device sends a raw motion event.
    pub fn warp_to(&self, x: i16, y: i16) {
        self.conn
            .warp_pointer(x11rb::NONE, self.root, 0, 0, 0, 0, x, y)
            .expect("WarpPointer request");
        self.conn.sync().expect("WarpPointer sync");
    }

    fn fake(&self, kind: u8, detail: u8, x: i16, y: i16) {
        self.conn
            .xtest_fake_input(kind, detail, 0, self.root, x, y, 0)
            .expect("XTEST request");
        self.conn.sync().expect("XTEST sync");
    }
}

/// The screen depth asked for with a `depth=N` pseudo-argument.
fn extra_depth(extra: &[&str]) -> Option<u8> {
    extra
        .iter()
        .find_map(|a| a.strip_prefix("depth=")?.parse().ok())
}

impl Drop for Xvfb {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// Starts the X server `program -nolisten tcp -displayfd 1 ARGS` (on
/// `host`'s display, if any): the server and its `DISPLAY`. Without the
/// program the test fails, or skips if asked to (see common/tools.rs).
fn launch(
    program: &str,
    args: &[&str],
    host: Option<&Xvfb>,
    install: &str,
) -> Option<(Child, String)> {
    let mut command = Command::new(program);
    command
        .args(["-nolisten", "tcp", "-displayfd", "1"])
        .args(args)
        .stdout(Stdio::piped())
        .stderr(Stdio::null());
    if let Some(host) = host {
        command.env("DISPLAY", host.display());
    }
    let mut child = match command.spawn() {
        Ok(c) => c,
        Err(e) => {
            let what = format!("{program} cannot start ({e})");
            super::tools::missing(&what, install, "MOUNTAINS_REQUIRE_DISPLAY");
            return None;
        }
    };
    let mut line = String::new();
    let stdout = child.stdout.take().expect("X server stdout");
    BufReader::new(stdout)
        .read_line(&mut line)
        .expect("X server display number");
    let number: u32 = match line.trim().parse() {
        Ok(n) => n,
        Err(_) => {
            let _ = child.kill();
            panic!("{program} did not report a display number: {line:?}");
        }
    };
    Some((child, format!(":{number}")))
}

/// An Xvfb the test holds no connection to, which ends when its last
/// client leaves (`-terminate`) where a default server resets and refuses
/// a connection made meanwhile: a person's `xinit mountains`, or a kiosk,
/// where the program is the only client. Killed on drop.
pub struct LoneServer {
    child: Child,
    /// Its `DISPLAY` value.
    pub display: String,
}

impl LoneServer {
    /// Starts `Xvfb -terminate` with one `width` x `height` x 24 screen.
    pub fn start(width: u16, height: u16) -> Option<LoneServer> {
        let screen = format!("{width}x{height}x24");
        let args = ["-terminate", "-screen", "0", &screen];
        let (child, display) = launch("Xvfb", &args, None, "apt-get install xvfb")?;
        Some(LoneServer { child, display })
    }
}

impl Drop for LoneServer {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// A temporary directory removed on drop.
pub struct TempDir(pub PathBuf);

impl TempDir {
    /// A fresh directory named after the test, and numbered: the tests of
    /// one binary share its process id, and two may pick one name.
    pub fn new(name: &str) -> TempDir {
        static MADE: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
        let n = MADE.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
        let pid = std::process::id();
        let dir = std::env::temp_dir().join(format!("mountains-{name}-{pid}-{n}"));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        TempDir(dir)
    }
}

impl Drop for TempDir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// The `mountains` binary running on a test display; killed on drop.
pub struct Saver {
    /// Its stderr, status and end (see [`Running`]).
    run: Running,
    _home: TempDir,
    /// When it was started.
    pub started: Instant,
}

impl Saver {
    /// Runs `mountains ARGS` on `xvfb` with a private home (no user config,
    /// logs and saves in a temp dir), quick pacing (overridable), and `env` added.
    pub fn start(xvfb: &Xvfb, name: &str, args: &[&str], env: &[(&str, &str)]) -> Saver {
        // The pacing comes before the test's own arguments, so that a test can override it.
        let mut all = vec!["--set", "draw_seconds=0.5", "--set", "pause_seconds=1"];
        all.extend_from_slice(args);
        let program = Path::new(env!("CARGO_BIN_EXE_mountains"));
        Saver::spawn(xvfb, name, program, &all, env, false)
    }

    /// Runs another `program ARGS` (Wine, say) on `xvfb` the same way, with
    /// the same private home, but no arguments added and its stdout kept
    /// (see `stdout`).
    pub fn start_program(
        xvfb: &Xvfb,
        name: &str,
        program: &Path,
        args: &[&str],
        env: &[(&str, &str)],
    ) -> Saver {
        Saver::spawn(xvfb, name, program, args, env, true)
    }

    fn spawn(
        xvfb: &Xvfb,
        name: &str,
        program: &Path,
        args: &[&str],
        env: &[(&str, &str)],
        keep_stdout: bool,
    ) -> Saver {
        let home = TempDir::new(name);
        let stderr = home.0.join("stderr.txt");
        let stdout = match keep_stdout {
            true => Stdio::from(std::fs::File::create(home.0.join("stdout.txt")).unwrap()),
            false => Stdio::null(),
        };
        let mut command = Command::new(program);
        command
            .args(args)
            .env("DISPLAY", xvfb.display())
            // Run on the Xvfb even inside a Wayland session.
            .env_remove("WAYLAND_DISPLAY")
            .env_remove("WAYLAND_SOCKET")
            .env("HOME", &home.0)
            .env("XDG_CONFIG_HOME", home.0.join("config"))
            .env("XDG_DATA_HOME", home.0.join("data"))
            .env_remove("XSCREENSAVER_WINDOW")
            .stdin(Stdio::null())
            .stdout(stdout)
            .stderr(std::fs::File::create(&stderr).unwrap());
        for (k, v) in env {
            command.env(k, v);
        }
        let child = signals::as_from_a_terminal(&mut command)
            .spawn()
            .unwrap_or_else(|e| panic!("start {}: {e}", program.display()));
        Saver {
            run: Running::new(child, stderr),
            _home: home,
            started: Instant::now(),
        }
    }

    /// Where it saves data sets and screenshots (`$XDG_DATA_HOME/mountains`).
    pub fn data_dir(&self) -> PathBuf {
        self._home.0.join("data").join("mountains")
    }

    /// What it wrote on stdout so far (empty unless started with `start_program`).
    pub fn stdout(&self) -> String {
        std::fs::read_to_string(self._home.0.join("stdout.txt")).unwrap_or_default()
    }

    /// Sends a signal with kill(1).
    pub fn signal(&self, name: &str) {
        let status = Command::new("kill")
            .args([format!("-{name}"), self.pid().to_string()])
            .status()
            .expect("run kill");
        assert!(status.success());
    }
}

impl std::ops::Deref for Saver {
    type Target = Running;
    fn deref(&self) -> &Running {
        &self.run
    }
}

impl std::ops::DerefMut for Saver {
    fn deref_mut(&mut self) -> &mut Running {
        &mut self.run
    }
}

/// Share of pixels that are not black.
pub fn lit_fraction(pixels: &[u32]) -> f64 {
    let lit = pixels.iter().filter(|&&p| p != 0).count();
    lit as f64 / pixels.len().max(1) as f64
}

/// True when not every pixel has the same colour.
pub fn varied(pixels: &[u32]) -> bool {
    pixels.windows(2).any(|w| w[0] != w[1])
}

/// True when the pixels look like a drawn mountain: varied and mostly lit.
pub fn looks_drawn(pixels: &[u32]) -> bool {
    varied(pixels) && lit_fraction(pixels) > 0.4
}

/// Polls `check` until it holds or `PATIENCE` runs out; returns the time it took.
pub fn poll(saver: &mut Saver, what: &str, mut check: impl FnMut() -> bool) -> Duration {
    let start = Instant::now();
    while start.elapsed() < PATIENCE {
        saver.assert_running();
        if check() {
            return start.elapsed();
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    panic!(
        "{what} did not happen within {PATIENCE:?}; stderr:\n{}",
        saver.stderr()
    );
}

/// Waits for `what` to end the saver and checks it ended with status 0.
pub fn expect_exit(saver: &mut Saver, what: &str) {
    let asked = Instant::now();
    let status = saver.wait(PATIENCE);
    let status = status.unwrap_or_else(|| panic!("{what} did not end the saver"));
    eprintln!("{what}: ended after {:?} with {status}", asked.elapsed());
    assert!(status.success(), "{what}: {status}\n{}", saver.stderr());
}

/// Waits for the saver to give up and checks it failed, saying `words`
/// on stderr without panicking.
pub fn expect_refusal(saver: &mut Saver, words: &str) {
    let status = saver.wait(PATIENCE).expect("mountains should give up");
    assert!(!status.success());
    let stderr = saver.stderr();
    assert!(stderr.contains(words), "{stderr}");
    assert!(!stderr.contains("panicked"), "{stderr}");
}

/// Waits until the saver has a mapped `w` x `h` window; returns it.
pub fn wait_for_window(x: &Xvfb, saver: &mut Saver, w: u16, h: u16) -> Window {
    let mut found = None;
    poll(saver, &format!("a {w}x{h} window"), || {
        found = x
            .mapped_windows()
            .into_iter()
            .find(|(_, g)| (g.2, g.3) == (w, h));
        found.is_some()
    });
    found.expect("polled until found").0
}

/// Path of a file in a directory, as &str for arguments.
pub fn arg(path: &Path) -> &str {
    path.to_str().expect("utf-8 temp path")
}
