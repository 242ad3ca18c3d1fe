//! The X11 room: the saver's talk with an X server (foreign windows, the
//! monitors and their changes, the input grab and its pointer, frames put
//! as plain images, the visual to draw with, the server going away), and
//! `host`, the winit saver's side on the desktop Unixes.

pub mod bands;
pub mod connect;
pub mod dpms;
pub mod embed;
pub mod grab;
pub mod heads;
pub mod host;
pub(super) mod motion;
mod placed;
mod pointer;
pub mod server_gone;
pub mod visual;

use raw_window_handle::{HasWindowHandle, RawWindowHandle};

/// The X11 window id behind a window handle, if it is an X11 window.
pub fn window_id(window: &impl HasWindowHandle) -> Option<u32> {
    match window.window_handle().ok()?.as_raw() {
        RawWindowHandle::Xlib(h) => u32::try_from(h.window).ok(),
        RawWindowHandle::Xcb(h) => Some(h.window.get()),
        _ => None,
    }
}
