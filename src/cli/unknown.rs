//! An argument nothing takes: what it may have been meant as (a flag
//! cut short or misspelt, a word, a file given without its flag).

use std::path::Path;

use super::{UsageError, key_flags, output};
use crate::quote::clipped;
use crate::terrain::heightmap;

/// Our subcommand words.
pub(super) const WORDS: [&str; 2] = ["render", "heightmap"];

/// The flags `Parser::option` takes besides the keys' own, without their
/// dashes (each also works with two): the names a mistyped flag is
/// compared with.
pub(super) const FLAGS: [&str; 21] = [
    "config",
    "open",
    "set",
    "output",
    "size",
    "root",
    "window",
    "window-id",
    "layer",
    "settings",
    "help",
    "version",
    "xscreensaver-xml",
    "man-page",
    "fps",
    "no-fps",
    "delay",
    "display",
    "install",
    "visual",
    "check-config",
];

/// Our one-letter flags besides the Windows letters (which take any case).
const LETTERS: [&str; 3] = ["-o", "-h", "-V"];

/// Whether `arg` is one of the Windows letters with a slash (`/s`, `/p`,
/// `/c:1234`), not a file's path.
pub(super) fn is_windows_letter(arg: &str) -> bool {
    let Some(rest) = arg.strip_prefix('/') else {
        return false;
    };
    let letter = rest.split_once(':').map_or(rest, |(l, _)| l);
    letter.len() == 1 && "spcaSPCA".contains(letter)
}

/// Whether `s` is one of our subcommand words (not a window handle).
pub(super) fn is_word(s: &str) -> bool {
    WORDS.contains(&s)
}

/// An argument nothing takes, with the flag or word nearest to it
/// (`--colour`: `--color`), written with two dashes whatever was typed;
/// a mode word typed as a flag (`--render`: `render`), a flag typed as a
/// word (`help`: `--help`), and a file name on its own (`render out.png`:
/// `-o out.png`; a PNG that is there: `--open`) are offered as meant.
pub(super) fn unknown_argument(arg: &str) -> UsageError {
    // `-shadows false`, as some programs' flags take it: ours are on or
    // off by their names.
    if matches!(arg, "true" | "false") {
        return UsageError(format!(
            "unknown argument `{arg}`: an on/off flag takes no value: \
             -KEY turns it on, -no-KEY off (-shadows, -no-shadows)"
        ));
    }
    // `--colour=sonar` is compared by its flag, `color=sonar` is a `--set`.
    let name = arg.split_once('=').map_or(arg, |(name, _)| name);
    // A one-letter flag in the other case (`-v` for the version, `-O`):
    // too short for a misspelling to be measured, and typed so often.
    let letter = LETTERS.iter().find(|l| l.eq_ignore_ascii_case(name));
    let nearest = match name.strip_prefix('-') {
        Some(_) if letter.is_some() => letter.map(|l| l.to_string()),
        Some(flag) => {
            // Lowercased as the names are: `--OUT` begins `--output`.
            let bare = flag
                .trim_start_matches('-')
                .replace('_', "-")
                .to_lowercase();
            let names: Vec<String> = FLAGS
                .iter()
                .map(|f| f.to_string())
                .chain(key_flags::names())
                .collect();
            match is_word(&bare) {
                true => Some(bare),
                false => completed(&bare, &names)
                    .or_else(|| crate::spelling::nearest(&bare, &names))
                    .map(|f| format!("--{f}")),
            }
        }
        None if FLAGS.contains(&arg) => Some(format!("--{arg}")),
        None if name != arg && crate::settings::keys::find(name.trim()).is_some() => {
            Some(format!("--set {arg}"))
        }
        None if is_file_name(arg) => Some(match opens(arg) {
            true => format!("--open {arg}"),
            false => format!("-o {arg}"),
        }),
        None => crate::spelling::nearest(arg, WORDS).map(str::to_string),
    };
    UsageError(format!(
        "unknown argument `{}`{}",
        clipped(arg),
        crate::spelling::offer(nearest.as_deref())
    ))
}

/// The one name among `names` that `bare` begins (`out`: `output`), if
/// `bare` is long enough to be a name cut short and begins no other:
/// `--out` was offered `--set` (two letters changed) over `--output`.
fn completed<'a>(bare: &str, names: &'a [String]) -> Option<&'a String> {
    if bare.chars().count() < 3 {
        return None;
    }
    let mut begun = names.iter().filter(|name| name.starts_with(bare));
    let first = begun.next()?;
    begun.next().is_none().then_some(first)
}

/// Whether `arg` names a file `-o` or `--open` takes (by its extension).
fn is_file_name(arg: &str) -> bool {
    let ext = Path::new(arg)
        .extension()
        .map(|e| e.to_string_lossy().to_ascii_lowercase());
    let known = output::PICTURES.iter().chain(output::DATA_SETS);
    ext.is_some_and(|ext| known.map(|(e, _)| *e).any(|e| e == ext))
}

/// Whether `arg` is a data set that is there, as `--open` reads: a PNG
/// or raw samples.
fn opens(arg: &str) -> bool {
    let path = Path::new(arg);
    heightmap::named_as_data_set(path) && path.is_file()
}
