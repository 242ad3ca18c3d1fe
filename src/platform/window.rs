//! What the saver and the settings screen ask of the window system, in
//! words of none: which backend (one choice for both), the attributes of
//! their windows, and why an event loop could not start.

use winit::event_loop::EventLoopBuilder;
use winit::monitor::MonitorHandle;
#[cfg(x11_platform)]
use winit::platform::x11::WindowAttributesExtX11;
use winit::window::{Window, WindowAttributes};

use super::backend::Backend;
use crate::saver::error::{SaverError, without_source_place};
use crate::saver::heads::Head;

/// The window system the saver and the settings screen use, after
/// checking that its libraries can be loaded: on the desktop Unixes X11
/// when `x_named` (`-display` was given), else Wayland first; Windows
/// there.
pub fn choose_backend(x_named: bool) -> Result<Backend, SaverError> {
    #[cfg(x11_platform)]
    return super::libcheck::check_display(x_named);
    #[cfg(windows_platform)]
    {
        let _ = x_named;
        Ok(Backend::Windows)
    }
}

/// Makes winit use `backend`, the one whose libraries were checked (winit
/// would choose by itself, without heeding `-display`). A Windows preview
/// (`parent`) leaves its DPI awareness to the window it goes into.
pub fn use_backend<T>(builder: &mut EventLoopBuilder<T>, backend: Backend, parent: Option<u64>) {
    #[cfg(x11_platform)]
    {
        use winit::platform::wayland::EventLoopBuilderExtWayland;
        use winit::platform::x11::EventLoopBuilderExtX11;
        let _ = parent;
        match backend {
            Backend::X11 => builder.with_x11(),
            Backend::Wayland => builder.with_wayland(),
            Backend::Windows => builder,
        };
    }
    #[cfg(windows_platform)]
    {
        let _ = backend;
        if parent.is_some() {
            super::win32::embed::leave_dpi_to_the_parent(builder);
        }
    }
}

/// Why the event loop on `backend` could not start, in the saver's
/// words: which display or compositor was named and why it cannot be
/// reached, not a place in winit's source.
pub fn event_loop_failed(detail: &str, backend: Backend) -> SaverError {
    match backend {
        Backend::Wayland => SaverError::no_compositor(detail),
        #[cfg(x11_platform)]
        Backend::X11 => super::x11::connect::x_unreachable(detail),
        _ => SaverError::Other(without_source_place(detail)),
    }
}

/// `attrs` named "mountains" (the Wayland app_id and the X11 class, as
/// the desktop entry is named), drawn with X `visual` when given.
pub fn named(attrs: WindowAttributes, visual: Option<u32>) -> WindowAttributes {
    #[cfg(x11_platform)]
    {
        let attrs = winit::platform::wayland::WindowAttributesExtWayland::with_name(
            attrs,
            "mountains",
            "mountains",
        );
        match visual {
            Some(id) => attrs.with_x11_visual(id),
            None => attrs,
        }
    }
    #[cfg(windows_platform)]
    {
        let _ = visual;
        attrs
    }
}

/// The settings window's attributes on `backend`: owned by `owner` on
/// Windows (`/c:<HWND>`); on X11 the visual to draw with where the
/// screen's own is not one softbuffer takes (a 30- or 16-bit screen).
pub fn settings_attributes(
    attrs: WindowAttributes,
    backend: Backend,
    owner: Option<u64>,
) -> WindowAttributes {
    #[cfg(x11_platform)]
    {
        let _ = owner;
        let visual = (backend == Backend::X11)
            .then(super::x11::visual::drawable_visual)
            .flatten();
        match visual {
            Some(id) => attrs.with_x11_visual(id),
            None => attrs,
        }
    }
    #[cfg(windows_platform)]
    {
        use winit::platform::windows::WindowAttributesExtWindows;
        let _ = backend;
        // winit 0.30 takes the handle as an isize.
        match owner.and_then(|p| isize::try_from(p).ok()) {
            Some(hwnd) if hwnd != 0 => attrs.with_owner_window(hwnd),
            _ => attrs,
        }
    }
}

/// Why nothing can be drawn on `backend`'s screen (an X screen of 8-bit
/// visuals only), before a window opens there.
pub fn refusal(backend: Backend) -> Option<String> {
    #[cfg(x11_platform)]
    if backend == Backend::X11 {
        return super::x11::visual::refusal();
    }
    let _ = backend;
    None
}

/// Full-screen attributes covering `head` (on `monitor`, where winit
/// knows it) where the saver places its own windows: on X11
/// override-redirect windows, placed exactly where asked with and without
/// a window manager; on Windows borderless full screen on the monitor.
pub fn on_head(
    attrs: WindowAttributes,
    head: &Head,
    monitor: Option<&MonitorHandle>,
) -> WindowAttributes {
    use winit::dpi::{PhysicalPosition, PhysicalSize};
    let placed = |attrs: WindowAttributes| {
        attrs
            .with_position(PhysicalPosition::new(head.x, head.y))
            .with_inner_size(PhysicalSize::new(head.width, head.height))
    };
    #[cfg(x11_platform)]
    {
        let _ = monitor;
        placed(attrs.with_override_redirect(true))
    }
    #[cfg(windows_platform)]
    match monitor {
        Some(monitor) => attrs.with_fullscreen(Some(winit::window::Fullscreen::Borderless(Some(
            monitor.clone(),
        )))),
        None => placed(attrs),
    }
}

/// winit taps Alt for every window created full screen (Windows): a
/// full-screen saver must not take that key for a person's.
pub const FULLSCREEN_TAPS_ALT: bool = cfg!(windows_platform);

/// Keeps a full-screen `window` covering its monitor across display
/// changes, which winit does not follow (Windows); elsewhere nothing.
pub fn keep_covering(window: &Window) {
    #[cfg(windows_platform)]
    super::win32::fullscreen::keep_covering(window);
    let _ = window;
}

/// Replaces Xlib's bare exit when the X server goes away with a message
/// and a log line; nothing to do elsewhere.
pub fn report_when_the_server_goes() {
    #[cfg(x11_platform)]
    super::x11::server_gone::report_when_the_server_goes();
}
