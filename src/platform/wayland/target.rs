//! A Wayland surface of our own connection, handed to softbuffer (through
//! `present::Presenter`) as a raw window handle: the layer-shell mode draws
//! with the same presenter and buffer history as the winit windows.

use std::ffi::c_void;
use std::ptr::NonNull;

use raw_window_handle::{
    DisplayHandle, HandleError, HasDisplayHandle, HasWindowHandle, RawDisplayHandle,
    RawWindowHandle, WaylandDisplayHandle, WaylandWindowHandle, WindowHandle,
};

/// The `wl_display` and `wl_surface` pointers of one surface.
///
/// Whoever makes one keeps the connection and the surface alive for as
/// long as any copy (and the presenter holding it) lives.
#[derive(Debug, Clone, Copy)]
pub(super) struct WaylandTarget {
    display: NonNull<c_void>,
    surface: NonNull<c_void>,
}

impl WaylandTarget {
    /// The pointers of `surface` on the connection of `display`; `None`
    /// if either is null (a connection not made by libwayland-client).
    pub(super) fn new(display: *mut c_void, surface: *mut c_void) -> Option<Self> {
        Some(WaylandTarget {
            display: NonNull::new(display)?,
            surface: NonNull::new(surface)?,
        })
    }
}

impl HasDisplayHandle for WaylandTarget {
    fn display_handle(&self) -> Result<DisplayHandle<'_>, HandleError> {
        let raw = RawDisplayHandle::Wayland(WaylandDisplayHandle::new(self.display));
        // SAFETY: the connection outlives every copy of this target (see the type).
        Ok(unsafe { DisplayHandle::borrow_raw(raw) })
    }
}

impl HasWindowHandle for WaylandTarget {
    fn window_handle(&self) -> Result<WindowHandle<'_>, HandleError> {
        let raw = RawWindowHandle::Wayland(WaylandWindowHandle::new(self.surface));
        // SAFETY: the surface outlives every copy of this target (see the type).
        Ok(unsafe { WindowHandle::borrow_raw(raw) })
    }
}
