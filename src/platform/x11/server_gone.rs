//! The X server going away under the windows winit opened: Xlib's own
//! handler prints a bare "X connection to :0 broken" and exits, with
//! nothing in the log a screensaver's user could find later. This one says
//! it in the program's words, on stderr and in mountains.log, then exits 1
//! as Xlib's does (Xlib allows no return from it).

use std::ffi::c_int;
use std::sync::OnceLock;

use x11_dl::xlib::{Display, Xlib};

use crate::saver::error::SaverError;

/// Xlib as loaded here, kept loaded so that the handler stays installed in
/// the one copy of the library winit and softbuffer use too.
static XLIB: OnceLock<Option<Xlib>> = OnceLock::new();

/// Installs the handler, if Xlib can be loaded (a Wayland-only system may
/// have none: then nothing uses it either).
pub fn report_when_the_server_goes() {
    let xlib = XLIB.get_or_init(|| Xlib::open().ok());
    if let Some(xlib) = xlib {
        // SAFETY: the handler is a plain function that never returns into
        // Xlib (it exits), as XSetIOErrorHandler asks.
        unsafe { (xlib.XSetIOErrorHandler)(Some(server_gone)) };
    }
}

/// Xlib's call when the connection breaks.
unsafe extern "C" fn server_gone(_display: *mut Display) -> c_int {
    crate::log::error(&SaverError::server_gone().to_string());
    std::process::exit(1)
}
