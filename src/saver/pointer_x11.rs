//! Where the X pointer is, asked of the server once: the origin a full
//! screen's pointer moves are measured from, taken before its windows map,
//! so a move that comes before the first motion event is still a move.

use x11rb::connection::Connection;
use x11rb::protocol::xproto::ConnectionExt as _;
use x11rb::rust_connection::RustConnection;

/// The pointer's place on `$DISPLAY`'s screen, in root coordinates.
pub fn pointer_position() -> Option<(f64, f64)> {
    let (conn, screen) = RustConnection::connect(None).ok()?;
    let root = conn.setup().roots.get(screen)?.root;
    let reply = conn.query_pointer(root).ok()?.reply().ok()?;
    Some((reply.root_x.into(), reply.root_y.into()))
}
