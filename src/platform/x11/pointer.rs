//! What the saver asks the X server once, before its windows map, on one
//! short-lived connection: the visual to draw with (chosen by visual.rs),
//! whether there is one at all, and, for full screen, where the pointer
//! is: the origin its moves are measured from, taken before the windows
//! map, so a move that comes before the first motion event is still a
//! move.

use x11rb::connection::Connection;
use x11rb::protocol::xproto::ConnectionExt as _;
use x11rb::rust_connection::RustConnection;

/// What the server said before the windows opened.
#[derive(Debug, Default, Clone)]
pub struct FirstLook {
    /// The visual to make windows with, when not the screen's own.
    pub visual: Option<u32>,
    /// The pointer's place on the screen (root coordinates), if asked for.
    pub pointer: Option<(f64, f64)>,
    /// Why nothing can be drawn on the screen (8-bit visuals only).
    pub refusal: Option<String>,
}

/// Asks `$DISPLAY` for the visual and, if `pointer`, the pointer's place;
/// nothing of either when the server cannot be reached.
pub fn first_look(pointer: bool) -> FirstLook {
    let Ok((conn, screen)) = RustConnection::connect(None) else {
        return FirstLook::default();
    };
    FirstLook {
        visual: crate::platform::x11::visual::drawable_visual_on(&conn, screen),
        pointer: pointer.then(|| pointer_position(&conn, screen)).flatten(),
        refusal: crate::platform::x11::visual::screen_refusal(conn.setup(), screen),
    }
}

/// The pointer's place on `screen`, in root coordinates.
fn pointer_position(conn: &RustConnection, screen: usize) -> Option<(f64, f64)> {
    let root = conn.setup().roots.get(screen)?.root;
    let reply = conn.query_pointer(root).ok()?.reply().ok()?;
    Some((reply.root_x.into(), reply.root_y.into()))
}
