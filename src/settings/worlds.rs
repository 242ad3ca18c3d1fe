//! What each world (`world = ...`) sets: the keys of its terrain, sky and
//! light, in place of their defaults, and which world a mountain stands in
//! under "varied". A world lies under the keys as a look does: a key a
//! person sets to anything but its default keeps that value. Unlike a
//! look's, a world's keys are laid per mountain (a varied world is drawn
//! from the mountain's seed), so they are laid where a mountain is made
//! and drawn ([`drawn`]), never into the preferences themselves. The
//! colours no key says (the ground's cover, the water, the air) are read
//! from `Settings::world` by the palette.
//!
//! Only data and the draws here, each key named by its row's constant:
//! the key table checks every value against its key's range, a test
//! applies every preset, and another draws every spread key
//! ([`spreads`], the keys a world draws per mountain within a range).

use super::keys::table::{CLIFFS, CRAGGINESS, EROSION, HEIGHT, LAKES, REFLECTIONS, SEA_LEVEL};
use super::keys::{self, Value};
use super::looks::Preset;
use super::{ColorMode, Look, Settings, World};

use Preset::{Bool, Float, Int, Str};

/// The worlds "varied" draws from, each with its weight: each as often
/// as the others (a commoner one makes more slides alike).
const DRAWN: &[(World, u64)] = &[
    (World::Temperate, 2),
    (World::Alpine, 2),
    (World::Winter, 2),
    (World::Autumn, 2),
    (World::Desert, 2),
    (World::Tropical, 2),
];

/// The worlds other than the temperate (today's picture): each draws its
/// own terrain, cover, water, sky and light per mountain.
pub const OWN_LOOKS: [World; 5] = [
    World::Alpine,
    World::Winter,
    World::Autumn,
    World::Desert,
    World::Tropical,
];

/// Mixed into a mountain's identity for its world, so the world is not
/// the time of day's draw again.
const WORLD_KEY: u64 = 0x776f_726c_6420_6b79;

/// High, jagged ranges, deep valleys worn by rain ([`spreads`]); the
/// water low, a lake at the foot of the range (the palette's glacial
/// water) and the valleys' basins holding more.
const ALPINE: &[(&str, Preset)] = &[(CRAGGINESS.name, Int(128)), (LAKES.name, Bool(true))];

/// Rolling hills to a frozen shore (the palette's ice and cold air; the
/// time of day stays the slide's own); their height and wear are drawn
/// ([`spreads`]).
const WINTER: &[(&str, Preset)] = &[];

/// Softer, lower hills for the forests. (The worlds keep the diamond
/// generator: the Brownian surface is not framed quite alike at every grid
/// size, and a varied slide must be one scene at every size.)
const AUTUMN: &[(&str, Preset)] = &[(CRAGGINESS.name, Int(80))];

/// Terraces, mesas and canyons (their cliffs drawn, [`spreads`]); the
/// low ground a dry basin (the palette draws its "water" as sand and
/// salt flats, which mirror nothing); no lakes; a sky mostly clear (the
/// palette's `clouds::skies`).
const DESERT: &[(&str, Preset)] = &[
    (EROSION.name, Float(0.9)),
    (LAKES.name, Bool(false)),
    (REFLECTIONS.name, Bool(false)),
];

/// Steep islands standing out of a wider sea.
const TROPICAL: &[(&str, Preset)] = &[(CRAGGINESS.name, Int(128))];

/// The number keys a world draws per mountain, each within its (least, most):
/// where the sea stands, so one world's slides are not all one coast
/// (the alpine and autumn valleys drowned deeper or left dry, the
/// tropics' islands larger or fewer, the desert's basin wider or
/// narrower); how high the land stands and how deep the rain has worn
/// it (the desert: how sheer its cliffs), so one world's slides are not
/// all one range. A key of whole numbers is drawn whole, each of its
/// values about as often. Drawn from the seed alone: the same at every
/// size.
fn spreads(world: World) -> &'static [(&'static str, (f64, f64))] {
    match world {
        World::Varied | World::Temperate => &[],
        World::Alpine => &[
            (SEA_LEVEL.name, (-0.45, -0.1)),
            (EROSION.name, (0.4, 1.0)),
            (HEIGHT.name, (5.0, 8.0)),
        ],
        World::Winter => &[
            (SEA_LEVEL.name, (-0.35, 0.05)),
            (EROSION.name, (0.2, 0.9)),
            (HEIGHT.name, (4.0, 8.0)),
        ],
        World::Autumn => &[
            (SEA_LEVEL.name, (-0.5, -0.1)),
            (EROSION.name, (0.3, 0.9)),
            (HEIGHT.name, (3.0, 7.0)),
        ],
        World::Desert => &[
            (SEA_LEVEL.name, (-0.55, -0.2)),
            (CLIFFS.name, (0.4, 1.0)),
            (HEIGHT.name, (4.0, 8.0)),
        ],
        World::Tropical => &[
            (SEA_LEVEL.name, (0.0, 0.3)),
            (EROSION.name, (0.2, 0.8)),
            (HEIGHT.name, (6.0, 9.0)),
        ],
    }
}

/// Mixed into a mountain's seed for its world's spread keys ([`spreads`]),
/// each key's draw its own by its place in the table.
const SPREAD_KEY: u64 = 0x7370_7265_6164_206b;

/// The value of the spread key at `place` in [`spreads`] for the mountain
/// of `seed`, within `(least, most)`; a mountain without a seed (a data
/// set's) takes the middle.
fn spread(seed: Option<u64>, place: usize, (least, most): (f64, f64)) -> Value {
    let unit = seed.map_or(0.5, |seed| {
        let draw = crate::terrain::splitmix::mix(seed ^ SPREAD_KEY ^ place as u64);
        (draw >> 11) as f64 / (1u64 << 53) as f64
    });
    Value::Float(least + (most - least) * unit)
}

/// [`spread`]'s value in the kind `key` holds: for a key of whole
/// numbers a whole number, each of `least..=most` about as often (the
/// middle's for a mountain without a seed).
fn spread_as(key: &keys::Key, seed: Option<u64>, place: usize, (least, most): (f64, f64)) -> Value {
    match ((key.default)(), spread(seed, place, (least, most + 1.0))) {
        (Value::Int(_), Value::Float(x)) => Value::Int((x.floor() as i64).min(most as i64)),
        _ => spread(seed, place, (least, most)),
    }
}

/// Whether the mountain of `seed` under `settings` stands as high as its
/// world draws it ([`spreads`]): not where a person set `height`, nor in
/// a world that keeps the key's own.
pub fn height_drawn(settings: &Settings, seed: Option<u64>) -> bool {
    let world = chosen(settings, seed);
    let drawn = spreads(world).iter().any(|&(name, _)| name == HEIGHT.name);
    drawn && keys::find(HEIGHT.name).is_some_and(|key| keys::get(settings, key) == (key.default)())
}

/// The keys `world` sets and their values (none for the temperate coast,
/// which is the keys' own defaults, nor for "varied", which is one of the
/// others).
pub fn presets(world: World) -> &'static [(&'static str, Preset)] {
    match world {
        World::Varied | World::Temperate => &[],
        World::Alpine => ALPINE,
        World::Winter => WINTER,
        World::Autumn => AUTUMN,
        World::Desert => DESERT,
        World::Tropical => TROPICAL,
    }
}

/// The world the mountain of `seed` stands in under `settings`: the one
/// named, or under "varied" one drawn from the seed (the same at every
/// size, grid and `low_detail`). The seed programs' looks and the colour
/// modes other than the natural colours keep their own pictures: the
/// temperate world's. So does a mountain without a seed (a foreign data
/// set: its heights were not made in any world).
pub fn chosen(settings: &Settings, seed: Option<u64>) -> World {
    if keeps_its_picture(settings) {
        return World::Temperate;
    }
    match (settings.world, seed) {
        (World::Varied, Some(seed)) => drawn_for(seed),
        (World::Varied, None) => World::Temperate,
        (world, _) => world,
    }
}

/// The world "varied" draws for the mountain of `seed`.
pub fn drawn_for(seed: u64) -> World {
    let draw = crate::terrain::splitmix::mix(seed ^ WORLD_KEY);
    let total: u64 = DRAWN.iter().map(|&(_, w)| w).sum();
    let mut pick = draw % total;
    for &(world, weight) in DRAWN {
        if pick < weight {
            return world;
        }
        pick -= weight;
    }
    World::Temperate
}

/// How settings drawn for a mountain ([`drawn`]) hold the temperate
/// coast of the varied draw: a temperate mountain whose day, light and
/// camera are drawn as the other worlds' are. The enum's "varied" has no
/// other meaning once a mountain's world is drawn, so it stands for this
/// one; the render matches on this name, not on "varied".
pub const COAST: World = World::Varied;

/// The world the mountain of `seed` is made and drawn in under
/// `settings`: [`chosen`]'s, except that a temperate mountain of the
/// varied draw stays `World::Varied`, which the render reads as the
/// temperate coast under a day drawn for it as the other worlds' days are
/// (its hour, its light, its camera). A temperate world named keeps the
/// picture from before the worlds, the slide show's twins among them.
pub fn drawn_world(settings: &Settings, seed: Option<u64>) -> World {
    match (chosen(settings, seed), settings.world, seed) {
        (World::Temperate, World::Varied, Some(_)) if !keeps_its_picture(settings) => COAST,
        (world, ..) => world,
    }
}

/// Whether `settings` keep a picture of their own in any world (the seed
/// programs' looks, the colour modes other than the natural colours): the
/// temperate world's.
fn keeps_its_picture(settings: &Settings) -> bool {
    settings.look != Look::Ours || settings.color != ColorMode::Natural
}

/// `settings` as the mountain of `seed` is made and drawn with: its world
/// ([`drawn_world`]) held in `world`, and each key the world sets
/// that `settings` leave at their default given the world's value (its
/// fixed [`presets`], and its [`spreads`] drawn for the mountain).
pub fn drawn(settings: &Settings, seed: Option<u64>) -> Settings {
    let world = chosen(settings, seed);
    let mut out = settings.clone();
    out.world = drawn_world(settings, seed);
    let fixed = presets(world).iter().map(|&(name, preset)| {
        let value = match preset {
            Int(i) => Value::Int(i),
            Float(x) => Value::Float(x),
            Bool(b) => Value::Bool(b),
            Str(s) => Value::Str(s.into()),
        };
        (name, value)
    });
    let ranged = (spreads(world).iter().enumerate()).filter_map(|(place, &(name, range))| {
        Some((name, spread_as(keys::find(name)?, seed, place, range)))
    });
    for (name, value) in fixed.chain(ranged) {
        let Some(key) = keys::find(name) else {
            continue;
        };
        if keys::get(settings, key) == (key.default)() {
            let set = keys::apply(&mut out, key, &value);
            debug_assert!(set.is_ok(), "{name}: a world's value is one its key allows");
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_preset_is_allowed_by_its_key() {
        for &world in DRAWN {
            for &(name, _) in presets(world.0) {
                assert!(keys::find(name).is_some(), "{name}");
            }
            let s = drawn(
                &Settings {
                    world: world.0,
                    ..Settings::default()
                },
                Some(1),
            );
            assert_eq!(s.world, world.0);
        }
    }

    /// Each world's spread keys are drawn within their ranges, over most
    /// of them, the same for one seed; a value a person sets wins; a
    /// mountain without a seed takes the middle (a key of whole numbers
    /// the whole number next to it, and each of its values drawn).
    #[test]
    fn a_worlds_spread_keys_lie_within_their_ranges() {
        for world in OWN_LOOKS {
            let prefs = Settings {
                world,
                ..Settings::default()
            };
            assert!(!spreads(world).is_empty(), "{world:?}");
            for (place, &(name, (least, most))) in spreads(world).iter().enumerate() {
                let key = keys::find(name).expect("a key");
                let whole = matches!((key.default)(), Value::Int(_));
                let value = |s: &Settings| match keys::get(s, key) {
                    Value::Float(x) if !whole => x,
                    Value::Int(i) if whole => i as f64,
                    other => panic!("{name}: {other:?}"),
                };
                let values: Vec<f64> = (1..=300)
                    .map(|seed| value(&drawn(&prefs, Some(seed))))
                    .collect();
                let (lo, hi) = values
                    .iter()
                    .fold((f64::MAX, f64::MIN), |(a, b), &x| (a.min(x), b.max(x)));
                assert!(lo >= least && hi <= most, "{world:?} {name}: {lo}..{hi}");
                assert!(
                    hi - lo >= 0.9 * (most - least),
                    "{world:?} {name}: {lo}..{hi}"
                );
                assert_eq!(
                    value(&drawn(&prefs, Some(7))),
                    values[6],
                    "{world:?} {name}"
                );
                let middle = value(&drawn(&prefs, None));
                let off = if whole { 0.5 } else { 1e-6 };
                assert!(
                    (middle - 0.5 * (least + most)).abs() <= off,
                    "{name}: {middle}"
                );
                if whole {
                    for i in least as i64..=most as i64 {
                        let n = values.iter().filter(|&&x| x == i as f64).count();
                        assert!(
                            n * 2 * (1 + (most - least) as usize) >= 300,
                            "{name} {i}: {n}"
                        );
                    }
                }
                let mut set = prefs.clone();
                // A value the key allows outside the world's range.
                let other = match whole {
                    true => Value::Int(if least > 1.0 { 1 } else { 10 }),
                    false => [-0.9, 0.9, 0.05, 0.99]
                        .into_iter()
                        .filter(|x| !(least..=most).contains(x))
                        .map(Value::Float)
                        .find(|x| keys::apply(&mut prefs.clone(), key, x).is_ok())
                        .expect("a value outside the range"),
                };
                keys::apply(&mut set, key, &other).expect("a value the key allows");
                assert_eq!(
                    keys::get(&drawn(&set, Some(3)), key),
                    other,
                    "{name} {place}"
                );
            }
        }
        assert!(spreads(World::Temperate).is_empty());
    }

    #[test]
    fn varied_draws_every_world() {
        let seen: std::collections::HashSet<_> =
            (0..200).map(|s| format!("{:?}", drawn_for(s))).collect();
        assert_eq!(seen.len(), DRAWN.len(), "{seen:?}");
    }
}
