//! The window layer: the slide shows on winit and softbuffer windows.
//! What one window system knows lives in `crate::platform`.
//!
//! `run` takes a window mode and paces a slide show of mountains on it:
//! full screen on every monitor (`app`), a small preview or a normal window
//! (`app`), or a window another program owns (`platform::modes`: a
//! foreign X window; a Windows preview's parent is `app`'s child mode).
//!
//! The pure parts, unit-tested without a display: `slideshow` (pacing),
//! `show` (one window's frame, painter and next mountain), `source` (where
//! each slide comes from), `input` (keys and what wakes the saver),
//! `actions` (settings steps, file names), `heads` (which monitors get a
//! window). The rest talks to the system through the platform's facade:
//! `app` runs winit with a `platform::Host` (the monitors, the pointer,
//! the input grab, the preview's parent), `placement` puts full-screen
//! windows on their monitors, `present` puts frames on screen (softbuffer,
//! else `platform::images`), `buffer_history` tells `present` what each
//! buffer lacks.

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
pub mod span;
pub(crate) mod trace;
pub mod watch;

use crate::cli::Mode;
use crate::mountain::Mountain;
use crate::platform;
use crate::platform::modes::run_embedded;
use crate::settings::Settings;

pub use error::{SaverError, without_source_place};
pub use options::set_options;
pub use trace::{Trace, mark_start};

/// Runs a window mode until it ends. `opened` is a data set to show instead
/// of generating; xscreensaver's common options (`-fps`, `-delay`) are the
/// run's, set once before ([`set_options`]).
pub fn run(mode: &Mode, settings: Settings, opened: Option<Mountain>) -> Result<(), SaverError> {
    mark_start();
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
