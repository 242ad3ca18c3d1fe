//! The settings screen (`/c`, `--settings`): every preference on one side,
//! a live preview mountain on the other, drawn with our own framebuffer and
//! bitmap font, usable by keyboard alone and by mouse.
//!
//! `model` (state and inputs), `layout` (geometry, hit-testing; the
//! settings list's scrolling window: `list_view`), `values`
//! (widgets from the key table) and `draw` are pure and tested without a
//! window; `screen` ties them to files and the preview; `window` is the
//! winit + softbuffer shell.

pub mod draw;
pub mod editor;
pub mod font;
mod font_ascii;
mod font_latin1;
mod help;
mod input;
pub mod layout;
pub mod list_view;
pub mod model;
pub mod open_list;
pub mod preview;
pub mod screen;
pub mod values;
mod widgets;
pub mod window;
mod wrap;

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use crate::platform::{Backend, ModalOwner, window_exists};
use crate::settings::{load, paths};

/// Runs the settings screen for the preferences file `config` (else the
/// platform's), starting from `loaded`, on `backend`. `parent` owns the
/// window on Windows.
///
/// Without a handle (`/c`, no argument, `--settings`) there is no owner:
/// the foreground window is not borrowed, because it is as likely the
/// console, Explorer or the desktop as the Screen Saver dialog (which sends
/// `/c:HWND`), and disabling it would leave it dead if we were killed.
pub fn run(
    config: Option<&Path>,
    loaded: &load::Loaded,
    parent: Option<u64>,
    backend: Backend,
) -> ExitCode {
    let Some(path) = config_path(config, loaded) else {
        crate::console::error("no home directory: cannot find the preferences file");
        return ExitCode::FAILURE;
    };
    // `--set` shows over the file's values as changes not yet saved.
    let (from_file, shown) = (loaded.from_file.clone(), loaded.settings.clone());
    let problems = loaded.problems.clone();
    let make: window::MakeScreen = Box::new(move |size, scale| {
        screen::Screen::with_unsaved(from_file, shown, &problems, path, size, scale)
    });
    let owner = parent.filter(|&h| window_exists(h));
    let _modal = ModalOwner::disable(owner);
    match window::run(make, owner, backend) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            crate::log::error(&e);
            ExitCode::FAILURE
        }
    }
}

fn config_path(config: Option<&Path>, loaded: &load::Loaded) -> Option<PathBuf> {
    config
        .map(Path::to_path_buf)
        .or_else(|| loaded.file.clone())
        .or_else(paths::config_file)
}
