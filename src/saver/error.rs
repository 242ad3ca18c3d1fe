//! Why a window mode could not run, worded for a person.

use std::fmt;

/// Why a window mode could not run, worded for a person.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum SaverError {
    /// `$DISPLAY` is unset or names no reachable X server.
    NoDisplay(String),
    /// Neither `$WAYLAND_DISPLAY` nor `$DISPLAY` is set.
    NoWindowSystem,
    /// `$WAYLAND_DISPLAY` names no reachable compositor.
    NoCompositor(String),
    /// A shared library winit needs is missing.
    MissingLibrary {
        /// The window system it belongs to: "X" or "Wayland".
        system: &'static str,
        /// The file name, e.g. `libxkbcommon-x11.so.0`.
        library: String,
        /// The Debian/Ubuntu package that provides it.
        package: String,
    },
    /// The window to draw into does not exist.
    NoSuchWindow(u32),
    /// The X server went away while the saver drew (the display's name).
    ServerGone(String),
    /// The mode is not a window mode, or not available on this platform.
    Unsupported(String),
    /// Anything else, already worded.
    Other(String),
}

impl fmt::Display for SaverError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SaverError::NoDisplay(why) => write!(f, "no X display: {why}"),
            SaverError::NoWindowSystem => f.write_str(
                "no display: set WAYLAND_DISPLAY (Wayland) or DISPLAY (X11); neither is set",
            ),
            SaverError::NoCompositor(why) => write!(f, "no Wayland compositor: {why}"),
            SaverError::MissingLibrary {
                system,
                library,
                package,
            } => write!(
                f,
                "missing {system} library {library}: apt-get install {package}"
            ),
            // Both spellings: the id may have been typed in either.
            SaverError::NoSuchWindow(id) => write!(f, "there is no X window 0x{id:x} ({id})"),
            SaverError::ServerGone(display) => write!(
                f,
                "the X server went away (display {display}): nothing left to draw on"
            ),
            SaverError::Unsupported(what) => f.write_str(what),
            SaverError::Other(what) => f.write_str(what),
        }
    }
}

impl std::error::Error for SaverError {}

impl SaverError {
    /// The X server of `$DISPLAY` went away.
    pub fn server_gone() -> Self {
        SaverError::ServerGone(std::env::var("DISPLAY").unwrap_or_else(|_| "?".into()))
    }

    /// The display could not be opened; says whether `DISPLAY` is unset or
    /// which display failed, keeping only the last part of `detail`.
    pub fn no_display(detail: &str) -> Self {
        let reason = detail.rsplit(": ").next().unwrap_or(detail);
        match std::env::var("DISPLAY") {
            Ok(d) if !d.is_empty() => SaverError::NoDisplay(format!("cannot open {d}: {reason}")),
            _ => SaverError::NoDisplay("set DISPLAY (it is not set)".into()),
        }
    }

    /// The display named by `DISPLAY` could not be reached.
    #[cfg(unix)]
    pub(crate) fn from_connect(e: x11rb::errors::ConnectError) -> Self {
        Self::no_display(&e.to_string())
    }
}
