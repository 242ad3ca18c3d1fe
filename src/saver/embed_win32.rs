//! The Windows preview: a child window filling the client area of the
//! Control Panel's little monitor, alive only as long as that parent.

use std::num::NonZeroIsize;
use std::time::Duration;

use raw_window_handle::{RawWindowHandle, Win32WindowHandle};
use windows_sys::Win32::Foundation::{HWND, RECT};
use windows_sys::Win32::UI::WindowsAndMessaging::{GetClientRect, IsWindow};
use winit::dpi::{PhysicalPosition, PhysicalSize};
use winit::window::WindowAttributes;

use super::error::SaverError;

/// How often the child checks that its parent still exists and its size.
pub const PARENT_POLL: Duration = Duration::from_millis(250);

fn hwnd(handle: u64) -> HWND {
    handle as usize as HWND
}

/// True while the parent window exists.
pub fn parent_alive(handle: u64) -> bool {
    // SAFETY: IsWindow accepts any value and only reports whether it names a window.
    unsafe { IsWindow(hwnd(handle)) != 0 }
}

/// Keeps the preview `window` the size of its parent's client area; false
/// once the parent is gone (the preview then ends).
pub fn follow_parent(parent: u64, window: &winit::window::Window) -> bool {
    if !parent_alive(parent) {
        return false;
    }
    if let Some((w, h)) = parent_client_size(parent) {
        let size = window.inner_size();
        if (size.width, size.height) != (w, h) {
            let _ = window.request_inner_size(PhysicalSize::new(w, h));
        }
    }
    true
}

/// The parent's client area in pixels, if it can be read.
pub fn parent_client_size(handle: u64) -> Option<(u32, u32)> {
    let mut rect = RECT {
        left: 0,
        top: 0,
        right: 0,
        bottom: 0,
    };
    // SAFETY: `rect` is a valid RECT to write to; a bad handle makes the call fail.
    let ok = unsafe { GetClientRect(hwnd(handle), &mut rect) } != 0;
    let w = u32::try_from(rect.right - rect.left).ok()?;
    let h = u32::try_from(rect.bottom - rect.top).ok()?;
    ok.then_some((w, h))
}

/// Attributes of a borderless child of `parent` covering its client area.
pub fn child_attributes(
    base: WindowAttributes,
    parent: u64,
) -> Result<WindowAttributes, SaverError> {
    let missing = || SaverError::Other(format!("there is no window {parent} to preview in"));
    let handle = isize::try_from(parent)
        .ok()
        .and_then(NonZeroIsize::new)
        .ok_or_else(missing)?;
    if !parent_alive(parent) {
        return Err(missing());
    }
    let (w, h) = parent_client_size(parent).ok_or_else(missing)?;
    let raw = RawWindowHandle::Win32(Win32WindowHandle::new(handle));
    // SAFETY: the parent was checked to exist; if it goes, the child goes with
    // it and `parent_alive` ends the process.
    let attrs = unsafe { base.with_parent_window(Some(raw)) };
    Ok(attrs
        .with_decorations(false)
        .with_position(PhysicalPosition::new(0, 0))
        .with_inner_size(PhysicalSize::new(w.max(1), h.max(1))))
}
