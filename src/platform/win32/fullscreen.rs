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

/// The rectangle of the monitor named `device` among `monitors` (device
/// name, bounds), else `nearest`: a window keeps its own monitor even when a
/// layout change makes it overlap another one more.
pub fn own_monitor<D: PartialEq>(device: &D, monitors: &[(D, Bounds)], nearest: Bounds) -> Bounds {
    monitors
        .iter()
        .find(|(d, _)| d == device)
        .map_or(nearest, |(_, b)| *b)
}

#[cfg(windows_platform)]
pub use win32::{cursor_position, keep_covering, take_display_change};

#[cfg(windows_platform)]
mod win32 {
    use std::cell::RefCell;

    use raw_window_handle::{HasWindowHandle, RawWindowHandle};
    use windows_sys::Win32::Foundation::BOOL;
    use windows_sys::Win32::Foundation::{HWND, LPARAM, LRESULT, RECT, WPARAM};
    use windows_sys::Win32::Graphics::Gdi::{
        EnumDisplayMonitors, GetMonitorInfoW, HDC, HMONITOR, MONITOR_DEFAULTTONEAREST, MONITORINFO,
        MONITORINFOEXW, MonitorFromWindow,
    };
    use windows_sys::Win32::System::LibraryLoader::GetModuleHandleW;
    use windows_sys::Win32::UI::WindowsAndMessaging::{
        CreateWindowExW, DefWindowProcW, GetWindowRect, KillTimer, RegisterClassExW,
        SWP_NOACTIVATE, SWP_NOZORDER, SetTimer, SetWindowPos, WM_DISPLAYCHANGE, WM_TIMER,
        WNDCLASSEXW, WS_POPUP,
    };
    use winit::window::Window;

    use super::Bounds;

    /// The second refit, after the display settles (DPI change, taskbar).
    const SETTLE_MS: u32 = 500;
    const SETTLE_TIMER: usize = 1;

    /// A monitor's device name (`\\.\DISPLAY1`), which stays the same
    /// when its place or resolution changes.
    type Device = [u16; 32];

    /// The windows to keep fitted (HWND values) with their monitors, and
    /// the hidden watcher window once it exists.
    type State = (Vec<(isize, Device)>, Option<isize>);

    thread_local! {
        /// winit runs on this thread, and so does the watcher's window procedure.
        static STATE: RefCell<State> = const { RefCell::new((Vec::new(), None)) };
        /// Set by WM_DISPLAYCHANGE, cleared by `take_display_change`.
        static CHANGED: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
    }

    /// True (once) if the display changed since the last call: the cursor
    /// may have been moved by Windows, so its old position means nothing.
    pub fn take_display_change() -> bool {
        CHANGED.replace(false)
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
        let hwnd = h.hwnd.get();
        let Some((device, _)) = monitor_of(hwnd as HWND) else {
            return;
        };
        STATE.with_borrow_mut(|(windows, watcher)| {
            windows.push((hwnd, device));
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
                CHANGED.set(true);
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
        let monitors = all_monitors();
        for (hwnd, device) in windows {
            fit(hwnd as HWND, &device, &monitors);
        }
    }

    fn bounds(r: RECT) -> Bounds {
        (r.left, r.top, r.right, r.bottom)
    }

    /// The device name and bounds of a monitor.
    fn describe(monitor: HMONITOR) -> Option<(Device, Bounds)> {
        // SAFETY: an all-zero MONITORINFOEXW is valid; cbSize says which
        // variant GetMonitorInfoW fills; a bad handle makes it fail.
        unsafe {
            let mut info: MONITORINFOEXW = std::mem::zeroed();
            info.monitorInfo.cbSize = size_of::<MONITORINFOEXW>() as u32;
            let ok = GetMonitorInfoW(
                monitor,
                &mut info as *mut MONITORINFOEXW as *mut MONITORINFO,
            );
            (ok != 0).then(|| (info.szDevice, bounds(info.monitorInfo.rcMonitor)))
        }
    }

    /// The monitor a window is (mostly) on.
    fn monitor_of(hwnd: HWND) -> Option<(Device, Bounds)> {
        // SAFETY: MonitorFromWindow takes any handle and falls back to the nearest.
        describe(unsafe { MonitorFromWindow(hwnd, MONITOR_DEFAULTTONEAREST) })
    }

    /// Every monitor now.
    fn all_monitors() -> Vec<(Device, Bounds)> {
        unsafe extern "system" fn add(m: HMONITOR, _: HDC, _: *mut RECT, list: LPARAM) -> BOOL {
            // SAFETY: `list` is the Vec passed below, alive for the call.
            let list = unsafe { &mut *(list as *mut Vec<(Device, Bounds)>) };
            list.extend(describe(m));
            1
        }
        let mut list: Vec<(Device, Bounds)> = Vec::new();
        // SAFETY: the callback only runs during this call, while `list` lives.
        unsafe {
            EnumDisplayMonitors(
                std::ptr::null_mut(),
                std::ptr::null(),
                Some(add),
                &mut list as *mut Vec<(Device, Bounds)> as LPARAM,
            )
        };
        list
    }

    /// Moves one window onto the whole of the monitor it covered.
    fn fit(hwnd: HWND, device: &Device, monitors: &[(Device, Bounds)]) {
        let mut window = RECT {
            left: 0,
            top: 0,
            right: 0,
            bottom: 0,
        };
        // SAFETY: a valid out-pointer; a window that is gone makes it fail.
        if unsafe { GetWindowRect(hwnd, &mut window) } == 0 {
            return;
        }
        let Some((_, nearest)) = monitor_of(hwnd) else {
            return;
        };
        let monitor = super::own_monitor(device, monitors, nearest);
        if let Some((x, y, w, h)) = super::refit(bounds(window), monitor) {
            // SAFETY: moving our own window; no pointers.
            unsafe {
                SetWindowPos(
                    hwnd,
                    std::ptr::null_mut(),
                    x,
                    y,
                    w,
                    h,
                    SWP_NOZORDER | SWP_NOACTIVATE,
                )
            };
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

    #[test]
    fn a_window_keeps_its_own_monitor_when_the_layout_moves() {
        // The primary shrank from 3840 to 1920 wide, so the second monitor
        // moved from x=3840 to x=1920: its window follows it by name.
        let monitors = [("one", (0, 0, 1920, 1080)), ("two", (1920, 0, 3840, 1080))];
        let nearest = (0, 0, 1920, 1080);
        assert_eq!(
            own_monitor(&"two", &monitors, nearest),
            (1920, 0, 3840, 1080)
        );
        assert_eq!(own_monitor(&"one", &monitors, nearest), (0, 0, 1920, 1080));
        // A monitor that went: the nearest one.
        assert_eq!(own_monitor(&"three", &monitors, nearest), nearest);
    }
}
