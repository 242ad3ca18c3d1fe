//! The Win32 room: foreign windows (the Screen Saver dialog's preview)
//! and full-screen windows refitted after a display change.

#[cfg(windows)]
pub mod display;
#[cfg(windows)]
pub mod embed;
pub mod fullscreen;
