//! Windows: keeps each full-screen window covering its monitor when the
//! display changes while the saver runs.
//!
//! winit places a `Fullscreen::Borderless` window once, on the monitor's
//! rectangle at that moment, and does not handle `WM_DISPLAYCHANGE`: after a
//! resolution change the window keeps its old size (part of the monitor
//! shows the desktop, or the window hangs over the edge). A hidden top-level
//! window of our own receives that broadcast; it fits every registered
//! window to the monitor it is on, at once and again a moment later (a DPI
//! change that comes with it makes winit set the window's old size again).
//! winit then reports `Resized` and the show redraws at the new size.

/// A window or monitor rectangle: left, top, right, bottom, as Win32 has them.
pub type Bounds = (i32, i32, i32, i32);

/// Where a window at `window` must go to cover `monitor` exactly: `None` when
/// it already does (so a refit never moves a window needlessly).
pub fn refit(window: Bounds, monitor: Bounds) -> Option<(i32, i32, i32, i32)> {
    if window == monitor {
        return None;
    }
    let (left, top, right, bottom) = monitor;
    Some((left, top, right - left, bottom - top))
}

#[cfg(windows)]
pub use win32::{cursor_position, keep_covering};

#[cfg(windows)]
mod win32 {
    use std::cell::RefCell;

    use raw_window_handle::{HasWindowHandle, RawWindowHandle};
    use windows_sys::Win32::Foundation::{HWND, LPARAM, LRESULT, RECT, WPARAM};
    use windows_sys::Win32::Graphics::Gdi::{
        GetMonitorInfoW, MONITOR_DEFAULTTONEAREST, MONITORINFO, MonitorFromWindow,
    };
    use windows_sys::Win32::System::LibraryLoader::GetModuleHandleW;
    use windows_sys::Win32::UI::WindowsAndMessaging::{
        CreateWindowExW, DefWindowProcW, GetWindowRect, KillTimer, RegisterClassExW,
        SWP_NOACTIVATE, SWP_NOZORDER, SetTimer, SetWindowPos, WM_DISPLAYCHANGE, WM_TIMER,
        WNDCLASSEXW, WS_POPUP,
    };
    use winit::window::Window;

    /// The second refit, after the display settles (DPI change, taskbar).
    const SETTLE_MS: u32 = 500;
    const SETTLE_TIMER: usize = 1;

    thread_local! {
        /// The full-screen windows to keep fitted (as HWND values), and the
        /// hidden watcher window once it exists. winit runs on this thread.
        static STATE: RefCell<(Vec<isize>, Option<isize>)> = const { RefCell::new((Vec::new(), None)) };
    }

    /// Where the mouse cursor is on the desktop, in physical pixels.
    pub fn cursor_position() -> Option<(i32, i32)> {
        let mut point = windows_sys::Win32::Foundation::POINT { x: 0, y: 0 };
        // SAFETY: `point` is a valid POINT to write to.
        let ok = unsafe { windows_sys::Win32::UI::WindowsAndMessaging::GetCursorPos(&mut point) };
        (ok != 0).then_some((point.x, point.y))
    }

    /// Keeps `window` covering its monitor across display changes.
    pub fn keep_covering(window: &Window) {
        let Ok(handle) = window.window_handle() else {
            return;
        };
        let RawWindowHandle::Win32(h) = handle.as_raw() else {
            return;
        };
        STATE.with_borrow_mut(|(windows, watcher)| {
            windows.push(h.hwnd.get());
            if watcher.is_none() {
                *watcher = create_watcher();
            }
        });
    }

    fn create_watcher() -> Option<isize> {
        let class: Vec<u16> = "mountains-display-watch\0".encode_utf16().collect();
        // SAFETY: the class and window are ours; every pointer passed lives
        // for the call, and `class` names a class registered just before.
        unsafe {
            let instance = GetModuleHandleW(std::ptr::null());
            let wc = WNDCLASSEXW {
                cbSize: size_of::<WNDCLASSEXW>() as u32,
                lpfnWndProc: Some(watch),
                hInstance: instance,
                lpszClassName: class.as_ptr(),
                ..std::mem::zeroed()
            };
            RegisterClassExW(&wc);
            // Top-level (not message-only: those miss broadcasts) and never shown.
            let hwnd = CreateWindowExW(
                0,
                class.as_ptr(),
                class.as_ptr(),
                WS_POPUP,
                0,
                0,
                0,
                0,
                std::ptr::null_mut(),
                std::ptr::null_mut(),
                instance,
                std::ptr::null(),
            );
            (!hwnd.is_null()).then_some(hwnd as isize)
        }
    }

    unsafe extern "system" fn watch(hwnd: HWND, msg: u32, wp: WPARAM, lp: LPARAM) -> LRESULT {
        match msg {
            WM_DISPLAYCHANGE => {
                refit_all();
                // SAFETY: a timer on our own window; it reports as WM_TIMER.
                unsafe { SetTimer(hwnd, SETTLE_TIMER, SETTLE_MS, None) };
                0
            }
            WM_TIMER if wp == SETTLE_TIMER => {
                // SAFETY: as above.
                unsafe { KillTimer(hwnd, SETTLE_TIMER) };
                refit_all();
                0
            }
            // SAFETY: the default handling for everything else.
            _ => unsafe { DefWindowProcW(hwnd, msg, wp, lp) },
        }
    }

    fn refit_all() {
        let windows = STATE.with_borrow(|(windows, _)| windows.clone());
        for hwnd in windows {
            fit(hwnd as HWND);
        }
    }

    /// Moves one window onto the whole of the monitor it is (mostly) on.
    fn fit(hwnd: HWND) {
        let zero = RECT {
            left: 0,
            top: 0,
            right: 0,
            bottom: 0,
        };
        let mut window = zero;
        let mut info = MONITORINFO {
            cbSize: size_of::<MONITORINFO>() as u32,
            rcMonitor: zero,
            rcWork: zero,
            dwFlags: 0,
        };
        // SAFETY: valid out-pointers; a window that is gone makes the calls
        // fail, and then nothing is moved.
        unsafe {
            if GetWindowRect(hwnd, &mut window) == 0 {
                return;
            }
            let monitor = MonitorFromWindow(hwnd, MONITOR_DEFAULTTONEAREST);
            if GetMonitorInfoW(monitor, &mut info) == 0 {
                return;
            }
            let bounds = |r: RECT| (r.left, r.top, r.right, r.bottom);
            if let Some((x, y, w, h)) = super::refit(bounds(window), bounds(info.rcMonitor)) {
                SetWindowPos(
                    hwnd,
                    std::ptr::null_mut(),
                    x,
                    y,
                    w,
                    h,
                    SWP_NOZORDER | SWP_NOACTIVATE,
                );
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_window_that_covers_its_monitor_stays_put() {
        let monitor = (-1920, 0, 0, 1080);
        assert_eq!(refit(monitor, monitor), None);
    }

    #[test]
    fn after_a_resolution_change_the_window_takes_the_new_size() {
        // 1920x1080 became 2560x1440 on a monitor to the right of the primary.
        let window = (1920, 0, 3840, 1080);
        let monitor = (1920, 0, 4480, 1440);
        assert_eq!(refit(window, monitor), Some((1920, 0, 2560, 1440)));
    }

    #[test]
    fn a_moved_monitor_moves_the_window() {
        let window = (0, 0, 1280, 1024);
        let monitor = (0, -1024, 1280, 0);
        assert_eq!(refit(window, monitor), Some((0, -1024, 1280, 1024)));
    }
}
