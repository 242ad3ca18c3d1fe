//! The platform rooms: everything that knows X11, Wayland or Win32, and
//! the OS specifics under them, behind a small facade the saver and the
//! settings screen share (as winit's own tree has one API over
//! `platform_impl/{linux/{x11,wayland},windows}`).
//!
//! The facade: `window` (which backend, for both; window attributes; why
//! an event loop could not start), `Host` (what one saver run asks of the
//! window system: its monitors, the pointer, the grab, the Windows
//! preview's parent, with `events` the words they are told in), `images`
//! (frames as plain X images where softbuffer cannot draw), `modes` (the
//! window modes of one platform: a foreign X window, layer-shell), and
//! `os` (signals, files, memory, the clock, the console).
//!
//! The rooms: `x11/`, `wayland/` and `win32/`; `backend` picks X11 or
//! Wayland, `libcheck` names a missing X or Wayland library before winit
//! panics on it, `single` keeps a second `/s` off a display that has one.
//!
//! `cfg(x11_platform)`, `cfg(wayland_platform)`, `cfg(layer_shell_platform)`
//! and `cfg(windows_platform)` (build.rs) say which window system code is
//! for; `unix`, `windows` and `target_os` are left for the OS itself.
//! Outside these rooms the crate has almost no platform `cfg`
//! (tests/cli/architecture.rs counts them).

pub mod backend;
pub mod events;
pub mod images;
pub mod libcheck;
pub mod modal;
pub mod modes;
pub mod os;
pub mod power;
pub mod signals;
#[cfg(target_os = "linux")]
pub mod single;
mod watch;
#[cfg(layer_shell_platform)]
pub mod wayland;
pub mod win32;
pub mod window;
#[cfg(x11_platform)]
pub mod x11;

pub use backend::Backend;
pub use modal::{ModalOwner, window_exists};
pub use watch::start as watch_power_and_display;
#[cfg(windows_platform)]
pub use win32::host::Host;
pub use window::{
    FULLSCREEN_TAPS_ALT, choose_backend, event_loop_failed, keep_covering, on_head, refusal,
    report_when_the_server_goes, settings_attributes, use_backend,
};
#[cfg(x11_platform)]
pub use x11::host::Host;

/// The hold on the display a full-screen saver keeps while it runs, so a
/// second one started by an idle daemon ends at once (Linux).
#[cfg(target_os = "linux")]
pub use single::Claim;

/// No such hold where there is no claim to make.
#[cfg(not(target_os = "linux"))]
#[derive(Debug)]
pub struct Claim;

/// Claims the display `backend` runs on for one full-screen saver:
/// `Ok(None)` when another holds it. An error says what could not be
/// done (the caller runs on without the claim).
pub fn claim_display(backend: Backend) -> Result<Option<Claim>, String> {
    #[cfg(target_os = "linux")]
    return single::claim(backend);
    #[cfg(not(target_os = "linux"))]
    {
        let _ = backend;
        Ok(Some(Claim))
    }
}
