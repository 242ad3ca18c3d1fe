//! The monitors of an X display, asked of the server itself: RandR 1.5
//! monitors and Xinerama heads. winit 0.30 lists CRTCs only, which misses
//! user-defined monitors (`xrandr --setmonitor`), tiled displays and
//! Xinerama-only servers, and it never tells when they change.
//!
//! Changes are followed through RandR's screen, CRTC and output events (a
//! mode change, a monitor plugged in or out). The server sends none when a
//! monitor is only defined or deleted (`--setmonitor`, `--delmonitor`): that
//! shows at the next such event, or the next start.

use std::time::Duration;

use x11rb::connection::Connection;
use x11rb::protocol::Event;
use x11rb::protocol::randr::{ConnectionExt as _, NotifyMask};
use x11rb::protocol::xinerama::ConnectionExt as _;
use x11rb::rust_connection::RustConnection;

use crate::saver::heads::{Head, choose};

/// Several RandR events arrive for one change; the list is read once they
/// have stopped for this long.
const SETTLE: Duration = Duration::from_millis(50);

/// The heads of the display in `$DISPLAY`, cleaned; `None` when the server
/// cannot be reached or tells nothing (the caller then asks winit).
pub fn query() -> Option<Vec<Head>> {
    let (conn, screen) = RustConnection::connect(None).ok()?;
    let heads = query_on(&conn, screen);
    (!heads.is_empty()).then_some(heads)
}

fn query_on(conn: &RustConnection, screen: usize) -> Vec<Head> {
    let root = conn.setup().roots[screen].root;
    choose(&randr_monitors(conn, root), &xinerama_heads(conn))
}

/// RandR 1.5 monitors with an active output, and those defined without one.
fn randr_monitors(conn: &RustConnection, root: u32) -> Vec<Head> {
    let version = conn
        .randr_query_version(1, 5)
        .ok()
        .and_then(|c| c.reply().ok());
    if version.is_none_or(|v| (v.major_version, v.minor_version) < (1, 5)) {
        return Vec::new();
    }
    let Some(reply) = conn
        .randr_get_monitors(root, true)
        .ok()
        .and_then(|c| c.reply().ok())
    else {
        return Vec::new();
    };
    reply
        .monitors
        .iter()
        .map(|m| Head {
            x: m.x.into(),
            y: m.y.into(),
            width: m.width.into(),
            height: m.height.into(),
            primary: m.primary,
        })
        .collect()
}

/// Xinerama heads; the first is the primary one by convention.
fn xinerama_heads(conn: &RustConnection) -> Vec<Head> {
    let active = conn
        .xinerama_is_active()
        .ok()
        .and_then(|c| c.reply().ok())
        .is_some_and(|r| r.state != 0);
    let Some(reply) = active
        .then(|| conn.xinerama_query_screens().ok()?.reply().ok())
        .flatten()
    else {
        return Vec::new();
    };
    reply
        .screen_info
        .iter()
        .enumerate()
        .map(|(i, s)| Head {
            x: s.x_org.into(),
            y: s.y_org.into(),
            width: s.width.into(),
            height: s.height.into(),
            primary: i == 0,
        })
        .collect()
}

/// The heads now, read on the connection that then watches for RandR
/// changes from a thread of its own: after every change that alters them (a
/// resolution change, a monitor plugged in or out) `tell` gets the new list.
/// Listening starts before the first read, so no change falls between.
/// Without RandR on the server: an error, and nothing is watched.
pub fn watch(tell: impl Fn(Vec<Head>) + Send + 'static) -> Result<Vec<Head>, String> {
    let (conn, screen) = RustConnection::connect(None).map_err(|e| e.to_string())?;
    let root = conn.setup().roots[screen].root;
    let selected = conn
        .randr_query_version(1, 5)
        .map_err(|e| e.to_string())
        .and_then(|_| {
            let mask =
                NotifyMask::SCREEN_CHANGE | NotifyMask::CRTC_CHANGE | NotifyMask::OUTPUT_CHANGE;
            conn.randr_select_input(root, mask)
                .map_err(|e| e.to_string())
        });
    selected.and_then(|_| conn.flush().map_err(|e| e.to_string()))?;
    let heads = query_on(&conn, screen);
    let last = heads.clone();
    std::thread::Builder::new()
        .name("mountains-heads".into())
        .spawn(move || follow(&conn, screen, last, tell))
        .map_err(|e| e.to_string())?;
    Ok(heads)
}

fn follow(conn: &RustConnection, screen: usize, mut last: Vec<Head>, tell: impl Fn(Vec<Head>)) {
    while let Ok(event) = conn.wait_for_event() {
        if !is_randr(&event) {
            continue;
        }
        settle(conn);
        let heads = query_on(conn, screen);
        if heads != last {
            last = heads.clone();
            tell(heads);
        }
    }
}

fn is_randr(event: &Event) -> bool {
    matches!(
        event,
        Event::RandrScreenChangeNotify(_) | Event::RandrNotify(_)
    )
}

/// Waits until no event has come for `SETTLE`, dropping what came.
fn settle(conn: &RustConnection) {
    loop {
        std::thread::sleep(SETTLE);
        let mut quiet = true;
        while let Ok(Some(_)) = conn.poll_for_event() {
            quiet = false;
        }
        if quiet {
            return;
        }
    }
}
