//! xscreensaver's common options of this run (`-delay`, `-fps`), set
//! once by `run`, and the show of each new window they shape.

use std::time::Instant;

use super::show::Show;
use super::slideshow;
use crate::cli::XssOptions;
use crate::mountain::Mountain;
use crate::render::Size;
use crate::settings::Settings;

/// Remembers this run's xscreensaver options for every window's show,
/// and for what is said of the X display (the settings screen's too).
pub fn set_options(xss: &XssOptions) {
    let _ = XSS.set(xss.clone());
}

/// True when `-display` named an X display for this run.
pub(crate) fn x_display_named() -> bool {
    x_display().is_some()
}

/// The X display `-display` named for this run, if it named one.
pub(crate) fn x_display() -> Option<&'static str> {
    XSS.get()?.display.as_deref()
}

/// xscreensaver's common options of this run, set once by `run`.
static XSS: std::sync::OnceLock<XssOptions> = std::sync::OnceLock::new();

/// A new window's show: its pacing with `-delay`, and `-fps` if asked for.
pub(crate) fn new_show(
    settings: Settings,
    opened: Option<Mountain>,
    pacing: slideshow::Pacing,
    size: Size,
    now: Instant,
) -> Show {
    let xss = XSS.get().cloned().unwrap_or_default();
    let pacing = match xss.delay_us {
        Some(us) => pacing.with_frame_interval(std::time::Duration::from_micros(us)),
        None => pacing,
    };
    let mut show = Show::new(settings, opened, pacing, size, now);
    if xss.fps {
        show.show_fps();
    }
    show
}
