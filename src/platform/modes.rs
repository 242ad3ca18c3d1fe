//! The window modes that are one platform's own: drawing into a foreign
//! X window (`--root`, `--window-id`, `/p` with an X window id) and
//! wlr-layer-shell surfaces (`--layer`). Where a mode cannot be, it says
//! so in words.

use crate::cli::Layer;
use crate::mountain::Mountain;
use crate::saver::error::SaverError;
use crate::settings::Settings;

/// True where `/p HANDLE` opens a winit child of that window (Windows);
/// elsewhere the handle is an X window to draw in.
pub const PREVIEW_AS_CHILD: bool = cfg!(windows_platform);

/// Draws into the X window `window` (the root window when `None`).
pub fn run_embedded(
    window: Option<u64>,
    settings: Settings,
    opened: Option<Mountain>,
) -> Result<(), SaverError> {
    #[cfg(x11_platform)]
    {
        check_library("libxcb.so.1", "libxcb1")?;
        let window = match window {
            Some(id) => Some(u32::try_from(id).map_err(|_| {
                SaverError::Unsupported(format!("{id} is not an X window id (too large)"))
            })?),
            None => None,
        };
        super::x11::embed::run(window, settings, opened)
    }
    #[cfg(not(x11_platform))]
    {
        let _ = (window, settings, opened);
        Err(SaverError::Unsupported(
            "--root and --window-id need X11; on Windows use /s or /p".into(),
        ))
    }
}

/// `--layer`: wlr-layer-shell surfaces, on Linux (where the Wayland
/// libraries are loaded at run time).
pub fn run_layer(
    layer: Layer,
    settings: Settings,
    opened: Option<Mountain>,
) -> Result<(), SaverError> {
    #[cfg(layer_shell_platform)]
    return super::wayland::layer::run(layer, settings, opened);
    #[cfg(not(layer_shell_platform))]
    {
        let _ = (layer, settings, opened);
        Err(SaverError::Unsupported(
            "--layer needs a Wayland compositor with wlr-layer-shell (Linux)".into(),
        ))
    }
}

#[cfg(x11_platform)]
fn check_library(library: &str, package: &str) -> Result<(), SaverError> {
    if super::libcheck::can_dlopen(library) {
        return Ok(());
    }
    Err(SaverError::MissingLibrary {
        system: "X",
        library: library.into(),
        package: package.into(),
    })
}
