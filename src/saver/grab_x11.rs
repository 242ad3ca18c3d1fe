//! Keeps the key or click that wakes the full-screen saver away from the
//! program underneath: an X11 keyboard and pointer grab on our window.
//!
//! Without it, an override-redirect window has no focus, so the key that
//! ends the saver would be typed into the focused program and the click
//! would land on whatever lies below. The grab is held by a connection of
//! our own; winit still sees the raw device events (XI 2.1 and later send
//! raw events regardless of grabs), which is what ends the saver.

use x11rb::protocol::xproto::{ConnectionExt as _, EventMask, GrabMode, GrabStatus};
use x11rb::rust_connection::RustConnection;
use x11rb::{CURRENT_TIME, NONE};

/// Attempts before giving up: the window may take a few frames to be viewable.
const ATTEMPTS: u32 = 50;

/// The grab, held as long as this lives (closing the connection releases it).
pub struct InputGrab {
    conn: Option<RustConnection>,
    window: u32,
    tries: u32,
    keyboard: bool,
    pointer: bool,
}

impl InputGrab {
    /// Prepares grabbing input for `window`; nothing happens without a display.
    pub fn new(window: u32) -> Self {
        InputGrab {
            conn: RustConnection::connect(None).ok().map(|(c, _)| c),
            window,
            tries: 0,
            keyboard: false,
            pointer: false,
        }
    }

    /// Tries the grabs that are not held yet; call again on later frames
    /// until it returns true (a window that is not yet viewable cannot grab).
    pub fn try_grab(&mut self) -> bool {
        let Some(conn) = self.conn.as_ref() else {
            return true;
        };
        if self.keyboard && self.pointer || self.tries >= ATTEMPTS {
            return true;
        }
        self.tries += 1;
        if !self.keyboard {
            let reply = conn
                .grab_keyboard(
                    false,
                    self.window,
                    CURRENT_TIME,
                    GrabMode::ASYNC,
                    GrabMode::ASYNC,
                )
                .ok()
                .and_then(|c| c.reply().ok());
            self.keyboard = reply.is_some_and(|r| r.status == GrabStatus::SUCCESS);
        }
        if !self.pointer {
            let reply = conn
                .grab_pointer(
                    false,
                    self.window,
                    EventMask::NO_EVENT,
                    GrabMode::ASYNC,
                    GrabMode::ASYNC,
                    NONE,
                    NONE,
                    CURRENT_TIME,
                )
                .ok()
                .and_then(|c| c.reply().ok());
            self.pointer = reply.is_some_and(|r| r.status == GrabStatus::SUCCESS);
        }
        if self.tries == ATTEMPTS && !(self.keyboard && self.pointer) {
            crate::log::warn(
                "another program holds the keyboard or mouse: input may also reach it",
            );
        }
        self.keyboard && self.pointer
    }
}
