//! The Win32 room: foreign windows (the Screen Saver dialog's preview),
//! full-screen windows refitted after a display change, `host` (the winit
//! saver's Windows side), the parent's console and the time zone.

#[cfg(windows_platform)]
pub mod clock;
#[cfg(windows_platform)]
pub mod console;
#[cfg(windows_platform)]
pub mod display;
#[cfg(windows_platform)]
pub mod embed;
pub mod fullscreen;
#[cfg(windows_platform)]
pub mod host;
