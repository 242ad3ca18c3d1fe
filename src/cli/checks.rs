//! What the command line must say as a whole, once every argument is
//! read: one mode, its output and size where it takes them, no option
//! it would pass over.

use std::path::{Path, PathBuf};

use super::{Invocation, Mode, UsageError, output};
use crate::render::Size;

/// A mode typed after another, each named as typed with its value (`--layer
/// top` after `--layer background`: both were `--layer`): the same mode
/// again is given once, two modes are chosen between.
pub(super) fn two_modes(
    (old_mode, old): (&Mode, &str),
    (new_mode, new): (&Mode, &str),
) -> UsageError {
    let same = std::mem::discriminant(old_mode) == std::mem::discriminant(new_mode);
    let what = match same {
        true => "give it once",
        false => "choose one mode",
    };
    UsageError(format!("`{new}` given after `{old}`: {what}"))
}

/// Why `mode` draws no slide show, if it draws none: the modes
/// xscreensaver never runs, whose options it never gives.
pub(super) fn no_slide_show(mode: &Mode) -> Option<&'static str> {
    match mode {
        Mode::Render { .. } => Some("render draws one picture to a file"),
        Mode::Heightmap { .. } => Some("heightmap writes one data set to a file"),
        Mode::CheckConfig(_) => Some(CHECKS_A_FILE_ONLY),
        Mode::Settings { .. } => Some("the settings screen takes -display alone of them"),
        mode => prints_only(mode),
    }
}

/// Why `--check-config` reads no data set and takes no option of a
/// slide show.
const CHECKS_A_FILE_ONLY: &str = "--check-config checks a preferences file only";

/// `--config A --check-config B` names two files where one is checked:
/// which one the user meant is not ours to guess (B was checked, A
/// passed over in silence).
pub(super) fn one_file_to_check(inv: &Invocation) -> Result<(), UsageError> {
    match (&inv.mode, &inv.config) {
        (Mode::CheckConfig(Some(file)), Some(config))
            if file != config && !crate::fsutil::same_file(file, config) =>
        {
            Err(UsageError(format!(
                "--check-config {} and --config {}: two files; give one",
                file.display(),
                config.display()
            )))
        }
        _ => Ok(()),
    }
}

/// `render --config X -o X` (or `heightmap`): the picture or data set
/// would replace the preferences file it was drawn with, as `--open X -o
/// X` would replace its data set. A data set typed after `--config` for
/// `--open` was lost so, with only a warning that it was no text. A
/// device (`--config /dev/null -o /dev/null`) is written to, not replaced,
/// and `-o -` is standard output.
pub(super) fn output_is_not_the_preferences(inv: &Invocation) -> Result<(), UsageError> {
    let (output, made) = match &inv.mode {
        Mode::Render { output, .. } => (output, "picture"),
        Mode::Heightmap { output } => (output, "data set"),
        _ => return Ok(()),
    };
    let Some(config) = inv.config.as_deref().filter(|_| output != Path::new("-")) else {
        return Ok(());
    };
    let regular = std::fs::metadata(config).is_ok_and(|m| m.is_file());
    if !regular || !crate::fsutil::same_file(config, output) {
        return Ok(());
    }
    Err(UsageError(format!(
        "-o {}: is the preferences file --config reads; give the {made} another name",
        output.display()
    )))
}

/// `--open` with a mode that shows no mountain (`--check-config`, the
/// settings screen, the printed files): the data set would be passed over
/// in silence, and `--check-config` said "ok" of a file it never read.
pub(super) fn nothing_to_open(inv: &Invocation) -> Result<(), UsageError> {
    let what = match &inv.mode {
        Mode::CheckConfig(_) => CHECKS_A_FILE_ONLY,
        Mode::Settings { .. } => "the settings screen opens data sets from its own list",
        mode => match prints_only(mode) {
            Some(why) => why,
            None => return Ok(()),
        },
    };
    let Some(open) = &inv.open else {
        return Ok(());
    };
    Err(UsageError(format!(
        "--open {}: no data set is opened here: {what}",
        open.display()
    )))
}

/// A preferences file (`--config`) or a key set (`--set`, a key's flag)
/// with a mode that only prints: it was passed over in silence, a set
/// unchecked, as `--open` was there. A bad set is refused before this,
/// in the words every mode says it in.
pub(super) fn nothing_to_set(inv: &Invocation) -> Result<(), UsageError> {
    let Some(why) = prints_only(&inv.mode) else {
        return Ok(());
    };
    if let Some(config) = &inv.config {
        return Err(UsageError(format!(
            "--config {}: no preferences are read here: {why}",
            config.display()
        )));
    }
    match inv.sets.first() {
        Some(set) => Err(UsageError(format!(
            "{}: no key is set here: {why}",
            set.typed
        ))),
        None => Ok(()),
    }
}

/// Why `mode` reads nothing a key or a data set could change, if it only
/// prints: a file (built from the key table, not from the preferences),
/// or `/a`'s one line.
fn prints_only(mode: &Mode) -> Option<&'static str> {
    match mode {
        Mode::XscreensaverXml | Mode::ManPage => Some("it prints a file and shows no mountain"),
        Mode::ChangePassword => Some("/a changes no password and shows no mountain"),
        _ => None,
    }
}

/// `-` for a preferences file (`--config -`, `--check-config -`), as
/// `--open -` and `-o -` take it for a pipe: no preferences are read from
/// standard input, and it was "no such file" or an unknown argument `-`.
/// A file named `-` is `./-`.
pub(super) fn no_standard_input(flag: &str, file: &std::ffi::OsStr) -> Result<(), UsageError> {
    if file != "-" {
        return Ok(());
    }
    Err(UsageError(format!(
        "{flag} -: preferences are read from a file, not from standard input \
         (a file named -: ./-)"
    )))
}

/// Fills in the output and size of the subcommands, and refuses them elsewhere.
pub(super) fn finish_mode(
    mode: Mode,
    output: Option<PathBuf>,
    size: Option<Size>,
) -> Result<Mode, UsageError> {
    match mode {
        Mode::Render { .. } => {
            let output = output.ok_or_else(|| UsageError("render needs -o FILE.png".into()))?;
            output::format_of(&output, output::PICTURES, "a picture")?;
            let size = size.unwrap_or(Size::new(1920, 1080));
            Ok(Mode::Render { size, output })
        }
        Mode::Heightmap { .. } => {
            let output = output.ok_or_else(|| UsageError("heightmap needs -o FILE.png".into()))?;
            output::format_of(&output, output::DATA_SETS, "a data set")?;
            if size.is_some() {
                return Err(UsageError(
                    "--size goes with render, not heightmap (use --set detail=N)".into(),
                ));
            }
            Ok(Mode::Heightmap { output })
        }
        _ if output.is_some() => Err(UsageError("-o goes with render or heightmap".into())),
        _ if size.is_some() => Err(UsageError("--size goes with render".into())),
        other => Ok(other),
    }
}
