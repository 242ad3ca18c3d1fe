//! Command-line arguments: the Windows and xscreensaver protocols and our subcommands.
//!
//! Windows sends `/s`, `/p <HWND>`, `/c:<HWND>` (any case, `-` for `/`);
//! xscreensaver sends `--root` or `--window-id 0x...` (one or two dashes).
//! Our own flags are long (`--config`, `--set`); subcommands are words.

use std::path::PathBuf;

use crate::render::Size;
use crate::settings::load::Problem;

mod checks;
pub mod key_flags;
pub mod output;
mod parser;
mod unknown;
mod values;

use parser::long_name;
pub use parser::parse;
pub use values::{MAX_SIDE, parse_handle};

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
    /// `--layer NAME`: a wlr-layer-shell surface on every Wayland output
    /// (a desktop background, or swaylock-plugin's lock-screen background).
    Layer(Layer),
    /// `render -o FILE`: one complete mountain to a PNG.
    Render {
        /// Frame size in pixels.
        size: Size,
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
    /// `--help`, `-help`.
    Help,
    /// `--version`, `-V`.
    Version,
    /// `--xscreensaver-xml`: print xscreensaver's settings description.
    XscreensaverXml,
    /// `--man-page`: print the man page.
    ManPage,
}

/// The wlr-layer-shell layer `--layer` puts its surfaces on, bottom to top.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Layer {
    /// Under everything: a wallpaper, or swaylock-plugin's background.
    Background,
    /// Above the background, under windows.
    Bottom,
    /// Above windows, under full-screen ones.
    Top,
    /// Above everything, full-screen windows included.
    Overlay,
}

impl Layer {
    /// Each layer with the name `--layer` takes for it, bottom to top.
    pub const NAMES: [(&'static str, Layer); 4] = [
        ("background", Layer::Background),
        ("bottom", Layer::Bottom),
        ("top", Layer::Top),
        ("overlay", Layer::Overlay),
    ];

    /// The layer named `name` (as `--layer` takes it), if any.
    pub fn named(name: &str) -> Option<Layer> {
        Self::NAMES
            .iter()
            .find(|(n, _)| n.eq_ignore_ascii_case(name.trim()))
            .map(|&(_, l)| l)
    }
}

/// A parsed command line: the mode plus the options every mode shares.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Invocation {
    /// What to do.
    pub mode: Mode,
    /// `--config FILE`: preferences file instead of the platform default.
    pub config: Option<PathBuf>,
    /// Each `--set key=value` and key flag (`-seed 9`), in the order given.
    pub sets: Vec<Set>,
    /// `--open FILE`: show a saved heightmap instead of generating.
    pub open: Option<PathBuf>,
    /// The xscreensaver options every hack takes.
    pub xss: XssOptions,
    /// A key's flag or `--set` typed last with no value after it
    /// (`-seed`): `--check-config` says it beside its verdict of the file;
    /// every other mode refuses it before any work.
    pub unfinished: Option<Mistake>,
    /// Each `--set` that gives no key=value (`--set nokey`), in the order
    /// given: said and refused as [`Self::unfinished`] is.
    pub malformed: Vec<Mistake>,
}

/// A mistake typed that gives no set to check: a key's flag or `--set`
/// typed last, its value left out (`--check-config p.toml -seed`), or a
/// `--set` that gives no key=value (`--set nokey`).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Mistake {
    /// The flag, with its value if it took one, as typed.
    pub typed: String,
    /// Its refusal, in the words every mode says it in.
    pub refusal: UsageError,
    /// Where it was typed among the arguments (the index of its flag):
    /// mistakes are said in the order they were typed.
    pub at: usize,
}

/// One preference set for this run: a `--set key=value` or a key's own
/// flag, with how it was typed. The two travel together: a message about
/// a value names it as the user typed it (`-seed 9` is no `--set seed=9`
/// to the one who typed it).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Set {
    /// The key, as the key table names it (`low_detail`, not `low-detail`).
    pub key: String,
    /// The value, as given (a flag of a boolean gives `true` or `false`).
    pub value: String,
    /// The arguments that gave it, as typed (`-seed 9`, `--seed=9`,
    /// `--set seed=9`), each cut as every echo is.
    pub typed: String,
    /// Where it was typed among the arguments (the index of its flag):
    /// a bad one is said among the other mistakes in the order typed.
    pub at: usize,
}

impl Set {
    /// `problem`, the loader's about this set's key or value, named as
    /// the set was typed: a key's flag by the flag (`-color: "pink" is not
    /// allowed; ...`), a `--set` as the loader names one (`--set: key
    /// `color`: ...`).
    pub fn named_as_typed(&self, mut problem: Problem) -> Problem {
        if !self.by_set() {
            problem.source = self.flag().to_string();
            problem.key = None;
        }
        problem
    }

    /// Whether it was typed as a `--set` (any spelling), not a key's flag.
    pub fn by_set(&self) -> bool {
        long_name(self.flag()) == "--set"
    }

    /// The flag that gave it, as typed (`-seed` of `-seed 9`, `--seed` of
    /// `--seed=9`): no flag's name holds a space or an `=`.
    fn flag(&self) -> &str {
        self.typed.split([' ', '=']).next().unwrap_or_default()
    }
}

impl Invocation {
    /// Every set's key and value, in the order given, as
    /// [`crate::settings::load::resolve`] takes them.
    pub fn key_values(&self) -> Vec<(String, String)> {
        let pair = |set: &Set| (set.key.clone(), set.value.clone());
        self.sets.iter().map(pair).collect()
    }
}

/// xscreensaver's common options, which it may pass to any hack.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct XssOptions {
    /// `-fps`: draw the frame rate and load in a corner.
    pub fps: bool,
    /// `-delay N`: microseconds between frames, if given.
    pub delay_us: Option<u64>,
    /// `-display NAME`: the X display to use instead of `$DISPLAY`.
    pub display: Option<String>,
}

/// A command line that could not be understood; the message names the flag.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct UsageError(pub String);

/// The line said after what was typed wrong (a flag, a `--set`, a key's
/// flag), in every mode: where to read the rest. The usage itself would
/// push the message off a small terminal.
pub const SEE_HELP: &str = "`mountains --help` lists every mode, flag and key.";

impl std::fmt::Display for UsageError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

/// The mode used when no mode argument is given: Windows opens the settings
/// (that is what Configure sends), elsewhere a normal window.
pub fn default_mode() -> Mode {
    if crate::platform::os::SETTINGS_WITHOUT_A_MODE {
        Mode::Settings { parent: None }
    } else {
        Mode::Window
    }
}

#[cfg(test)]
mod tests {
    use std::ffi::OsString;

    use super::unknown::{FLAGS, WORDS};
    use super::values::NAMED_SIZES;
    use super::*;

    /// Every flag that is taken with nothing after it refuses a value
    /// after `=`, in either spelling (`--version=3` was taken as
    /// `--version`, its `3` dropped): [`NO_VALUE`] holds them all. Only
    /// `--check-config`'s file may be left out or given.
    #[test]
    fn a_flag_taken_without_a_value_refuses_one() {
        let parse = |args: &[String]| parse(&args.iter().map(OsString::from).collect::<Vec<_>>());
        for name in FLAGS.iter().filter(|&&n| n != "check-config") {
            for dashes in ["--", "-"] {
                let bare = format!("{dashes}{name}");
                if parse(std::slice::from_ref(&bare)).is_err() {
                    continue;
                }
                let given = parse(&[format!("{bare}=3")]);
                assert!(given.is_err(), "{bare}=3 was taken");
            }
        }
    }

    /// `--help` names every screen `--size` takes by name.
    #[test]
    fn the_help_names_every_named_size() {
        let help = crate::help::text();
        for (name, ..) in NAMED_SIZES {
            assert!(help.contains(name), "--help leaves out {name}");
        }
    }

    /// The names a mistyped flag is compared with are ones `parse` takes.
    #[test]
    fn every_name_offered_is_taken() {
        let flags = FLAGS.iter().map(|f| format!("--{f}"));
        for arg in flags.chain(WORDS.iter().map(|w| w.to_string())) {
            let args = [OsString::from(&arg), OsString::from("1")];
            // A flag that takes no value leaves the `1` unknown.
            if let Err(e) = parse(&args) {
                let unknown = format!("unknown argument `{arg}`");
                assert!(!e.0.contains(&unknown), "{e}");
            }
        }
    }
}
