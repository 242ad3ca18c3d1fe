//! The table of every preference key, one row a key, each row a constant
//! code refers to (`keys::SEA_LEVEL`): a key's name is written here only,
//! and a misspelt key is a compile error. `Settings::default` is built
//! from the same rows.

use super::field::Field;
use super::kind::{Change, Key, Kind, Value};
use crate::settings::{
    ColorMode, Generator, Look, MAX_GRID_EXPONENT, MIN_GRID_EXPONENT, Monitors, OnBattery, Profile,
    Settings, Shading, Sun, ViewKind, WaterLine, World,
};

/// The table: for each row `CONST = (field, kind, change, default, doc)`,
/// the constant `CONST`, key `field` of the field of that name in
/// `Settings`, read and written through its type's [`Field`] under `kind`
/// (the name is written once, so a row cannot read one field and write
/// another); then [`KEYS`], every row in order, and `Settings::default`,
/// every field at its row's default (a field without a row does not
/// compile).
macro_rules! rows {
    ($(
        $konst:ident = (
            $field:ident,
            $kind:expr,
            $change:ident,
            $default:expr,
            $doc:literal $(,)?
        ),
    )*) => {
        $(
            #[doc = concat!("`", stringify!($field), "`: ", $doc)]
            pub const $konst: Key = Key {
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
            };
        )*

        /// Every key, in the order the settings file and `--help` list them.
        pub const KEYS: &[Key] = &[$($konst),*];

        impl Default for Settings {
            /// Every key at the default its row in the key table gives.
            fn default() -> Self {
                Settings {
                    $($field: default_of(&$konst),)*
                }
            }
        }
    };
}

/// The value of `key`'s default in its field's type.
fn default_of<T: Field>(key: &Key) -> T {
    T::parse(key, &(key.default)()).unwrap_or_else(|| {
        unreachable!(
            "the default of `{}` is not allowed; expected {}",
            key.name,
            key.kind.allowed()
        )
    })
}

rows! {
    SEED = (
        seed,
        Kind::Seed,
        Next,
        Value::Str("random".into()),
        "seed of the next mountain; \"random\" picks a new one each time"
    ),
    GENERATOR = (
        generator,
        Kind::Choice(Generator::NAMES),
        Next,
        Value::Str(Generator::Diamond.name().into()),
        "how heights are made"
    ),
    CRAGGINESS = (
        cragginess,
        Kind::Int { min: 1, max: 128 },
        Next,
        Value::Int(96),
        "square generators: how sharply heights crease"
    ),
    ELEVATION = (
        elevation,
        Kind::Float {
            min: 1.0,
            max: 1000.0
        },
        Next,
        Value::Float(100.0),
        "square generators: range of the corner heights"
    ),
    ROUGHNESS = (
        roughness,
        // Seed 000's Smoothness menu: 1.00 to 5.00, and a blank item that
        // deviates no point (0 here).
        Kind::Float { min: 0.0, max: 5.0 },
        Next,
        Value::Float(2.0),
        "triangle generator: smoothness base (higher = smoother sides; 0 = no deviation at all)"
    ),
    CONTOUR = (
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
    PROFILE = (
        profile,
        Kind::Choice(Profile::NAMES),
        Next,
        Value::Str(Profile::Slope.name().into()),
        "triangle generator: overall shape"
    ),
    HURST = (
        hurst,
        Kind::Float { min: 0.1, max: 0.9 },
        Next,
        Value::Float(0.8),
        "brownian generator: Hurst exponent (0.1 rough and jagged, 0.9 smooth and rolling)"
    ),
    HEIGHT = (
        height,
        Kind::Int { min: 1, max: 10 },
        Next,
        Value::Int(5),
        "height of the peaks; also raises the treeline and snow"
    ),
    EROSION = (
        erosion,
        Kind::Float { min: 0.0, max: 1.0 },
        Next,
        Value::Float(0.5),
        "rain wearing gullies into the slopes and silt at their feet (0 = none)"
    ),
    CLIFFS = (
        cliffs,
        Kind::Float { min: 0.0, max: 1.0 },
        Next,
        Value::Float(0.0),
        "sharp edges: level terraces, mesas and cliffs cut into the land (0 = none, 1 = sheer)"
    ),
    DETAIL = (
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
    LOW_DETAIL = (
        low_detail,
        Kind::Bool,
        Remake,
        Value::Bool(false),
        "a quarter of the points: larger faces, faster drawing"
    ),
    SEA_LEVEL = (
        sea_level,
        Kind::Float {
            min: -1.0,
            max: 1.0
        },
        Next,
        Value::Float(0.0),
        "water line as a fraction of the relief above or below water_line"
    ),
    WATER_LINE = (
        water_line,
        Kind::Choice(WaterLine::NAMES),
        Next,
        Value::Str(WaterLine::Coast.name().into()),
        "sea_level 0: a coast on every mountain, or the generator's own zero"
    ),
    LAKES = (
        lakes,
        Kind::Bool,
        Remake,
        Value::Bool(true),
        "basins above the sea filled to their lowest lip and drawn as lakes"
    ),
    // Choosing a look also moves the keys that follow it: `keys::apply`.
    LOOK = (
        look,
        Kind::Choice(Look::NAMES),
        Remake,
        Value::Str(Look::Ours.name().into()),
        "whose picture: ours, or a seed program's generator, view, light and colours \
              (a key set to anything but its default overrides the look)"
    ),
    // A world is a layer of defaults drawn per mountain: `settings/worlds.rs`.
    WORLD = (
        world,
        Kind::Choice(World::NAMES),
        Remake,
        Value::Str(World::Varied.name().into()),
        "where the mountain stands: its terrain, ground, water and air; \"varied\" draws one \
              per mountain (a key set to anything but its default overrides the world)"
    ),
    COLOR = (
        color,
        Kind::Choice(ColorMode::NAMES),
        Repaint,
        Value::Str(ColorMode::Natural.name().into()),
        "colour mode or filter"
    ),
    RELATIVE_DEPTH = (
        relative_depth,
        Kind::Bool,
        Repaint,
        Value::Bool(true),
        "darker water over deeper ground"
    ),
    SHADOWS = (
        shadows,
        Kind::Bool,
        Repaint,
        Value::Bool(true),
        "cast shadows from the light"
    ),
    SUN = (
        sun,
        Kind::Choice(Sun::NAMES),
        Repaint,
        Value::Str(Sun::Varied.name().into()),
        "time of day of the light; \"varied\" draws one per mountain (night too), \
              \"clock\" follows the real hour at latitude and longitude"
    ),
    LATITUDE = (
        latitude,
        Kind::Float {
            min: -90.0,
            max: 90.0
        },
        Repaint,
        Value::Float(51.48),
        "degrees north (south negative) of the place whose hour sun = \"clock\" shows"
    ),
    LONGITUDE = (
        longitude,
        Kind::Float {
            min: -180.0,
            max: 180.0
        },
        Repaint,
        Value::Float(0.0),
        "degrees east (west negative) of the place whose hour sun = \"clock\" shows"
    ),
    SHADING = (
        shading,
        Kind::Choice(Shading::NAMES),
        Repaint,
        Value::Str(Shading::Smooth.name().into()),
        "light blended across each face, or one colour a face (classic looks are flat)"
    ),
    CLOUDS = (
        clouds,
        Kind::AmountOrVaried,
        Repaint,
        Value::Str("varied".into()),
        "cloud in the sky, 0 clear to 1 overcast; \"varied\" draws an amount per mountain"
    ),
    FINE_RELIEF = (
        fine_relief,
        Kind::Bool,
        Repaint,
        Value::Bool(true),
        "near land lit from a finer terrain than its grid, down to the pixel (false: the grid's own light)"
    ),
    REFLECTIONS = (
        reflections,
        Kind::Bool,
        Repaint,
        Value::Bool(true),
        "the land and the sky mirrored in the water (the classic looks keep plain water)"
    ),
    VIEW = (
        view,
        Kind::Choice(ViewKind::NAMES),
        Repaint,
        Value::Str(ViewKind::Vista.name().into()),
        "projection"
    ),
    ROTATION = (
        rotation,
        Kind::QuarterTurn,
        Repaint,
        Value::Int(0),
        "side the mountain is seen from, in degrees"
    ),
    AUTO_REDRAW = (
        auto_redraw,
        Kind::Bool,
        Nothing,
        Value::Bool(true),
        "start a new mountain after the pause (slide show)"
    ),
    DRAW_SECONDS = (
        draw_seconds,
        Kind::Float {
            min: 0.0,
            max: 600.0
        },
        Nothing,
        Value::Float(8.0),
        "seconds to draw one mountain strip by strip"
    ),
    PAUSE_SECONDS = (
        pause_seconds,
        Kind::Float {
            min: 0.0,
            max: 3600.0
        },
        Nothing,
        Value::Float(10.0),
        "seconds to hold a finished mountain"
    ),
    MONITORS = (
        monitors,
        Kind::Choice(Monitors::NAMES),
        Nothing,
        Value::Str(Monitors::All.name().into()),
        "full screen: a mountain on every monitor, the primary only, or one across all"
    ),
    ON_BATTERY = (
        on_battery,
        Kind::Choice(OnBattery::NAMES),
        Nothing,
        Value::Str(OnBattery::Hold.name().into()),
        "on battery or in power-saver mode: hold the finished slide, slow the slide show, or the same as on mains"
    ),
    HEIGHTMAPS_DIR = (
        heightmaps_dir,
        Kind::Path,
        Nothing,
        Value::Str(String::new()),
        "folder of heightmaps (PNG or raw) mixed into the slide show (a relative one: beside the preferences file)"
    ),
}
