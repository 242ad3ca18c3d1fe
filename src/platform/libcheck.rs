//! A friendly check for the X and Wayland libraries winit loads at run
//! time: winit panics inside its loader when one is missing (or says only
//! "not available"), so look first and name it.

#[cfg(any(x11_platform, wayland_platform))]
use super::backend::{self, Backend};
#[cfg(any(x11_platform, wayland_platform))]
use crate::saver::error::SaverError;

/// Each library winit and softbuffer open under X11, and the Debian/Ubuntu package holding it.
pub const X11_LIBRARIES: &[(&str, &str)] = &[
    ("libX11.so.6", "libx11-6"),
    ("libX11-xcb.so.1", "libx11-xcb1"),
    ("libxcb.so.1", "libxcb1"),
    ("libXcursor.so.1", "libxcursor1"),
    ("libXi.so.6", "libxi6"),
    ("libxkbcommon.so.0", "libxkbcommon0"),
    ("libxkbcommon-x11.so.0", "libxkbcommon-x11-0"),
];

/// libwayland-client, the one library `--layer` opens (it reads no keys).
pub const WAYLAND_CLIENT: (&str, &str) = ("libwayland-client.so.0", "libwayland-client0");

/// Each library winit and softbuffer open under Wayland, and its package.
pub const WAYLAND_LIBRARIES: &[(&str, &str)] =
    &[WAYLAND_CLIENT, ("libxkbcommon.so.0", "libxkbcommon0")];

/// The first library in `libraries` that `can_open` cannot open, with its package.
pub fn first_missing<'a>(
    libraries: &'a [(&'a str, &'a str)],
    can_open: impl Fn(&str) -> bool,
) -> Option<(&'a str, &'a str)> {
    libraries.iter().copied().find(|(name, _)| !can_open(name))
}

/// True when the dynamic loader can open `name`.
#[cfg(any(x11_platform, wayland_platform))]
pub fn can_dlopen(name: &str) -> bool {
    // SAFETY: these are the system X libraries winit itself is about to
    // load; their initialisers are the ones that run in any X program.
    unsafe { libloading::Library::new(name).is_ok() }
}

/// The window system the winit modes will use (X11 when `x_named`, i.e.
/// `-display` was given, else Wayland first), after checking that its
/// libraries can be loaded.
#[cfg(any(x11_platform, wayland_platform))]
pub fn check_display(x_named: bool) -> Result<Backend, SaverError> {
    let (chosen, passed_over) = backend::from_env(x_named);
    if let Some(why) = passed_over {
        crate::log::warn(&format!("warning: no Wayland compositor: {why}"));
    }
    let chosen = chosen.ok_or(SaverError::NoWindowSystem)?;
    match chosen {
        Backend::X11 => check_libraries("X", X11_LIBRARIES)?,
        Backend::Wayland => check_libraries("Wayland", WAYLAND_LIBRARIES)?,
        Backend::Windows => {}
    }
    Ok(chosen)
}

/// `--layer`: libwayland-client, checked before the connection (which
/// would say only that a library is missing, not which package has it).
#[cfg(any(x11_platform, wayland_platform))]
pub fn check_wayland_client() -> Result<(), SaverError> {
    check_libraries("Wayland", &[WAYLAND_CLIENT])
}

#[cfg(any(x11_platform, wayland_platform))]
fn check_libraries(system: &'static str, libraries: &[(&str, &str)]) -> Result<(), SaverError> {
    match first_missing(libraries, can_dlopen) {
        Some((library, package)) => Err(SaverError::MissingLibrary {
            system,
            library: library.into(),
            package: package.into(),
        }),
        None => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::saver::error::SaverError;

    #[test]
    fn names_the_first_missing_library_and_its_package() {
        let missing = first_missing(X11_LIBRARIES, |name| !name.starts_with("libxkbcommon"));
        assert_eq!(missing, Some(("libxkbcommon.so.0", "libxkbcommon0")));
        let (lib, pkg) = first_missing(X11_LIBRARIES, |n| n != "libxkbcommon-x11.so.0").unwrap();
        let error = SaverError::MissingLibrary {
            system: "X",
            library: lib.into(),
            package: pkg.into(),
        };
        assert_eq!(
            error.to_string(),
            "missing X library libxkbcommon-x11.so.0: apt-get install libxkbcommon-x11-0"
        );
        assert_eq!(first_missing(X11_LIBRARIES, |_| true), None);
        let (lib, pkg) =
            first_missing(WAYLAND_LIBRARIES, |n| !n.starts_with("libwayland")).unwrap();
        let error = SaverError::MissingLibrary {
            system: "Wayland",
            library: lib.into(),
            package: pkg.into(),
        };
        assert_eq!(
            error.to_string(),
            "missing Wayland library libwayland-client.so.0: apt-get install libwayland-client0"
        );
    }

    #[cfg(any(x11_platform, wayland_platform))]
    #[test]
    fn a_library_that_does_not_exist_cannot_be_opened() {
        assert!(!can_dlopen("libmountains-no-such-library.so.42"));
    }
}
