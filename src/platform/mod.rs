//! The platform rooms: everything that knows X11, Wayland or Win32.
//!
//! `x11/`, `wayland/` and `win32/` each hold one window system's code;
//! `backend` picks X11 or Wayland, `libcheck` names a missing X or
//! Wayland library before winit panics on it, `single` keeps a second `/s`
//! off a display that has one.

pub mod backend;
pub mod libcheck;
#[cfg(target_os = "linux")]
pub mod single;
#[cfg(target_os = "linux")]
pub mod wayland;
pub mod win32;
#[cfg(unix)]
pub mod x11;
