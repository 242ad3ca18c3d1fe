//! Keeps the key or click that wakes the full-screen saver away from the
//! program underneath: an X11 keyboard and pointer grab on our window.
//!
//! Without it, an override-redirect window has no focus, so the key that
//! ends the saver would be typed into the focused program and the click
//! would land on whatever lies below. The grab is held by a connection of
//! our own; winit still sees the raw device events (XI 2.1 and later send
//! raw events regardless of grabs), which is what ends the saver. A warped
//! pointer (`xdotool mousemove`, remote desktops) sends no raw event: the
//! grab asks for the pointer's motion and a thread passes each place on,
//! and with it the relative devices' raw motion (see x11/motion.rs: winit
//! counts an absolute device's place as motion). The pointer the server
//! moves itself when the screen changes is no person (see x11/placed.rs).

use std::sync::Arc;

use x11rb::connection::Connection as _;
use x11rb::protocol::Event;
use x11rb::protocol::xproto::{ConnectionExt as _, EventMask, GrabMode, GrabStatus};
use x11rb::rust_connection::RustConnection;
use x11rb::{CURRENT_TIME, NONE};

use super::motion::Devices;
use super::placed::{self, ServerMoves};

/// Attempts before giving up: the window may take a few frames to be viewable.
const ATTEMPTS: u32 = 50;

/// What the grab's thread tells of the pointer.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Pointer {
    /// It is at this place on the screen (root coordinates).
    At(i16, i16),
    /// A relative device moved it by this much (perhaps against an edge).
    Moved(f64, f64),
    /// The screen changed and the server may have moved it itself: it is
    /// at this place now, the origin to measure from (see x11/placed.rs).
    Placed(i16, i16),
}

/// The grab, held as long as this lives (closing the connection releases it).
pub struct InputGrab {
    conn: Option<Arc<RustConnection>>,
    /// The root window of the connection's screen.
    root: u32,
    window: u32,
    tries: u32,
    keyboard: bool,
    pointer: bool,
}

impl InputGrab {
    /// Prepares grabbing input for `window`; nothing happens without a display.
    pub fn new(window: u32) -> Self {
        let conn = RustConnection::connect(None).ok();
        let root = conn
            .as_ref()
            .and_then(|(c, screen)| c.setup().roots.get(*screen))
            .map_or(0, |s| s.root);
        // Before the pointer grab, whose motion events they explain: a
        // screen change before the grab's thread starts is then queued.
        if let Some((c, _)) = conn.as_ref()
            && !placed::watch_screen(c, root)
        {
            crate::log::warn("screen changes cannot be told from pointer moves");
        }
        InputGrab {
            conn: conn.map(|(c, _)| Arc::new(c)),
            root,
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
                    EventMask::POINTER_MOTION,
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

    /// Calls `tell` with the pointer's place on the screen (root
    /// coordinates) at each motion the pointer grab reports and with each
    /// relative device's raw motion, and after a screen change with the
    /// place the server put it, on a thread of its own, until the
    /// connection ends. True when the raw motion is watched (XInput 2.2);
    /// nothing is without a connection.
    pub fn watch_motion(&self, tell: impl Fn(Pointer) + Send + 'static) -> bool {
        let Some(conn) = self.conn.clone() else {
            return false;
        };
        let devices = Devices::watch(&*conn, self.root);
        let raw = devices.is_some();
        let root = self.root;
        let watch = move || follow_pointer(&conn, root, devices, tell);
        let spawned = std::thread::Builder::new()
            .name("x11-pointer".into())
            .spawn(watch);
        if let Err(e) = spawned {
            crate::log::warn(&format!("cannot watch the pointer: {e}"));
            return false;
        }
        raw
    }
}

/// The grab's thread: tells each place and relative move of the pointer
/// until the connection ends.
fn follow_pointer(
    conn: &RustConnection,
    root: u32,
    devices: Option<Devices>,
    tell: impl Fn(Pointer),
) {
    let mut follower = Follower {
        conn,
        root,
        devices,
        server_moves: ServerMoves::default(),
        last: None,
        tell,
    };
    // A move before the grab held and the raw motion was asked for
    // reached neither: the place now tells of it, unless the screen
    // changed meanwhile (its events came before the answer, and are
    // queued now).
    let Some(first) = follower.server_moves.look(conn, root) else {
        return;
    };
    let mut queued = Vec::new();
    while let Ok(Some(event)) = conn.poll_for_event_with_sequence() {
        queued.push(event);
    }
    let moves = follower.server_moves;
    let changed = queued
        .iter()
        .any(|(e, seq)| moves.before_the_answer(*seq) && placed::is_screen_change(e, root));
    follower.last = Some(first);
    (follower.tell)(match changed {
        true => Pointer::Placed(first.0, first.1),
        false => Pointer::At(first.0, first.1),
    });
    for (event, sequence) in queued {
        follower.handle(event, sequence);
    }
    while let Ok((event, sequence)) = conn.wait_for_event_with_sequence() {
        follower.handle(event, sequence);
    }
}

/// What the grab's thread knows between two events.
struct Follower<'a, T: Fn(Pointer)> {
    conn: &'a RustConnection,
    root: u32,
    devices: Option<Devices>,
    server_moves: ServerMoves,
    /// The place last told: a screen change that left the pointer there
    /// tells nothing new (one change sends several events).
    last: Option<(i16, i16)>,
    tell: T,
}

impl<T: Fn(Pointer)> Follower<'_, T> {
    fn handle(&mut self, event: Event, sequence: u64) {
        match event {
            Event::MotionNotify(_) if self.server_moves.before_the_answer(sequence) => {}
            Event::MotionNotify(e) => {
                self.last = Some((e.root_x, e.root_y));
                (self.tell)(Pointer::At(e.root_x, e.root_y));
            }
            e if placed::is_screen_change(&e, self.root) => {
                let place = self.server_moves.look(self.conn, self.root);
                if let Some(p) = place.filter(|&p| Some(p) != self.last) {
                    self.last = Some(p);
                    (self.tell)(Pointer::Placed(p.0, p.1));
                }
            }
            Event::XinputRawMotion(e) => {
                if let Some((dx, dy)) = self.devices.as_ref().map(|d| d.travel(&e)) {
                    (self.tell)(Pointer::Moved(dx, dy));
                }
            }
            Event::XinputHierarchy(_) => self.devices = Devices::query(self.conn),
            _ => {}
        }
    }
}
