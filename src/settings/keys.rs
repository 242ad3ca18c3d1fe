//! The table of every preference key: its name, what values it allows, and
//! how it reads and writes `Settings`. TOML files, `--set`, `--help` and the
//! settings screen all go through this one table, so a range is checked in
//! exactly one place.

use serde::Deserialize;
use serde::de::IntoDeserializer;

use super::looks::{self, Preset};
use super::{
    Clouds, ColorMode, Detail, Generator, Look, MAX_GRID_EXPONENT, MIN_GRID_EXPONENT, Monitors,
    Profile, Settings, Shading, Sun, ViewKind, WaterLine,
};

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
    read: fn(&Settings) -> Value,
    /// Sets it in a `Settings` from a value `kind` allows; `None` otherwise.
    write: fn(&mut Settings, &Key, &Value) -> Option<()>,
}

const LOOKS: &[&str] = &[
    "ours",
    "fractal-mountain-climbing",
    "mountain-terrain",
    "fl3",
    "essay",
];
const GENERATORS: &[&str] = &["square", "diamond", "triangle", "brownian"];
const PROFILES: &[&str] = &["slope", "peak", "bay", "massif"];
const COLORS: &[&str] = &[
    "natural", "gray", "red", "green", "blue", "yellow", "cyan", "purple", "sonar", "filled",
    "outline", "mono", "ridges",
];
const VIEWS: &[&str] = &["vista", "oblique", "perspective"];
const WATER_LINES: &[&str] = &["coast", "generator"];
const SUNS: &[&str] = &[
    "varied", "morning", "midday", "evening", "sunset", "classic",
];
const MONITORS: &[&str] = &["all", "primary"];
const SHADINGS: &[&str] = &["smooth", "flat"];

/// One row of the table: key `$field` is the field of that name in
/// `Settings`, read and written through its type's [`Field`] under `$kind`;
/// the name is written once, so a row cannot read one field and write
/// another.
macro_rules! row {
    ($field:ident, $kind:expr, $change:ident, $default:expr, $doc:literal) => {
        Key {
            name: stringify!($field),
            kind: $kind,
            change: Change::$change,
            doc: $doc,
            default: || $default,
            read: |s| Field::value(&s.$field),
            write: |s, key, value| {
                s.$field = Field::parse(key, value)?;
                Some(())
            },
        }
    };
}

/// Every key, in the order the settings file and `--help` list them.
pub const KEYS: &[Key] = &[
    row!(
        seed,
        Kind::Seed,
        Next,
        Value::Str("random".into()),
        "seed of the next mountain; \"random\" picks a new one each time"
    ),
    row!(
        generator,
        Kind::Choice(GENERATORS),
        Next,
        Value::Str("diamond".into()),
        "how heights are made"
    ),
    row!(
        cragginess,
        Kind::Int { min: 1, max: 128 },
        Next,
        Value::Int(96),
        "square generators: how sharply heights crease"
    ),
    row!(
        elevation,
        Kind::Float {
            min: 1.0,
            max: 1000.0
        },
        Next,
        Value::Float(100.0),
        "square generators: range of the corner heights"
    ),
    row!(
        roughness,
        // Seed 000's Smoothness menu: 1.00 to 5.00, and a blank item that
        // deviates no point (0 here).
        Kind::Float { min: 0.0, max: 5.0 },
        Next,
        Value::Float(2.0),
        "triangle generator: smoothness base (higher = smoother sides; 0 = no deviation at all)"
    ),
    row!(
        contour,
        Kind::Float {
            min: 0.25,
            max: 5.0
        },
        Next,
        // Seed 000's Contour menu starts checked at 1.50.
        Value::Float(1.5),
        "triangle generator: power on heights (<1 concave, >1 convex)"
    ),
    row!(
        profile,
        Kind::Choice(PROFILES),
        Next,
        Value::Str("slope".into()),
        "triangle generator: overall shape"
    ),
    row!(
        hurst,
        Kind::Float { min: 0.1, max: 0.9 },
        Next,
        Value::Float(0.8),
        "brownian generator: Hurst exponent (0.1 rough and jagged, 0.9 smooth and rolling)"
    ),
    row!(
        height,
        Kind::Int { min: 1, max: 10 },
        Next,
        Value::Int(5),
        "height of the peaks; also raises the treeline and snow"
    ),
    row!(
        erosion,
        Kind::Float { min: 0.0, max: 1.0 },
        Next,
        Value::Float(0.5),
        "rain wearing gullies into the slopes and silt at their feet (0 = none)"
    ),
    row!(
        cliffs,
        Kind::Float { min: 0.0, max: 1.0 },
        Next,
        Value::Float(0.0),
        "sharp edges: level terraces, mesas and cliffs cut into the land (0 = none, 1 = sheer)"
    ),
    row!(
        detail,
        // The grid sizes a heightfield can have.
        Kind::IntOrAuto {
            min: MIN_GRID_EXPONENT as i64,
            max: MAX_GRID_EXPONENT as i64
        },
        Remake,
        Value::Str("auto".into()),
        "grid of 2^detail+1 points a side; \"auto\" fits it to the screen"
    ),
    row!(
        low_detail,
        Kind::Bool,
        Remake,
        Value::Bool(false),
        "a quarter of the points: larger faces, faster drawing"
    ),
    row!(
        sea_level,
        Kind::Float {
            min: -1.0,
            max: 1.0
        },
        Next,
        Value::Float(0.0),
        "water line as a fraction of the relief above or below water_line"
    ),
    row!(
        water_line,
        Kind::Choice(WATER_LINES),
        Next,
        Value::Str("coast".into()),
        "sea_level 0: a coast on every mountain, or the generator's own zero"
    ),
    row!(
        lakes,
        Kind::Bool,
        Remake,
        Value::Bool(true),
        "basins above the sea filled to their lowest lip and drawn as lakes"
    ),
    // Not a `row!`: choosing a look also moves the keys that follow it.
    Key {
        name: "look",
        kind: Kind::Choice(LOOKS),
        change: Change::Remake,
        doc: "whose picture: ours, or a seed program's generator, view, light and colours \
              (a key set to anything but its default overrides the look)",
        default: || Value::Str("ours".into()),
        read: |s| Field::value(&s.look),
        write: |s, key, value| {
            switch_look(s, Field::parse(key, value)?);
            Some(())
        },
    },
    row!(
        color,
        Kind::Choice(COLORS),
        Repaint,
        Value::Str("natural".into()),
        "colour mode or filter"
    ),
    row!(
        relative_depth,
        Kind::Bool,
        Repaint,
        Value::Bool(true),
        "darker water over deeper ground"
    ),
    row!(
        shadows,
        Kind::Bool,
        Repaint,
        Value::Bool(true),
        "cast shadows from the light"
    ),
    row!(
        sun,
        Kind::Choice(SUNS),
        Repaint,
        Value::Str("varied".into()),
        "time of day of the light; \"varied\" draws one per mountain"
    ),
    row!(
        shading,
        Kind::Choice(SHADINGS),
        Repaint,
        Value::Str("smooth".into()),
        "light blended across each face, or one colour a face (classic looks are flat)"
    ),
    row!(
        clouds,
        Kind::AmountOrVaried,
        Repaint,
        Value::Str("varied".into()),
        "cloud in the sky, 0 clear to 1 overcast; \"varied\" draws an amount per mountain"
    ),
    row!(
        reflections,
        Kind::Bool,
        Repaint,
        Value::Bool(true),
        "the land and the sky mirrored in the water (the classic looks keep plain water)"
    ),
    row!(
        view,
        Kind::Choice(VIEWS),
        Repaint,
        Value::Str("vista".into()),
        "projection"
    ),
    row!(
        rotation,
        Kind::QuarterTurn,
        Repaint,
        Value::Int(0),
        "side the mountain is seen from, in degrees"
    ),
    row!(
        auto_redraw,
        Kind::Bool,
        Nothing,
        Value::Bool(true),
        "start a new mountain after the pause (slide show)"
    ),
    row!(
        draw_seconds,
        Kind::Float {
            min: 0.0,
            max: 600.0
        },
        Nothing,
        Value::Float(8.0),
        "seconds to draw one mountain strip by strip"
    ),
    row!(
        pause_seconds,
        Kind::Float {
            min: 0.0,
            max: 3600.0
        },
        Nothing,
        Value::Float(10.0),
        "seconds to hold a finished mountain"
    ),
    row!(
        monitors,
        Kind::Choice(MONITORS),
        Nothing,
        Value::Str("all".into()),
        "full screen: a mountain on every monitor, or the primary only"
    ),
    row!(
        heightmaps_dir,
        Kind::Path,
        Nothing,
        Value::Str(String::new()),
        "folder of PNG heightmaps mixed into the slide show"
    ),
];

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
            look: Look::Ours,
            generator: Generator::Square,
            cragginess: 0,
            elevation: 0.0,
            roughness: 0.0,
            contour: 0.0,
            profile: Profile::Slope,
            hurst: 0.0,
            height: 0,
            erosion: 0.0,
            cliffs: 0.0,
            detail: Detail::Auto,
            low_detail: false,
            sea_level: 0.0,
            water_line: WaterLine::Coast,
            lakes: false,
            color: ColorMode::Natural,
            relative_depth: false,
            shadows: false,
            sun: Sun::Varied,
            shading: Shading::Smooth,
            clouds: Clouds::Varied,
            reflections: false,
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

/// Looks a key up by name; for an unknown one, a message naming the
/// closest known key, if any is close, for a file's line or `--set`.
pub fn known(name: &str) -> Result<&'static Key, String> {
    find(name).ok_or_else(|| {
        let hint = crate::spelling::did_you_mean(name, KEYS.iter().map(|k| k.name));
        format!("unknown key{hint} (`mountains --help` lists every key)")
    })
}

/// Checks `value` against `key` and stores it in `settings`; on refusal,
/// says why in words that name the allowed values.
///
/// Under a look other than ours, a key given its default takes the look's
/// value instead: the look is a layer of defaults under the keys, whatever
/// order they come in (see [`follow_look`]).
pub fn apply(settings: &mut Settings, key: &Key, value: &Value) -> Result<(), String> {
    (key.write)(settings, key, value).ok_or_else(|| {
        format!(
            "{} is not allowed; expected {}",
            value.shown(),
            key.kind.allowed()
        )
    })?;
    follow_look(settings, key);
    Ok(())
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
        let _ = (key.write)(settings, key, &wanted);
    }
}

/// Changes the look: keys holding the old look's values return to their
/// defaults, then every key at its default takes the new look's value.
fn switch_look(settings: &mut Settings, look: Look) {
    for key in KEYS {
        if look_value(settings.look, key).is_some_and(|v| v == (key.read)(settings)) {
            let _ = (key.write)(settings, key, &(key.default)());
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

/// How a `Settings` field's type is written as a [`Value`] and read back
/// under its key's [`Kind`] (the row macro picks the impl by the field).
trait Field: Sized {
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

/// The settings enums, each written by its name in the file (serde's).
macro_rules! choice_fields {
    ($($t:ty),*) => {$(
        impl Field for $t {
            fn value(&self) -> Value {
                Value::Str(erased::Named::name(self))
            }
            fn parse(key: &Key, value: &Value) -> Option<Self> {
                choice(key, value)
            }
        }
    )*};
}

choice_fields!(
    Look, Generator, Profile, WaterLine, ColorMode, Sun, Shading, ViewKind, Monitors
);

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
