//! Saving preferences into the user's TOML file without disturbing it.
//!
//! The file is edited, not regenerated: comments, blank lines, key order,
//! number formatting and unknown keys stay as the user left them. Only keys
//! whose value differs from the settings are rewritten; a key the file lacks
//! is added at the end, with its one-line doc as a comment, and only when its
//! value is not the default (an absent key already means the default).

use std::fmt;
use std::path::{Path, PathBuf};

use toml_edit::{DocumentMut, Item};

use super::Settings;
use super::keys::{self, KEYS, Key, Value};
use super::load::DEFAULT_TOML;
use super::text::{Form, decode, encode, line_col};

/// Why the preferences could not be saved. The file on disk is unchanged.
#[derive(Debug, Clone, PartialEq)]
pub struct SaveError {
    /// The preferences file.
    pub path: PathBuf,
    /// 1-based line and column of a syntax error, when that is the reason.
    pub position: Option<(usize, usize)>,
    /// What went wrong, for a person.
    pub message: String,
    /// The system's reason when reading or writing failed; `None` when the
    /// file's text is the trouble.
    pub io: Option<std::io::ErrorKind>,
}

impl SaveError {
    /// What the person can do about it, as the settings screen says it: a
    /// broken file is mended with Edit file, a full disk by freeing space,
    /// a file or folder that cannot be written by its permissions.
    pub fn advice(&self) -> &'static str {
        use std::io::ErrorKind as K;
        match self.io {
            None => "Use Edit file to fix it, or Cancel.",
            Some(K::StorageFull | K::QuotaExceeded) => {
                "Free some space on the disk, then OK again; Cancel keeps the file as it is."
            }
            Some(K::PermissionDenied | K::ReadOnlyFilesystem) => {
                "Make the file and its folder writable, then OK again; Cancel keeps the file as it is."
            }
            // Not a regular file, or far too large: nothing here can mend it.
            Some(K::InvalidInput | K::InvalidData) => "Cancel keeps the file as it is.",
            Some(_) => "OK tries again; Cancel keeps the file as it is.",
        }
    }
}

impl fmt::Display for SaveError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.path.display())?;
        if let Some((line, col)) = self.position {
            write!(f, ":{line}:{col}")?;
        }
        write!(f, ": {}", self.message)
    }
}

impl std::error::Error for SaveError {}

/// A file that is not valid TOML: where and why. Saving refuses such a file.
#[derive(Debug, Clone, PartialEq)]
pub struct ParseError {
    /// 1-based line and column, when known.
    pub position: Option<(usize, usize)>,
    /// The parser's message.
    pub message: String,
}

/// Rewrites the TOML `text` so that it holds `settings`, changing as little
/// as possible. Pure: the caller decides where the result goes.
///
/// Every value is checked with `keys::apply` first; a value the key table
/// refuses is an error and nothing is produced.
pub fn merge(text: &str, settings: &Settings) -> Result<String, ParseError> {
    let mut doc: DocumentMut = text.parse().map_err(|e: toml_edit::TomlError| ParseError {
        position: e.span().map(|s| line_col(text, s.start)),
        message: e.message().trim().to_string(),
    })?;
    let defaults = Settings::default();
    let mut added = false;
    for key in KEYS {
        let wanted = checked_value(settings, key).map_err(|message| ParseError {
            position: None,
            message,
        })?;
        let table = doc.as_table_mut();
        match table.get_mut(key.name) {
            // A value the file holds is left alone if it means the wanted
            // one under the look (a default the look replaces).
            Some(item)
                if current_value(item, key).map(|v| keys::under_look(settings.look, key, v))
                    != Some(wanted.clone()) =>
            {
                replace_value(item, &wanted);
            }
            Some(_) => {}
            None if wanted != keys::under_look(settings.look, key, keys::get(&defaults, key)) => {
                if !added {
                    drop_blank_end(&mut doc);
                }
                append_key(&mut doc, key, &wanted, added || !text.is_empty());
                added = true;
            }
            None => {}
        }
    }
    let mut out = doc.to_string();
    if !out.is_empty() && !out.ends_with('\n') {
        out.push('\n');
    }
    // The parser ends every line it writes with `\n`; a file written on
    // Windows keeps its `\r\n` (a save changes only the values edited).
    // A file of mixed endings is left to the parser's.
    if windows_lines(text) {
        out = out.replace("\r\n", "\n").replace('\n', "\r\n");
    }
    Ok(out)
}

/// Drops the blank lines `doc` ends with: the parser writes them after
/// every key added, so a file ending in a blank line got its new keys with
/// none before them and the blank line after.
fn drop_blank_end(doc: &mut DocumentMut) {
    let blank = doc.trailing().as_str().is_some_and(|t| t.trim().is_empty());
    if blank {
        doc.set_trailing("");
    }
}

/// Whether every line of `text` ends with `\r\n` (and one does).
fn windows_lines(text: &str) -> bool {
    text.contains("\r\n") && !text.replace("\r\n", "").contains('\n')
}

/// Saves `settings` into the file at `path`, atomically: every key takes
/// its value from `settings`. See [`save_changes`].
pub fn save(path: &Path, settings: &Settings) -> Result<(), SaveError> {
    let every: Vec<&Key> = KEYS.iter().collect();
    save_changes(path, settings, &every)
}

/// How often a save starts over because the file changed while it was
/// being merged; a file rewritten that often is someone's busy loop.
const SAVE_ATTEMPTS: usize = 8;

/// Saves the keys in `changed`, with their values in `edited`, into the
/// file at `path` as it is on disk at this moment, atomically. Every other
/// key keeps what the file says now, so a change another program made
/// since the screen read the file survives; for a key both changed, this
/// save's value wins (it is the later word). The file is read again just
/// before it is replaced and compared by content (not modification time,
/// which `cp -p` or `rsync -t` keep): if it changed, the merge starts over.
/// An absent file is started from the commented defaults; a file that does
/// not parse is left alone and the error says where it is broken.
pub fn save_changes(path: &Path, edited: &Settings, changed: &[&Key]) -> Result<(), SaveError> {
    for _ in 0..SAVE_ATTEMPTS {
        let (on_disk, form) = match read_text(path)? {
            Some((text, form)) => (Some(text), form),
            None => (None, Form::Utf8),
        };
        let text = on_disk.as_deref().unwrap_or(DEFAULT_TOML);
        let mut wanted = Settings::default();
        // A syntax error is reported by `merge` below, with its position,
        // in the words loading uses (`read`'s problem).
        let read = super::load::apply_toml(&mut wanted, text, "");
        for key in changed {
            let value = checked_value(edited, key).map_err(|m| text_error(path, None, m))?;
            keys::apply(&mut wanted, key, &value).map_err(|m| text_error(path, None, m))?;
        }
        let merged = merge(text, &wanted).map_err(|e| {
            let said = match read.iter().find(|p| p.drops_the_file()) {
                Some(p) => p.what(),
                None => format!("not valid TOML ({})", e.message),
            };
            text_error(path, e.position, format!("{said}; not saved"))
        })?;
        if on_disk.as_deref() == Some(merged.as_str()) {
            return Ok(());
        }
        if write_unless_changed(path, &encode(&merged, form), &on_disk)? {
            return Ok(());
        }
    }
    Err(SaveError {
        io: Some(std::io::ErrorKind::Interrupted),
        ..text_error(
            path,
            None,
            "the file kept changing while it was saved".into(),
        )
    })
}

fn text_error(path: &Path, position: Option<(usize, usize)>, message: String) -> SaveError {
    SaveError {
        path: path.to_path_buf(),
        position,
        message,
        io: None,
    }
}

fn io_error(path: &Path, message: String, e: &std::io::Error) -> SaveError {
    SaveError {
        io: Some(e.kind()),
        ..text_error(path, None, message)
    }
}

/// The file's text now and its form (a save keeps it), or `None` when
/// there is no file.
fn read_text(path: &Path) -> Result<Option<(String, Form)>, SaveError> {
    match crate::fsutil::read_regular(path, crate::fsutil::MAX_PREFERENCES_BYTES) {
        Ok(bytes) => decode(bytes).map(Some).map_err(|e| {
            text_error(
                path,
                Some((e.line, e.column)),
                format!("{}; fix it with Edit file", e.message),
            )
        }),
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => Ok(None),
        Err(e) => Err(io_error(path, crate::fsutil::cannot_read(&e), &e)),
    }
}

/// Writes `merged` (the file's new bytes) over the file atomically if the
/// file still holds what `was` says (its text, or no file); false when it
/// changed meanwhile.
fn write_unless_changed(
    path: &Path,
    merged: &[u8],
    was: &Option<String>,
) -> Result<bool, SaveError> {
    if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir)
            .map_err(|e| io_error(path, format!("cannot create {}: {e}", dir.display()), &e))?;
    }
    // Unreadable now counts as changed: the next attempt says why.
    let unchanged =
        || Ok(matches!(read_text(path), Ok(now) if now.as_ref().map(|(t, _)| t) == was.as_ref()));
    crate::fsutil::write_atomic_checked(path, |w| w.write_all(merged), unchanged)
        .map_err(|e| io_error(path, crate::fsutil::cannot_write(&e), &e))
}

/// The value to write for `key`, after the key table has accepted it.
fn checked_value(settings: &Settings, key: &Key) -> Result<Value, String> {
    let value = tidy(keys::get(settings, key));
    let mut probe = settings.clone();
    keys::apply(&mut probe, key, &value).map_err(|e| format!("key `{}`: {e}", key.name))?;
    Ok(value)
}

/// Floats are stored as f32: write the shortest decimal that reads back as
/// the same f32 (0.35, not 0.3499999940395355).
fn tidy(value: Value) -> Value {
    match value {
        Value::Float(x) => Value::Float(shortest_f32(x)),
        other => other,
    }
}

fn shortest_f32(x: f64) -> f64 {
    (x as f32).to_string().parse().unwrap_or(x)
}

/// What the file says for `key`, read the way loading reads it, so that a
/// value written differently but meaning the same (`8` vs `8.0`) is kept.
fn current_value(item: &Item, key: &Key) -> Option<Value> {
    let v = item.as_value()?;
    let raw = if let Some(i) = v.as_integer() {
        Value::Int(i)
    } else if let Some(x) = v.as_float() {
        Value::Float(x)
    } else if let Some(b) = v.as_bool() {
        Value::Bool(b)
    } else {
        Value::Str(v.as_str()?.to_string())
    };
    let mut probe = Settings::default();
    keys::apply(&mut probe, key, &raw).ok()?;
    Some(tidy(keys::get(&probe, key)))
}

fn toml_value(value: &Value) -> toml_edit::Value {
    match value {
        Value::Int(i) => (*i).into(),
        Value::Float(x) => (*x).into(),
        Value::Bool(b) => (*b).into(),
        Value::Str(s) => s.as_str().into(),
    }
}

/// Replaces the value in `item`, keeping the spacing and any comment after it.
fn replace_value(item: &mut Item, value: &Value) {
    let mut new = toml_value(value);
    if let Some(old) = item.as_value() {
        *new.decor_mut() = old.decor().clone();
    } else {
        new.decor_mut().set_prefix(" ");
    }
    *item = Item::Value(new);
}

fn append_key(doc: &mut DocumentMut, key: &Key, value: &Value, blank_line: bool) {
    let table = doc.as_table_mut();
    let mut new = toml_value(value);
    new.decor_mut().set_prefix(" ");
    table.insert(key.name, Item::Value(new));
    if let Some(mut k) = table.key_mut(key.name) {
        let gap = if blank_line { "\n" } else { "" };
        k.leaf_decor_mut()
            .set_prefix(format!("{gap}# {}\n", key.doc));
        k.leaf_decor_mut().set_suffix(" ");
    }
}
