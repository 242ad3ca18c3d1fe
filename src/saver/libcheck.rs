//! A friendly check for the X libraries winit loads at run time: winit
//! panics inside its loader when one is missing, so look first and name it.

#[cfg(unix)]
use super::error::SaverError;

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

/// The first library in `libraries` that `can_open` cannot open, with its package.
pub fn first_missing<'a>(
    libraries: &'a [(&'a str, &'a str)],
    can_open: impl Fn(&str) -> bool,
) -> Option<(&'a str, &'a str)> {
    libraries.iter().copied().find(|(name, _)| !can_open(name))
}

/// True when the dynamic loader can open `name`.
#[cfg(unix)]
pub fn can_dlopen(name: &str) -> bool {
    // SAFETY: these are the system X libraries winit itself is about to
    // load; their initialisers are the ones that run in any X program.
    unsafe { libloading::Library::new(name).is_ok() }
}

/// `$DISPLAY` and the libraries winit loads, checked before winit panics on them.
#[cfg(unix)]
pub fn check_x11() -> Result<(), SaverError> {
    if std::env::var_os("DISPLAY").is_none_or(|d| d.is_empty()) {
        return Err(SaverError::no_display(""));
    }
    match first_missing(X11_LIBRARIES, can_dlopen) {
        Some((library, package)) => Err(SaverError::MissingLibrary {
            library: library.into(),
            package: package.into(),
        }),
        None => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_the_first_missing_library_and_its_package() {
        let missing = first_missing(X11_LIBRARIES, |name| !name.starts_with("libxkbcommon"));
        assert_eq!(missing, Some(("libxkbcommon.so.0", "libxkbcommon0")));
        let (lib, pkg) = first_missing(X11_LIBRARIES, |n| n != "libxkbcommon-x11.so.0").unwrap();
        let error = SaverError::MissingLibrary {
            library: lib.into(),
            package: pkg.into(),
        };
        assert_eq!(
            error.to_string(),
            "missing X library libxkbcommon-x11.so.0: apt-get install libxkbcommon-x11-0"
        );
        assert_eq!(first_missing(X11_LIBRARIES, |_| true), None);
    }

    #[cfg(unix)]
    #[test]
    fn a_library_that_does_not_exist_cannot_be_opened() {
        assert!(!can_dlopen("libmountains-no-such-library.so.42"));
    }
}
