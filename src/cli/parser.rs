//! The arguments read one by one: each flag, its value and the mode it
//! names, into an [`Invocation`].

use std::ffi::OsString;
use std::path::PathBuf;

use super::checks::{
    finish_mode, no_slide_show, no_standard_input, nothing_to_open, nothing_to_set,
    one_file_to_check, output_is_not_the_preferences, two_modes,
};
use super::unknown::{is_windows_letter, is_word, unknown_argument};
use super::values::{handle_for, layer_named, parse_size, x_window_id};
use super::{Invocation, Mistake, Mode, Set, UsageError, XssOptions, default_mode, key_flags};
use crate::quote::clipped;
use crate::render::Size;

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

/// The arguments being read, and what they said so far.
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
pub(super) fn long_name(arg: &str) -> String {
    match arg {
        "-root" | "-window" | "-window-id" | "-layer" | "-settings" | "-config" | "-set"
        | "-open" | "-size" | "-xscreensaver-xml" | "-man-page" => format!("-{arg}"),
        _ => arg.to_string(),
    }
}

/// The flags that take a file's name (by their long names): the name
/// given after `=` may be any the system allows, text or not.
const FILE_NAME_FLAGS: [&str; 5] = ["--config", "--open", "-o", "--output", "--check-config"];
