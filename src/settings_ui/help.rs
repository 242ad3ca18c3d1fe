//! The help under the settings list: what the focused key does and takes,
//! or how to move about. The layout leaves room for the longest; draw.rs
//! draws it.

use super::values;
use super::wrap::wrap;
use crate::settings::keys::Key;

/// How a line of help is set: plain, or as a hint.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Tone {
    /// What the key does.
    Text,
    /// What it allows, how to type, what the keys do.
    Hint,
}

/// The line added while a value on the screen differs from the file.
pub(super) const CHANGED: &str = "* changed here; OK saves, Cancel forgets.";

/// Lines kept for the message under the help (what happened, what is
/// wrong), so a short one does not push the help out.
pub(super) const MESSAGE_ROWS: usize = 3;

/// The help for the focused key, or for the buttons when `key` is `None`;
/// each line with its tone, before wrapping.
pub(super) fn lines(key: Option<&Key>) -> Vec<(String, Tone)> {
    let Some(key) = key else {
        let moving = "Tab moves, arrows change, Enter saves, Esc cancels.";
        return vec![(moving.into(), Tone::Hint)];
    };
    let mut lines = vec![
        (key.doc.to_string(), Tone::Text),
        (format!("Allowed: {}", key.kind.allowed()), Tone::Hint),
    ];
    if values::accepts_typing(key) {
        let typing = "Type a value and press Enter; Esc cancels.";
        lines.push((typing.into(), Tone::Hint));
    }
    lines
}

/// Lines of `chars` characters that the longest help of `keys` takes,
/// with the changed line and the message under it.
pub(super) fn most_rows(keys: &[Key], chars: usize) -> usize {
    let wrapped =
        |key: Option<&Key>| -> usize { lines(key).iter().map(|(l, _)| wrap(l, chars).len()).sum() };
    let longest = keys.iter().map(|k| wrapped(Some(k))).max();
    longest.unwrap_or(0).max(wrapped(None)) + 1 + MESSAGE_ROWS
}
