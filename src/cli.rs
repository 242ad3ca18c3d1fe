//! Command-line arguments: the Windows and xscreensaver protocols and our subcommands.
//!
//! STUB: the types are final; parsing is being written.

use std::path::PathBuf;

/// What the program was asked to do.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Mode {
    /// `/s`: full screen on every monitor, ends on input.
    Fullscreen,
    /// `/p <HWND>`: preview inside a foreign Windows window; `/p` alone: a small window.
    Preview {
        /// The parent window handle, when one was given.
        parent: Option<u64>,
    },
    /// `/c`, `--settings`: the settings screen, optionally modal to a window.
    Settings {
        /// The window the dialog belongs to, when one was given.
        parent: Option<u64>,
    },
    /// `/a`: Windows 95 password change; not needed.
    ChangePassword,
    /// `--root`: draw into `$XSCREENSAVER_WINDOW`, else the root window.
    XRoot,
    /// `--window-id ID`: draw into a window another process owns.
    XWindowId(u64),
    /// `--window` (and no argument outside Windows): a normal resizable window.
    Window,
    /// `render -o FILE`: one complete mountain to a PNG.
    Render {
        /// Frame size in pixels.
        width: u32,
        /// Frame height in pixels.
        height: u32,
        /// Where the PNG goes.
        output: PathBuf,
    },
    /// `heightmap -o FILE`: generate and save a data set.
    Heightmap {
        /// Where the PNG goes.
        output: PathBuf,
    },
    /// `--check-config [PATH]`: validate a preferences file.
    CheckConfig(Option<PathBuf>),
    /// `--help`.
    Help,
}

/// A parsed command line: the mode plus the options every mode shares.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Invocation {
    /// What to do.
    pub mode: Mode,
    /// `--config FILE`: preferences file instead of the platform default.
    pub config: Option<PathBuf>,
    /// `--set key=value`, in the order given.
    pub sets: Vec<(String, String)>,
    /// `--open FILE`: show a saved heightmap instead of generating.
    pub open: Option<PathBuf>,
}
