//! Which window system the winit modes talk to on Linux and the BSDs: one
//! binary carries X11 and Wayland, both loaded at run time, and this picks
//! one from the environment before winit does (so that a missing library
//! or display is named in words, and `-display` means X11).

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

/// [`choose`] on this process's environment.
pub fn from_env(x_named: bool) -> Option<Backend> {
    let var = |name: &str| std::env::var(name).ok().filter(|v| !v.is_empty());
    let wayland = var("WAYLAND_DISPLAY").or_else(|| var("WAYLAND_SOCKET"));
    choose(wayland.as_deref(), var("DISPLAY").as_deref(), x_named)
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
}
