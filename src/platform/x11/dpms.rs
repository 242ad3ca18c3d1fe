//! Whether the X server has powered the monitor down (the DPMS extension):
//! asked over a connection of our own each time the watcher looks
//! (`saver::watch`). A server without DPMS (Xvfb, Xwayland) cannot say,
//! and the display counts as on.

use x11rb::connection::{Connection, RequestConnection};
use x11rb::protocol::dpms::{self, ConnectionExt as _, DPMSMode};
use x11rb::rust_connection::RustConnection;

/// A probe of the display's power (true: on; `None` when it cannot
/// tell), or `None` when the server has no DPMS.
pub fn probe() -> Option<impl FnMut() -> Option<bool> + Send + 'static> {
    let (conn, _) = RustConnection::connect(None).ok()?;
    conn.extension_information(dpms::X11_EXTENSION_NAME)
        .ok()
        .flatten()?;
    Some(move || is_on(&conn))
}

/// True unless DPMS is enabled and the monitor is in standby, suspend or
/// off; `None` if the server did not answer.
fn is_on(conn: &RustConnection) -> Option<bool> {
    let info = conn.dpms_info().ok()?.reply().ok()?;
    // Events, if any came, are of no use here: drop them.
    while let Ok(Some(_)) = conn.poll_for_event() {}
    Some(!info.state || info.power_level == DPMSMode::ON)
}
