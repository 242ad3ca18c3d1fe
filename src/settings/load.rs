//! Reading preferences: TOML files and `--set key=value`, with messages that
//! name the file, line, column, key and the allowed values.
//!
//! Loading is lenient: every good key is used, every bad one is reported and
//! keeps its previous value, so a screensaver with a broken file still runs,
//! and `render` still draws (with a warning). `--check-config`, whose work
//! is to find them, looks at the problems and fails.

use std::fmt;
use std::path::Path;

use toml_edit::{Document, Item};

use super::Settings;
use super::keys::{self, Value};

/// One thing wrong in a preferences source.
#[derive(Debug, Clone, PartialEq)]
pub struct Problem {
    /// Where it came from: a file path (`--config PATH` when that flag's
    /// file is refused), or `--set`.
    pub source: String,
    /// 1-based line and column, when the source is a file.
    pub position: Option<(usize, usize)>,
    /// The key concerned, when there is one.
    pub key: Option<String>,
    /// What is wrong and what is allowed.
    pub message: String,
    /// How much of the source it costs.
    pub reach: Reach,
}

/// How much of its source a [`Problem`] leaves unused.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Reach {
    /// One key: the rest of the source still means what it says.
    Key,
    /// The file could not be read at all (missing, not a regular file, too
    /// large, no permission).
    Unreadable,
    /// The file was read, but is not text, or not TOML (a syntax error
    /// stops the reading, see [`apply_toml`]).
    Unparsed,
}

impl Problem {
    /// The file could not be read at all (missing, not a regular file, too
    /// large, no permission): nothing in it was used.
    pub fn is_unreadable(&self) -> bool {
        self.reach == Reach::Unreadable
    }

    /// A key this version does not know (a newer version's, or a typo): the
    /// rest of the file still means what it says.
    pub fn is_unknown_key(&self) -> bool {
        self.key.as_deref().is_some_and(|k| keys::find(k).is_none())
    }

    /// Nothing in the file was used: it could not be read, is not text
    /// (`text::decode`'s refusal), or is not TOML (a syntax error stops
    /// the reading, see [`apply_toml`]).
    pub fn drops_the_file(&self) -> bool {
        self.reach != Reach::Key
    }

    /// The problem without its place: the key (clipped) and the message.
    pub fn what(&self) -> String {
        match &self.key {
            Some(key) => format!("key `{}`: {}", crate::quote::clipped(key), self.message),
            None => self.message.clone(),
        }
    }
}

impl fmt::Display for Problem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.source)?;
        if let Some((line, col)) = self.position {
            write!(f, ":{line}:{col}")?;
        }
        write!(f, ": {}", self.what())
    }
}

/// What a TOML value that no key takes is, in words.
fn kind_of(item: &Item) -> &'static str {
    match item.as_value() {
        Some(v) if v.is_datetime() => "a date and time",
        Some(v) if v.is_array() => "an array",
        _ => "a table",
    }
}

/// toml_edit's `message` said better where it leaves out what matters: the
/// key of a duplicate, a key with nothing after `=`, the key of a value it
/// cannot read (`color = sonar`: "string values must be quoted", about no
/// key) and what that key takes. `line` is the line the error is on, `at`
/// the error's byte offset in it. Returns the key concerned, if known, and
/// the words.
fn explain(message: &str, line: &str, at: usize) -> (Option<String>, String) {
    let key = line
        .split_once('=')
        .map(|(k, _)| k.trim().trim_matches(['"', '\'']).to_string())
        .filter(|k| !k.is_empty());
    let value_missing = line
        .split_once('=')
        .is_some_and(|(_, v)| v.trim().is_empty());
    if message.contains("duplicate key") {
        return (key, "the key is given twice; keep one".to_string());
    }
    // Old Mac line endings (a lone `\r`) make the file one long line,
    // whose error was put to its first key and what that key takes.
    if message.contains("carriage return") {
        let said = "a carriage return without a newline after it: \
                    lines end in \\n or \\r\\n (old Mac line endings are not read)";
        return (None, said.to_string());
    }
    if let Some(key) = key_without_equals(line) {
        let said = format!("{message}; write it as `{key} = VALUE`");
        return (Some(key), said);
    }
    if value_missing {
        return (key, "nothing after `=`; give a value".to_string());
    }
    // A number too large for TOML: name its key, so the hint fits it.
    if message.contains("overflow") {
        return (key, message.to_string());
    }
    // An error after the `=` is in the value: its key is the one before
    // it. One before the `=` is in the key itself, which is no key yet.
    let in_value = line.find('=').is_some_and(|eq| at > eq);
    match key.filter(|_| in_value) {
        Some(key) => {
            let takes = keys::find(&key).map_or(String::new(), |k| {
                format!("; it takes {}", k.kind.allowed())
            });
            (Some(key), format!("{message}{takes}"))
        }
        None => (None, message.to_string()),
    }
}

/// The key a line without `=` begins, when it begins with one (`seed: 5`,
/// `seed 5`: another format's habit): TOML said only "expected `=`", about
/// no key. A first word that is no key is left unnamed.
fn key_without_equals(line: &str) -> Option<String> {
    if line.contains('=') {
        return None;
    }
    let word = line.trim_start().split([':', ' ', '\t']).next()?;
    keys::find(word).map(|k| k.name.to_string())
}

/// What to do about a TOML error a person is likely to meet, on the key
/// `key` (if known).
fn hint(message: &str, key: Option<&str>) -> &'static str {
    if message.contains("overflow") && key == Some("seed") {
        // TOML integers stop at 2^63-1; our seeds go to 2^64-1.
        "; a seed above 9223372036854775807 is written in quotes, e.g. seed = \"18446744073709551615\""
    } else if message.contains("overflow") {
        "; no key takes a number this large (`mountains --help` lists each key's range)"
    } else {
        ""
    }
}

/// Where each line of a text starts, to turn byte offsets into positions.
struct Lines<'a> {
    text: &'a str,
    starts: Vec<usize>,
}

impl<'a> Lines<'a> {
    fn new(text: &'a str) -> Self {
        let starts = std::iter::once(0)
            .chain(text.match_indices('\n').map(|(i, _)| i + 1))
            .collect();
        Lines { text, starts }
    }

    /// Where the line holding byte `offset` starts.
    fn start_of(&self, offset: usize) -> usize {
        let offset = offset.min(self.text.len());
        let line = self.starts.partition_point(|&s| s <= offset);
        self.starts[line - 1]
    }

    /// The text of the line holding byte `offset`.
    fn line_of(&self, offset: usize) -> &'a str {
        let offset = offset.min(self.text.len());
        let line = self.starts.partition_point(|&s| s <= offset);
        let start = self.starts[line - 1];
        let end = self.starts.get(line).map_or(self.text.len(), |&e| e);
        self.text[start..end].trim_end_matches(['\n', '\r'])
    }

    /// 1-based line and column (in characters) of byte `offset`.
    fn line_col(&self, offset: usize) -> (usize, usize) {
        let offset = offset.min(self.text.len());
        let line = self.starts.partition_point(|&s| s <= offset);
        let start = self.starts[line - 1];
        let col = self
            .text
            .get(start..offset)
            .map_or(0, |s| s.chars().count())
            + 1;
        (line, col)
    }
}

/// At most this many problems are reported one by one; the rest are counted.
pub const SHOWN_PROBLEMS: usize = 20;

/// The lines a person reads about `problems`: the first [`SHOWN_PROBLEMS`],
/// then how many more there are.
pub fn report(problems: &[Problem]) -> Vec<String> {
    report_with(problems, Problem::to_string)
}

/// As [`report`], each problem's line made by `line` (which says whether
/// it is an error or a warning, and what follows from it). Any list said
/// a line an item is capped so (`--check-config`'s mistakes typed are
/// more than the loader's problems).
pub fn report_with<T>(problems: &[T], line: impl Fn(&T) -> String) -> Vec<String> {
    let mut lines: Vec<String> = problems.iter().take(SHOWN_PROBLEMS).map(line).collect();
    if problems.len() > SHOWN_PROBLEMS {
        lines.push(format!(
            "... and {} more problems",
            problems.len() - SHOWN_PROBLEMS
        ));
    }
    lines
}

/// Applies the TOML `text` (read from `source`) on top of `settings`,
/// returning every problem found. A syntax error stops the reading (nothing
/// from the file is used); any other problem skips only its key.
pub fn apply_toml(settings: &mut Settings, text: &str, source: &str) -> Vec<Problem> {
    // Line starts found once: finding each key's line from the top would
    // be quadratic in a hostile file of many keys.
    let lines = Lines::new(text);
    let at = |offset: Option<usize>| offset.map(|o| lines.line_col(o));
    let doc = match Document::parse(text) {
        Ok(doc) => doc,
        Err(e) => {
            let start = e.span().map(|s| s.start);
            let line = start.map_or("", |o| lines.line_of(o));
            let in_line = start.map_or(0, |o| o - lines.start_of(o));
            // toml_edit names neither the key of a duplicate nor a missing
            // value, nor the key whose value it cannot read.
            let (key, said) = explain(e.message(), line, in_line);
            let message = format!(
                "not valid TOML: {said}{}",
                hint(e.message(), key.as_deref())
            );
            return vec![Problem {
                source: source.into(),
                position: at(start),
                key,
                message,
                reach: Reach::Unparsed,
            }];
        }
    };
    let mut problems = Vec::new();
    let mut candidate = settings.clone();
    for (name, item) in doc.as_table().iter() {
        let key_pos = at(doc
            .as_table()
            .key(name)
            .and_then(|k| k.span())
            .map(|s| s.start));
        let value_pos = at(item.span().map(|s| s.start)).or(key_pos);
        let mut report = |position, message: String| {
            problems.push(Problem {
                source: source.into(),
                position,
                key: Some(name.into()),
                message,
                reach: Reach::Key,
            })
        };
        let key = match keys::known(name) {
            Ok(key) => key,
            Err(message) => {
                // A file's problem has no line after it to say where the
                // keys are, as a command line's mistake has.
                report(
                    key_pos,
                    format!(
                        "{message}{} (`mountains --help` lists every key)",
                        keys_in_a_table(item)
                    ),
                );
                continue;
            }
        };
        match item_value(item) {
            Some(value) => {
                if let Err(message) = keys::apply(&mut candidate, key, &value) {
                    report(value_pos, message);
                }
            }
            None => report(
                value_pos,
                format!("expected {}, found {}", key.kind.allowed(), kind_of(item)),
            ),
        }
    }
    *settings = candidate;
    problems
}

/// What to say of an unknown key that is a table holding keys of ours
/// (`[mountains]` over `seed = 5`, a habit of other formats): its keys were
/// passed over with only the table named, as if they were read.
fn keys_in_a_table(item: &Item) -> String {
    let Some(table) = item.as_table_like() else {
        return String::new();
    };
    let ours: Vec<String> = table
        .iter()
        .filter(|(name, _)| keys::find(name).is_some())
        .map(|(name, _)| format!("`{name}`"))
        .take(3)
        .collect();
    if ours.is_empty() {
        return String::new();
    }
    format!(
        "; the keys in it ({}) are read only at the top of the file, before any [table]",
        ours.join(", ")
    )
}

fn item_value(item: &Item) -> Option<Value> {
    let v = item.as_value()?;
    if let Some(i) = v.as_integer() {
        Some(Value::Int(i))
    } else if let Some(x) = v.as_float() {
        Some(Value::Float(x))
    } else if let Some(b) = v.as_bool() {
        Some(Value::Bool(b))
    } else {
        v.as_str().map(|s| Value::Str(s.to_string()))
    }
}

/// Applies one `--set key=value`. The value is read as TOML (`42`, `true`,
/// `"sonar"`), and a bare word that is not TOML is taken as a string, so
/// `--set color=sonar` works without shell quoting.
pub fn apply_set(settings: &mut Settings, key: &str, raw: &str) -> Result<(), Problem> {
    let problem = |message: String| Problem {
        source: "--set".into(),
        position: None,
        key: Some(key.into()),
        message,
        reach: Reach::Key,
    };
    let spec = keys::known(key).map_err(problem)?;
    let value = parse_set_value(raw);
    keys::apply(settings, spec, &value).map_err(problem)
}

fn parse_set_value(raw: &str) -> Value {
    let doc = format!("v = {raw}");
    match Document::parse(doc.as_str())
        .ok()
        .and_then(|d| d.as_table().get("v").and_then(item_value))
    {
        Some(v) => v,
        None => Value::Str(raw.to_string()),
    }
}

/// Where the value of `key` stands in the preferences file at `path`
/// (1-based line and column), if the file reads and holds it: what a
/// warning about a good value (a folder that is not there) names, as a
/// [`Problem`] names a bad one.
pub fn value_position(path: &Path, key: &str) -> Option<(usize, usize)> {
    let bytes = crate::fsutil::read_regular(path, crate::fsutil::MAX_PREFERENCES_BYTES).ok()?;
    let (text, _) = super::text::decode(bytes).ok()?;
    let doc = Document::parse(text.as_str()).ok()?;
    let start = doc.as_table().get(key)?.span()?.start;
    Some(Lines::new(&text).line_col(start))
}

/// Reads the file at `path` and applies it on top of `settings`. An
/// unreadable file is one problem; the settings are then left unchanged.
pub fn apply_file(settings: &mut Settings, path: &Path) -> Vec<Problem> {
    let source = path.display().to_string();
    match crate::fsutil::read_regular(path, crate::fsutil::MAX_PREFERENCES_BYTES) {
        Ok(bytes) => match super::text::decode(bytes) {
            Ok((text, _)) => {
                let before = settings.clone();
                let problems = apply_toml(settings, &text, &source);
                folders_beside(settings, &before, path);
                problems
            }
            Err(e) => vec![Problem {
                source,
                position: Some((e.line, e.column)),
                key: None,
                message: e.message.to_string(),
                reach: Reach::Unparsed,
            }],
        },
        Err(e) => vec![Problem {
            source,
            position: None,
            key: None,
            message: crate::fsutil::cannot_read(&e),
            reach: Reach::Unreadable,
        }],
    }
}

/// Makes each folder the file at `path` gave (a key of the folder kind
/// that `settings` holds other than `before`) one beside the file, when
/// relative: see [`super::paths::beside`].
fn folders_beside(settings: &mut Settings, before: &Settings, path: &Path) {
    let folders = keys::KEYS.iter().filter(|k| k.kind == keys::Kind::Path);
    for key in folders {
        if let Value::Str(written) = keys::get(settings, key)
            && keys::get(before, key) != Value::Str(written.clone())
        {
            let anchored = Value::Str(super::paths::beside(&written, path));
            // The anchored name is a folder path as the written one is.
            let _ = keys::apply(settings, key, &anchored);
        }
    }
}

/// The settings file that ships with the program, every key commented; what
/// an absent file means.
pub const DEFAULT_TOML: &str = include_str!("../../config/default.toml");

/// Settings gathered from the defaults, a preferences file and `--set`.
#[derive(Debug, Clone)]
pub struct Loaded {
    /// The result: every good value applied, bad ones left at their defaults.
    pub settings: Settings,
    /// The preferences file that was read, if any.
    pub file: Option<std::path::PathBuf>,
    /// What was wrong in that file (its good keys were still used, unless
    /// a problem drops the whole file: [`Problem::drops_the_file`]).
    pub problems: Vec<Problem>,
    /// The defaults and the file alone, before any `--set`: what the
    /// settings screen takes for the file's values.
    pub from_file: Settings,
}

/// What an explicit `--config` that cannot be read means to a mode. The
/// null device (`--config /dev/null`) is never unreadable: it is the usual
/// way to say "no preferences", and means the defaults in every mode.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Unreadable {
    /// A mistake on the command line, refused (the one-shot commands).
    Refuse,
    /// Refused too, except a file not there yet, which is a new one: the
    /// defaults (the settings screen creates it on OK).
    NewIfMissing,
    /// The defaults, with the reason among the problems: a screensaver
    /// always starts, or the screen stays unprotected.
    Defaults,
}

/// Builds the settings: defaults, then the file (`config`, or the platform's
/// preferences file if anything is at its name, a link to nowhere too),
/// then each `--set` in order.
///
/// An explicit `config` that cannot be read is handled as `unreadable` says;
/// any bad `--set` is an error (a mistake on the command line). Problems
/// inside the file, and an unreadable file the platform's path names, are
/// returned for the caller to report: their keys keep the defaults.
pub fn resolve(
    config: Option<&Path>,
    sets: &[(String, String)],
    unreadable: Unreadable,
) -> Result<Loaded, Problem> {
    let mut settings = Settings::default();
    let file = match config {
        Some(p) => Some(p.to_path_buf()),
        // A link to nowhere is a file that cannot be read, said as one
        // (`exists` follows the link, and the file was passed over).
        None => super::paths::config_file().filter(|p| crate::fsutil::taken(p)),
    };
    // Nothing at all at the name: a link to nowhere is someone's, and
    // cannot be read (`exists` would follow it).
    let new_file = |p: &Path| {
        unreadable == Unreadable::NewIfMissing && config.is_some() && !crate::fsutil::taken(p)
    };
    let file = file.filter(|p| !new_file(p) && !crate::fsutil::is_null_device(p));
    let mut problems = Vec::new();
    if let Some(path) = &file {
        problems = apply_file(&mut settings, path);
        if config.is_some() {
            // A file typed on the command line: named by its flag, where
            // it is refused and where the screensaver starts without it.
            for p in problems.iter_mut().filter(|p| p.is_unreadable()) {
                p.source = format!("--config {}", p.source);
            }
        }
        let refused = config.is_some() && unreadable != Unreadable::Defaults;
        if refused && problems.iter().any(Problem::is_unreadable) {
            return Err(problems.remove(0));
        }
    }
    let from_file = settings.clone();
    for (key, value) in sets {
        apply_set(&mut settings, key, value)?;
    }
    Ok(Loaded {
        settings,
        file,
        problems,
        from_file,
    })
}
