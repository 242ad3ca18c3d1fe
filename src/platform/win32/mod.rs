//! The Win32 room: foreign windows (the Screen Saver dialog's preview)
//! and full-screen windows refitted after a display change.

#[cfg(windows)]
pub mod clock;
#[cfg(windows)]
pub mod console;
#[cfg(windows)]
pub mod embed;
pub mod fullscreen;
#[cfg(windows)]
pub mod host;
