//! The table of every preference key: its name, what values it allows, and
//! how it reads and writes `Settings`. TOML files, `--set`, `--help` and the
//! settings screen all go through this one table, so a range is checked in
//! exactly one place.
//!
//! The rows are in `table.rs`, each a constant code refers to; what a key
//! is in `kind.rs`; how a field's type is read and written in `field.rs`.
//! Here: finding a key, and setting one under a look (`looks.rs`), which
//! is a layer of defaults under the keys.

mod field;
mod kind;
pub(super) mod table;

pub use kind::{AMOUNT_MENU, Change, Key, Kind, Value};
pub use table::*;

use super::looks::{self, Preset};
use super::{Look, Settings};

/// Gives `to` the value `key` has in `from`. A value read from a Settings
/// is one the key allows, so this cannot fail.
pub fn copy(key: &Key, from: &Settings, to: &mut Settings) {
    let _ = write(to, key, &(key.read)(from));
}

/// Looks a key up by name.
pub fn find(name: &str) -> Option<&'static Key> {
    KEYS.iter().find(|k| k.name == name)
}

/// Looks a key up by name; for an unknown one, a message naming the
/// closest known key, if any is close, for a file's line or `--set`.
/// Where every key is listed is said by the caller: a file's problem
/// says it inside (`load::apply_toml`), a mistake typed in the line after
/// it (`cli::SEE_HELP`).
pub fn known(name: &str) -> Result<&'static Key, String> {
    find(name).ok_or_else(|| {
        let hint = crate::spelling::did_you_mean(name, KEYS.iter().map(|k| k.name));
        format!("unknown key{hint}")
    })
}

/// Checks `value` against `key` and stores it in `settings`; on refusal,
/// says why in words that name the allowed values.
///
/// Under a look other than ours, a key given its default takes the look's
/// value instead: the look is a layer of defaults under the keys, whatever
/// order they come in (see [`follow_look`]).
pub fn apply(settings: &mut Settings, key: &Key, value: &Value) -> Result<(), String> {
    write(settings, key, value).ok_or_else(|| {
        // A name typed another way ("Desert", "desret") is offered as meant.
        let hint = match (key.kind, value) {
            (Kind::Choice(names), Value::Str(typed)) => {
                match names.iter().find(|n| n.eq_ignore_ascii_case(typed)) {
                    Some(same) => crate::spelling::offer(Some(same)),
                    None => crate::spelling::did_you_mean(&typed.to_lowercase(), names.iter()),
                }
            }
            (_, Value::Str(typed)) => unquoted(key, typed),
            _ => String::new(),
        };
        format!(
            "{} is not allowed; expected {}{hint}",
            value.shown(),
            key.kind.allowed()
        )
    })?;
    follow_look(settings, key);
    Ok(())
}

/// `; did you mean 8, without quotes?` for a number or a true/false that
/// `key` takes, written as a string (`detail = "8"`), or nothing.
fn unquoted(key: &Key, typed: &str) -> String {
    let t = typed.trim();
    let value = match (t.parse::<i64>(), t.parse::<f64>(), t.parse::<bool>()) {
        (Ok(i), ..) => Value::Int(i),
        (_, Ok(x), _) => Value::Float(x),
        (.., Ok(b)) => Value::Bool(b),
        _ => return String::new(),
    };
    match (key.write)(&mut Settings::default(), key, &value) {
        Some(()) => format!("; did you mean {value}, without quotes?"),
        None => String::new(),
    }
}

/// The value `look` gives `key` in place of its default, if it gives one.
pub fn look_value(look: Look, key: &Key) -> Option<Value> {
    looks::preset(look, key.name).map(|p| match p {
        Preset::Int(i) => Value::Int(i),
        Preset::Float(x) => Value::Float(x),
        Preset::Bool(b) => Value::Bool(b),
        Preset::Str(s) => Value::Str(s.into()),
    })
}

/// What `value` of `key` means under `look`: the look's value where
/// `value` is the key's default and the look gives one, else `value`.
pub fn under_look(look: Look, key: &Key, value: Value) -> Value {
    match look_value(look, key) {
        Some(v) if value == (key.default)() => v,
        _ => value,
    }
}

/// Gives `key` the look's value if it holds its own default: the rule
/// that puts a look under every key a person sets. A key set to its
/// default under a look therefore shows the look's value (to keep the
/// default there, choose the look "ours").
pub fn follow_look(settings: &mut Settings, key: &Key) {
    let now = (key.read)(settings);
    let wanted = under_look(settings.look, key, now.clone());
    if wanted != now {
        let _ = write(settings, key, &wanted);
    }
}

/// Sets `key` in `settings` from a value its kind allows (`None` if it
/// does not); a new look also moves the keys that follow it.
fn write(settings: &mut Settings, key: &Key, value: &Value) -> Option<()> {
    if key.name != LOOK.name {
        return (key.write)(settings, key, value);
    }
    let old = settings.look;
    (key.write)(settings, key, value)?;
    let new = std::mem::replace(&mut settings.look, old);
    switch_look(settings, new);
    Some(())
}

/// Changes the look: keys holding the old look's values return to their
/// defaults, then every key at its default takes the new look's value.
fn switch_look(settings: &mut Settings, look: Look) {
    for key in KEYS {
        if look_value(settings.look, key).is_some_and(|v| v == (key.read)(settings)) {
            let _ = write(settings, key, &(key.default)());
        }
    }
    settings.look = look;
    for key in KEYS {
        follow_look(settings, key);
    }
}

/// The current value of `key` in `settings`, as it would be written in TOML.
pub fn get(settings: &Settings, key: &Key) -> Value {
    (key.read)(settings)
}
