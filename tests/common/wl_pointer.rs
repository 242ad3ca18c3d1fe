//! A virtual pointer on a wlroots compositor (zwlr_virtual_pointer_v1):
//! relative moves and left clicks, as a mouse would send them. The test
//! connects to the compositor's socket by its path, so it needs no
//! environment of its own (root may connect to another user's socket).
#![allow(dead_code)]

use std::os::unix::net::UnixStream;
use std::path::Path;
use std::time::{SystemTime, UNIX_EPOCH};

use wayland_client::globals::{GlobalListContents, registry_queue_init};
use wayland_client::protocol::{wl_pointer, wl_registry};
use wayland_client::{Connection, Dispatch, EventQueue, QueueHandle, delegate_noop};
use wayland_protocols_wlr::virtual_pointer::v1::client::{
    zwlr_virtual_pointer_manager_v1::ZwlrVirtualPointerManagerV1,
    zwlr_virtual_pointer_v1::ZwlrVirtualPointerV1,
};

/// linux/input-event-codes.h: the left button.
const BTN_LEFT: u32 = 0x110;

struct State;

impl Dispatch<wl_registry::WlRegistry, GlobalListContents> for State {
    fn event(
        _: &mut State,
        _: &wl_registry::WlRegistry,
        _: wl_registry::Event,
        _: &GlobalListContents,
        _: &Connection,
        _: &QueueHandle<State>,
    ) {
    }
}

delegate_noop!(State: ignore ZwlrVirtualPointerManagerV1);
delegate_noop!(State: ignore ZwlrVirtualPointerV1);

/// A pointer device added to the compositor's seat; removed on drop.
pub struct VirtualPointer {
    pointer: ZwlrVirtualPointerV1,
    queue: EventQueue<State>,
}

impl VirtualPointer {
    /// Adds a pointer to the compositor listening on `socket`.
    pub fn connect(socket: &Path) -> Result<VirtualPointer, String> {
        let stream = UnixStream::connect(socket)
            .map_err(|e| format!("connect to {}: {e}", socket.display()))?;
        let conn = Connection::from_socket(stream).map_err(|e| e.to_string())?;
        let (globals, mut queue) =
            registry_queue_init::<State>(&conn).map_err(|e| e.to_string())?;
        let qh = queue.handle();
        let manager: ZwlrVirtualPointerManagerV1 = globals
            .bind(&qh, 1..=2, ())
            .map_err(|e| format!("no zwlr_virtual_pointer_manager_v1: {e}"))?;
        let pointer = manager.create_virtual_pointer(None, &qh, ());
        queue.roundtrip(&mut State).map_err(|e| e.to_string())?;
        Ok(VirtualPointer { pointer, queue })
    }

    /// Moves the pointer by (`dx`, `dy`) pixels.
    pub fn move_by(&mut self, dx: f64, dy: f64) {
        self.pointer.motion(now_ms(), dx, dy);
        self.pointer.frame();
        self.sync();
    }

    /// Presses and releases the left button where the pointer is.
    pub fn click(&mut self) {
        for state in [
            wl_pointer::ButtonState::Pressed,
            wl_pointer::ButtonState::Released,
        ] {
            self.pointer.button(now_ms(), BTN_LEFT, state);
            self.pointer.frame();
        }
        self.sync();
    }

    fn sync(&mut self) {
        self.queue
            .roundtrip(&mut State)
            .expect("the compositor answers");
    }
}

impl Drop for VirtualPointer {
    fn drop(&mut self) {
        self.pointer.destroy();
        let _ = self.queue.roundtrip(&mut State);
    }
}

fn now_ms() -> u32 {
    let since = SystemTime::now()
        .duration_since(UNIX_EPOCH)
        .unwrap_or_default();
    since.as_millis() as u32
}
