//! The Windows preview: a child window filling the client area of the
//! Control Panel's little monitor, alive only as long as that parent.
//!
//! DPI: the preview window takes the DPI awareness of the window it goes
//! into. winit would make the whole process per-monitor aware, and a
//! per-monitor-aware child in a parent of another awareness is what
//! Windows' DPI hosting rules forbid or scale oddly; the way around them,
//! `SetThreadDpiHostingBehavior(MIXED)`, only lets windows the calling
//! thread creates host such children, and the dialog's window is not ours.

use std::ffi::CStr;
use std::num::NonZeroIsize;
use std::time::Duration;

use raw_window_handle::{RawWindowHandle, Win32WindowHandle};
use windows_sys::Win32::Foundation::{HWND, RECT};
use windows_sys::Win32::System::LibraryLoader::{GetModuleHandleW, GetProcAddress};
use windows_sys::Win32::UI::HiDpi::DPI_AWARENESS_CONTEXT;
use windows_sys::Win32::UI::WindowsAndMessaging::{GetClientRect, IsWindow};
use winit::dpi::{PhysicalPosition, PhysicalSize};
use winit::event_loop::EventLoopBuilder;
use winit::platform::windows::EventLoopBuilderExtWindows;
use winit::window::WindowAttributes;

use crate::render::Size;
use crate::saver::error::SaverError;

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
    if let Some(Size {
        width: w,
        height: h,
    }) = parent_client_size(parent)
    {
        let size = window.inner_size();
        if (size.width, size.height) != (w, h) {
            let _ = window.request_inner_size(PhysicalSize::new(w, h));
        }
    }
    true
}

/// The parent's client area in pixels, if it can be read.
pub fn parent_client_size(handle: u64) -> Option<Size> {
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
    ok.then_some(Size::new(w, h))
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
    let Size {
        width: w,
        height: h,
    } = parent_client_size(parent).ok_or_else(missing)?;
    let raw = RawWindowHandle::Win32(Win32WindowHandle::new(handle));
    // SAFETY: the parent was checked to exist; if it goes, the child goes with
    // it and `parent_alive` ends the process.
    let attrs = unsafe { base.with_parent_window(Some(raw)) };
    Ok(attrs
        .with_decorations(false)
        .with_position(PhysicalPosition::new(0, 0))
        .with_inner_size(PhysicalSize::new(w.max(1), h.max(1))))
}

/// Keeps winit from making the process per-monitor DPI aware: the preview
/// takes its parent's awareness instead (`match_parent_dpi`).
pub fn leave_dpi_to_the_parent<T>(builder: &mut EventLoopBuilder<T>) {
    builder.with_dpi_aware(false);
}

/// Gives this thread the DPI awareness of `parent`, so that the preview
/// window it creates next has the same; false if that cannot be done
/// (before Windows 10 1607, or no such window), and the preview stays
/// DPI-unaware, which Windows scales like the rest of an old dialog.
pub fn match_parent_dpi(parent: u64) -> bool {
    type GetContext = unsafe extern "system" fn(HWND) -> DPI_AWARENESS_CONTEXT;
    type SetContext = unsafe extern "system" fn(DPI_AWARENESS_CONTEXT) -> DPI_AWARENESS_CONTEXT;
    let (Some(get), Some(set)) = (
        user32(c"GetWindowDpiAwarenessContext"),
        user32(c"SetThreadDpiAwarenessContext"),
    ) else {
        return false;
    };
    // SAFETY: both names are user32 functions of exactly these signatures
    // (winuser.h); a FARPROC is a function pointer of the same size.
    let (get, set) = unsafe {
        (
            std::mem::transmute::<unsafe extern "system" fn() -> isize, GetContext>(get),
            std::mem::transmute::<unsafe extern "system" fn() -> isize, SetContext>(set),
        )
    };
    // SAFETY: any HWND may be asked (a bad one gives null), and the context
    // passed on is one Windows handed out.
    unsafe {
        let context = get(hwnd(parent));
        !context.is_null() && !set(context).is_null()
    }
}

/// A user32 function looked up at run time: linking it would stop the exe
/// from starting on a Windows (or Wine) without it.
fn user32(name: &CStr) -> Option<unsafe extern "system" fn() -> isize> {
    let module: Vec<u16> = "user32.dll\0".encode_utf16().collect();
    // SAFETY: both strings are NUL-terminated and live for the calls;
    // user32 stays loaded (winit links it).
    unsafe {
        let user32 = GetModuleHandleW(module.as_ptr());
        if user32.is_null() {
            return None;
        }
        GetProcAddress(user32, name.as_ptr().cast())
    }
}
