//! Drawing into a window another program owns (xscreensaver's window, its
//! preview, the root window): softbuffer on the bare XID, plus our own
//! x11rb connection that watches the window's size and its destruction.

use std::num::NonZeroU32;
use std::sync::Arc;
use std::sync::mpsc::{self, Receiver, RecvTimeoutError, Sender};
use std::time::Instant;

use raw_window_handle::{
    DisplayHandle, HandleError, HasDisplayHandle, HasWindowHandle, RawDisplayHandle,
    RawWindowHandle, WindowHandle, XcbDisplayHandle, XcbWindowHandle,
};
use x11rb::connection::Connection;
use x11rb::protocol::Event;
use x11rb::protocol::xproto::{ChangeWindowAttributesAux, ConnectionExt as _, EventMask};
use x11rb::rust_connection::RustConnection;

use crate::mountain::Mountain;
use crate::render::Size;
use crate::saver::error::SaverError;
use crate::saver::present::Presenter;
use crate::saver::show::Show;
use crate::saver::slideshow::Pacing;
use crate::settings::Settings;

/// A window owned by someone else, named by its XID, as softbuffer wants it.
#[derive(Debug, Clone, Copy)]
struct ForeignWindow {
    xid: NonZeroU32,
    screen: i32,
}

impl HasWindowHandle for ForeignWindow {
    fn window_handle(&self) -> Result<WindowHandle<'_>, HandleError> {
        let raw = RawWindowHandle::Xcb(XcbWindowHandle::new(self.xid));
        // SAFETY: the handle is plain data (an XID); softbuffer checks the
        // window exists, and we stop drawing when it is destroyed.
        Ok(unsafe { WindowHandle::borrow_raw(raw) })
    }
}

impl HasDisplayHandle for ForeignWindow {
    fn display_handle(&self) -> Result<DisplayHandle<'_>, HandleError> {
        // No connection: softbuffer opens its own to $DISPLAY.
        let raw = RawDisplayHandle::Xcb(XcbDisplayHandle::new(None, self.screen));
        // SAFETY: a handle without a connection pointer refers to no memory.
        Ok(unsafe { DisplayHandle::borrow_raw(raw) })
    }
}

/// What the watcher threads tell the drawing loop.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Notice {
    Resized(Size),
    Exposed,
    Destroyed,
    /// The connection to the X server broke.
    ServerGone,
    Terminate,
    /// The power or the display's state changed.
    Seen(crate::saver::watch::Seen),
}

/// The window `$XSCREENSAVER_WINDOW` names (hex `0x..` or decimal).
pub fn parse_window_id(text: &str) -> Option<u32> {
    let text = text.trim();
    let id = match text.strip_prefix("0x").or_else(|| text.strip_prefix("0X")) {
        Some(hex) => u32::from_str_radix(hex, 16).ok()?,
        None => text.parse().ok()?,
    };
    (id != 0).then_some(id)
}

/// The window `--root` draws on: `$XSCREENSAVER_WINDOW`, else the root
/// window; with the variable as set when it named the window.
fn root_target(conn: &RustConnection, screen: usize) -> (u32, Option<String>) {
    let named = std::env::var("XSCREENSAVER_WINDOW").ok();
    match named_window(named.as_deref()) {
        Ok(Some(id)) => return (id, named.map(|v| format!("XSCREENSAVER_WINDOW={v:?}"))),
        Ok(None) => {}
        Err(why) => crate::log::warn(&why),
    }
    (conn.setup().roots[screen].root, None)
}

/// `error`, said with the variable that named its window (`by`): a stale
/// `XSCREENSAVER_WINDOW` left in a shell was named by its id alone, which
/// nobody had typed.
fn named_by(error: SaverError, by: Option<&str>) -> SaverError {
    match (error, by) {
        (SaverError::NoSuchWindow(id), Some(by)) => {
            SaverError::Other(format!("{by}: {}", SaverError::NoSuchWindow(id)))
        }
        (error, _) => error,
    }
}

/// The window `$XSCREENSAVER_WINDOW` (`var`) names: `None` unset or
/// empty (as a shell's `XSCREENSAVER_WINDOW= mountains --root` leaves
/// it: the root window, as unset), or why its text is no window id.
fn named_window(var: Option<&str>) -> Result<Option<u32>, String> {
    match var.filter(|text| !text.trim().is_empty()) {
        None => Ok(None),
        Some(text) => parse_window_id(text).map(Some).ok_or_else(|| {
            format!("XSCREENSAVER_WINDOW={text:?} is not a window id; drawing on the root window")
        }),
    }
}

/// Draws the slide show into `window` (`None`: `--root`) until the window is
/// destroyed or the process gets SIGTERM/SIGINT.
pub fn run(
    window: Option<u32>,
    settings: Settings,
    opened: Option<Mountain>,
) -> Result<(), SaverError> {
    let (conn, screen) = RustConnection::connect(None).map_err(super::connect::connect_failed)?;
    let conn = Arc::new(conn);
    let (xid, by) = match window {
        Some(xid) => (xid, None),
        None => root_target(&conn, screen),
    };
    let size = watch_window(&conn, xid).map_err(|e| named_by(e, by.as_deref()))?;
    if let Some(why) = crate::platform::x11::visual::window_refusal(&*conn, screen, xid) {
        return Err(SaverError::Unsupported(why));
    }
    let (tx, rx) = mpsc::channel();
    spawn_event_thread(conn.clone(), xid, tx.clone())?;
    let seen_tx = tx.clone();
    let watcher =
        crate::platform::watch_power_and_display(crate::platform::Backend::X11, move |seen| {
            let _ = seen_tx.send(Notice::Seen(seen));
        });
    crate::platform::signals::on_terminate(move || {
        let _ = tx.send(Notice::Terminate);
    })
    .map_err(|e| SaverError::Other(format!("cannot watch for SIGTERM: {e}")))?;

    let target = ForeignWindow {
        xid: NonZeroU32::new(xid).ok_or(SaverError::NoSuchWindow(xid))?,
        screen: screen as i32,
    };
    let presenter =
        Presenter::new(target).map_err(|e| SaverError::Other(format!("window 0x{xid:x}: {e}")))?;
    let pacing = Pacing::from_seconds(settings.draw_seconds, settings.pause_seconds, true);
    let now = Instant::now();
    let mut show = crate::saver::options::new_show(settings, opened, pacing, size, now);
    crate::saver::watch::apply(watcher.seen(), &mut show, now);
    let mut embedded = Embedded {
        conn,
        xid,
        presenter,
        show,
        trace: crate::saver::trace::Trace::from_env(),
    };
    embedded.present_all()?;
    embedded.run(rx)
}

/// Reads the window's size and asks for its structure and expose events.
fn watch_window(conn: &RustConnection, xid: u32) -> Result<Size, SaverError> {
    let geometry = conn
        .get_geometry(xid)
        .ok()
        .and_then(|c| c.reply().ok())
        .ok_or(SaverError::NoSuchWindow(xid))?;
    let mask = EventMask::STRUCTURE_NOTIFY | EventMask::EXPOSURE;
    conn.change_window_attributes(xid, &ChangeWindowAttributesAux::new().event_mask(mask))
        .ok()
        .and_then(|c| c.check().ok())
        .ok_or(SaverError::NoSuchWindow(xid))?;
    Ok(Size::new(geometry.width.into(), geometry.height.into()))
}

/// Forwards the window's X events to the drawing loop as they arrive.
fn spawn_event_thread(
    conn: Arc<RustConnection>,
    xid: u32,
    tx: Sender<Notice>,
) -> Result<(), SaverError> {
    let watch = move || {
        while let Ok(event) = conn.wait_for_event() {
            let notice = match event {
                Event::ConfigureNotify(e) if e.window == xid => {
                    Notice::Resized(Size::new(e.width.into(), e.height.into()))
                }
                Event::Expose(e) if e.window == xid && e.count == 0 => Notice::Exposed,
                // A server that shuts down (SIGTERM, the session ending)
                // destroys the other clients' windows, xscreensaver's among
                // them, before it closes our connection: that is no
                // daemon ending us, and it must be said.
                Event::DestroyNotify(e) if e.window == xid && !server_answers(&conn) => break,
                Event::DestroyNotify(e) if e.window == xid => Notice::Destroyed,
                _ => continue,
            };
            if tx.send(notice).is_err() {
                return;
            }
        }
        // The X server went away: nothing left to draw on.
        let _ = tx.send(Notice::ServerGone);
    };
    std::thread::Builder::new()
        .name("x11-events".into())
        .spawn(watch)
        .map(drop)
        .map_err(|e| SaverError::Other(format!("cannot start the X event thread: {e}")))
}

/// True if the X server still answers a request: false while it shuts
/// down, which serves no request from then on.
fn server_answers(conn: &RustConnection) -> bool {
    conn.get_input_focus().is_ok_and(|c| c.reply().is_ok())
}

/// The drawing loop of an embedded slide show.
struct Embedded {
    conn: Arc<RustConnection>,
    xid: u32,
    presenter: Presenter<ForeignWindow>,
    show: Show,
    trace: crate::saver::trace::Trace,
}

impl Embedded {
    fn run(&mut self, rx: Receiver<Notice>) -> Result<(), SaverError> {
        loop {
            let now = Instant::now();
            let damage = self.show.tick(now);
            if !damage.is_empty() {
                self.present(damage)?;
            }
            // The signal handler's flag: strips being drawn stopped for it.
            if crate::platform::signals::ending() {
                self.trace.ended_by(&Notice::Terminate);
                return Ok(());
            }
            let first = match self.show.wake_at(now) {
                Some(at) => rx.recv_timeout(at.saturating_duration_since(Instant::now())),
                None => rx.recv().map_err(|_| RecvTimeoutError::Disconnected),
            };
            let notice = match first {
                Ok(n) => n,
                Err(RecvTimeoutError::Timeout) => continue,
                Err(RecvTimeoutError::Disconnected) => return Ok(()),
            };
            if self.handle(std::iter::once(notice).chain(rx.try_iter()))? {
                return Ok(());
            }
        }
    }

    /// Handles a batch of notices (resizes coalesced); true when it is time to end.
    fn handle(&mut self, notices: impl Iterator<Item = Notice>) -> Result<bool, SaverError> {
        let mut size = None;
        let mut exposed = false;
        for notice in notices {
            match notice {
                Notice::Terminate => {
                    self.trace.ended_by(&notice);
                    return Ok(true);
                }
                Notice::Destroyed => return Ok(true),
                Notice::ServerGone => return Err(SaverError::server_gone()),
                Notice::Resized(s) => size = Some(s),
                Notice::Exposed => exposed = true,
                Notice::Seen(seen) => {
                    let fresh = crate::saver::watch::apply(seen, &mut self.show, Instant::now());
                    exposed |= !fresh.is_empty();
                }
            }
        }
        let current = self.show.size();
        if let Some(size) = size.filter(|&s| s != current) {
            self.show.resize(size, Instant::now());
            exposed = true;
        }
        if exposed {
            self.present_all()?;
        }
        Ok(false)
    }

    fn present_all(&mut self) -> Result<(), SaverError> {
        match self.show.frame().map(|f| f.bounds()) {
            Some(bounds) => self.present(bounds.into()),
            None => Ok(()),
        }
    }

    fn present(&mut self, damage: crate::render::Damage) -> Result<(), SaverError> {
        let Some(frame) = self.show.frame() else {
            return Ok(());
        };
        match self.presenter.present(frame, &damage) {
            Ok(()) => {
                self.trace.presented();
                Ok(())
            }
            // A window destroyed between two events is the normal way to end.
            Err(_) if !self.window_exists() => Ok(()),
            Err(e) => Err(SaverError::Other(format!("window 0x{:x}: {e}", self.xid))),
        }
    }

    fn window_exists(&self) -> bool {
        let reply = self.conn.get_geometry(self.xid).map(|c| c.reply());
        matches!(reply, Ok(Ok(_)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_empty_xscreensaver_window_is_unset_and_a_wrong_one_is_named() {
        assert_eq!(named_window(None), Ok(None));
        assert_eq!(named_window(Some("")), Ok(None));
        assert_eq!(named_window(Some("  ")), Ok(None));
        assert_eq!(named_window(Some("0x2a")), Ok(Some(42)));
        let why = named_window(Some("window")).unwrap_err();
        assert!(why.contains("\"window\" is not a window id"), "{why}");
    }

    #[test]
    fn window_ids_parse_in_hex_and_decimal() {
        assert_eq!(parse_window_id("0x1c00007"), Some(0x1c00007));
        assert_eq!(parse_window_id("0X1C00007"), Some(0x1c00007));
        assert_eq!(parse_window_id(" 29360135 "), Some(29360135));
        assert_eq!(parse_window_id("0"), None);
        assert_eq!(parse_window_id("window"), None);
        assert_eq!(parse_window_id("0x"), None);
        assert_eq!(parse_window_id("0x1ffffffff"), None);
    }
}
