//! How each type of `Settings` field is written as a [`Value`] and read
//! back under its key's [`Kind`]: the parsing the key table's rows share.

use serde::Deserialize;
use serde::de::IntoDeserializer;

use super::kind::{Key, Kind, Value};
use crate::settings::{
    Clouds, ColorMode, Detail, Generator, Look, Monitors, OnBattery, Profile, Shading, Sun,
    ViewKind, WaterLine, World,
};

/// How a `Settings` field's type is written as a [`Value`] and read back
/// under its key's [`Kind`] (the row macro picks the impl by the field).
pub(super) trait Field: Sized {
    /// The field's value as it would be written in TOML.
    fn value(&self) -> Value;
    /// The field's value from one `key` allows; `None` if it does not.
    fn parse(key: &Key, value: &Value) -> Option<Self>;
}

impl Field for u32 {
    fn value(&self) -> Value {
        Value::Int((*self).into())
    }
    fn parse(key: &Key, value: &Value) -> Option<Self> {
        match key.kind {
            Kind::QuarterTurn => rotation(value),
            _ => int(key, value).and_then(|i| u32::try_from(i).ok()),
        }
    }
}

impl Field for f32 {
    fn value(&self) -> Value {
        // Through the f32's shortest decimal, as a person writes it: 0.8
        // reads back as 0.8 (the row's default, what `--help` shows), not
        // as the 0.800000011920929 the widened bits spell.
        Value::Float(self.to_string().parse().unwrap_or((*self).into()))
    }
    fn parse(key: &Key, value: &Value) -> Option<Self> {
        float(key, value)
    }
}

impl Field for bool {
    fn value(&self) -> Value {
        Value::Bool(*self)
    }
    fn parse(_: &Key, value: &Value) -> Option<Self> {
        match value {
            Value::Bool(b) => Some(*b),
            _ => None,
        }
    }
}

/// The seed: "random" (`None`) or a number.
impl Field for Option<u64> {
    fn value(&self) -> Value {
        // Seeds that fit a TOML integer are written as one; larger ones as a string.
        self.map_or(Value::Str("random".into()), |seed| {
            i64::try_from(seed).map_or(Value::Str(seed.to_string()), Value::Int)
        })
    }
    fn parse(_: &Key, value: &Value) -> Option<Self> {
        seed(value)
    }
}

impl Field for Detail {
    fn value(&self) -> Value {
        match self {
            Detail::Auto => Value::Str("auto".into()),
            Detail::Level(n) => Value::Int((*n).into()),
        }
    }
    fn parse(key: &Key, value: &Value) -> Option<Self> {
        detail(key, value)
    }
}

/// Cloud: "varied" or an amount.
impl Field for Clouds {
    fn value(&self) -> Value {
        match self {
            Clouds::Varied => Value::Str("varied".into()),
            Clouds::Amount(a) => a.value(),
        }
    }
    fn parse(_: &Key, value: &Value) -> Option<Self> {
        let amount = match value {
            Value::Str(s) if s == "varied" => return Some(Clouds::Varied),
            Value::Int(i) => *i as f64,
            Value::Float(x) => *x,
            _ => return None,
        };
        (0.0..=1.0)
            .contains(&amount)
            .then_some(Clouds::Amount(amount as f32))
    }
}

/// A folder: "" is none.
impl Field for Option<String> {
    fn value(&self) -> Value {
        Value::Str(self.clone().unwrap_or_default())
    }
    fn parse(_: &Key, value: &Value) -> Option<Self> {
        match value {
            Value::Str(s) if s.is_empty() => Some(None),
            Value::Str(s) => Some(Some(s.clone())),
            _ => None,
        }
    }
}

/// The settings enums, each written by its name in the file.
macro_rules! choice_fields {
    ($($t:ty),*) => {$(
        impl Field for $t {
            fn value(&self) -> Value {
                Value::Str(self.name().into())
            }
            fn parse(key: &Key, value: &Value) -> Option<Self> {
                choice(key, value)
            }
        }
    )*};
}

choice_fields!(
    Look, World, Generator, Profile, WaterLine, ColorMode, Sun, Shading, ViewKind, Monitors,
    OnBattery
);

fn int(key: &Key, value: &Value) -> Option<i64> {
    let Kind::Int { min, max } = key.kind else {
        return None;
    };
    match value {
        Value::Int(i) if (min..=max).contains(i) => Some(*i),
        _ => None,
    }
}

fn detail(key: &Key, value: &Value) -> Option<Detail> {
    let Kind::IntOrAuto { min, max } = key.kind else {
        return None;
    };
    match value {
        Value::Str(s) if s == "auto" => Some(Detail::Auto),
        Value::Int(i) if (min..=max).contains(i) => Some(Detail::Level(*i as u32)),
        _ => None,
    }
}

fn float(key: &Key, value: &Value) -> Option<f32> {
    let Kind::Float { min, max } = key.kind else {
        return None;
    };
    let x = match value {
        Value::Int(i) => *i as f64,
        Value::Float(x) => *x,
        _ => return None,
    };
    (x.is_finite() && (min..=max).contains(&x)).then_some(x as f32)
}

fn choice<T: for<'de> Deserialize<'de>>(key: &Key, value: &Value) -> Option<T> {
    let (Kind::Choice(names), Value::Str(s)) = (key.kind, value) else {
        return None;
    };
    if !names.contains(&s.as_str()) {
        return None;
    }
    let de: serde::de::value::StrDeserializer<'_, serde::de::value::Error> =
        s.as_str().into_deserializer();
    T::deserialize(de).ok()
}

fn seed(value: &Value) -> Option<Option<u64>> {
    match value {
        Value::Int(i) => u64::try_from(*i).ok().map(Some),
        Value::Str(s) if s == "random" => Some(None),
        Value::Str(s) => s.parse::<u64>().ok().map(Some),
        _ => None,
    }
}

fn rotation(value: &Value) -> Option<u32> {
    let Value::Int(r) = *value else { return None };
    matches!(r, 0 | 90 | 180 | 270).then_some(r as u32)
}
