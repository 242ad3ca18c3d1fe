//! Command-line arguments: the Windows and xscreensaver protocols and our subcommands.
//!
//! Windows sends `/s`, `/p <HWND>`, `/c:<HWND>` (any case, `-` for `/`);
//! xscreensaver sends `--root` or `--window-id 0x...` (one or two dashes).
//! Our own flags are long (`--config`, `--set`); subcommands are words.

use std::ffi::OsString;
use std::path::{Path, PathBuf};

use crate::quote::clipped;
use crate::render::Size;
use crate::settings::load::Problem;
use crate::terrain::heightmap;

pub mod key_flags;
pub mod output;

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

/// Parses the arguments after the program name.
pub fn parse(args: &[OsString]) -> Result<Invocation, UsageError> {
    let mut p = Parser {
        args,
        pos: 0,
        files: Vec::new(),
        shared: Vec::new(),
        bad_value: None,
        raw_inline: None,
        inv: Invocation {
            mode: default_mode(),
            config: None,
            sets: Vec::new(),
            open: None,
            xss: XssOptions::default(),
            unfinished: None,
            malformed: Vec::new(),
        },
    };
    let read = p.arguments();
    // A bad `--set` or key flag, or one without its value, waits for the
    // mode: `--check-config` says it beside the file's verdict
    // (refused here, the file went unchecked); every other mode refuses
    // it, as the first mistake typed.
    match (p.bad_value.take(), read) {
        (Some(_), Ok(())) if matches!(p.inv.mode, Mode::CheckConfig(_)) => Ok(p.inv),
        (Some(bad), _) => Err(bad),
        (None, read) => read.map(|()| p.inv),
    }
}

impl Parser<'_> {
    /// Reads every argument into `self.inv`, its mode last.
    fn arguments(&mut self) -> Result<(), UsageError> {
        let mut mode: Option<(Mode, String)> = None;
        let mut output: Option<PathBuf> = None;
        let mut size: Option<Size> = None;
        while let Some(arg) = self.next_str()? {
            let from = self.pos - 1;
            let new_mode = match self.option(&arg, &mut output, &mut size)? {
                Some(m) => m,
                None => continue,
            };
            // `mountains render --help` asks about the program, as it would of
            // most commands: it is answered, whatever mode came before.
            if matches!(new_mode, Mode::Help | Mode::Version) {
                self.inv.mode = new_mode;
                return Ok(());
            }
            let typed = self.typed_since(from);
            mode = Some(match mode {
                None => (new_mode, typed),
                Some((old_mode, old)) => match (old_mode, new_mode) {
                    // What xscreensaver's settings dialog runs for its preview.
                    (Mode::XRoot, id @ Mode::XWindowId(_))
                    | (id @ Mode::XWindowId(_), Mode::XRoot) => (id, typed),
                    (old_mode, new_mode) => {
                        return Err(two_modes((&old_mode, &old), (&new_mode, &typed)));
                    }
                },
            });
        }
        let mode = mode.map_or_else(default_mode, |(m, _)| m);
        self.inv.mode = finish_mode(mode, output, size)?;
        one_file_to_check(&self.inv)?;
        output_is_not_the_preferences(&self.inv)?;
        nothing_to_open(&self.inv)?;
        nothing_to_set(&self.inv)?;
        self.nothing_for_xscreensaver()
    }

    /// xscreensaver's shared options (`-fps`, `-delay`, `-display`,
    /// `-install`, `-visual`) beside a mode that draws no slide show:
    /// xscreensaver passes them to the slide show's modes alone, so there
    /// they are a slip, and they were passed over in silence. The settings
    /// screen takes `-display`, the X display its window opens on.
    fn nothing_for_xscreensaver(&self) -> Result<(), UsageError> {
        self.no_x_display_for_layer()?;
        let Some(why) = no_slide_show(&self.inv.mode) else {
            return Ok(());
        };
        let settings = matches!(self.inv.mode, Mode::Settings { .. });
        let taken = |name: &str| settings && name == "display";
        match self.shared.iter().find(|(name, _)| !taken(name)) {
            Some((_, typed)) => Err(UsageError(format!(
                "{typed}: xscreensaver's option does nothing here: {why}"
            ))),
            None => Ok(()),
        }
    }

    /// `-display` beside `--layer`, which draws on Wayland alone: the X
    /// display it names was passed over in silence.
    fn no_x_display_for_layer(&self) -> Result<(), UsageError> {
        if !matches!(self.inv.mode, Mode::Layer(_)) {
            return Ok(());
        }
        match self.shared.iter().find(|(name, _)| name == "display") {
            Some((_, typed)) => Err(UsageError(format!(
                "{typed}: --layer draws on Wayland, never on an X display"
            ))),
            None => Ok(()),
        }
    }
}

/// A mode typed after another, each named as typed with its value (`--layer
/// top` after `--layer background`: both were `--layer`): the same mode
/// again is given once, two modes are chosen between.
fn two_modes((old_mode, old): (&Mode, &str), (new_mode, new): (&Mode, &str)) -> UsageError {
    let same = std::mem::discriminant(old_mode) == std::mem::discriminant(new_mode);
    let what = match same {
        true => "give it once",
        false => "choose one mode",
    };
    UsageError(format!("`{new}` given after `{old}`: {what}"))
}

/// Why `mode` draws no slide show, if it draws none: the modes
/// xscreensaver never runs, whose options it never gives.
fn no_slide_show(mode: &Mode) -> Option<&'static str> {
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
fn one_file_to_check(inv: &Invocation) -> Result<(), UsageError> {
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
fn output_is_not_the_preferences(inv: &Invocation) -> Result<(), UsageError> {
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
fn nothing_to_open(inv: &Invocation) -> Result<(), UsageError> {
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
fn nothing_to_set(inv: &Invocation) -> Result<(), UsageError> {
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
fn no_standard_input(flag: &str, file: &std::ffi::OsStr) -> Result<(), UsageError> {
    if file != "-" {
        return Ok(());
    }
    Err(UsageError(format!(
        "{flag} -: preferences are read from a file, not from standard input \
         (a file named -: ./-)"
    )))
}

/// The flags that take no value (as they are matched: see `long_name`).
const NO_VALUE: [&str; 17] = [
    "--version",
    "-V",
    "-version",
    "--root",
    "--window",
    "--settings",
    "--xscreensaver-xml",
    "--man-page",
    "--help",
    "-h",
    "-help",
    "-fps",
    "--fps",
    "-no-fps",
    "--no-fps",
    "-install",
    "--install",
];

/// Fills in the output and size of the subcommands, and refuses them elsewhere.
fn finish_mode(
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

struct Parser<'a> {
    args: &'a [OsString],
    pos: usize,
    /// Each file flag given so far (by its long name) and how it was typed:
    /// what a second one of it is refused with.
    files: Vec<(&'static str, String)>,
    /// Each of xscreensaver's shared options given (`-fps`, `-delay 5`),
    /// by its name without dashes and as typed: what a mode that takes
    /// none of them refuses.
    shared: Vec<(String, String)>,
    /// The refusal of the first `--set` or key flag whose key or value is
    /// bad (`-color pink`), of a `--set` that gives no key=value, or of a
    /// key flag or `--set` typed last without its value (`-seed`): see
    /// [`parse`] for when it is said.
    bad_value: Option<UsageError>,
    /// The file name typed after `=` in the argument being read, where it
    /// is not valid text (`--config=NAME`): what [`Self::take`] gives in
    /// place of the text the argument is read by.
    raw_inline: Option<OsString>,
    inv: Invocation,
}

/// One option as typed, what the parts of `Parser::option` read it by.
struct Flag<'a> {
    /// The argument as typed (`-o`, `--seed=5`): what a message names.
    arg: &'a str,
    /// Its name as matched (see `long_name`), without a value after `=`.
    name: String,
    /// The value typed after `=`, if one was.
    inline: Option<String>,
    /// Where it was in the arguments: with what it takes after it, the
    /// option as typed (see `Parser::typed_since`).
    from: usize,
}

impl<'a> Flag<'a> {
    /// `arg`, found at `from`. `--seed=5`, and with one dash as
    /// xscreensaver's flags are typed (`-seed=5`, `-config=FILE`), is
    /// taken as `-seed 5` is.
    fn read(arg: &'a str, from: usize) -> Self {
        let (name, inline) = match arg.split_once('=') {
            Some((f, v)) if f.len() > 1 && f.starts_with('-') => {
                (long_name(f), Some(v.to_string()))
            }
            _ => (long_name(arg), None),
        };
        Flag {
            arg,
            name,
            inline,
            from,
        }
    }

    /// The flag as typed, without a value given after `=` (`-layer` of
    /// `-layer=top`).
    fn typed_name(&self) -> &'a str {
        match &self.inline {
            Some(v) => &self.arg[..self.arg.len() - v.len() - 1],
            None => self.arg,
        }
    }
}

impl Parser<'_> {
    fn next_os(&mut self) -> Option<&OsString> {
        let a = self.args.get(self.pos);
        self.pos += 1;
        a
    }

    /// The next argument as text. A file flag's name typed after `=`
    /// need not be text: it is kept in `raw_inline`, and the argument read
    /// with its text in its place.
    fn next_str(&mut self) -> Result<Option<String>, UsageError> {
        self.raw_inline = None;
        let Some(a) = self.next_os() else {
            return Ok(None);
        };
        if let Some(s) = a.to_str() {
            return Ok(Some(s.to_string()));
        }
        match crate::platform::os::split_at_equals(a) {
            Some((flag, name)) if FILE_NAME_FLAGS.contains(&long_name(&flag).as_str()) => {
                let typed = format!("{flag}={}", name.to_string_lossy());
                self.raw_inline = Some(name);
                Ok(Some(typed))
            }
            _ => Err(UsageError(format!("argument {a:?} is not valid text"))),
        }
    }

    fn value(&mut self, flag: &str) -> Result<OsString, UsageError> {
        self.next_os()
            .cloned()
            .ok_or_else(|| UsageError(format!("{flag} needs a value")))
    }

    /// The value given after `=` (`inline`), else the next argument.
    fn inline_or_next(&mut self, inline: Option<String>, flag: &str) -> Result<String, UsageError> {
        inline.map_or_else(|| self.value_str(flag), Ok)
    }

    fn value_str(&mut self, flag: &str) -> Result<String, UsageError> {
        let v = self.value(flag)?;
        v.into_string()
            .map_err(|v| UsageError(format!("{flag}: {v:?} is not valid text")))
    }

    /// A window handle for `flag` may follow as the next argument (`/p
    /// 1234`); a word that is not a flag is taken as one (`/p abc` says it
    /// is no handle).
    fn optional_handle(&mut self, flag: &str) -> Result<Option<u64>, UsageError> {
        match self.args.get(self.pos).and_then(|a| a.to_str()) {
            Some(s) if !s.is_empty() && !s.starts_with(['-', '/']) && !is_word(s) => {
                self.pos += 1;
                handle_for(flag, s).map(Some)
            }
            _ => Ok(None),
        }
    }

    /// Handles one argument: a shared option (returns `None`) or a mode.
    fn option(
        &mut self,
        arg: &str,
        output: &mut Option<PathBuf>,
        size: &mut Option<Size>,
    ) -> Result<Option<Mode>, UsageError> {
        if let Some(mode) = self.windows_flag(arg)? {
            return Ok(Some(mode));
        }
        let flag = Flag::read(arg, self.pos - 1);
        // `-root=1` dropped its value, as `--fps=false` had.
        if flag.inline.is_some() && NO_VALUE.contains(&flag.name.as_str()) {
            return Err(UsageError(format!("{} takes no value", flag.name)));
        }
        if self.file_flag(&flag, output, size)? {
            return Ok(None);
        }
        if let Some(mode) = self.mode_flag(&flag)? {
            return Ok(Some(mode));
        }
        if self.xscreensaver_option(&flag)? {
            return Ok(None);
        }
        // `--cragginess=40`: a key's flag takes `--flag=VALUE` as the
        // file flags do (`--output=x.png`).
        match flag.inline {
            Some(v) if key_flags::lookup(&flag.name).is_some() => {
                self.key_flag_with(&flag.name, Some(v), flag.from)
            }
            _ => self.key_flag(arg, flag.from),
        }
        .map(|()| None)
    }

    /// The value `flag` takes (named `long`, as `--output` for `-o`), as
    /// typed after `=` or as the next argument.
    fn take(&mut self, flag: &Flag, long: &str) -> Result<OsString, UsageError> {
        let arg = flag.arg;
        let v = match &flag.inline {
            Some(v) => self.raw_inline.take().unwrap_or_else(|| OsString::from(v)),
            None => self.value(arg)?,
        };
        // `render -o --help` wrote a picture named `--help`: a flag
        // where a file or key=value belongs is a slip, not a name
        // (`-` alone is standard output).
        if flag.inline.is_none() && v.len() > 1 && v.to_string_lossy().starts_with('-') {
            return Err(UsageError(format!(
                "{arg} needs a value, not the flag `{}` (a value that starts with `-`: write {long}={0})",
                clipped(&v.to_string_lossy())
            )));
        }
        if v.is_empty() {
            let wanted = match long {
                "--set" => "give key=value",
                "--size" => "give WIDTHxHEIGHT, e.g. 1920x1080",
                _ => "give a file name",
            };
            return Err(UsageError(format!("{arg}: an empty value; {wanted}")));
        }
        Ok(v)
    }

    /// The flags that take a file or a value of this run's own
    /// (`--config`, `--open`, `--set`, `-o`, `--size`); whether `flag`
    /// was one.
    fn file_flag(
        &mut self,
        flag: &Flag,
        output: &mut Option<PathBuf>,
        size: &mut Option<Size>,
    ) -> Result<bool, UsageError> {
        match flag.name.as_str() {
            "--config" => {
                let file = self.take(flag, "--config")?;
                no_standard_input("--config", &file)?;
                self.once("--config", "preferences file", self.typed_since(flag.from))?;
                self.inv.config = Some(file.into());
            }
            "--open" => {
                let file = self.take(flag, "--open")?;
                self.once("--open", "data set", self.typed_since(flag.from))?;
                self.inv.open = Some(file.into());
            }
            "--set" => self.set(flag)?,
            "-o" | "--output" => {
                let file = self.take(flag, "--output")?;
                self.once("--output", "output file", self.typed_since(flag.from))?;
                *output = Some(file.into());
            }
            "--size" => {
                let text = self.take(flag, "--size")?;
                // Ours alone (no X toolkit convention, nothing we ship
                // repeats it): a second one is a slip, refused as the
                // file flags' are. `-delay` and `-display` stay last-wins.
                self.once("--size", "size", self.typed_since(flag.from))?;
                *size = Some(parse_size(&text.to_string_lossy())?);
            }
            _ => return Ok(false),
        }
        Ok(true)
    }

    /// `--set key=value`: a set checked as a key's flag is (see
    /// [`Self::check_the_last_set`]). One that gives no key=value, or
    /// none at all, is held as a key's flag with a bad value or none is
    /// (see [`parse`] for when it is said).
    fn set(&mut self, flag: &Flag) -> Result<(), UsageError> {
        let unfinished = flag.inline.is_none() && self.pos >= self.args.len();
        let kv = match self.take(flag, "--set").and_then(key_value) {
            Ok(kv) => kv,
            Err(refusal) if unfinished => {
                self.hold_unfinished(flag.from, refusal);
                return Ok(());
            }
            Err(refusal) => {
                self.hold_malformed(flag.from, refusal);
                return Ok(());
            }
        };
        self.push_set(kv, flag.from);
        self.check_the_last_set();
        Ok(())
    }

    /// The mode `flag` names, if it names one (the Windows letters are
    /// read before it, by [`Self::windows_flag`]).
    fn mode_flag(&mut self, flag: &Flag) -> Result<Option<Mode>, UsageError> {
        let arg = flag.arg;
        let mode = match flag.name.as_str() {
            "--root" => Mode::XRoot,
            "--window" => Mode::Window,
            // A value is named as it was typed (`--layer=foo`, `--layer
            // foo`): `--layer=foo foo` named it twice.
            "--layer" => {
                let name = self.inline_or_next(flag.inline.clone(), arg)?;
                Mode::Layer(layer_named(&self.typed_since(flag.from), &name)?)
            }
            "--window-id" => {
                let id = self.inline_or_next(flag.inline.clone(), arg)?;
                let typed = self.typed_since(flag.from);
                Mode::XWindowId(x_window_id(flag.typed_name(), &typed, &id)?)
            }
            "--settings" => Mode::Settings { parent: None },
            "--help" | "-h" | "-help" => Mode::Help,
            "--version" | "-V" | "-version" => Mode::Version,
            "--xscreensaver-xml" => Mode::XscreensaverXml,
            "--man-page" => Mode::ManPage,
            "--check-config" => Mode::CheckConfig(self.file_to_check(flag)?),
            "render" => Mode::Render {
                size: Size::default(),
                output: PathBuf::new(),
            },
            "heightmap" => Mode::Heightmap {
                output: PathBuf::new(),
            },
            _ => return Ok(None),
        };
        Ok(Some(mode))
    }

    /// `--check-config`'s file, which may be left out (the usual file):
    /// a next argument that starts with a dash is a flag, not the file.
    fn file_to_check(&mut self, flag: &Flag) -> Result<Option<PathBuf>, UsageError> {
        // Read as text only to be tested, and taken as it is: a file's name
        // need not be valid text (`--config` takes such a name; here it was
        // passed over, then refused as "not valid text").
        let next_name = self.args.get(self.pos).cloned();
        let next_text = next_name.as_ref().map(|a| a.to_string_lossy());
        let next = next_text.as_deref();
        // `--check-config ""` (an unset variable in a script) as
        // `--check-config=`: a bad value, not a file that is missing.
        let inline = flag.inline.as_deref();
        let (empty_inline, empty_next) = (inline == Some(""), next == Some(""));
        if empty_inline || (inline.is_none() && empty_next) {
            return Err(UsageError(format!(
                "{}: an empty value; give a file name, or none for the usual file",
                flag.arg
            )));
        }
        if inline.or(next) == Some("-") {
            no_standard_input("--check-config", "-".as_ref())?;
        }
        let file = match (inline, next) {
            (Some(v), _) => Some(
                self.raw_inline
                    .take()
                    .map_or_else(|| v.into(), PathBuf::from),
            ),
            (None, Some(next)) if !next.starts_with('-') => {
                self.pos += 1;
                next_name.map(PathBuf::from)
            }
            _ => None,
        };
        self.one_file_checked(flag)?;
        Ok(file)
    }

    /// A second file after `--check-config`'s (`--check-config a.toml
    /// b.toml`, as a shell's `*.toml` gives them): it checks one, and the
    /// second was "unknown argument", with no word of why.
    fn one_file_checked(&self, flag: &Flag) -> Result<(), UsageError> {
        let Some(next) = self.args.get(self.pos).map(|a| a.to_string_lossy()) else {
            return Ok(());
        };
        if next.is_empty() || next.starts_with('-') || is_word(&next) || is_windows_letter(&next) {
            return Ok(());
        }
        Err(UsageError(format!(
            "`{}` given after `{}`: --check-config checks one file; run it once for each",
            clipped(&next),
            self.typed_since(flag.from)
        )))
    }

    /// The options xscreensaver may pass to any hack (`-fps`, `-delay`,
    /// `-display`, `-install`, `-visual`); whether `flag` was one.
    fn xscreensaver_option(&mut self, flag: &Flag) -> Result<bool, UsageError> {
        let name = flag.name.as_str();
        match name {
            "-fps" | "--fps" => self.inv.xss.fps = true,
            "-no-fps" | "--no-fps" => self.inv.xss.fps = false,
            // X toolkit programs, xscreensaver's hacks among them, take the
            // last of a repeated option (XrmParseCommand puts each into the
            // resource database in order, a later one over an earlier), and
            // a command line edited in xscreensaver's settings may keep the
            // `-delay` it had and gain one: it and `-display` stay last-wins.
            "-delay" | "--delay" => {
                let v = self.inline_or_next(flag.inline.clone(), name)?;
                let us = v.trim().parse::<u64>().map_err(|e| {
                    // A number of more digits than any delay was said not to
                    // be a number of microseconds at all.
                    let why = match e.kind() {
                        std::num::IntErrorKind::PosOverflow => "too large: microseconds",
                        _ => "expected microseconds",
                    };
                    UsageError(format!(
                        "`{name} {}`: {why} between frames, e.g. -delay 20000",
                        clipped(&v)
                    ))
                })?;
                self.inv.xss.delay_us = Some(us);
            }
            "-display" | "--display" => {
                let display = self.inline_or_next(flag.inline.clone(), name)?;
                // An empty name emptied DISPLAY: the run was then said to
                // have no display set at all, or went to Wayland.
                if display.trim().is_empty() {
                    return Err(UsageError(format!(
                        "{name}: an empty value; give an X display, e.g. -display :0"
                    )));
                }
                self.inv.xss.display = Some(display);
            }
            // xscreensaver's colormap and visual choices: a true-colour
            // framebuffer needs neither.
            "-install" | "--install" => {}
            "-visual" | "--visual" => {
                self.inline_or_next(flag.inline.clone(), name)?;
            }
            _ => return Ok(false),
        }
        let bare = name.trim_start_matches('-').to_string();
        self.shared.push((bare, self.typed_since(flag.from)));
        Ok(true)
    }

    /// Records the file flag `long` (naming `what`), typed as `typed`;
    /// refuses it if it was given before. Last-wins passed the first file
    /// over in silence (`-o a.png -o b.png` wrote b.png alone), and which
    /// one was meant is not ours to guess.
    fn once(&mut self, long: &'static str, what: &str, typed: String) -> Result<(), UsageError> {
        if let Some((_, first)) = self.files.iter().find(|(flag, _)| *flag == long) {
            return Err(UsageError(format!(
                "`{typed}` given after `{first}`: give one {what}"
            )));
        }
        self.files.push((long, typed));
        Ok(())
    }

    /// The arguments from `from` to the last one taken, as typed (`-seed
    /// 9`, `--seed=9`, `-o x.png`), each cut as every echo is: how a
    /// message names an option.
    fn typed_since(&self, from: usize) -> String {
        let taken = &self.args[from..self.pos.min(self.args.len())];
        let typed: Vec<String> = taken
            .iter()
            .map(|a| clipped(&a.to_string_lossy()))
            .collect();
        typed.join(" ")
    }

    /// Adds `kv` to the sets, typed as the arguments from `from` were.
    fn push_set(&mut self, (key, value): (String, String), from: usize) {
        let typed = self.typed_since(from);
        self.inv.sets.push(Set {
            key,
            value,
            typed,
            at: from,
        });
    }

    /// A preference key given as a flag of its own (`-cragginess 40`),
    /// typed from the argument at `from`.
    fn key_flag(&mut self, arg: &str, from: usize) -> Result<(), UsageError> {
        self.key_flag_with(arg, None, from)
    }

    /// As [`Self::key_flag`], the value given inline (`--seed=5`) if `inline`.
    fn key_flag_with(
        &mut self,
        arg: &str,
        inline: Option<String>,
        from: usize,
    ) -> Result<(), UsageError> {
        let (key, own) = key_flags::lookup(arg).ok_or_else(|| unknown_argument(arg))?;
        let last = self.pos >= self.args.len();
        let kv = match (inline, own) {
            (Some(_), Some(_)) => {
                return Err(UsageError(format!(
                    "{arg} takes no value: -{0} turns it on, -no-{0} off",
                    key.name.replace('_', "-")
                )));
            }
            (Some(v), None) => (key.name.to_string(), v),
            (None, _) => match key_flags::take(arg, key, own, || self.value_str(arg).ok()) {
                Ok(kv) => kv,
                // Typed last, it leaves nothing unread: held as a bad value is.
                Err(refusal) if last => {
                    self.hold_unfinished(from, refusal);
                    return Ok(());
                }
                Err(refusal) => return Err(refusal),
            },
        };
        self.push_set(kv, from);
        self.check_the_last_set();
        Ok(())
    }

    /// Holds `refusal` of the key's flag typed from `from` to the end,
    /// its value left out, as a bad value is held (see [`parse`]).
    fn hold_unfinished(&mut self, from: usize, refusal: UsageError) {
        let typed = self.typed_since(from);
        self.bad_value.get_or_insert_with(|| refusal.clone());
        self.inv.unfinished = Some(Mistake {
            typed,
            refusal,
            at: from,
        });
    }

    /// Holds `refusal` of the `--set` typed from `from` that gives no
    /// key=value (`--set nokey`), as a bad value is held (see [`parse`]).
    fn hold_malformed(&mut self, from: usize, refusal: UsageError) {
        let typed = self.typed_since(from);
        self.bad_value.get_or_insert_with(|| refusal.clone());
        self.inv.malformed.push(Mistake {
            typed,
            refusal,
            at: from,
        });
    }

    /// Checks the set last pushed, and holds its refusal if it is the
    /// first bad one. Checked here, against the defaults (a value's range
    /// and type do not depend on the other keys), so the message names it
    /// as typed, and a bad `--set` is refused as a bad key flag is.
    fn check_the_last_set(&mut self) {
        let Some(set) = self.inv.sets.last().filter(|_| self.bad_value.is_none()) else {
            return;
        };
        let mut scratch = crate::settings::Settings::default();
        if let Err(problem) = crate::settings::load::apply_set(&mut scratch, &set.key, &set.value) {
            self.bad_value = Some(UsageError(set.named_as_typed(problem).to_string()));
        }
    }

    /// The Windows screensaver letters: `/s`, `/p[:]<HWND>`, `/c[:<HWND>]`, `/a`.
    fn windows_flag(&mut self, arg: &str) -> Result<Option<Mode>, UsageError> {
        let Some(rest) = arg
            .strip_prefix('/')
            .or_else(|| arg.strip_prefix('-').filter(|r| !r.starts_with('-')))
        else {
            return Ok(None);
        };
        let (letter, attached) = match rest.split_once(':') {
            Some((l, h)) => (l, Some(h)),
            None => (rest, None),
        };
        if letter.len() != 1 || !"spca".contains(letter.to_ascii_lowercase().as_str()) {
            return Ok(None);
        }
        // The flag as typed, without its handle: `/p` of `/p:abc`.
        let flag = &arg[..arg.len() - rest.len() + letter.len()];
        let handle = match attached {
            Some(h) => Some(handle_for(flag, h)?),
            None => None,
        };
        let mode = match letter.to_ascii_lowercase().as_str() {
            "s" => Mode::Fullscreen,
            "p" => Mode::Preview {
                parent: handle.or(self.optional_handle(flag)?),
            },
            "c" => Mode::Settings {
                parent: handle.or(self.optional_handle(flag)?),
            },
            "a" => {
                let _ = handle.or(self.optional_handle(flag)?);
                Mode::ChangePassword
            }
            _ => return Ok(None),
        };
        Ok(Some(mode))
    }
}

/// The key and value a `--set` gives (`key=value`), each trimmed.
fn key_value(text: OsString) -> Result<(String, String), UsageError> {
    let kv = text
        .into_string()
        .map_err(|_| UsageError("--set: not valid text".into()))?;
    let (k, v) = kv
        .split_once('=')
        .filter(|(k, _)| !k.trim().is_empty())
        .ok_or_else(|| UsageError(format!("--set {}: expected key=value", clipped(&kv))))?;
    Ok((k.trim().to_string(), v.trim().to_string()))
}

/// `-root`, `-window-id`, `-window` are the old xscreensaver spellings of the
/// long flags; everything else is returned as it was.
fn long_name(arg: &str) -> String {
    match arg {
        "-root" | "-window" | "-window-id" | "-layer" | "-settings" | "-config" | "-set"
        | "-open" | "-size" | "-xscreensaver-xml" | "-man-page" => format!("-{arg}"),
        _ => arg.to_string(),
    }
}

/// The flags that take a file's name (by their long names): the name
/// given after `=` may be any the system allows, text or not.
const FILE_NAME_FLAGS: [&str; 5] = ["--config", "--open", "-o", "--output", "--check-config"];

/// Our subcommand words.
const WORDS: [&str; 2] = ["render", "heightmap"];

/// The flags `Parser::option` takes besides the keys' own, without their
/// dashes (each also works with two): the names a mistyped flag is
/// compared with.
const FLAGS: [&str; 21] = [
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
fn is_windows_letter(arg: &str) -> bool {
    let Some(rest) = arg.strip_prefix('/') else {
        return false;
    };
    let letter = rest.split_once(':').map_or(rest, |(l, _)| l);
    letter.len() == 1 && "spcaSPCA".contains(letter)
}

/// Whether `s` is one of our subcommand words (not a window handle).
fn is_word(s: &str) -> bool {
    WORDS.contains(&s)
}

/// An argument nothing takes, with the flag or word nearest to it
/// (`--colour`: `--color`), written with two dashes whatever was typed;
/// a mode word typed as a flag (`--render`: `render`), a flag typed as a
/// word (`help`: `--help`), and a file name on its own (`render out.png`:
/// `-o out.png`; a PNG that is there: `--open`) are offered as meant.
fn unknown_argument(arg: &str) -> UsageError {
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

/// `--layer NAME`, typed as `typed`: one of [`Layer::NAMES`], or a
/// message listing them.
fn layer_named(typed: &str, name: &str) -> Result<Layer, UsageError> {
    Layer::named(name).ok_or_else(|| {
        let names: Vec<&str> = Layer::NAMES.iter().map(|(n, _)| *n).collect();
        UsageError(format!("{typed}: expected one of {}", names.join(", ")))
    })
}

/// An X window id `text` for `flag`, typed with it as `typed`: a handle
/// that fits X's 32 bits.
fn x_window_id(flag: &str, typed: &str, text: &str) -> Result<u64, UsageError> {
    let id = handle_for(flag, text)?;
    if id > u64::from(u32::MAX) {
        return Err(UsageError(format!(
            "{typed}: X window ids have 32 bits (at most 0xffffffff)"
        )));
    }
    Ok(id)
}

/// The window handle `text` given to `flag`, or a message naming both.
fn handle_for(flag: &str, text: &str) -> Result<u64, UsageError> {
    parse_handle(text).map_err(|e| UsageError(format!("{flag}: {e}")))
}

/// A window handle: decimal, or hex with `0x` (xscreensaver writes both).
pub fn parse_handle(text: &str) -> Result<u64, UsageError> {
    let t = text.trim();
    let parsed = match t.strip_prefix("0x").or_else(|| t.strip_prefix("0X")) {
        Some(hex) => u64::from_str_radix(hex, 16),
        None => t.parse::<u64>(),
    };
    match parsed {
        Ok(h) if h != 0 => Ok(h),
        _ => Err(UsageError(format!(
            "`{}` is not a window handle (a decimal number, or hex with 0x)",
            clipped(text)
        ))),
    }
}

/// The longest side `--size` takes, in pixels. No screen or picture needs
/// more, and a frame one pixel high and 2^28 wide (inside the frame's
/// pixel count) took 97 s and 3.5 GB: the work of a frame grows with each
/// side, not only with its pixels.
pub const MAX_SIDE: u32 = 32768;

/// The screens' sizes `--size` also takes by name (any case), as people
/// call them.
const NAMED_SIZES: &[(&str, u32, u32)] = &[
    ("720p", 1280, 720),
    ("1080p", 1920, 1080),
    ("1440p", 2560, 1440),
    ("4k", 3840, 2160),
    ("2160p", 3840, 2160),
    ("5k", 5120, 2880),
    ("8k", 7680, 4320),
];

/// `--size WIDTHxHEIGHT` (or one of [`NAMED_SIZES`]): both sides from 1
/// to [`MAX_SIDE`].
fn parse_size(text: &str) -> Result<Size, UsageError> {
    let text = text.trim();
    if let Some(&(_, w, h)) = NAMED_SIZES
        .iter()
        .find(|(n, ..)| n.eq_ignore_ascii_case(text))
    {
        return Ok(Size::new(w, h));
    }
    // The size as a message echoes it: a flood typed is no flood said.
    let shown = clipped(text);
    let bad = || {
        let names: Vec<&str> = NAMED_SIZES.iter().map(|(n, ..)| *n).collect();
        UsageError(format!(
            "--size {shown}: expected WIDTHxHEIGHT, e.g. 1920x1080, or one of {}",
            names.join(", ")
        ))
    };
    let (w, h) = text.split_once(['x', 'X']).ok_or_else(bad)?;
    let too_large = || {
        UsageError(format!(
            "--size {shown}: too large (each side at most {MAX_SIDE} pixels)"
        ))
    };
    // A side of digits past what a number holds is a size too large, not
    // a misspelling (`4294967296x1` was "expected WIDTHxHEIGHT").
    let side = |s: &str| -> Result<u32, UsageError> {
        let s = s.trim();
        match s.parse::<u32>() {
            Ok(n) => Ok(n),
            Err(_) if !s.is_empty() && s.bytes().all(|b| b.is_ascii_digit()) => Err(too_large()),
            Err(_) => Err(bad()),
        }
    };
    let size = Size::new(side(w)?, side(h)?);
    if size.is_empty() {
        return Err(UsageError(format!(
            "--size {shown}: too small (each side at least 1 pixel)"
        )));
    }
    if size.width.max(size.height) > MAX_SIDE {
        return Err(too_large());
    }
    // Said here with the other bounds, before any other check or warning:
    // `render` found it only once its output was asked about.
    let most = crate::render::frame::MAX_PIXELS;
    if size.pixels() > most {
        return Err(UsageError(format!(
            "--size {shown}: too large (at most {most} pixels in all)"
        )));
    }
    Ok(size)
}

#[cfg(test)]
mod tests {
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
