//! What a key is: its row's shape ([`Key`]), the values it accepts
//! ([`Kind`]), a value as a person writes it ([`Value`]) and what changing
//! it does on screen ([`Change`]).

use crate::settings::Settings;

/// A value as written by a user, before it is checked against a key.
#[derive(Debug, Clone, PartialEq)]
pub enum Value {
    /// A TOML integer.
    Int(i64),
    /// A TOML float.
    Float(f64),
    /// A TOML boolean.
    Bool(bool),
    /// A TOML string.
    Str(String),
}

impl Value {
    /// The value for a message: a long string is cut (see `quote::quoted`).
    pub fn shown(&self) -> String {
        match self {
            Value::Str(s) => crate::quote::quoted(s),
            v => v.to_string(),
        }
    }
}

impl std::fmt::Display for Value {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Value::Int(i) => write!(f, "{i}"),
            // With its point: `detail = 8.0` is not the integer 8.
            Value::Float(x) => write!(f, "{x:?}"),
            Value::Bool(b) => write!(f, "{b}"),
            Value::Str(s) => write!(f, "\"{s}\""),
        }
    }
}

/// What values a key accepts.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Kind {
    /// A whole number in `min..=max`.
    Int {
        /// Smallest allowed.
        min: i64,
        /// Largest allowed.
        max: i64,
    },
    /// A number in `min..=max`; integers are accepted too.
    Float {
        /// Smallest allowed.
        min: f64,
        /// Largest allowed.
        max: f64,
    },
    /// "auto", or a whole number in `min..=max`.
    IntOrAuto {
        /// Smallest allowed.
        min: i64,
        /// Largest allowed.
        max: i64,
    },
    /// `true` or `false`.
    Bool,
    /// One of these strings.
    Choice(&'static [&'static str]),
    /// A whole number from 0 to 2^64-1 (as an integer or a string of digits), or "random".
    Seed,
    /// A folder path; "" means none.
    Path,
    /// 0, 90, 180 or 270 (degrees).
    QuarterTurn,
    /// "varied" (drawn per mountain), or a number in `0..=1`.
    AmountOrVaried,
}

/// The amounts a menu offers for a [`Kind::AmountOrVaried`] key, after
/// "varied" (any other number in range may still be written in the file).
pub const AMOUNT_MENU: &[f64] = &[0.0, 0.25, 0.5, 0.75, 1.0];

impl Kind {
    /// The allowed values, in words, for error messages and `--help`.
    pub fn allowed(&self) -> String {
        match self {
            Kind::Int { min, max } => format!("an integer from {min} to {max}"),
            Kind::Float { min, max } => format!("a number from {min} to {max}"),
            Kind::IntOrAuto { min, max } => format!("\"auto\" or an integer from {min} to {max}"),
            Kind::Bool => "true or false".into(),
            Kind::Choice(names) => format!("one of {}", quoted_list(names)),
            Kind::Seed => "\"random\" or an integer from 0 to 18446744073709551615".into(),
            Kind::Path => "a folder path as a string (\"\" for none)".into(),
            Kind::QuarterTurn => "0, 90, 180 or 270".into(),
            Kind::AmountOrVaried => "\"varied\" or a number from 0 to 1".into(),
        }
    }
}

fn quoted_list(names: &[&str]) -> String {
    let quoted: Vec<String> = names.iter().map(|n| format!("\"{n}\"")).collect();
    quoted.join(", ")
}

/// What a changed key does to the mountain on screen. Mountain Terrain's
/// settings dialog: "Choosing OK causes the program to redraw the mountains
/// with the options that apply to the current set (Color, Relative Depth,
/// Low Detail). Other changes will be used for the next data set."
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Change {
    /// The same heights drawn again (colours, light, the camera).
    Repaint,
    /// The same mountain made again from its seed at the new value, then
    /// drawn (Low Detail, and the detail it halves).
    Remake,
    /// Shapes the next mountain only.
    Next,
    /// Nothing on screen changes (the slide show's pacing, monitors, folders).
    Nothing,
}

/// One preference key.
#[derive(Debug, Clone, Copy)]
pub struct Key {
    /// The name used in TOML, `--set` and the settings screen.
    pub name: &'static str,
    /// What values it accepts.
    pub kind: Kind,
    /// What a change of it does to the mountain on screen.
    pub change: Change,
    /// One line for `--help` and the settings screen.
    pub doc: &'static str,
    /// Its value when nothing sets it (what `Settings::default` holds).
    pub default: fn() -> Value,
    /// Its value in a `Settings`.
    pub(super) read: fn(&Settings) -> Value,
    /// Sets its field in a `Settings` from a value `kind` allows; `None`
    /// otherwise. Only the field: what a change moves besides (a look's
    /// keys) is `keys::apply`'s.
    pub(super) write: fn(&mut Settings, &Key, &Value) -> Option<()>,
}
