//! Which display the saver's watcher asks (`saver::watch`): X11's DPMS
//! every second, a Wayland compositor's output power events, or Windows'
//! console display state; the power supply is looked at on every system.

use super::Backend;
use crate::saver::watch::{Probe, Seen, Watcher};

/// Starts watching the power and the display of `backend`.
pub fn start(backend: Backend, notify: impl Fn(Seen) + Send + 'static) -> Watcher {
    match backend {
        Backend::Wayland => wayland(notify),
        Backend::X11 => x11(notify),
        Backend::Windows => windows(notify),
    }
}

/// The compositor tells us when an output's power changes (where it
/// speaks wlr-output-power-management).
fn wayland(notify: impl Fn(Seen) + Send + 'static) -> Watcher {
    let watcher = Watcher::start(None, notify);
    #[cfg(layer_shell_platform)]
    {
        let told = watcher.clone();
        super::wayland::power::watch(move |on| told.set_display(on));
    }
    watcher
}

/// DPMS has no events: its state is asked for every second.
fn x11(notify: impl Fn(Seen) + Send + 'static) -> Watcher {
    #[cfg(x11_platform)]
    let probe = super::x11::dpms::probe().map(|p| Box::new(p) as Probe);
    #[cfg(not(x11_platform))]
    let probe: Option<Probe> = None;
    Watcher::start(probe, notify)
}

/// Windows calls us back when the console's display state changes.
fn windows(notify: impl Fn(Seen) + Send + 'static) -> Watcher {
    let watcher = Watcher::start(None, notify);
    #[cfg(windows_platform)]
    {
        let told = watcher.clone();
        super::win32::display::watch(move |on| told.set_display(on));
    }
    watcher
}
