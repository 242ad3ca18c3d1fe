//! The settings dialog's owner on Windows (`/c:<HWND>`, the Screen Saver
//! dialog): the dialog is modal to it. No owner elsewhere.

/// Whether `hwnd` names a window: a stale handle would make creating the
/// owned window fail, so the settings then open on their own instead.
/// Always true where windows have no such handles.
pub fn window_exists(hwnd: u64) -> bool {
    #[cfg(windows_platform)]
    // SAFETY: IsWindow accepts any value and only reports whether it names a window.
    return unsafe {
        windows_sys::Win32::UI::WindowsAndMessaging::IsWindow(hwnd as usize as _) != 0
    };
    #[cfg(not(windows_platform))]
    {
        let _ = hwnd;
        true
    }
}

/// Makes the dialog modal: its owner takes no input while it is open, and
/// is enabled again when this drops (on OK, Cancel, error or panic alike).
pub struct ModalOwner {
    #[cfg(windows_platform)]
    hwnd: Option<windows_sys::Win32::Foundation::HWND>,
}

impl ModalOwner {
    /// Disables `owner` (none: nothing to do) until this drops.
    pub fn disable(owner: Option<u64>) -> Self {
        #[cfg(windows_platform)]
        {
            use windows_sys::Win32::UI::Input::KeyboardAndMouse::EnableWindow;
            let hwnd = owner.map(|h| h as usize as windows_sys::Win32::Foundation::HWND);
            if let Some(h) = hwnd {
                // SAFETY: EnableWindow accepts any handle; a stale one fails harmlessly.
                unsafe { EnableWindow(h, 0) };
            }
            ModalOwner { hwnd }
        }
        #[cfg(not(windows_platform))]
        {
            let _ = owner;
            ModalOwner {}
        }
    }
}

#[cfg(windows_platform)]
impl Drop for ModalOwner {
    fn drop(&mut self) {
        use windows_sys::Win32::UI::Input::KeyboardAndMouse::EnableWindow;
        if let Some(h) = self.hwnd {
            // SAFETY: as in `disable`.
            unsafe { EnableWindow(h, 1) };
        }
    }
}
