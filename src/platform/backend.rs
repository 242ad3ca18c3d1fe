//! Which window system the winit modes talk to on Linux and the BSDs: one
//! binary carries X11 and Wayland, both loaded at run time, and this picks
//! one from the environment before winit does (so that a missing library
//! or display is named in words, and `-display` means X11).

use std::path::{Path, PathBuf};

/// A window system the winit modes can run on.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Backend {
    /// An X server (`$DISPLAY`), Xwayland included.
    X11,
    /// A Wayland compositor (`$WAYLAND_DISPLAY` or `$WAYLAND_SOCKET`).
    Wayland,
    /// Windows' own, the one window system there.
    Windows,
}

/// The window system to use, given the values of `WAYLAND_DISPLAY` (or
/// `WAYLAND_SOCKET`) and `DISPLAY` (empty counts as unset) and whether an X
/// display was named on the command line (`-display`). Wayland comes first,
/// as in winit: where a compositor runs, `DISPLAY` is usually its Xwayland,
/// which draws scaled outputs at a fraction of their pixels. `None`: neither.
pub fn choose(wayland: Option<&str>, display: Option<&str>, x_named: bool) -> Option<Backend> {
    let set = |v: Option<&str>| v.is_some_and(|v| !v.is_empty());
    match (set(wayland), set(display)) {
        (_, true) if x_named => Some(Backend::X11),
        (true, _) => Some(Backend::Wayland),
        (false, true) => Some(Backend::X11),
        (false, false) => None,
    }
}

/// [`choose`] on this process's environment, and why it passed over a
/// compositor, if it did: a `WAYLAND_DISPLAY` where none listens (left
/// from a session that ended, or carried into another) gives way to
/// `DISPLAY`, as winit's own choice would, rather than leave the screen
/// unprotected. A `WAYLAND_SOCKET` handed down is taken on trust.
pub fn from_env(x_named: bool) -> (Option<Backend>, Option<String>) {
    let var = |name: &str| std::env::var(name).ok().filter(|v| !v.is_empty());
    let display = var("DISPLAY");
    let socket = var("WAYLAND_SOCKET");
    let wayland = var("WAYLAND_DISPLAY").or_else(|| socket.clone());
    let chosen = choose(wayland.as_deref(), display.as_deref(), x_named);
    let (Some(Backend::Wayland), Some(x), None) = (chosen, &display, &socket) else {
        return (chosen, None);
    };
    let name = wayland.unwrap_or_default();
    let runtime = std::env::var_os("XDG_RUNTIME_DIR").map(PathBuf::from);
    match wayland_socket(&name, runtime.as_deref()) {
        Some(at) if listening(&at) => (chosen, None),
        at => {
            let place = at.map_or("XDG_RUNTIME_DIR is not set".into(), |at| {
                format!("nothing listens at {}", at.display())
            });
            let why = format!("WAYLAND_DISPLAY={name:?}: {place}; using the X display {x}");
            (Some(Backend::X11), Some(why))
        }
    }
}

/// Where the compositor `name` (`WAYLAND_DISPLAY`) listens, as
/// libwayland looks for it: the name itself if it is a path, else under
/// `runtime` (`XDG_RUNTIME_DIR`; none without it).
pub fn wayland_socket(name: &str, runtime: Option<&Path>) -> Option<PathBuf> {
    let path = Path::new(name);
    match path.is_absolute() {
        true => Some(path.to_path_buf()),
        false => runtime.map(|r| r.join(path)),
    }
}

/// Whether something takes a connection at the Unix socket `at`.
fn listening(at: &Path) -> bool {
    #[cfg(unix)]
    return std::os::unix::net::UnixStream::connect(at).is_ok();
    #[cfg(not(unix))]
    {
        let _ = at;
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn wayland_comes_first_unless_an_x_display_is_named() {
        assert_eq!(
            choose(Some("wayland-1"), Some(":0"), false),
            Some(Backend::Wayland)
        );
        assert_eq!(
            choose(Some("wayland-1"), Some(":0"), true),
            Some(Backend::X11)
        );
        assert_eq!(
            choose(Some("wayland-1"), None, false),
            Some(Backend::Wayland)
        );
        assert_eq!(choose(None, Some(":0"), false), Some(Backend::X11));
    }

    #[test]
    fn empty_values_count_as_unset() {
        assert_eq!(choose(Some(""), Some(":0"), false), Some(Backend::X11));
        assert_eq!(
            choose(Some("wayland-0"), Some(""), true),
            Some(Backend::Wayland)
        );
        assert_eq!(choose(Some(""), Some(""), false), None);
        assert_eq!(choose(None, None, true), None);
    }

    #[test]
    fn the_compositors_socket_is_under_the_runtime_folder_unless_a_path() {
        let run = Path::new("/run/user/1000");
        let at = wayland_socket("wayland-1", Some(run));
        assert_eq!(at, Some(run.join("wayland-1")));
        let own = wayland_socket("/tmp/w/wayland-9", Some(run));
        assert_eq!(own, Some(PathBuf::from("/tmp/w/wayland-9")));
        assert_eq!(wayland_socket("wayland-1", None), None);
    }

    #[cfg(unix)]
    #[test]
    fn a_socket_is_listening_only_while_someone_listens() {
        let dir = std::env::temp_dir().join(format!("mountains-wl-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        let at = dir.join("wayland-test");
        assert!(!listening(&at), "no socket yet");
        let listener = std::os::unix::net::UnixListener::bind(&at).unwrap();
        assert!(listening(&at));
        drop(listener);
        assert!(!listening(&at), "a socket left behind takes no connection");
        let _ = std::fs::remove_dir_all(&dir);
    }
}
