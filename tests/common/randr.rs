//! Test helpers that change an Xvfb's monitors the way `xrandr` would:
//! user-defined monitors (`--setmonitor`) and a new resolution (`--mode`).
#![allow(dead_code)]

use x11rb::protocol::randr::{ConnectionExt as _, ModeFlag, ModeInfo, MonitorInfo, Rotation};
use x11rb::protocol::xproto::{ConnectionExt as _, Window};
use x11rb::rust_connection::RustConnection;
use x11rb::wrapper::ConnectionExt as _;

/// The first output and CRTC of the screen (Xvfb has one of each).
fn output_and_crtc(conn: &RustConnection, root: Window) -> (u32, u32, u32) {
    conn.randr_query_version(1, 5).unwrap().reply().unwrap();
    let res = conn
        .randr_get_screen_resources_current(root)
        .unwrap()
        .reply()
        .unwrap();
    (res.outputs[0], res.crtcs[0], res.config_timestamp)
}

/// The name (an atom) of the `i`th monitor `set_monitors` defines.
fn monitor_name(conn: &RustConnection, i: usize) -> u32 {
    let name = format!("test-monitor-{i}");
    let atom = conn.intern_atom(false, name.as_bytes()).unwrap();
    atom.reply().unwrap().atom
}

/// Splits the screen into monitors at `rects` (x, y, w, h), like
/// `xrandr --setmonitor`: the first takes over the output's own monitor,
/// the others have no output. The `primary`th, if any, is marked primary.
pub fn set_monitors(
    conn: &RustConnection,
    root: Window,
    rects: &[(i16, i16, u16, u16)],
    primary: Option<usize>,
) {
    let (output, _, _) = output_and_crtc(conn, root);
    for (i, &(x, y, width, height)) in rects.iter().enumerate() {
        let atom = monitor_name(conn, i);
        let info = MonitorInfo {
            name: atom,
            primary: primary == Some(i),
            automatic: false,
            x,
            y,
            width,
            height,
            width_in_millimeters: u32::from(width) / 4,
            height_in_millimeters: u32::from(height) / 4,
            outputs: if i == 0 { vec![output] } else { vec![] },
        };
        conn.randr_set_monitor(root, info).unwrap();
    }
    conn.sync().unwrap();
}

/// Switches the output to a `width` x `height` mode and the screen to that
/// size, like `xrandr --output screen --mode WxH`. Growing cannot go past
/// the size the server started with.
pub fn set_resolution(conn: &RustConnection, root: Window, width: u16, height: u16) {
    let (output, crtc, config_timestamp) = output_and_crtc(conn, root);
    let mode = find_or_add_mode(conn, root, output, width, height);
    let (now_w, now_h) = screen_size(conn, root);
    let growing = width > now_w || height > now_h;
    let set_size = || {
        let mm = |px: u16| u32::from(px) / 4;
        conn.randr_set_screen_size(root, width, height, mm(width), mm(height))
            .unwrap();
        conn.sync().unwrap();
    };
    if growing {
        set_size();
    }
    let reply = conn
        .randr_set_crtc_config(
            crtc,
            x11rb::CURRENT_TIME,
            config_timestamp,
            0,
            0,
            mode,
            Rotation::ROTATE0,
            &[output],
        )
        .unwrap()
        .reply()
        .unwrap();
    assert_eq!(
        u8::from(reply.status),
        0,
        "SetCrtcConfig refused ({:?})",
        reply.status
    );
    if !growing {
        set_size();
    }
}

/// Turns the output off, like `xrandr --output screen --off`: the screen
/// keeps its size, with no monitor showing it. `set_resolution` turns it
/// on again.
pub fn switch_off(conn: &RustConnection, root: Window) {
    let (_, crtc, config_timestamp) = output_and_crtc(conn, root);
    let reply = conn
        .randr_set_crtc_config(
            crtc,
            x11rb::CURRENT_TIME,
            config_timestamp,
            0,
            0,
            x11rb::NONE,
            Rotation::ROTATE0,
            &[],
        )
        .unwrap()
        .reply()
        .unwrap();
    assert_eq!(
        u8::from(reply.status),
        0,
        "SetCrtcConfig refused ({:?})",
        reply.status
    );
}

fn screen_size(conn: &RustConnection, root: Window) -> (u16, u16) {
    let g = conn.get_geometry(root).unwrap().reply().unwrap();
    (g.width, g.height)
}

fn find_or_add_mode(
    conn: &RustConnection,
    root: Window,
    output: u32,
    width: u16,
    height: u16,
) -> u32 {
    let res = conn
        .randr_get_screen_resources_current(root)
        .unwrap()
        .reply()
        .unwrap();
    if let Some(m) = res
        .modes
        .iter()
        .find(|m| (m.width, m.height) == (width, height))
    {
        return m.id;
    }
    let name = format!("{width}x{height}_test");
    let (htotal, vtotal) = (width + 256, height + 28);
    let info = ModeInfo {
        id: 0,
        width,
        height,
        dot_clock: u32::from(htotal) * u32::from(vtotal) * 60,
        hsync_start: width + 40,
        hsync_end: width + 168,
        htotal,
        hskew: 0,
        vsync_start: height + 1,
        vsync_end: height + 5,
        vtotal,
        name_len: name.len() as u16,
        mode_flags: ModeFlag::default(),
    };
    let mode = conn
        .randr_create_mode(root, info, name.as_bytes())
        .unwrap()
        .reply()
        .unwrap()
        .mode;
    conn.randr_add_output_mode(output, mode).unwrap();
    conn.sync().unwrap();
    mode
}

/// Deletes the monitors `set_monitors` defined, like `xrandr --delmonitor`,
/// from the `first`th on.
pub fn delete_monitors(conn: &RustConnection, root: Window, first: usize, count: usize) {
    for i in first..first + count {
        let atom = monitor_name(conn, i);
        conn.randr_delete_monitor(root, atom).unwrap();
    }
    conn.sync().unwrap();
}

/// Sends the RandR events a monitor plugged in or out would, by changing
/// the screen's physical size (the server tells nothing when monitors are
/// only defined or deleted). Each call gives a size the last did not.
pub fn announce_change(conn: &RustConnection, root: Window) {
    // Counted per connection: the tests of one binary share this process,
    // and a count shared between their servers could repeat one's size.
    static CALLS: std::sync::Mutex<Vec<(usize, u32)>> = std::sync::Mutex::new(Vec::new());
    let key = std::ptr::from_ref(conn) as usize;
    let mut calls = CALLS.lock().unwrap_or_else(|e| e.into_inner());
    let n = match calls.iter_mut().find(|(k, _)| *k == key) {
        Some((_, n)) => {
            *n += 1;
            *n
        }
        None => {
            calls.push((key, 0));
            0
        }
    };
    drop(calls);
    let extra = 1 + n % 2;
    let (width, height) = screen_size(conn, root);
    let (mm_w, mm_h) = (u32::from(width) / 4 + extra, u32::from(height) / 4);
    conn.randr_set_screen_size(root, width, height, mm_w, mm_h)
        .unwrap();
    conn.sync().unwrap();
}
