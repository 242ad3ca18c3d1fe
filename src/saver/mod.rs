//! The window layer: the only module that knows about winit, softbuffer and X11.
//!
//! `run` takes a window mode and paces a slide show of mountains on it:
//! full screen on every monitor (`app`), a small preview or a normal window
//! (`app`), or a window another program owns (`embed_x11`, `embed_win32`).
//!
//! The pure parts, unit-tested without a display: `slideshow` (pacing),
//! `show` (one window's frame, painter and next mountain), `source` (where
//! each slide comes from), `input` (keys and what wakes the saver),
//! `actions` (settings steps, file names), `heads` (which monitors get a
//! window). The rest talks to the system: `heads_x11` asks the X server for
//! its monitors and follows their changes, `fullscreen_win32` refits
//! full-screen windows after a Windows display change, `present` and
//! `bands_x11` put frames on screen, `grab_x11` keeps input from other
//! programs (crate::signals turns SIGTERM into a clean exit), `libcheck` names a
//! missing X library before winit panics on it.

pub mod actions;
pub mod app;
#[cfg(unix)]
pub mod bands_x11;
#[cfg(windows)]
pub mod embed_win32;
#[cfg(unix)]
pub mod embed_x11;
pub mod fullscreen_win32;
#[cfg(unix)]
pub mod grab_x11;
pub mod heads;
#[cfg(unix)]
pub mod heads_x11;
pub mod input;
pub mod libcheck;
mod overlay;
pub mod present;
mod redraw;
pub mod show;
pub mod slideshow;
pub mod source;

use std::fmt;
use std::sync::Arc;
use std::time::Instant;

use crate::cli::{Mode, XssOptions};
use crate::settings::Settings;
use crate::terrain::heightmap::DataSet;
use show::Mountain;

/// Why a window mode could not run, worded for a person.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum SaverError {
    /// `$DISPLAY` is unset or names no reachable X server.
    NoDisplay(String),
    /// A shared library winit needs is missing.
    MissingLibrary {
        /// The file name, e.g. `libxkbcommon-x11.so.0`.
        library: String,
        /// The Debian/Ubuntu package that provides it.
        package: String,
    },
    /// The window to draw into does not exist.
    NoSuchWindow(u32),
    /// The mode is not a window mode, or not available on this platform.
    Unsupported(String),
    /// Anything else, already worded.
    Other(String),
}

impl fmt::Display for SaverError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SaverError::NoDisplay(why) => write!(f, "no X display: {why}"),
            SaverError::MissingLibrary { library, package } => {
                f.write_str(&libcheck::missing_message(library, package))
            }
            // Both spellings: the id may have been typed in either.
            SaverError::NoSuchWindow(id) => write!(f, "there is no X window 0x{id:x} ({id})"),
            SaverError::Unsupported(what) => f.write_str(what),
            SaverError::Other(what) => f.write_str(what),
        }
    }
}

impl std::error::Error for SaverError {}

impl SaverError {
    /// The display could not be opened; says whether `DISPLAY` is unset or
    /// which display failed, keeping only the last part of `detail`.
    pub fn no_display(detail: &str) -> Self {
        let reason = detail.rsplit(": ").next().unwrap_or(detail);
        match std::env::var("DISPLAY") {
            Ok(d) if !d.is_empty() => SaverError::NoDisplay(format!("cannot open {d}: {reason}")),
            _ => SaverError::NoDisplay("set DISPLAY (it is not set)".into()),
        }
    }

    #[cfg(unix)]
    fn from_connect(e: x11rb::errors::ConnectError) -> Self {
        Self::no_display(&e.to_string())
    }
}

/// Runs a window mode until it ends. `open` is a data set to show instead
/// of generating; `xss` are xscreensaver's common options (`-fps`, `-delay`).
pub fn run(
    mode: &Mode,
    settings: Settings,
    open: Option<DataSet>,
    xss: &XssOptions,
) -> Result<(), SaverError> {
    START.get_or_init(Instant::now);
    let _ = XSS.set(xss.clone());
    let opened = open.map(|d| Mountain {
        field: Arc::new(d.field),
        seed: d.seed,
        generated: false,
    });
    match mode {
        Mode::Fullscreen => app::run(app::AppMode::Fullscreen, settings, opened),
        Mode::Preview { parent: None } => app::run(app::AppMode::Preview, settings, opened),
        Mode::Window => app::run(app::AppMode::Window, settings, opened),
        Mode::Preview {
            parent: Some(handle),
        } => run_in_parent(*handle, settings, opened),
        Mode::XRoot => run_embedded(None, settings, opened),
        Mode::XWindowId(id) => run_embedded(Some(*id), settings, opened),
        other => Err(SaverError::Unsupported(format!(
            "{other:?} is not a window mode"
        ))),
    }
}

/// `/p HWND`: a child of the Windows preview; on X11 the number is an XID.
fn run_in_parent(
    handle: u64,
    settings: Settings,
    opened: Option<Mountain>,
) -> Result<(), SaverError> {
    #[cfg(windows)]
    {
        app::run(app::AppMode::Child(handle), settings, opened)
    }
    #[cfg(not(windows))]
    {
        run_embedded(Some(handle), settings, opened)
    }
}

#[cfg(unix)]
fn run_embedded(
    window: Option<u64>,
    settings: Settings,
    opened: Option<Mountain>,
) -> Result<(), SaverError> {
    check_library("libxcb.so.1", "libxcb1")?;
    let window = match window {
        Some(id) => Some(u32::try_from(id).map_err(|_| {
            SaverError::Unsupported(format!("{id} is not an X window id (too large)"))
        })?),
        None => None,
    };
    embed_x11::run(window, settings, opened)
}

#[cfg(not(unix))]
fn run_embedded(
    _window: Option<u64>,
    _settings: Settings,
    _opened: Option<Mountain>,
) -> Result<(), SaverError> {
    Err(SaverError::Unsupported(
        "--root and --window-id need X11; on Windows use /s or /p".into(),
    ))
}

#[cfg(unix)]
fn check_library(library: &str, package: &str) -> Result<(), SaverError> {
    if libcheck::can_dlopen(library) {
        return Ok(());
    }
    Err(SaverError::MissingLibrary {
        library: library.into(),
        package: package.into(),
    })
}

/// The zero of the start-up trace: `main`'s first line (see `mark_start`),
/// else when `run` was entered.
static START: std::sync::OnceLock<Instant> = std::sync::OnceLock::new();

/// xscreensaver's common options of this run, set once by `run`.
static XSS: std::sync::OnceLock<XssOptions> = std::sync::OnceLock::new();

/// A new window's show: its pacing with `-delay`, and `-fps` if asked for.
pub(crate) fn new_show(
    settings: Settings,
    opened: Option<Mountain>,
    pacing: slideshow::Pacing,
    size: (u32, u32),
    now: Instant,
) -> show::Show {
    let xss = XSS.get().cloned().unwrap_or_default();
    let pacing = match xss.delay_us {
        Some(us) => pacing.with_frame_interval(std::time::Duration::from_micros(us)),
        None => pacing,
    };
    let mut show = show::Show::new(settings, opened, pacing, size, now);
    if xss.fps {
        show.show_fps();
    }
    show
}

/// Starts the start-up trace's clock; `main` calls it first, so the traced
/// time to the first present includes reading the settings and the data set.
pub fn mark_start() {
    START.get_or_init(Instant::now);
}

/// With `MOUNTAINS_TRACE=1`, reports on stderr how long the first present
/// took and what ended the saver (to tell a real wake from a spurious one).
#[derive(Debug, Clone, Copy)]
pub struct Trace {
    on: bool,
    start: Option<Instant>,
}

impl Trace {
    /// Starts the clock if `MOUNTAINS_TRACE=1`.
    pub fn from_env() -> Self {
        let on = std::env::var("MOUNTAINS_TRACE").is_ok_and(|v| v == "1");
        Trace {
            on,
            start: on.then(|| *START.get_or_init(Instant::now)),
        }
    }

    /// Reports what ended the saver.
    pub fn ended_by(&self, why: &dyn fmt::Debug) {
        if self.on {
            eprintln!("mountains: trace: ended by {why:?}");
        }
    }

    /// Call after each present; the first one prints the time since start.
    pub fn presented(&mut self) {
        if let Some(start) = self.start.take() {
            let ms = start.elapsed().as_secs_f64() * 1000.0;
            eprintln!("mountains: trace: first frame presented after {ms:.1} ms");
        }
    }
}
