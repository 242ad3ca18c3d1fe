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

/// The X display `d` (`DISPLAY`'s value) as the user named it: `-display
/// :1` where the flag gave it, else `DISPLAY=":1"`.
pub fn display_as_named(d: &str) -> String {
    match super::options::x_display() {
        Some(named) if named == d => format!("-display {d}"),
        _ => format!("DISPLAY={d:?}"),
    }
}

impl SaverError {
    /// The X server of `$DISPLAY` went away.
    pub fn server_gone() -> Self {
        SaverError::ServerGone(std::env::var("DISPLAY").unwrap_or_else(|_| "?".into()))
    }

    /// The display could not be opened; says whether `DISPLAY` is unset or
    /// what it was, keeping only the last part of `detail`.
    pub fn no_display(detail: &str) -> Self {
        let reason = detail.rsplit(": ").next().unwrap_or(detail);
        match std::env::var("DISPLAY") {
            Ok(d) if !d.is_empty() => {
                SaverError::NoDisplay(format!("cannot open {}: {reason}", display_as_named(&d)))
            }
            _ => SaverError::NoDisplay("set DISPLAY (it is not set)".into()),
        }
    }

    /// The Wayland compositor could not be reached (`detail`: winit's
    /// words): which one was named and why, without winit's source place.
    pub fn no_compositor(detail: &str) -> Self {
        let reason = without_source_place(detail);
        let var = |name| std::env::var(name).ok().filter(|v: &String| !v.is_empty());
        SaverError::NoCompositor(match var("WAYLAND_DISPLAY") {
            Some(d) => format!("cannot connect to {d} (WAYLAND_DISPLAY): {reason}"),
            None => reason,
        })
    }
}

/// winit's error text without the place in winit's source where it was
/// made ("os error at /root/.cargo/registry/.../mod.rs:788: "), which
/// tells a user nothing.
pub fn without_source_place(text: &str) -> String {
    let place = text.find("os error at ").and_then(|start| {
        let file = start + text[start..].find(".rs:")?;
        let end = file + text[file..].find(": ")? + 2;
        Some((start, end))
    });
    match place {
        Some((start, end)) => format!("{}{}", &text[..start], &text[end..]),
        None => text.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn winit_s_place_in_its_source_is_left_out() {
        let winit = "os error at /root/.cargo/registry/src/index.crates.io-1949cf8c6b5b557f/\
                     winit-0.30.13/src/platform_impl/linux/mod.rs:788: Failed to open connection";
        assert_eq!(without_source_place(winit), "Failed to open connection");
        let wrapped = format!("cannot open a window: {winit}");
        assert_eq!(
            without_source_place(&wrapped),
            "cannot open a window: Failed to open connection"
        );
        assert_eq!(without_source_place("no place: here"), "no place: here");
    }
}
