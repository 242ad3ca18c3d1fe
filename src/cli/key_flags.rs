//! Every preference key as a flag of its own, the way xscreensaver hacks take
//! options (`-cragginess 40`, `--cragginess 40`, `-color sonar`; booleans as
//! `-shadows` / `-no-shadows`). Read from the key table, so a new key is a new
//! flag with nothing else to write. `--set key=value` stays.

use super::UsageError;
use crate::settings::keys::{self, Key, Kind};

/// The flag a key is written as on a command line: dashes, not underscores
/// (`draw_seconds` is `-draw-seconds`).
pub fn flag_name(key: &Key) -> String {
    key.name.replace('_', "-")
}

/// Every key's flag without its dashes, and `no-NAME` for a boolean's: what
/// a mistyped flag is compared with.
pub(super) fn names() -> impl Iterator<Item = String> {
    keys::KEYS.iter().flat_map(|key| {
        let name = flag_name(key);
        let negated = (key.kind == Kind::Bool).then(|| format!("no-{name}"));
        std::iter::once(name).chain(negated)
    })
}

/// What an argument names, if it is a key's flag: the key, and for a
/// boolean the value the flag itself says (`-shadows` true, `-no-shadows` false).
pub(super) fn lookup(arg: &str) -> Option<(&'static Key, Option<bool>)> {
    let bare = arg.strip_prefix("--").or_else(|| arg.strip_prefix('-'))?;
    let name = bare.replace('-', "_");
    if let Some(key) = keys::find(&name) {
        let own = (key.kind == Kind::Bool).then_some(true);
        return Some((key, own));
    }
    let key = keys::find(name.strip_prefix("no_")?)?;
    (key.kind == Kind::Bool).then_some((key, Some(false)))
}

/// The `(key, value)` a key's flag sets; `next` gives the following argument
/// when the flag takes one.
pub(super) fn take(
    arg: &str,
    key: &Key,
    own: Option<bool>,
    next: impl FnOnce() -> Option<String>,
) -> Result<(String, String), UsageError> {
    let value = match own {
        Some(b) => b.to_string(),
        None => next()
            .ok_or_else(|| UsageError(format!("`{arg}` needs a value: {}", key.kind.allowed())))?,
    };
    Ok((key.name.to_string(), value))
}
