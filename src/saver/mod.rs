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
mod buffer_history;
pub(crate) mod error;
pub mod heads;
pub mod input;
mod on_screen;
pub(crate) mod options;
mod overlay;
mod placement;
pub mod present;
mod redraw;
mod screen;
pub mod show;
pub mod slideshow;
pub mod source;
pub(crate) mod trace;

use crate::cli::{Mode, XssOptions};
use crate::mountain::Mountain;
use crate::platform;
use crate::platform::modes::run_embedded;
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
        Mode::Layer(layer) => platform::modes::run_layer(*layer, settings, opened),
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
    match platform::modes::PREVIEW_AS_CHILD {
        true => app::run(app::AppMode::Child(handle), settings, opened),
        false => run_embedded(Some(handle), settings, opened),
    }
}
