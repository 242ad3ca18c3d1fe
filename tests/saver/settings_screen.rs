//! The settings window under Xvfb: it opens, keys change a value, Enter
//! saves keeping comments, Esc leaves the file byte-identical, and the
//! screen is drawn at 100% and 200%.
//!
//! Each test starts its own `Xvfb -noreset -displayfd` (one a `-terminate`
//! server with no other client, as under `xinit`). Without Xvfb or
//! xdotool the tests say they skipped, unless `MOUNTAINS_REQUIRE_DISPLAY=1`.
#![cfg(unix)]

use crate::common::tools;
use crate::common::xvfb;

use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::thread::sleep;
use std::time::Duration;

use mountains::render::Size;
use x11rb::connection::Connection;
use x11rb::protocol::xproto::{ConnectionExt, ImageFormat};
use xvfb::Xvfb;

/// Waits are bounded so a broken build fails instead of hanging CI; the
/// bound is generous because the machine may be busy.
const POLL: Duration = Duration::from_millis(100);
const MAX_POLLS: u32 = 600;

/// Starts a private Xvfb with autorepeat off, because a busy machine may
/// deliver a key release late; a missing Xvfb or xdotool fails the test
/// (or skips it if asked to: see common/tools.rs).
fn start_display() -> Option<Xvfb> {
    let x = Xvfb::start(2560, 1600, &["-ardelay", "60000"])?;
    has_xdotool().then_some(x)
}

/// Whether xdotool runs; if not, the test fails (or skips if asked to).
fn has_xdotool() -> bool {
    if Command::new("xdotool").arg("version").output().is_err() {
        tools::missing(
            "xdotool is not installed",
            "apt-get install xdotool",
            "MOUNTAINS_REQUIRE_DISPLAY",
        );
        return false;
    }
    true
}

/// Runs xdotool against the test's display and returns what it printed.
fn xdotool(x: &Xvfb, args: &[&str]) -> String {
    xdotool_on(x.display(), args)
}

/// Runs xdotool against `display` and returns what it printed.
fn xdotool_on(display: &str, args: &[&str]) -> String {
    let out = Command::new("xdotool")
        .args(args)
        .env("DISPLAY", display)
        .output()
        .expect("xdotool runs");
    String::from_utf8_lossy(&out.stdout).trim().to_string()
}

/// The settings window process; killed if the test ends early.
struct App {
    child: Child,
    stderr_path: PathBuf,
}

impl Drop for App {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

impl App {
    fn start(x: &Xvfb, config: &Path, home: &Path, scale: u32) -> App {
        App::start_on(x.display(), config, home, scale)
    }

    /// [`App::start`] on `display`.
    fn start_on(display: &str, config: &Path, home: &Path, scale: u32) -> App {
        App::start_with(display, config, home, scale, &[], &[])
    }

    /// [`App::start_on`] with `more` arguments after the file's, and `env`.
    fn start_with(
        display: &str,
        config: &Path,
        home: &Path,
        scale: u32,
        more: &[&str],
        env: &[(&str, &str)],
    ) -> App {
        let stderr_path = home.join("stderr.txt");
        let stderr = std::fs::File::create(&stderr_path).unwrap();
        let mut command = Command::new(env!("CARGO_BIN_EXE_mountains"));
        let child = xvfb::signals::as_from_a_terminal(&mut command)
            .arg("--settings")
            .arg("--config")
            .arg(config)
            .args(more)
            .envs(env.iter().copied())
            .env("DISPLAY", display)
            .env("HOME", home)
            .env("WINIT_X11_SCALE_FACTOR", scale.to_string())
            .env_remove("XDG_CONFIG_HOME")
            .env_remove("XDG_DATA_HOME")
            .env_remove("WAYLAND_DISPLAY")
            .stdout(Stdio::null())
            .stderr(stderr)
            .spawn()
            .expect("the binary starts");
        App { child, stderr_path }
    }

    fn stderr(&self) -> String {
        std::fs::read_to_string(&self.stderr_path).unwrap_or_default()
    }

    /// The window id, once the window is mapped.
    fn window(&mut self, x: &Xvfb) -> u32 {
        self.window_on(x.display())
    }

    /// Waits until the app holds a socket (on a server with no other
    /// client, its connection to it).
    fn wait_connected(&mut self) {
        let fds = format!("/proc/{}/fd", self.child.id());
        let socket = |entry: std::fs::DirEntry| {
            std::fs::read_link(entry.path())
                .is_ok_and(|to| to.to_string_lossy().starts_with("socket:"))
        };
        // Polled finely (its connection follows the check's within
        // milliseconds), as long in all as the other waits.
        const FINE: Duration = Duration::from_millis(5);
        for _ in 0..MAX_POLLS * (POLL.as_millis() / FINE.as_millis()) as u32 {
            if let Ok(Some(status)) = self.child.try_wait() {
                panic!(
                    "the app exited ({status}) before connecting: {}",
                    self.stderr()
                );
            }
            let mut open = std::fs::read_dir(&fds).expect("the app's fds");
            if open.any(|entry| entry.is_ok_and(socket)) {
                return;
            }
            sleep(FINE);
        }
        panic!("the app never connected: {}", self.stderr());
    }

    /// [`App::window`] on `display`.
    fn window_on(&mut self, display: &str) -> u32 {
        for _ in 0..MAX_POLLS {
            let found = xdotool_on(
                display,
                &["search", "--onlyvisible", "--name", "^Mountains settings$"],
            );
            if let Some(id) = found.lines().next().and_then(|l| l.trim().parse().ok()) {
                return id;
            }
            if let Ok(Some(status)) = self.child.try_wait() {
                panic!(
                    "the app exited ({status}) before showing a window: {}",
                    self.stderr()
                );
            }
            sleep(POLL);
        }
        panic!("no settings window appeared: {}", self.stderr());
    }

    fn wait_exit(&mut self) -> std::process::ExitStatus {
        for _ in 0..MAX_POLLS {
            if let Ok(Some(status)) = self.child.try_wait() {
                return status;
            }
            sleep(POLL);
        }
        panic!("the settings window did not close: {}", self.stderr());
    }
}

fn scratch(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("display-{name}"));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

const COMMENTED: &str = "# my mountains\n\n# sharp ones\ncragginess = 40   # keep this\n\
                         color = \"sonar\"\nmystery = \"unknown key\"\n";

fn press(x: &Xvfb, window: u32, keys: &[&str]) {
    press_on(x.display(), window, keys);
}

/// [`press`] on `display`.
fn press_on(display: &str, window: u32, keys: &[&str]) {
    let id = window.to_string();
    // No window manager runs under Xvfb: give the window the focus ourselves.
    xdotool_on(display, &["windowfocus", "--sync", &id]);
    let mut args = vec!["key", "--delay", "80"];
    args.extend_from_slice(keys);
    xdotool_on(display, &args);
}

/// Waits until the window shows the dialog grey at `(x, y)`: drawn.
fn wait_drawn(display: &str, window: u32) -> (u32, u32, Vec<u32>) {
    let (conn, _) = x11rb::connect(Some(display)).expect("connect to Xvfb");
    for _ in 0..MAX_POLLS {
        if let Some((w, h, px)) = grab(&conn, window)
            && px.get((h / 2 * w + w - 3) as usize) == Some(&0xC0C0C0)
        {
            return (w, h, px);
        }
        sleep(POLL);
    }
    panic!("the window was never drawn");
}

/// The window's pixels as 0x00RRGGBB.
fn grab(conn: &impl Connection, window: u32) -> Option<(u32, u32, Vec<u32>)> {
    let geo = conn.get_geometry(window).ok()?.reply().ok()?;
    let (w, h) = (u32::from(geo.width), u32::from(geo.height));
    let img = conn
        .get_image(
            ImageFormat::Z_PIXMAP,
            window,
            0,
            0,
            geo.width,
            geo.height,
            !0,
        )
        .ok()?
        .reply()
        .ok()?;
    if img.data.len() < (w * h * 4) as usize {
        return None;
    }
    let px = img
        .data
        .chunks_exact(4)
        .map(|b| u32::from_le_bytes([b[0], b[1], b[2], 0]))
        .collect();
    Some((w, h, px))
}

#[test]
fn display_keys_change_a_value_and_enter_saves_keeping_comments() {
    let Some(x) = start_display() else { return };
    let home = scratch("enter");
    let config = home.join("mountains.toml");
    std::fs::write(&config, COMMENTED).unwrap();
    let mut app = App::start(&x, &config, &home, 1);
    let window = app.window(&x);
    wait_drawn(x.display(), window);
    // Seed, Generator, Cragginess: two rows down, one step right, Enter = OK.
    press(&x, window, &["Down", "Down", "Right", "Return"]);
    let status = app.wait_exit();
    assert!(status.success(), "{status}: {}", app.stderr());
    let saved = std::fs::read_to_string(&config).unwrap();
    assert_eq!(saved, COMMENTED.replace("= 40 ", "= 41 "));
}

/// SIGTERM and SIGHUP close the settings screen as Cancel does: exit 0,
/// the file untouched (they used to kill it by the signal).
#[test]
fn display_sigterm_and_sighup_close_the_settings_like_cancel() {
    for signal in ["TERM", "HUP"] {
        let Some(x) = start_display() else { return };
        let home = scratch(&format!("signal-{signal}"));
        let config = home.join("mountains.toml");
        std::fs::write(&config, COMMENTED).unwrap();
        let mut app = App::start(&x, &config, &home, 1);
        let window = app.window(&x);
        wait_drawn(x.display(), window);
        let sent = Command::new("kill")
            .args([format!("-{signal}"), app.child.id().to_string()])
            .status()
            .expect("run kill");
        assert!(sent.success());
        let status = app.wait_exit();
        assert!(status.success(), "SIG{signal}: {status}: {}", app.stderr());
        assert_eq!(std::fs::read(&config).unwrap(), COMMENTED.as_bytes());
    }
}

/// Another client destroying the settings window (as `xdotool search
/// --pid`, then XDestroyWindow) ends the screen as Cancel does: exit 0,
/// the file untouched. It used to run on with no window until SIGTERM,
/// where `--window` and `/p` end at once.
#[test]
fn display_a_destroyed_window_ends_the_settings_like_cancel() {
    let Some(x) = start_display() else { return };
    let home = scratch("destroyed");
    let config = home.join("mountains.toml");
    std::fs::write(&config, COMMENTED).unwrap();
    let mut app = App::start(&x, &config, &home, 1);
    let window = app.window(&x);
    wait_drawn(x.display(), window);
    x.conn
        .destroy_window(window)
        .expect("send DestroyWindow")
        .check()
        .expect("DestroyWindow");
    let status = app.wait_exit();
    assert!(status.success(), "{status}: {}", app.stderr());
    assert_eq!(std::fs::read(&config).unwrap(), COMMENTED.as_bytes());
}

/// `-display` means X11 for the settings screen as for the saver (one
/// choice for both): beside a compositor named in `WAYLAND_DISPLAY`, the
/// window opens on the X display named, not on the compositor winit
/// itself would pick (here none answers, so that pick fails).
#[test]
fn display_the_settings_open_on_the_x_display_named_beside_a_compositor() {
    let Some(x) = start_display() else { return };
    let home = scratch("display-flag");
    let config = home.join("mountains.toml");
    std::fs::write(&config, COMMENTED).unwrap();
    let stderr_path = home.join("stderr.txt");
    let mut command = Command::new(env!("CARGO_BIN_EXE_mountains"));
    let child = xvfb::signals::as_from_a_terminal(&mut command)
        .args(["--settings", "-display", x.display(), "--config"])
        .arg(&config)
        .env("HOME", &home)
        .env("XDG_RUNTIME_DIR", &home)
        .env("WAYLAND_DISPLAY", "mountains-no-such-compositor")
        .env_remove("DISPLAY")
        .env_remove("WAYLAND_SOCKET")
        .env_remove("XDG_CONFIG_HOME")
        .env_remove("XDG_DATA_HOME")
        .stdout(Stdio::null())
        .stderr(std::fs::File::create(&stderr_path).unwrap())
        .spawn()
        .expect("the binary starts");
    let mut app = App { child, stderr_path };
    let window = app.window(&x);
    wait_drawn(x.display(), window);
    press(&x, window, &["Escape"]);
    let status = app.wait_exit();
    assert!(status.success(), "{status}: {}", app.stderr());
    assert_eq!(std::fs::read(&config).unwrap(), COMMENTED.as_bytes());
}

/// A key `--set` beside `--settings` is a change not yet saved: OK writes
/// it (it was shown as the file's value, unstarred, and OK wrote nothing).
#[test]
fn display_a_key_set_on_the_command_line_is_saved_by_ok() {
    let Some(x) = start_display() else { return };
    let home = scratch("set-saved");
    let config = home.join("mountains.toml");
    std::fs::write(&config, COMMENTED).unwrap();
    let set = ["--set", "cragginess=50"];
    let mut app = App::start_with(x.display(), &config, &home, 1, &set, &[]);
    let window = app.window(&x);
    wait_drawn(x.display(), window);
    press(&x, window, &["Return"]);
    let status = app.wait_exit();
    assert!(status.success(), "{status}: {}", app.stderr());
    let saved = std::fs::read_to_string(&config).unwrap();
    assert_eq!(saved, COMMENTED.replace("= 40 ", "= 50 "));
}

/// Edit file with `$VISUAL` set but empty runs `$EDITOR`: an empty
/// `$VISUAL` counted as no editor and hid `$EDITOR` (xdg-open ran, or
/// "Cannot start the editor ``" where it is not installed).
#[test]
fn display_edit_file_runs_editor_when_visual_is_empty() {
    let Some(x) = start_display() else { return };
    let home = scratch("empty-visual");
    let config = home.join("mountains.toml");
    std::fs::write(&config, COMMENTED).unwrap();
    let opened = home.join("opened");
    let script = home.join("editor.sh");
    std::fs::write(
        &script,
        format!("printf '%s' \"$1\" > '{}'\n", opened.display()),
    )
    .unwrap();
    let editor = format!("sh '{}'", script.display());
    let env = [("VISUAL", ""), ("EDITOR", editor.as_str())];
    let mut app = App::start_with(x.display(), &config, &home, 1, &[], &env);
    let window = app.window(&x);
    wait_drawn(x.display(), window);
    // Back from the first row: Cancel, OK, Edit file.
    press(
        &x,
        window,
        &["shift+Tab", "shift+Tab", "shift+Tab", "Return"],
    );
    for _ in 0..MAX_POLLS {
        if opened.exists() {
            break;
        }
        sleep(POLL);
    }
    press(&x, window, &["Escape"]);
    let status = app.wait_exit();
    assert!(status.success(), "{status}: {}", app.stderr());
    let said = std::fs::read_to_string(&opened).expect("$EDITOR was never run");
    assert_eq!(Path::new(&said), config);
}

#[test]
fn display_escape_leaves_the_file_byte_identical() {
    let Some(x) = start_display() else { return };
    let home = scratch("escape");
    let config = home.join("mountains.toml");
    std::fs::write(&config, COMMENTED).unwrap();
    let mut app = App::start(&x, &config, &home, 1);
    let window = app.window(&x);
    wait_drawn(x.display(), window);
    press(&x, window, &["Down", "Down", "Right", "Right", "Escape"]);
    let status = app.wait_exit();
    assert!(status.success(), "{status}: {}", app.stderr());
    assert_eq!(std::fs::read(&config).unwrap(), COMMENTED.as_bytes());
}

#[test]
fn display_mouse_clicks_plus_then_ok() {
    use mountains::settings_ui::layout::{Button, Layout};
    let Some(x) = start_display() else { return };
    let home = scratch("mouse");
    let config = home.join("mountains.toml");
    std::fs::write(&config, COMMENTED).unwrap();
    let mut app = App::start(&x, &config, &home, 1);
    let window = app.window(&x);
    wait_drawn(x.display(), window);
    let l = Layout::new(Size::new(960, 620), 1);
    let crag = mountains::settings::keys::KEYS
        .iter()
        .position(|k| k.name == "cragginess")
        .unwrap();
    let (_, (p0, p1)) = l.minus_plus();
    let plus = ((p0 + p1) / 2, l.row(crag).y0 + 9);
    let ok = l.button(Button::Ok);
    let ok = ((ok.x0 + ok.x1) / 2, (ok.y0 + ok.y1) / 2);
    let id = window.to_string();
    for (px, py) in [plus, plus, ok] {
        let (px, py) = (px.to_string(), py.to_string());
        xdotool(&x, &["mousemove", "--window", &id, &px, &py]);
        xdotool(&x, &["click", "1"]);
    }
    let status = app.wait_exit();
    assert!(status.success(), "{status}: {}", app.stderr());
    let saved = std::fs::read_to_string(&config).unwrap();
    assert_eq!(saved, COMMENTED.replace("= 40 ", "= 42 "));
}

/// Opens the window at `scale`, checks its size, and writes a screenshot
/// (`target/tmp/settings-ui-<scale>x.png`) for a person to look at.
fn screenshot(scale: u32) {
    let Some(x) = start_display() else { return };
    let home = scratch(&format!("shot{scale}"));
    let config = home.join("mountains.toml");
    std::fs::write(&config, COMMENTED).unwrap();
    let mut app = App::start(&x, &config, &home, scale);
    let window = app.window(&x);
    wait_drawn(x.display(), window);
    press(&x, window, &["Down", "Down", "Right"]);
    // Exactly two rows down: the Cragginess label is highlighted in navy.
    let l = mountains::settings_ui::layout::Layout::new(Size::new(960 * scale, 620 * scale), scale);
    let probe = |row: usize, w: u32| {
        let r = l.row(row);
        ((r.y0 + l.px(2)) * w + r.x0 + l.px(20)) as usize
    };
    let mut shot = wait_drawn(x.display(), window);
    for _ in 0..MAX_POLLS {
        if shot.2.get(probe(2, shot.0)) == Some(&0x000080) {
            break;
        }
        sleep(POLL);
        shot = wait_drawn(x.display(), window);
    }
    let (w, h, px) = shot;
    assert_eq!(
        (w, h),
        (960 * scale, 620 * scale),
        "the window follows the scale"
    );
    assert_eq!(
        px[probe(2, w)],
        0x000080,
        "the Cragginess row has the focus"
    );
    assert_ne!(px[probe(1, w)], 0x000080);
    assert_ne!(px[probe(3, w)], 0x000080, "each key press counts once");
    let mut frame = mountains::render::Frame::new(w, h).unwrap();
    frame.pixels_mut().copy_from_slice(&px);
    let out = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("settings-ui-{scale}x.png"));
    mountains::snapshot::write_png(&out, &frame).unwrap();
    eprintln!("screenshot: {}", out.display());
    press(&x, window, &["Escape"]);
    assert!(app.wait_exit().success(), "{}", app.stderr());
    assert_eq!(std::fs::read(&config).unwrap(), COMMENTED.as_bytes());
}

#[test]
fn display_screenshot_at_100_percent() {
    screenshot(1);
}

#[test]
fn display_screenshot_at_200_percent() {
    screenshot(2);
}

/// Grabs the window until `ready` holds for its pixels (width, height,
/// 0x00RRGGBB), within the bounded wait.
fn wait_until(
    display: &str,
    window: u32,
    what: &str,
    ready: impl Fn(u32, u32, &[u32]) -> bool,
) -> (u32, u32, Vec<u32>) {
    let (conn, _) = x11rb::connect(Some(display)).expect("connect to Xvfb");
    for _ in 0..MAX_POLLS {
        if let Some((w, h, px)) = grab(&conn, window)
            && ready(w, h, &px)
        {
            return (w, h, px);
        }
        sleep(POLL);
    }
    panic!("never shown: {what}");
}

/// Whether the last row is drawn focused (white on navy) where a layout of
/// `w` x `h` scrolled to show it puts it, its help's first line is inked,
/// and so is the file line.
fn last_row_and_help_drawn(w: u32, h: u32, px: &[u32]) -> bool {
    use mountains::settings_ui::layout::Layout;
    let mut l = Layout::new(Size::new(w, h), 1);
    let last = mountains::settings::keys::KEYS.len() - 1;
    l.reveal_row(last);
    let r = l.row(last);
    let at = |x: u32, y: u32| px.get((y * w + x) as usize).copied();
    let inked = |y0: u32| {
        (y0..y0 + 8)
            .any(|y| (l.panel_x..l.panel_x + 300).any(|x| matches!(at(x, y), Some(0x404040 | 0))))
    };
    at(r.x0 + 2, r.y0 + 2) == Some(0x000080) && inked(l.help_y) && inked(l.file_y + 2)
}

fn save_shot(w: u32, h: u32, px: &[u32], name: &str) {
    let mut frame = mountains::render::Frame::new(w, h).unwrap();
    frame.pixels_mut().copy_from_slice(px);
    let out = Path::new(env!("CARGO_TARGET_TMPDIR")).join(name);
    mountains::snapshot::write_png(&out, &frame).unwrap();
    eprintln!("screenshot: {}", out.display());
}

/// Issue 36: the window opens at 960x620 and may be made no smaller than
/// the layout's minimum (its size hints say so); at both sizes the last
/// row, reached with the keys, is drawn whole with its help and the file
/// line below it, and the wheel scrolls the list. Writes
/// `target/tmp/settings-ui-960x620-last.png` and `...-640x310-last.png`.
#[test]
fn display_the_last_row_and_its_help_show_at_the_default_and_the_smallest_size() {
    use mountains::settings_ui::layout::{Layout, MIN_H, MIN_W};
    use x11rb::protocol::xproto::AtomEnum;
    let Some(x) = start_display() else { return };
    let home = scratch("fit");
    let config = home.join("mountains.toml");
    std::fs::write(&config, COMMENTED).unwrap();
    let mut app = App::start(&x, &config, &home, 1);
    let window = app.window(&x);
    wait_drawn(x.display(), window);
    let hints = x
        .conn
        .get_property(
            false,
            window,
            AtomEnum::WM_NORMAL_HINTS,
            AtomEnum::WM_SIZE_HINTS,
            0,
            18,
        )
        .unwrap()
        .reply()
        .unwrap();
    let hints: Vec<u32> = hints.value32().expect("32-bit size hints").collect();
    assert!(hints[0] & 16 != 0, "a minimum size is set: {hints:?}");
    assert_eq!((hints[5], hints[6]), (MIN_W, MIN_H), "the minimum size");

    // Up from the first row: Cancel, the other six buttons, the last row.
    press(&x, window, &["Up"; 8]);
    let (w, h, px) = wait_until(
        x.display(),
        window,
        "the last row at 960x620",
        |w, h, px| (w, h) == (960, 620) && last_row_and_help_drawn(w, h, px),
    );
    save_shot(w, h, &px, "settings-ui-960x620-last.png");

    xdotool(
        &x,
        &[
            "windowsize",
            &window.to_string(),
            &MIN_W.to_string(),
            &MIN_H.to_string(),
        ],
    );
    let (w, h, px) = wait_until(x.display(), window, "the last row, smallest", |w, h, px| {
        (w, h) == (MIN_W, MIN_H) && last_row_and_help_drawn(w, h, px)
    });
    save_shot(w, h, &px, &format!("settings-ui-{MIN_W}x{MIN_H}-last.png"));

    // The wheel over a label scrolls the list: the focused row goes out of
    // sight below and comes back.
    let mut l = Layout::new(Size::new(MIN_W, MIN_H), 1);
    l.reveal_row(mountains::settings::keys::KEYS.len() - 1);
    let area = l.list.area();
    let (lx, ly) = (
        (l.panel_x + 40).to_string(),
        ((area.y0 + area.y1) / 2).to_string(),
    );
    let id = window.to_string();
    xdotool(&x, &["mousemove", "--window", &id, &lx, &ly]);
    xdotool(&x, &["click", "4"]);
    wait_until(x.display(), window, "the list scrolled up", |w, h, px| {
        (w, h) == (MIN_W, MIN_H) && !last_row_and_help_drawn(w, h, px)
    });
    xdotool(&x, &["click", "5"]);
    wait_until(x.display(), window, "the list scrolled back", |w, h, px| {
        (w, h) == (MIN_W, MIN_H) && last_row_and_help_drawn(w, h, px)
    });
    press(&x, window, &["Escape"]);
    assert!(app.wait_exit().success(), "{}", app.stderr());
    assert_eq!(std::fs::read(&config).unwrap(), COMMENTED.as_bytes());
}

/// The settings open on an X server with no other client. The check for
/// a drawable screen (`platform::refusal`) was its only client, and closed
/// before winit opened its own connection: on this server the window
/// never opened, and on a resetting Xvfb about one time in seven ("Failed
/// to open connection to X server"). Now the check comes after winit has
/// connected.
#[test]
fn display_the_settings_open_on_a_server_with_no_other_client() {
    if !has_xdotool() {
        return;
    }
    let Some(server) = xvfb::LoneServer::start(1280, 800) else {
        return;
    };
    let home = scratch("lone-server");
    let config = home.join("mountains.toml");
    std::fs::write(&config, COMMENTED).unwrap();
    let mut app = App::start_on(&server.display, &config, &home, 1);
    // xdotool's connections, coming and going, would end the server if
    // they came before the settings held one of their own.
    app.wait_connected();
    let window = app.window_on(&server.display);
    press_on(&server.display, window, &["Escape"]);
    let status = app.wait_exit();
    assert!(status.success(), "{status}: {}", app.stderr());
    assert_eq!(std::fs::read(&config).unwrap(), COMMENTED.as_bytes());
}
