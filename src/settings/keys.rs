//! The table of every preference key: its name, what values it allows, and
//! how it reads and writes `Settings`. TOML files, `--set`, `--help` and the
//! settings screen all go through this one table, so a range is checked in
//! exactly one place.

use serde::Deserialize;
use serde::de::IntoDeserializer;

use super::{ColorMode, Detail, Generator, Monitors, Profile, Settings, Sun, ViewKind, WaterLine};

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
}

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
    read: fn(&Settings) -> Value,
    /// Sets it in a `Settings` from a value `kind` allows; `None` otherwise.
    write: fn(&mut Settings, &Key, &Value) -> Option<()>,
}

const GENERATORS: &[&str] = &["square", "diamond", "triangle"];
const PROFILES: &[&str] = &["slope", "peak", "bay", "massif"];
const COLORS: &[&str] = &[
    "natural", "gray", "red", "green", "blue", "yellow", "cyan", "purple", "sonar", "outline",
    "mono", "ridges",
];
const VIEWS: &[&str] = &["vista", "oblique", "perspective"];
const WATER_LINES: &[&str] = &["coast", "generator"];
const SUNS: &[&str] = &["varied", "morning", "midday", "evening", "classic"];
const MONITORS: &[&str] = &["all", "primary"];

/// One row of the table: what the key is, its default, then how it is
/// read from and written into `Settings`.
const fn key(
    name: &'static str,
    kind: Kind,
    change: Change,
    doc: &'static str,
    default: fn() -> Value,
    read: fn(&Settings) -> Value,
    write: fn(&mut Settings, &Key, &Value) -> Option<()>,
) -> Key {
    Key {
        name,
        kind,
        change,
        doc,
        default,
        read,
        write,
    }
}

/// Every key, in the order the settings file and `--help` list them.
pub const KEYS: &[Key] = &[
    key(
        "seed",
        Kind::Seed,
        Change::Next,
        "seed of the next mountain; \"random\" picks a new one each time",
        || Value::Str("random".into()),
        |s| s.seed.map_or(Value::Str("random".into()), seed_value),
        |s, _, value| {
            s.seed = seed(value)?;
            Some(())
        },
    ),
    key(
        "generator",
        Kind::Choice(GENERATORS),
        Change::Next,
        "how heights are made",
        || Value::Str("diamond".into()),
        |s| named(&s.generator),
        |s, key, value| {
            s.generator = choice::<Generator>(key, value)?;
            Some(())
        },
    ),
    key(
        "cragginess",
        Kind::Int { min: 1, max: 128 },
        Change::Next,
        "square generators: how sharply heights crease",
        || Value::Int(96),
        |s| Value::Int(s.cragginess.into()),
        |s, key, value| {
            s.cragginess = int(key, value)? as u32;
            Some(())
        },
    ),
    key(
        "elevation",
        Kind::Float {
            min: 1.0,
            max: 1000.0,
        },
        Change::Next,
        "square generators: range of the corner heights",
        || Value::Float(100.0),
        |s| Value::Float(s.elevation.into()),
        |s, key, value| {
            s.elevation = float(key, value)?;
            Some(())
        },
    ),
    key(
        "roughness",
        Kind::Float { min: 1.0, max: 5.0 },
        Change::Next,
        "triangle generator: smoothness base (higher = smoother sides)",
        || Value::Float(2.0),
        |s| Value::Float(s.roughness.into()),
        |s, key, value| {
            s.roughness = float(key, value)?;
            Some(())
        },
    ),
    key(
        "contour",
        Kind::Float {
            min: 0.25,
            max: 5.0,
        },
        Change::Next,
        "triangle generator: power on heights (<1 concave, >1 convex)",
        || Value::Float(1.0),
        |s| Value::Float(s.contour.into()),
        |s, key, value| {
            s.contour = float(key, value)?;
            Some(())
        },
    ),
    key(
        "profile",
        Kind::Choice(PROFILES),
        Change::Next,
        "triangle generator: overall shape",
        || Value::Str("slope".into()),
        |s| named(&s.profile),
        |s, key, value| {
            s.profile = choice::<Profile>(key, value)?;
            Some(())
        },
    ),
    key(
        "height",
        Kind::Int { min: 1, max: 10 },
        Change::Next,
        "height of the peaks; also raises the treeline and snow",
        || Value::Int(5),
        |s| Value::Int(s.height.into()),
        |s, key, value| {
            s.height = int(key, value)? as u32;
            Some(())
        },
    ),
    key(
        "erosion",
        Kind::Float { min: 0.0, max: 1.0 },
        Change::Next,
        "rain wearing gullies into the slopes and silt at their feet (0 = none)",
        || Value::Float(0.5),
        |s| Value::Float(s.erosion.into()),
        |s, key, value| {
            s.erosion = float(key, value)?;
            Some(())
        },
    ),
    key(
        "detail",
        Kind::IntOrAuto { min: 4, max: 12 },
        Change::Remake,
        "grid of 2^detail+1 points a side; \"auto\" fits it to the screen",
        || Value::Str("auto".into()),
        |s| match s.detail {
            Detail::Auto => Value::Str("auto".into()),
            Detail::Level(n) => Value::Int(n.into()),
        },
        |s, key, value| {
            s.detail = detail(key, value)?;
            Some(())
        },
    ),
    key(
        "low_detail",
        Kind::Bool,
        Change::Remake,
        "a quarter of the points: larger faces, faster drawing",
        || Value::Bool(false),
        |s| Value::Bool(s.low_detail),
        |s, _, value| {
            s.low_detail = boolean(value)?;
            Some(())
        },
    ),
    key(
        "sea_level",
        Kind::Float {
            min: -1.0,
            max: 1.0,
        },
        Change::Next,
        "water line as a fraction of the relief above or below water_line",
        || Value::Float(0.0),
        |s| Value::Float(s.sea_level.into()),
        |s, key, value| {
            s.sea_level = float(key, value)?;
            Some(())
        },
    ),
    key(
        "water_line",
        Kind::Choice(WATER_LINES),
        Change::Next,
        "sea_level 0: a coast on every mountain, or the generator's own zero",
        || Value::Str("coast".into()),
        |s| named(&s.water_line),
        |s, key, value| {
            s.water_line = choice::<WaterLine>(key, value)?;
            Some(())
        },
    ),
    key(
        "color",
        Kind::Choice(COLORS),
        Change::Repaint,
        "colour mode or filter",
        || Value::Str("natural".into()),
        |s| named(&s.color),
        |s, key, value| {
            s.color = choice::<ColorMode>(key, value)?;
            Some(())
        },
    ),
    key(
        "relative_depth",
        Kind::Bool,
        Change::Repaint,
        "darker water over deeper ground",
        || Value::Bool(true),
        |s| Value::Bool(s.relative_depth),
        |s, _, value| {
            s.relative_depth = boolean(value)?;
            Some(())
        },
    ),
    key(
        "shadows",
        Kind::Bool,
        Change::Repaint,
        "cast shadows from the light",
        || Value::Bool(true),
        |s| Value::Bool(s.shadows),
        |s, _, value| {
            s.shadows = boolean(value)?;
            Some(())
        },
    ),
    key(
        "sun",
        Kind::Choice(SUNS),
        Change::Repaint,
        "time of day of the light; \"varied\" draws one per mountain",
        || Value::Str("varied".into()),
        |s| named(&s.sun),
        |s, key, value| {
            s.sun = choice::<Sun>(key, value)?;
            Some(())
        },
    ),
    key(
        "view",
        Kind::Choice(VIEWS),
        Change::Repaint,
        "projection",
        || Value::Str("vista".into()),
        |s| named(&s.view),
        |s, key, value| {
            s.view = choice::<ViewKind>(key, value)?;
            Some(())
        },
    ),
    key(
        "rotation",
        Kind::QuarterTurn,
        Change::Repaint,
        "side the mountain is seen from, in degrees",
        || Value::Int(0),
        |s| Value::Int(s.rotation.into()),
        |s, _, value| {
            s.rotation = rotation(value)?;
            Some(())
        },
    ),
    key(
        "auto_redraw",
        Kind::Bool,
        Change::Nothing,
        "start a new mountain after the pause (slide show)",
        || Value::Bool(true),
        |s| Value::Bool(s.auto_redraw),
        |s, _, value| {
            s.auto_redraw = boolean(value)?;
            Some(())
        },
    ),
    key(
        "draw_seconds",
        Kind::Float {
            min: 0.0,
            max: 600.0,
        },
        Change::Nothing,
        "seconds to draw one mountain strip by strip",
        || Value::Float(8.0),
        |s| Value::Float(s.draw_seconds.into()),
        |s, key, value| {
            s.draw_seconds = float(key, value)?;
            Some(())
        },
    ),
    key(
        "pause_seconds",
        Kind::Float {
            min: 0.0,
            max: 3600.0,
        },
        Change::Nothing,
        "seconds to hold a finished mountain",
        || Value::Float(10.0),
        |s| Value::Float(s.pause_seconds.into()),
        |s, key, value| {
            s.pause_seconds = float(key, value)?;
            Some(())
        },
    ),
    key(
        "monitors",
        Kind::Choice(MONITORS),
        Change::Nothing,
        "full screen: a mountain on every monitor, or the primary only",
        || Value::Str("all".into()),
        |s| named(&s.monitors),
        |s, key, value| {
            s.monitors = choice::<Monitors>(key, value)?;
            Some(())
        },
    ),
    key(
        "heightmaps_dir",
        Kind::Path,
        Change::Nothing,
        "folder of PNG heightmaps mixed into the slide show",
        || Value::Str(String::new()),
        |s| Value::Str(s.heightmaps_dir.clone().unwrap_or_default()),
        |s, _, value| {
            s.heightmaps_dir = path(value)?;
            Some(())
        },
    ),
];

/// `value` clamped into number key `name`'s range, or the key's default if
/// it is NaN: for code given `Settings` built by hand rather than read
/// through this table (the generator, the palette), so no value can stall
/// them.
pub fn clamp_float(name: &str, value: f32) -> f32 {
    let key = find(name).unwrap_or_else(|| unreachable!("`{name}` is not a key"));
    let (Kind::Float { min, max }, Value::Float(default)) = (key.kind, (key.default)()) else {
        unreachable!("`{name}` is not a number key")
    };
    if value.is_nan() {
        default as f32
    } else {
        value.clamp(min as f32, max as f32)
    }
}

/// `value` clamped into whole-number key `name`'s range (see
/// [`clamp_float`]).
pub fn clamp_int(name: &str, value: u32) -> u32 {
    let Some(Kind::Int { min, max }) = find(name).map(|k| k.kind) else {
        unreachable!("`{name}` is not a whole-number key")
    };
    (i64::from(value)).clamp(min, max) as u32
}

impl Default for Settings {
    /// Every key at the default its row in the key table gives.
    fn default() -> Self {
        let mut s = Settings::unset();
        for key in KEYS {
            if let Err(e) = apply(&mut s, key, &(key.default)()) {
                unreachable!("the default of `{}` is not allowed: {e}", key.name);
            }
        }
        s
    }
}

impl Settings {
    /// Every field with a placeholder, each overwritten by `default` from
    /// the key table (the values here mean nothing).
    fn unset() -> Self {
        Settings {
            seed: None,
            generator: Generator::Square,
            cragginess: 0,
            elevation: 0.0,
            roughness: 0.0,
            contour: 0.0,
            profile: Profile::Slope,
            height: 0,
            erosion: 0.0,
            detail: Detail::Auto,
            low_detail: false,
            sea_level: 0.0,
            water_line: WaterLine::Coast,
            color: ColorMode::Natural,
            relative_depth: false,
            shadows: false,
            sun: Sun::Varied,
            view: ViewKind::Vista,
            rotation: 0,
            auto_redraw: false,
            draw_seconds: 0.0,
            pause_seconds: 0.0,
            monitors: Monitors::All,
            heightmaps_dir: None,
        }
    }
}

/// Gives `to` the value `key` has in `from`. A value read from a Settings
/// is one the key allows, so this cannot fail.
pub fn copy(key: &Key, from: &Settings, to: &mut Settings) {
    let _ = (key.write)(to, key, &(key.read)(from));
}

/// Looks a key up by name.
pub fn find(name: &str) -> Option<&'static Key> {
    KEYS.iter().find(|k| k.name == name)
}

/// The known key closest to a misspelt one, if any is close.
pub fn suggest(name: &str) -> Option<&'static str> {
    KEYS.iter()
        .map(|k| (edit_distance(name, k.name), k.name))
        .filter(|(d, k)| *d <= 2.max(k.len() / 3))
        .min_by_key(|(d, _)| *d)
        .map(|(_, k)| k)
}

fn edit_distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut prev: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut cur = vec![i + 1];
        for (j, cb) in b.iter().enumerate() {
            let sub = prev[j] + usize::from(ca != *cb);
            cur.push(sub.min(prev[j + 1] + 1).min(cur[j] + 1));
        }
        prev = cur;
    }
    prev[b.len()]
}

/// Checks `value` against `key` and stores it in `settings`; on refusal,
/// says why in words that name the allowed values.
pub fn apply(settings: &mut Settings, key: &Key, value: &Value) -> Result<(), String> {
    (key.write)(settings, key, value).ok_or_else(|| {
        format!(
            "{} is not allowed; expected {}",
            value.shown(),
            key.kind.allowed()
        )
    })
}

/// The current value of `key` in `settings`, as it would be written in TOML.
pub fn get(settings: &Settings, key: &Key) -> Value {
    (key.read)(settings)
}

/// A settings enum's value by its name in the file (serde's).
fn named(v: &dyn erased::Named) -> Value {
    Value::Str(v.name())
}

/// Seeds that fit a TOML integer are written as one; larger ones as a string.
fn seed_value(seed: u64) -> Value {
    i64::try_from(seed).map_or(Value::Str(seed.to_string()), Value::Int)
}

mod erased {
    use serde::Serialize;

    /// The snake_case name serde gives a unit enum variant.
    pub trait Named {
        fn name(&self) -> String;
    }

    impl<T: Serialize> Named for T {
        fn name(&self) -> String {
            match toml::Value::try_from(self) {
                Ok(toml::Value::String(s)) => s,
                _ => String::new(),
            }
        }
    }
}

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

fn boolean(value: &Value) -> Option<bool> {
    match value {
        Value::Bool(b) => Some(*b),
        _ => None,
    }
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

fn path(value: &Value) -> Option<Option<String>> {
    match value {
        Value::Str(s) if s.is_empty() => Some(None),
        Value::Str(s) => Some(Some(s.clone())),
        _ => None,
    }
}
