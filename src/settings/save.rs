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
use super::load::{DEFAULT_TOML, line_col};

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
            Some(item) if current_value(item, key).as_ref() != Some(&wanted) => {
                replace_value(item, &wanted);
            }
            Some(_) => {}
            None if wanted != keys::get(&defaults, key) => {
                let gap = added || !(text.is_empty() || text.ends_with("\n\n"));
                append_key(&mut doc, key, &wanted, gap);
                added = true;
            }
            None => {}
        }
    }
    let mut out = doc.to_string();
    if !out.is_empty() && !out.ends_with('\n') {
        out.push('\n');
    }
    Ok(out)
}

/// Saves `settings` into the file at `path`, atomically. An absent file is
/// started from the commented defaults; a file that does not parse is left
/// alone and the error says where it is broken.
pub fn save(path: &Path, settings: &Settings) -> Result<(), SaveError> {
    let error = |position, message: String| SaveError {
        path: path.to_path_buf(),
        position,
        message,
        io: None,
    };
    let io_error = |message: String, e: &std::io::Error| SaveError {
        io: Some(e.kind()),
        ..error(None, message)
    };
    let text = match crate::fsutil::read_regular(path, crate::fsutil::MAX_PREFERENCES_BYTES) {
        Ok(bytes) => String::from_utf8(bytes)
            .map_err(|_| error(None, "not valid UTF-8 text; fix it with Edit file".into()))?,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => DEFAULT_TOML.to_string(),
        Err(e) => return Err(io_error(format!("cannot read: {e}"), &e)),
    };
    let merged = merge(&text, settings).map_err(|e| {
        error(
            e.position,
            format!("not valid TOML ({}); not saved", e.message),
        )
    })?;
    if merged == text && path.exists() {
        return Ok(());
    }
    if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir)
            .map_err(|e| io_error(format!("cannot create {}: {e}", dir.display()), &e))?;
    }
    crate::fsutil::write_atomic_with(path, |w| w.write_all(merged.as_bytes()))
        .map_err(|e| io_error(format!("cannot write: {e}"), &e))
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
