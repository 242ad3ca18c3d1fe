//! The window layer: the only module that knows about winit, softbuffer and X11.
//!
//! `run` takes a window mode and paces a slide show of mountains on it:
//! full screen on every monitor (`app`), a small preview or a normal window
//! (`app`), or a window another program owns (`x11::embed`, `win32::embed`).
//!
//! Each platform's own files have a room: `x11/`, `win32/` and `wayland/`;
//! the platform-neutral show and its window logic stay here.
//!
//! The pure parts, unit-tested without a display: `slideshow` (pacing),
//! `show` (one window's frame, painter and next mountain), `source` (where
//! each slide comes from), `input` (keys and what wakes the saver),
//! `actions` (settings steps, file names), `heads` (which monitors get a
//! window). The rest talks to the system: `x11::heads` asks the X server for
//! its monitors and follows their changes, `win32::fullscreen` refits
//! full-screen windows after a Windows display change, `present` and
//! `x11::bands` put frames on screen, `x11::grab` keeps input from other
//! programs (crate::signals turns SIGTERM into a clean exit), `libcheck` names a
//! missing X or Wayland library before winit panics on it, `backend` picks
//! X11 or Wayland, `buffer_history` tells `present` what each buffer lacks,
//! `single` keeps a second `/s` off a display that has one. `wayland::layer`
//! runs the shows on wlr-layer-shell surfaces (`--layer`), presenting
//! through `wayland::target`'s raw handles, each buffer covering its output
//! as `wayland::cover` reckons.

pub mod actions;
pub mod app;
#[cfg(unix)]
pub mod backend;
mod buffer_history;
mod error;
pub mod heads;
pub mod input;
pub mod libcheck;
mod on_screen;
mod options;
mod overlay;
mod placement;
pub mod present;
mod redraw;
mod screen;
pub mod show;
#[cfg(target_os = "linux")]
pub mod single;
pub mod slideshow;
pub mod source;
mod trace;
pub mod watch;
#[cfg(target_os = "linux")]
pub mod wayland;
pub mod win32;
#[cfg(unix)]
pub mod x11;

use crate::cli::{Mode, XssOptions};
use crate::mountain::Mountain;
use crate::settings::Settings;

pub use error::{SaverError, without_source_place};
pub use trace::{Trace, mark_start};

/// Runs a window mode until it ends. `opened` is a data set to show instead
/// of generating; `xss` are xscreensaver's common options (`-fps`, `-delay`).
pub fn run(
    mode: &Mode,
    settings: Settings,
    opened: Option<Mountain>,
    xss: &XssOptions,
) -> Result<(), SaverError> {
    mark_start();
    options::set_options(xss);
    match mode {
        Mode::Fullscreen => app::run(app::AppMode::Fullscreen, settings, opened),
        Mode::Preview { parent: None } => app::run(app::AppMode::Preview, settings, opened),
        Mode::Window => app::run(app::AppMode::Window, settings, opened),
        Mode::Preview {
            parent: Some(handle),
        } => run_in_parent(*handle, settings, opened),
        Mode::XRoot => run_embedded(None, settings, opened),
        Mode::XWindowId(id) => run_embedded(Some(*id), settings, opened),
        Mode::Layer(layer) => run_layer(*layer, settings, opened),
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
    x11::embed::run(window, settings, opened)
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

/// `--layer`: wlr-layer-shell surfaces, on Linux (where the Wayland
/// libraries are loaded at run time).
#[cfg(target_os = "linux")]
fn run_layer(
    layer: crate::cli::Layer,
    settings: Settings,
    opened: Option<Mountain>,
) -> Result<(), SaverError> {
    wayland::layer::run(layer, settings, opened)
}

#[cfg(not(target_os = "linux"))]
fn run_layer(
    _layer: crate::cli::Layer,
    _settings: Settings,
    _opened: Option<Mountain>,
) -> Result<(), SaverError> {
    Err(SaverError::Unsupported(
        "--layer needs a Wayland compositor with wlr-layer-shell (Linux)".into(),
    ))
}

#[cfg(unix)]
fn check_library(library: &str, package: &str) -> Result<(), SaverError> {
    if libcheck::can_dlopen(library) {
        return Ok(());
    }
    Err(SaverError::MissingLibrary {
        system: "X",
        library: library.into(),
        package: package.into(),
    })
}
