//! How each kind of key is shown and stepped on the screen: sliders for
//! numbers, check boxes for booleans, spinners for choices. Every range comes
//! from the key table; every change goes through `keys::apply`.

use crate::settings::Settings;
use crate::settings::keys::{self, Key, Kind, Value};

/// The control a key is edited with.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Widget {
    /// A number in a range: minus, track, plus.
    Slider,
    /// On or off.
    Check,
    /// One of a few values, stepped with arrows.
    Choice,
    /// Typed text (a folder path).
    Text,
    /// A seed: "random" or a number typed in.
    Seed,
}

/// The control for `key`.
pub fn widget(key: &Key) -> Widget {
    match key.kind {
        Kind::Int { .. } | Kind::Float { .. } => Widget::Slider,
        Kind::Bool => Widget::Check,
        Kind::Choice(_) | Kind::QuarterTurn | Kind::IntOrAuto { .. } | Kind::AmountOrVaried => {
            Widget::Choice
        }
        Kind::Path => Widget::Text,
        Kind::Seed => Widget::Seed,
    }
}

/// True when the key takes typed text (numbers may be typed too).
pub fn accepts_typing(key: &Key) -> bool {
    !matches!(
        key.kind,
        Kind::Bool
            | Kind::Choice(_)
            | Kind::QuarterTurn
            | Kind::IntOrAuto { .. }
            | Kind::AmountOrVaried
    )
}

const QUARTER_TURNS: &[i64] = &[0, 90, 180, 270];

/// The slider's range, for numeric keys.
pub fn range(key: &Key) -> Option<(f64, f64)> {
    match key.kind {
        Kind::Int { min, max } => Some((min as f64, max as f64)),
        Kind::Float { min, max } => Some((min, max)),
        _ => None,
    }
}

/// The current value of a numeric key as a number.
pub fn number(settings: &Settings, key: &Key) -> Option<f64> {
    match keys::get(settings, key) {
        Value::Int(i) => Some(i as f64),
        Value::Float(x) => Some(x as f32 as f64),
        _ => None,
    }
}

/// Wide ranges (seconds up to an hour) use a square-root slider and steps
/// that grow with the value, so both 2 s and 20 min can be picked.
fn is_wide(key: &Key) -> bool {
    matches!(key.kind, Kind::Float { min, max } if min >= 0.0 && max >= 100.0)
}

/// 1, 2 or 5 times a power of ten, at most `x`.
fn nice_floor(x: f64) -> f64 {
    if x <= 0.0 || !x.is_finite() {
        return 1.0;
    }
    let p = 10f64.powf(x.log10().floor());
    let m = x / p;
    let k = if m >= 5.0 {
        5.0
    } else if m >= 2.0 {
        2.0
    } else {
        1.0
    };
    k * p
}

/// One arrow-key step of a numeric key at value `v`.
pub fn step(key: &Key, v: f64) -> f64 {
    match key.kind {
        Kind::Int { .. } => 1.0,
        Kind::Float { min, max } => {
            let fine = nice_floor((max - min) / 100.0);
            if is_wide(key) {
                nice_floor((v.abs() / 10.0).max((max - min) / 1000.0)).min(fine)
            } else {
                fine
            }
        }
        _ => 0.0,
    }
}

/// Where value `v` sits on the slider track, 0.0 to 1.0.
pub fn fraction(key: &Key, v: f64) -> f64 {
    let Some((min, max)) = range(key) else {
        return 0.0;
    };
    let f = ((v - min) / (max - min)).clamp(0.0, 1.0);
    if is_wide(key) { f.sqrt() } else { f }
}

/// The value at fraction `f` of the slider track, snapped to a step.
pub fn at_fraction(key: &Key, f: f64) -> Option<f64> {
    let (min, max) = range(key)?;
    let f = f.clamp(0.0, 1.0);
    let f = if is_wide(key) { f * f } else { f };
    let raw = min + f * (max - min);
    Some(snap(key, raw, step(key, raw)))
}

fn snap(key: &Key, v: f64, step: f64) -> f64 {
    let (min, max) = range(key).unwrap_or((v, v));
    let snapped = if step > 0.0 {
        (v / step).round() * step
    } else {
        v
    };
    // Round away binary noise (0.1 * 3) before it reaches the file.
    let tidy = (snapped * 1e6).round() / 1e6;
    tidy.clamp(min, max)
}

/// The value to store for number `v` of a numeric key.
pub fn number_value(key: &Key, v: f64) -> Value {
    match key.kind {
        Kind::Int { .. } => Value::Int(v.round() as i64),
        _ => Value::Float(v),
    }
}

/// Moves a numeric key `steps` steps (negative: down); `big` moves a tenth
/// of the range at a time. Returns the new value.
pub fn stepped(key: &Key, v: f64, steps: i32, big: bool) -> Option<f64> {
    let (min, max) = range(key)?;
    let unit = if big {
        let tenth = (max - min) / 10.0;
        match key.kind {
            Kind::Int { .. } => tenth.round().max(1.0),
            _ => nice_floor(tenth),
        }
    } else {
        step(key, v)
    };
    let target = v + unit * f64::from(steps);
    let unit_there = if big {
        unit
    } else {
        step(key, target).min(unit)
    };
    Some(snap(key, target, unit_there))
}

/// The choices of a choice key, as values.
pub fn choices(key: &Key) -> Vec<Value> {
    match key.kind {
        Kind::Choice(names) => names.iter().map(|n| Value::Str((*n).into())).collect(),
        Kind::QuarterTurn => QUARTER_TURNS.iter().map(|d| Value::Int(*d)).collect(),
        Kind::IntOrAuto { min, max } => std::iter::once(Value::Str("auto".into()))
            .chain((min..=max).map(Value::Int))
            .collect(),
        Kind::AmountOrVaried => std::iter::once(Value::Str("varied".into()))
            .chain(keys::AMOUNT_MENU.iter().map(|&a| Value::Float(a)))
            .collect(),
        _ => Vec::new(),
    }
}

/// The choice `delta` places from the current one, wrapping around.
pub fn next_choice(settings: &Settings, key: &Key, delta: i32) -> Option<Value> {
    let all = choices(key);
    if all.is_empty() {
        return None;
    }
    let now = keys::get(settings, key);
    let i = all.iter().position(|c| *c == now).unwrap_or(0) as i32;
    let n = all.len() as i32;
    Some(all[(i + delta).rem_euclid(n) as usize].clone())
}

/// The value as shown on the screen.
pub fn display(settings: &Settings, key: &Key) -> String {
    let value = keys::get(settings, key);
    match (key.kind, &value) {
        (Kind::QuarterTurn, Value::Int(d)) => format!("{d} degrees"),
        (Kind::Bool, Value::Bool(b)) => if *b { "on" } else { "off" }.into(),
        (Kind::Path, Value::Str(s)) if s.is_empty() => "(none)".into(),
        (_, Value::Str(s)) => s.clone(),
        (_, Value::Float(x)) => format_float(*x),
        (_, v) => v.to_string(),
    }
}

/// The shortest text that reads back as the same f32, with a decimal point.
pub fn format_float(x: f64) -> String {
    let s = (x as f32).to_string();
    if s.contains('.') || s.contains('e') || s.contains("inf") || s.contains("NaN") {
        s
    } else {
        format!("{s}.0")
    }
}

/// The name of a key as a person reads it: `low_detail` -> `Low detail`.
pub fn label(key: &Key) -> String {
    let mut s = key.name.replace('_', " ");
    if let Some(first) = s.get(0..1) {
        let upper = first.to_uppercase();
        s.replace_range(0..1, &upper);
    }
    s
}

/// Whether `key` matters for the generator chosen in `settings`: the key
/// docs say "square generators:", "triangle generator:" or "brownian
/// generator:" for those that only one family uses. Rows that do not
/// matter are drawn dimmed.
pub fn matters(settings: &Settings, key: &Key) -> bool {
    use crate::settings::Generator;
    let g = settings.generator;
    if key.doc.starts_with("square generators:") {
        matches!(g, Generator::Square | Generator::Diamond)
    } else if key.doc.starts_with("triangle generator:") {
        g == Generator::Triangle
    } else if key.doc.starts_with("brownian generator:") {
        g == Generator::Brownian
    } else {
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nice_steps_are_one_two_or_five() {
        assert_eq!(nice_floor(0.0475), 0.02);
        assert_eq!(nice_floor(9.99), 5.0);
        assert_eq!(nice_floor(3.6), 2.0);
        assert_eq!(nice_floor(0.6), 0.5);
    }

    #[test]
    fn a_generators_own_keys_matter_only_for_it() {
        use crate::settings::Generator;
        let of = |generator| Settings {
            generator,
            ..Settings::default()
        };
        let brownian = of(Generator::Brownian);
        assert!(matters(&brownian, &keys::HURST));
        assert!(!matters(&brownian, &keys::CRAGGINESS));
        assert!(!matters(&brownian, &keys::ROUGHNESS));
        assert!(matters(&brownian, &keys::HEIGHT));
        assert!(!matters(&of(Generator::Diamond), &keys::HURST));
        assert!(matters(&of(Generator::Diamond), &keys::CRAGGINESS));
        assert!(!matters(&of(Generator::Triangle), &keys::HURST));
    }

    #[test]
    fn labels_read_like_words() {
        let key = &keys::LOW_DETAIL;
        assert_eq!(label(key), "Low detail");
    }
}
