//! The `mountains:` PNG text chunks: which keys, how they are written and read.
//!
//! Keys fall in two tiers, and a bad value is treated by tier:
//! - **Height keys** (`scale`, `offset`, `sea_level`, `extent`, `format`) say
//!   how to read the samples. A bad value is an error naming the key: the
//!   mountain would otherwise be misread.
//! - **Origin keys** (`seed` and the generator parameters) only say where the
//!   mountain came from; the heights are complete without them. A bad value
//!   drops that information with a note in [`DataSet::notes`](super::DataSet),
//!   so a file from a newer version (say, a new generator name) still loads.
//!
//! Keys outside this list are ignored; a known key given twice is an error.
//! Values are plain ASCII decimal text.

use crate::quote::quoted;
use std::path::Path;

use super::error::HeightmapError;
use super::quantise::{MAX_SAMPLE, Quantisation};
use crate::settings::keys::{self, Value};
use crate::settings::{AUTO_DETAIL_FALLBACK, Detail, Settings, World, load, worlds};

/// Version of this key set; bumped only if a key changes meaning.
pub const FORMAT_VERSION: u32 = 1;
/// Version of the key set the file follows.
pub const KEY_FORMAT: &str = "mountains:format";
/// Height units per sample step (`f64`, > 0).
pub const KEY_SCALE: &str = "mountains:scale";
/// Elevation of sample 0 (`f32`).
pub const KEY_OFFSET: &str = "mountains:offset";
/// Elevation of the water line (`f32`); loaded heights are relative to it.
pub const KEY_SEA_LEVEL: &str = "mountains:sea_level";
/// Width of the whole grid in height units (`f32`, > 0).
pub const KEY_EXTENT: &str = "mountains:extent";
/// The seed that generated the mountain (`u64`).
pub const KEY_SEED: &str = "mountains:seed";
/// Generator name, as in the config file (`square`, `diamond`, `triangle`).
pub const KEY_GENERATOR: &str = "mountains:generator";
/// `Settings::cragginess`.
pub const KEY_CRAGGINESS: &str = "mountains:cragginess";
/// `Settings::elevation`.
pub const KEY_ELEVATION: &str = "mountains:elevation";
/// `Settings::roughness`.
pub const KEY_ROUGHNESS: &str = "mountains:roughness";
/// `Settings::contour`.
pub const KEY_CONTOUR: &str = "mountains:contour";
/// `Settings::profile`, as in the config file.
pub const KEY_PROFILE: &str = "mountains:profile";
/// `Settings::height`.
pub const KEY_HEIGHT: &str = "mountains:height";
/// `Settings::detail`.
pub const KEY_DETAIL: &str = "mountains:detail";
/// `Settings::low_detail` (`true`/`false`).
pub const KEY_LOW_DETAIL: &str = "mountains:low_detail";
/// `Settings::sea_level`, the water-line setting as a fraction of the relief.
pub const KEY_SEA_FRACTION: &str = "mountains:sea_fraction";
/// `Settings::erosion`; absent in files made before erosion, which had none.
pub const KEY_EROSION: &str = "mountains:erosion";
/// `Settings::hurst`; absent in files made before the Brownian generator.
pub const KEY_HURST: &str = "mountains:hurst";
/// `Settings::cliffs`; absent in files made before cliffs, which had none.
pub const KEY_CLIFFS: &str = "mountains:cliffs";
/// `Settings::look`, as in the config file; absent in files made before
/// the looks, whose mountains were ours.
pub const KEY_LOOK: &str = "mountains:look";
/// `Settings::world`, the world the mountain was made in: the one drawn
/// for its seed, and "varied" only for the temperate coast the varied
/// draw gives (its day drawn as the other worlds' are, which the temperate
/// world named does not: `worlds::drawn_world`; the set's seed draws it
/// again); absent in files made before the worlds, whose mountains were
/// temperate.
pub const KEY_WORLD: &str = "mountains:world";

/// Parameters files from before they existed lack: their default is taken
/// without a note (an older file's mountain did not use them, or, for
/// erosion, had none: see `read_params`).
const LATER_KEYS: &[&str] = &[KEY_EROSION, KEY_HURST, KEY_CLIFFS, KEY_LOOK, KEY_WORLD];

const KNOWN_KEYS: [&str; 21] = [
    KEY_FORMAT,
    KEY_SCALE,
    KEY_OFFSET,
    KEY_SEA_LEVEL,
    KEY_EXTENT,
    KEY_SEED,
    KEY_GENERATOR,
    KEY_CRAGGINESS,
    KEY_ELEVATION,
    KEY_ROUGHNESS,
    KEY_CONTOUR,
    KEY_PROFILE,
    KEY_HEIGHT,
    KEY_DETAIL,
    KEY_LOW_DETAIL,
    KEY_SEA_FRACTION,
    KEY_EROSION,
    KEY_HURST,
    KEY_CLIFFS,
    KEY_LOOK,
    KEY_WORLD,
];

/// The generator settings that made a mountain, read back from its file:
/// the keys of `PARAM_KEYS`, held in a `Settings` (every other key at its
/// default). The key table reads, writes and checks each of them.
#[derive(Debug, Clone, PartialEq)]
pub struct GeneratorParams(Settings);

impl GeneratorParams {
    /// The generator part of `settings` (`detail = "auto"` stored as the
    /// level it stands for when no frame is known).
    pub fn from_settings(s: &Settings) -> Self {
        let mut params = Settings::default();
        copy_param_keys(s, &mut params);
        if params.detail == Detail::Auto {
            params.detail = Detail::Level(AUTO_DETAIL_FALLBACK);
        }
        GeneratorParams(params)
    }

    /// Puts these parameters into `settings` (e.g. to regenerate or re-save).
    pub fn apply_to(&self, s: &mut Settings) {
        copy_param_keys(&self.0, s);
    }

    /// The settings a data set made with these parameters is drawn with,
    /// for a person whose preferences are `prefs`. The recorded keys lie
    /// under the preferences, as a look lies under the keys: each key the
    /// person left at its default takes the file's value, exactly as
    /// recorded; a key they set to anything else wins. The recorded look,
    /// when theirs is the default (ours), is chosen as `--set look=...`
    /// chooses it, so the keys it sets that no file records (the view, the
    /// colours, the light) follow it too.
    pub fn drawn_under(&self, prefs: &Settings) -> Settings {
        let at_default = |key: &keys::Key| keys::get(prefs, key) == (key.default)();
        let mut drawn = prefs.clone();
        let look = table_key(LOOK);
        if at_default(look) {
            let chosen = keys::apply(&mut drawn, look, &keys::get(&self.0, look));
            debug_assert!(chosen.is_ok(), "a recorded look is one of the table's");
        }
        for &(_, name) in PARAM_KEYS.iter().filter(|(_, name)| *name != LOOK) {
            let key = table_key(name);
            if at_default(key) {
                keys::copy(key, &self.0, &mut drawn);
            }
        }
        drawn
    }

    fn to_pairs(&self) -> Vec<(&'static str, String)> {
        PARAM_KEYS
            .iter()
            .map(|&(meta_key, name)| (meta_key, text(&keys::get(&self.0, table_key(name)))))
            .collect()
    }
}

/// Copies the generator keys from `from` into `to`, through the key table.
fn copy_param_keys(from: &Settings, to: &mut Settings) {
    for &(_, name) in PARAM_KEYS.iter().filter(|(_, name)| *name != LOOK) {
        keys::copy(table_key(name), from, to);
    }
    // Set by itself, not through the table: the keys copied stay exact.
    to.look = from.look;
}

/// A key [`PARAM_KEYS`] names (a test checks they are all in the table).
fn table_key(name: &str) -> &'static keys::Key {
    keys::find(name).unwrap_or_else(|| unreachable!("`{name}` is not in the key table"))
}

/// A value as the text chunk holds it: plain decimal, a float as the
/// shortest text that reads back as the same f32, names as in the file.
fn text(value: &Value) -> String {
    match value {
        Value::Int(n) => n.to_string(),
        Value::Float(x) => (*x as f32).to_string(),
        Value::Bool(b) => b.to_string(),
        Value::Str(s) => s.clone(),
    }
}

/// The text chunks `save` writes, in order.
pub fn to_pairs(
    q: &Quantisation,
    extent: f32,
    seed: Option<u64>,
    settings: &Settings,
) -> Vec<(&'static str, String)> {
    let mut pairs = vec![
        (KEY_FORMAT, FORMAT_VERSION.to_string()),
        (KEY_SCALE, q.scale.to_string()),
        (KEY_OFFSET, q.offset.to_string()),
        (KEY_SEA_LEVEL, WRITTEN_SEA_LEVEL.to_string()),
        (KEY_EXTENT, extent.to_string()),
    ];
    // Parameters without the seed could not regenerate anything, and a field
    // with no seed did not come from these settings, so they go together.
    if let Some(seed) = seed {
        pairs.push((KEY_SEED, seed.to_string()));
        // The world drawn for the seed, so the set comes back in it.
        let made = Settings {
            world: worlds::drawn_world(settings, Some(seed)),
            ..settings.clone()
        };
        pairs.extend(GeneratorParams::from_settings(&made).to_pairs());
    }
    pairs
}

/// The sea level our files carry: heights are stored as the generator made
/// them, whose sea is at 0.
const WRITTEN_SEA_LEVEL: f32 = 0.0;

/// Whether a field stored with `q` over `extent` would be read back: the
/// writer holds itself to the reader's ranges, so no file of ours is refused
/// on loading. On failure, the key and why.
pub fn check_storable(q: &Quantisation, extent: f32) -> Result<(), (&'static str, String)> {
    check_ranges(&Metadata {
        scale: Some(q.scale),
        offset: Some(q.offset),
        sea_level: Some(WRITTEN_SEA_LEVEL),
        extent: Some(extent),
        ..Metadata::default()
    })
}

/// What the text chunks said, checked.
#[derive(Debug, Default)]
pub struct Metadata {
    /// `mountains:scale`, if given.
    pub scale: Option<f64>,
    /// `mountains:offset`, if given.
    pub offset: Option<f32>,
    /// `mountains:sea_level`, if given.
    pub sea_level: Option<f32>,
    /// `mountains:extent`, if given.
    pub extent: Option<f32>,
    /// `mountains:seed`, if given and valid.
    pub seed: Option<u64>,
    /// The generator parameters, if `mountains:generator` was given and valid.
    pub params: Option<GeneratorParams>,
    /// Origin keys that were dropped or defaulted, for a person.
    pub notes: Vec<String>,
}

/// Reads our keys from the (keyword, text) pairs of a file.
pub fn parse(pairs: &[(String, String)], path: &Path) -> Result<Metadata, HeightmapError> {
    let mut found: Vec<(&'static str, &str)> = Vec::new();
    for (key, text) in pairs {
        let Some(&known) = KNOWN_KEYS.iter().find(|k| **k == key) else {
            continue;
        };
        if found.iter().any(|(k, _)| *k == known) {
            return Err(HeightmapError::metadata(
                path,
                known,
                "given more than once",
            ));
        }
        found.push((known, text.trim()));
    }
    let get = |key: &str| found.iter().find(|(k, _)| *k == key).map(|(_, v)| *v);
    let height_key = |key: &'static str, check: fn(&str) -> Result<f64, String>| {
        get(key)
            .map(|v| check(v).map_err(|e| HeightmapError::metadata(path, key, e)))
            .transpose()
    };
    if let Some(v) = get(KEY_FORMAT) {
        check_format(v).map_err(|e| HeightmapError::metadata(path, KEY_FORMAT, e))?;
    }
    let mut meta = Metadata {
        scale: height_key(KEY_SCALE, positive_f64)?,
        offset: height_key(KEY_OFFSET, finite_f32)?.map(|v| v as f32),
        sea_level: height_key(KEY_SEA_LEVEL, finite_f32)?.map(|v| v as f32),
        extent: height_key(KEY_EXTENT, positive_f32)?.map(|v| v as f32),
        ..Metadata::default()
    };
    check_ranges(&meta).map_err(|(key, e)| HeightmapError::metadata(path, key, e))?;
    if let Some(v) = get(KEY_SEED) {
        match v.parse::<u64>() {
            Ok(seed) => meta.seed = Some(seed),
            Err(_) => meta.notes.push(format!(
                "{KEY_SEED}: {} is not a whole number from 0 to 2^64-1; seed ignored",
                quoted(v)
            )),
        }
    }
    if get(KEY_GENERATOR).is_some() {
        match read_params(&get, &mut meta.notes) {
            Ok(p) => meta.params = Some(p),
            Err(e) => meta
                .notes
                .push(format!("{e}; generator parameters ignored")),
        }
    }
    Ok(meta)
}

/// The values a file of ours can hold, with room to spare: the tallest
/// mountain the settings make rises a few thousand units over a grid 250 or
/// 500 wide. Beyond them the picture would be one colour (a needle, or a
/// plain seen from a thousand miles), so the file is refused instead.
/// (A tiny scale is a nearly flat field, which draws well: only > 0.)
const SCALE_RANGE: (f64, f64) = (f64::MIN_POSITIVE, 1.0);
const HEIGHT_RANGE: (f64, f64) = (-1e5, 1e5);
const EXTENT_RANGE: (f64, f64) = (1.0, 1e5);
/// Most relief (all `MAX_SAMPLE` steps) per unit of width.
const MAX_RELIEF_PER_WIDTH: f64 = 256.0;

/// Checks each value against its range, and the relief against the width.
fn check_ranges(m: &Metadata) -> Result<(), (&'static str, String)> {
    let within = |key: &'static str, v: Option<f64>, (lo, hi): (f64, f64)| match v {
        Some(x) if !(lo..=hi).contains(&x) => {
            let from = if lo == f64::MIN_POSITIVE {
                "above 0".to_string()
            } else {
                format!("{lo}")
            };
            Err((
                key,
                format!("{} is out of range (allowed: {from} to {hi})", shown(x)),
            ))
        }
        _ => Ok(()),
    };
    within(KEY_SCALE, m.scale, SCALE_RANGE)?;
    within(KEY_OFFSET, m.offset.map(f64::from), HEIGHT_RANGE)?;
    within(KEY_SEA_LEVEL, m.sea_level.map(f64::from), HEIGHT_RANGE)?;
    within(KEY_EXTENT, m.extent.map(f64::from), EXTENT_RANGE)?;
    if let (Some(scale), Some(extent)) = (m.scale, m.extent) {
        let relief = scale * f64::from(MAX_SAMPLE);
        if relief > MAX_RELIEF_PER_WIDTH * f64::from(extent) {
            return Err((
                KEY_SCALE,
                format!(
                    "{} makes a relief of {} over a width of {extent}: \
                     more than {MAX_RELIEF_PER_WIDTH} times the width",
                    shown(scale),
                    shown(relief)
                ),
            ));
        }
    }
    Ok(())
}

/// `x` as a person reads it: whole digits while they are few, else with
/// an exponent (1e300 was said as its 301 digits); a value read as an f32
/// in its f32 digits (1e30, not 1.0000000150474662e30).
fn shown(x: f64) -> String {
    let short = x as f32;
    let exponent = x != 0.0 && !(1e-4..1e7).contains(&x.abs());
    match (f64::from(short) == x, exponent) {
        (true, true) => format!("{short:e}"),
        (true, false) => format!("{short}"),
        (false, true) => format!("{x:e}"),
        (false, false) => format!("{x}"),
    }
}

fn check_format(v: &str) -> Result<(), String> {
    match v.parse::<u32>() {
        Ok(FORMAT_VERSION) => Ok(()),
        Ok(n) if n > FORMAT_VERSION => Err(format!(
            "format {n} is newer than this program, which reads format {FORMAT_VERSION}"
        )),
        _ => Err(format!("{} is not a known format", quoted(v))),
    }
}

fn number(v: &str) -> Result<f64, String> {
    let x: f64 = v
        .parse()
        .map_err(|_| format!("{} is not a number", quoted(v)))?;
    if x.is_finite() {
        Ok(x)
    } else {
        Err(format!("{} is not a finite number", quoted(v)))
    }
}

fn finite_f32(v: &str) -> Result<f64, String> {
    number(v)?;
    let x: f32 = v
        .parse()
        .map_err(|_| format!("{} is not a number", quoted(v)))?;
    if x.is_finite() {
        Ok(f64::from(x))
    } else {
        Err(format!("{} is too large", quoted(v)))
    }
}

fn positive_f64(v: &str) -> Result<f64, String> {
    positive(v, number(v)?)
}

fn positive_f32(v: &str) -> Result<f64, String> {
    positive(v, finite_f32(v)?)
}

/// `x` (read from `v`) if it is greater than 0.
fn positive(v: &str, x: f64) -> Result<f64, String> {
    if x > 0.0 {
        Ok(x)
    } else {
        Err(format!("{} must be greater than 0", quoted(v)))
    }
}

fn read_params<'a>(
    get: &impl Fn(&str) -> Option<&'a str>,
    notes: &mut Vec<String>,
) -> Result<GeneratorParams, String> {
    // Each value is checked by the settings key table, so the ranges a file
    // may hold are exactly the ranges a user may set.
    let mut settings = Settings {
        // A file from before erosion existed holds an uneroded mountain,
        // one from before the worlds a temperate one.
        erosion: 0.0,
        world: World::Temperate,
        ..Settings::default()
    };
    let mut look = settings.look;
    for (meta_key, key) in PARAM_KEYS {
        let Some(raw) = get(meta_key) else {
            if LATER_KEYS.contains(meta_key) {
                continue;
            }
            notes.push(format!("{meta_key} missing; the default is assumed"));
            continue;
        };
        let problem = |p: load::Problem| format!("{meta_key}: {}", p.message);
        if *key == LOOK {
            // Checked by the table on a scratch copy, then set by itself
            // (see `LOOK`): a look would otherwise replace every key read
            // at its default (height 5 under the essay would come back 10).
            let mut scratch = Settings::default();
            load::apply_set(&mut scratch, key, raw).map_err(problem)?;
            look = scratch.look;
        } else {
            load::apply_set(&mut settings, key, raw).map_err(problem)?;
        }
    }
    settings.look = look;
    Ok(GeneratorParams::from_settings(&settings))
}

/// The generator parameters stored with a seed, and the settings key each sets.
const PARAM_KEYS: &[(&str, &str)] = &[
    (KEY_GENERATOR, keys::GENERATOR.name),
    (KEY_CRAGGINESS, keys::CRAGGINESS.name),
    (KEY_ELEVATION, keys::ELEVATION.name),
    (KEY_ROUGHNESS, keys::ROUGHNESS.name),
    (KEY_CONTOUR, keys::CONTOUR.name),
    (KEY_PROFILE, keys::PROFILE.name),
    (KEY_HEIGHT, keys::HEIGHT.name),
    (KEY_DETAIL, keys::DETAIL.name),
    (KEY_LOW_DETAIL, keys::LOW_DETAIL.name),
    (KEY_SEA_FRACTION, keys::SEA_LEVEL.name),
    (KEY_EROSION, keys::EROSION.name),
    (KEY_HURST, keys::HURST.name),
    (KEY_CLIFFS, keys::CLIFFS.name),
    (KEY_LOOK, LOOK),
    (KEY_WORLD, keys::WORLD.name),
];

/// The settings keys a data set's generator record holds, for the tests
/// that tie it to the other lists of keys.
#[cfg(test)]
pub(crate) fn recorded_keys() -> impl Iterator<Item = &'static str> {
    PARAM_KEYS.iter().map(|&(_, name)| name)
}

/// The settings key of the look: held apart from the others, because
/// choosing a look through the key table also moves the keys that follow
/// it (a key at its default takes the look's value), and a recorded key
/// must come back exactly as it was written.
const LOOK: &str = keys::LOOK.name;

#[cfg(test)]
mod tests {
    use super::*;
    use crate::settings::{Generator, Profile};

    #[test]
    fn every_stored_parameter_is_a_key_of_the_table() {
        for (meta_key, name) in PARAM_KEYS {
            assert!(keys::find(name).is_some(), "{meta_key}: `{name}`");
        }
    }

    fn pairs(list: &[(&str, &str)]) -> Vec<(String, String)> {
        list.iter()
            .map(|(k, v)| (k.to_string(), v.to_string()))
            .collect()
    }

    #[test]
    fn settings_round_trip_through_text() {
        let s = Settings {
            generator: Generator::Triangle,
            profile: Profile::Massif,
            contour: 0.25,
            low_detail: true,
            ..Settings::default()
        };
        let q = Quantisation::spanning(-3.0, 9.0);
        let written: Vec<(String, String)> = to_pairs(&q, 400.0, Some(42), &s)
            .into_iter()
            .map(|(k, v)| (k.to_string(), v))
            .collect();
        let meta = parse(&written, Path::new("x.png")).unwrap();
        assert_eq!(meta.seed, Some(42));
        // The world recorded is the one drawn for the seed (42's desert,
        // not "varied", which stands for a temperate coast only).
        let made = Settings {
            world: worlds::drawn_world(&s, Some(42)),
            ..s.clone()
        };
        assert_ne!(made.world, World::Varied);
        assert_eq!(meta.params, Some(GeneratorParams::from_settings(&made)));
        assert_eq!(meta.offset, Some(-3.0));
        assert!(meta.notes.is_empty(), "{:?}", meta.notes);
    }

    /// A temperate mountain of the varied draw is recorded as "varied"
    /// (its day drawn, which the temperate world named does not draw), and
    /// comes back to be drawn as it was; a temperate one named as
    /// "temperate".
    #[test]
    fn a_varied_temperate_mountain_is_recorded_as_varied() {
        let seed = (1..)
            .find(|&s| worlds::drawn_for(s) == World::Temperate)
            .expect("a temperate seed");
        let q = Quantisation::spanning(-3.0, 9.0);
        for (world, recorded) in [
            (World::Varied, World::Varied),
            (World::Temperate, World::Temperate),
        ] {
            let s = Settings {
                world,
                ..Settings::default()
            };
            let written: Vec<(String, String)> = to_pairs(&q, 400.0, Some(seed), &s)
                .into_iter()
                .map(|(k, v)| (k.to_string(), v))
                .collect();
            let meta = parse(&written, Path::new("x.png")).unwrap();
            let params = meta.params.expect("its parameters");
            assert_eq!(params.0.world, recorded, "{world:?}");
            let back = params.drawn_under(&Settings::default());
            assert_eq!(
                worlds::drawn_world(&back, Some(seed)),
                worlds::drawn_world(&s, Some(seed)),
                "{world:?}"
            );
        }
    }

    #[test]
    fn unknown_generator_is_a_note_not_an_error() {
        let meta = parse(
            &pairs(&[(KEY_GENERATOR, "ridged"), (KEY_SEED, "7")]),
            Path::new("x.png"),
        )
        .unwrap();
        assert_eq!(meta.params, None);
        assert_eq!(meta.seed, Some(7));
        assert!(meta.notes.iter().any(|n| n.contains(KEY_GENERATOR)));
    }

    #[test]
    fn bad_height_keys_are_errors_naming_the_key() {
        for (key, value) in [
            (KEY_SCALE, "abc"),
            (KEY_SCALE, "NaN"),
            (KEY_SCALE, "0"),
            (KEY_SCALE, "-2"),
            (KEY_OFFSET, "inf"),
            (KEY_OFFSET, "1e39"),
            (KEY_SEA_LEVEL, ""),
            (KEY_EXTENT, "-400"),
            (KEY_FORMAT, "2"),
        ] {
            let err = parse(&pairs(&[(key, value)]), Path::new("m.png")).unwrap_err();
            assert_eq!(err.kind, super::super::ErrorKind::Metadata(key.into()));
            assert!(
                err.to_string().starts_with(&format!("m.png: {key}")),
                "{err}"
            );
        }
    }

    #[test]
    fn duplicate_key_is_an_error() {
        let err = parse(
            &pairs(&[(KEY_SCALE, "1"), (KEY_SCALE, "2")]),
            Path::new("m.png"),
        )
        .unwrap_err();
        assert!(err.problem.contains("more than once"));
    }
}
