//! Files for the systems we plug into, generated from the key table so they
//! can never drift from the program: xscreensaver's settings description
//! (`contrib/mountains.xml`) and the man page (`contrib/mountains.6`).
//! `sh scripts/contrib_files.sh` writes both; a test fails when the committed
//! copies differ from what the program prints.

pub mod man_page;
pub mod xscreensaver;

use crate::settings::Settings;
use crate::settings::keys::{self, Key, Value};

/// A key's default as it is typed on a command line (strings unquoted).
pub fn default_text(key: &Key) -> String {
    match keys::get(&Settings::default(), key) {
        Value::Str(s) => s,
        v => v.to_string(),
    }
}

/// A key's name as a label: "draw_seconds" is "Draw seconds".
pub fn label(key: &Key) -> String {
    let words = key.name.replace('_', " ");
    let mut chars = words.chars();
    chars.next().map_or(String::new(), |c| {
        c.to_uppercase().chain(chars).collect::<String>()
    })
}
