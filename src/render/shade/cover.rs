//! Each world's ground cover, water and air (`world = ...`; the keys a
//! world sets are `settings/worlds.rs`'s): the colour of the ground by its
//! height and steepness, the water's colour by its depth, and the tint of
//! the air at the horizon, each made richer on its way out ([`richer`]).
//! The temperate world is the palette's own natural colours and is never
//! asked here.
//!
//! Heights are fractions of the highest peak (0 the water line, 1 the
//! top), steepness is relative to the mountain's own steep faces (0 flat,
//! 1 its steep faces): as the palette's zones have them.

use glam::{Vec2, Vec3};

use super::hour::SunAt;
use super::light::Lighting;
use crate::render::base::colour::{Rgb, luminance, mix, ramp, smoothstep};
use crate::settings::World;
use crate::settings::worlds::COAST;

/// Colours of the ground, full sun.
mod ground {
    use super::Rgb;
    pub const SNOW: Rgb = [0.95, 0.96, 1.00];
    pub const FIRN: Rgb = [0.84, 0.88, 0.95];
    pub const GLACIER: Rgb = [0.74, 0.84, 0.92];
    pub const DARK_ROCK: Rgb = [0.27, 0.26, 0.27];
    pub const GREY_ROCK: Rgb = [0.50, 0.48, 0.47];
    pub const VALLEY: Rgb = [0.34, 0.52, 0.22];
    pub const CONIFER: Rgb = [0.13, 0.27, 0.15];
    pub const LARCH_GREEN: Rgb = [0.22, 0.36, 0.19];
    pub const DARK_CONIFER: Rgb = [0.10, 0.15, 0.13];
    pub const SCREE: Rgb = [0.55, 0.52, 0.46];
    pub const GOLD: Rgb = [0.86, 0.62, 0.14];
    pub const ORANGE: Rgb = [0.82, 0.38, 0.10];
    pub const RED: Rgb = [0.64, 0.18, 0.10];
    pub const OAK: Rgb = [0.48, 0.32, 0.16];
    pub const LARCH: Rgb = [0.88, 0.72, 0.26];
    pub const HEATH: Rgb = [0.50, 0.36, 0.28];
    pub const PLAYA: Rgb = [0.93, 0.91, 0.86];
    pub const DUNE: Rgb = [0.88, 0.76, 0.55];
    pub const RUST: Rgb = [0.60, 0.26, 0.14];
    pub const BRICK: Rgb = [0.72, 0.36, 0.20];
    pub const OCHRE: Rgb = [0.82, 0.56, 0.28];
    pub const CREAM: Rgb = [0.88, 0.78, 0.60];
    pub const CHOCOLATE: Rgb = [0.42, 0.24, 0.16];
    pub const CORAL_SAND: Rgb = [0.97, 0.95, 0.86];
    pub const JUNGLE: Rgb = [0.09, 0.42, 0.13];
    pub const BASALT: Rgb = [0.24, 0.22, 0.21];
    pub const DRY_GRASS: Rgb = [0.66, 0.58, 0.30];
    pub const SCRUB: Rgb = [0.34, 0.36, 0.17];
}

/// Mixed into a mountain's identity for its draw within its world.
const DRAW_KEY: u64 = 0x636f_7665_7220_6472;

/// A number from 0 to 1 drawn from the mountain's `identity`: where in
/// its world's range this mountain's cover lies (a snow line, a season's
/// progress, a rock's colour), so two slides of one world differ.
pub fn draw(identity: u64) -> f32 {
    crate::terrain::splitmix::unit(crate::terrain::splitmix::mix(identity ^ DRAW_KEY))
}

/// Where between its world's palettes the mountain of draw `v` ([`draw`])
/// lies, 0 to 1 (another of the draw's digits, apart from its snow line
/// and season): the bare granite or the slate and pastures of a range,
/// winter's fresh snow or its wind-scoured rock, autumn's gold, red or
/// brown, the desert's pale or red sand, the tropics' emerald or
/// yellow-green. A world of one palette made its slides alike.
pub fn mood(v: f32) -> f32 {
    (v * 17.0).fract()
}

/// The ground's colour in `world` at height fraction `u` on a face of
/// relative steepness `steep`, `facing` from -1 (a face turned from the
/// mountain's sunward side, [`sunward`]) to 1 (turned to it), which only
/// a world that [`faces`] tells apart, where water runs `wet` (0 a dry
/// ridge, 1 a stream: `terrain::Wetness`); `beach` when the land meets a
/// sea; `v` the mountain's draw ([`draw`]).
pub fn land(world: World, at: (f32, f32, f32, f32), beach: bool, v: f32) -> Rgb {
    richer(world, land_drawn(world, at, beach, v))
}

/// [`land`] before the world's richness ([`richer`]).
fn land_drawn(
    world: World,
    (u, steep, facing, wet): (f32, f32, f32, f32),
    beach: bool,
    v: f32,
) -> Rgb {
    let ground = match world {
        World::Alpine => alpine(u, steep, v),
        World::Winter => winter(u, steep, v),
        World::Autumn => autumn(u, steep, beach, v, facing),
        World::Desert => desert(u, steep, v),
        World::Tropical => tropical(u, steep, beach, v),
        COAST | World::Temperate => return ground::VALLEY,
    };
    watered(world, ground, (u, steep), beach, v, wet)
}

/// `c` as `world` shows it: in a world of its own cover, its colour
/// strengthened at the same luminance, the more the duller it is (a
/// photographer's vibrance), up to [`VIBRANCE`] times for a grey's
/// faintest tint, and clamped to the gamut. The temperate world keeps its
/// colours. A world's pigments are mixed with haze, sky and each other
/// before they reach the screen; drawn as named, the six worlds' slides
/// were told apart by their light more than by their places (issue 32's
/// survey: a slide's nearest other 18.1 apart, all pairs 32.8).
fn richer(world: World, c: Rgb) -> Rgb {
    if matches!(world, World::Temperate | COAST) {
        return c;
    }
    let k = 1.0 + (VIBRANCE - 1.0) * (1.0 - spread(c).clamp(0.0, 1.0));
    let y = luminance(c);
    c.map(|v| (y + k * (v - y)).clamp(0.0, 1.0))
}

/// How many times stronger [`richer`] makes a world's dullest colours;
/// a full colour (one channel 0, another 1) keeps its own.
const VIBRANCE: f32 = 1.6;

/// How far `c` is from a grey: its largest channel less its smallest.
fn spread(c: Rgb) -> f32 {
    c.iter().fold(0.0f32, |a, &v| a.max(v)) - c.iter().fold(1.0f32, |a, &v| a.min(v))
}

/// Whether `world`'s ground follows where water runs (every world's own
/// cover; the temperate world keeps its picture).
pub fn wets(world: World) -> bool {
    !matches!(world, World::Temperate | COAST)
}

/// Greener where the ground drains much (`wet` near 1: the valley
/// floors, the gullies), barer and drier where it drains only itself
/// (`wet` 0: the ridges), each world in its own way: the alpine meadows
/// lush along the streams and scree on the ridges, winter's forest
/// thicker along its valleys, autumn's streams lined with alders still
/// green and its ridges brown with heath, the desert green only along
/// its wettest gullies and oases, the tropics' jungle deep in the gullies
/// and grass on the ridges. Never the snow, the bare rock of the steepest
/// faces or the beaches.
fn watered(
    world: World,
    ground: Rgb,
    (u, steep): (f32, f32),
    beach: bool,
    v: f32,
    wet: f32,
) -> Rgb {
    use ground::*;
    // The lush and the parched colours, how far towards each, and up to
    // which height.
    let (lush, parched, (more, less), top) = match world {
        World::Alpine => (VALLEY, SCREE, (0.45, 0.3), 0.3 + 0.4 * v),
        World::Winter => (DARK_CONIFER, ground, (0.35, 0.0), 0.35 + 0.35 * v),
        World::Autumn => ([0.26, 0.38, 0.14], HEATH, (0.22, 0.08), 0.7),
        World::Desert => ([0.30, 0.40, 0.16], ground, (0.75, 0.0), 0.35),
        World::Tropical => (JUNGLE, DRY_GRASS, (0.4, 0.35), 0.8),
        COAST | World::Temperate => return ground,
    };
    let low = 1.0 - smoothstep(top, top + 0.15, u);
    let shore = if beach {
        smoothstep(0.04, 0.09, u)
    } else {
        1.0
    };
    // Not the snow (nor the ice): nothing grows through it.
    let white = smoothstep(0.6, 0.8, ground[0].min(ground[1]).min(ground[2]));
    let soil = low * shore * (1.0 - smoothstep(0.55, 0.9, steep)) * (1.0 - white);
    let ground = mix(ground, lush, more * wet * soil);
    mix(ground, parched, less * (1.0 - wet) * soil)
}

/// How far along from the driest ground's colour to the streams' a point
/// where water runs `wet` (`terrain::Wetness`) lies in `world`: as wet
/// as it is, but in the desert only where the water gathers most (its
/// oases and wettest gullies; the rest of it is dry alike).
#[inline]
pub fn streams(world: World, wet: f32) -> f32 {
    match world {
        World::Desert => smoothstep(0.55, 1.0, wet),
        _ => wet,
    }
}

/// Green valley floors, dark forest on the lower slopes, scree, then
/// snowfields and glaciers far down: dark rock where the faces are too
/// steep to hold snow.
fn alpine(u: f32, steep: f32, v: f32) -> Rgb {
    use ground::*;
    // From a bare granite range (dry turf, pale rock) through today's to
    // one of dark slate over lush pastures, by the mountain.
    let k = smoothstep(0.0, 1.0, mood(v));
    let pick = |[bare, slate]: [Rgb; 2], today: Rgb| match k < 0.5 {
        true => mix(bare, today, 2.0 * k),
        false => mix(today, slate, 2.0 * k - 1.0),
    };
    let valley = pick([[0.50, 0.52, 0.36], [0.30, 0.58, 0.18]], VALLEY);
    let wood = pick([[0.40, 0.40, 0.33], [0.12, 0.28, 0.13]], LARCH_GREEN);
    let low = ramp(
        &[
            (0.0, valley),
            (0.07, valley),
            (0.12, wood),
            (0.2, wood),
            (0.28, SCREE),
        ],
        u,
    );
    let grey = pick([[0.64, 0.62, 0.60], [0.34, 0.35, 0.38]], GREY_ROCK);
    let dark = pick([[0.42, 0.40, 0.40], [0.17, 0.18, 0.21]], DARK_ROCK);
    let rock = mix(grey, dark, smoothstep(0.5, 1.0, steep));
    let low = mix(low, rock, smoothstep(0.45, 0.85, steep));
    // Snow from low on the flats (from the valleys after a fresh fall,
    // only on the high ground late in a summer), higher on steep ground.
    let line = 0.04 + 0.46 * v + 0.4 * smoothstep(0.3, 0.95, steep);
    let snow = smoothstep(line, line + 0.08, u) * (1.0 - smoothstep(0.8, 1.0, steep));
    let white = ramp(&[(0.0, GLACIER), (0.5, FIRN), (0.8, SNOW)], u);
    mix(low, white, snow)
}

/// Snow down to the shore wherever a slope holds it; dark forest in
/// patches on the lower slopes; dark rock on the steep faces.
fn winter(u: f32, steep: f32, v: f32) -> Rgb {
    use ground::*;
    let snow = ramp(&[(0.0, FIRN), (0.3, SNOW)], u);
    // Forest on the middle slopes of the lower land, the snow in its gaps.
    // A wooded country or an open one, by the mountain.
    let treeline = 0.3 + 0.35 * v;
    let forest = smoothstep(0.2, 0.45, steep)
        * (1.0 - smoothstep(treeline, treeline + 0.2, u))
        * (0.15 + 0.85 * v);
    let ground = mix(snow, DARK_CONIFER, forest * bands(u, 9.0));
    // Fresh snow on every face that holds it, or a wind that has scoured
    // the ridges and the steeper slopes to brown rock, by the mountain.
    let wind = mood(v);
    let bare = smoothstep(0.62 - 0.4 * wind, 0.92 - 0.25 * wind, steep)
        * (1.0 - 0.4 * wind * bands(u, 6.0));
    let rock = mix(DARK_ROCK, [0.36, 0.31, 0.27], wind);
    mix(ground, rock, bare)
}

/// Whether `world`'s ground differs by the way a slope faces: autumn's
/// woods turn earlier on the slopes that face the sun, and its shaded
/// slopes keep more evergreens.
pub fn faces(world: World) -> bool {
    world == World::Autumn
}

/// The mountain's sunward side, a unit vector in the grid's plane, drawn
/// from its `identity`: where its slopes face the sun over the season,
/// whatever the hour of the slide (the leaves do not follow the light).
/// `quarters` is the quarter turns the drawn grid is turned by
/// (`Settings::quarter_turns`): the side belongs to the land, so it turns
/// with it.
pub fn sunward(identity: u64, quarters: u32) -> Vec2 {
    let turn =
        crate::terrain::splitmix::unit(crate::terrain::splitmix::mix(identity ^ SUNWARD_KEY));
    let side = Vec2::from_angle(turn * std::f32::consts::TAU);
    // A quarter turn takes the old right edge (+x) to the row y = 0.
    (0..quarters % 4).fold(side, |d, _| Vec2::new(d.y, -d.x))
}

/// Mixed into a mountain's identity for its sunward side.
const SUNWARD_KEY: u64 = 0x7375_6e77_6172_6473;

/// How far a face of unit normal `normal` (z up) turns to `sunward`, from
/// 0 (away) to 1 (towards it); 0.5 on the flat, whose colour is thus the
/// mean of the two facings' (not exactly `land`'s at `facing` 0: the
/// season's ramp is not straight). A moderate slope already
/// counts fully: the facing shows in patches, not only on the cliffs.
#[inline]
pub fn facing_weight(normal: Vec3, sunward: Vec2) -> f32 {
    let toward = normal.x * sunward.x + normal.y * sunward.y;
    0.5 + 0.5 * (FACING_GAIN * toward).clamp(-1.0, 1.0)
}

/// The sideways part of a face's normal (the sine of its slope) at which
/// it counts as facing fully one way: about 17 degrees.
const FACING_GAIN: f32 = 3.5;

/// Forests in gold, orange, red and brown by height, evergreens dark on
/// the steeper slopes, larches yellow and heath brown above them. The
/// slopes facing the sun (`facing` 1) are further into the season, redder
/// and browner; those turned from it keep more gold and more evergreens.
fn autumn(u: f32, steep: f32, beach: bool, v: f32, facing: f32) -> Rgb {
    use ground::*;
    let b = bands(u, 5.0 + 4.0 * v);
    let broadleaf = ramp(
        &[
            (0.0, GOLD),
            (0.2, ORANGE),
            (0.35, RED),
            (0.5, OAK),
            (0.62, LARCH),
            (0.78, HEATH),
            (1.0, GREY_ROCK),
        ],
        // Early in the season the lower woods are gold, late red and
        // brown.
        u + 0.08 * (b - 0.5) + 0.3 * (v - 0.4) + 0.14 * facing,
    );
    // Woods of larch and birch gold, of maple red, or of oak and heath
    // brown, by the mountain.
    let leaves = ramp(
        &[
            (0.0, [0.90, 0.68, 0.18]),
            (0.5, [0.74, 0.20, 0.10]),
            (1.0, [0.46, 0.32, 0.20]),
        ],
        // The slopes facing the sun further into the season, as above.
        mood(v) + 0.25 * facing,
    );
    let broadleaf = mix(broadleaf, leaves, 0.55);
    let evergreen = smoothstep(0.35, 0.6, steep - 0.2 * facing)
        * (1.0 - smoothstep(0.6, 0.75, u))
        * (0.3 + 0.6 * b);
    let ground = mix(broadleaf, CONIFER, evergreen);
    let ground = mix(ground, GREY_ROCK, smoothstep(0.75, 1.0, steep) * 0.6);
    // Late in a season the first snow has fallen on the tops.
    let snow_line = 1.3 - 0.7 * smoothstep(0.6, 1.0, v);
    let ground = mix(
        ground,
        FIRN,
        smoothstep(snow_line, snow_line + 0.1, u) * (1.0 - smoothstep(0.55, 0.85, steep)),
    );
    if beach && u < 0.03 {
        return mix(CREAM, ground, smoothstep(0.0, 0.03, u));
    }
    ground
}

/// Strata in red, ochre and cream, darker and redder on the cliffs, pale
/// sand on the flats below and white playa where the lowest flats lie.
fn desert(u: f32, steep: f32, v: f32) -> Rgb {
    use ground::*;
    // Layers of rock of uneven thickness: a few repeats over the relief,
    // more or fewer, and redder or paler, by the mountain.
    let t = (u * (3.5 + 3.0 * v) + v).fract();
    let [brick, ochre, cream, rust, chocolate] = strata(v);
    let layer = ramp(
        &[
            (0.0, brick),
            (0.22, ochre),
            (0.36, cream),
            (0.46, ochre),
            (0.62, rust),
            (0.8, brick),
            (0.9, chocolate),
            (1.0, brick),
        ],
        t,
    );
    // Flats take sand; faces show their layers.
    let flat = 1.0 - smoothstep(0.15, 0.45, steep);
    // Pale sand, or red, by the mountain.
    let sand = ramp(&[(0.0, DUNE), (0.1, DUNE), (1.0, OCHRE)], u);
    let sand = mix(sand, [0.74, 0.40, 0.22], 0.9 * mood(v));
    let cover = flat * (1.0 - smoothstep(0.1, 0.35, u)) + flat * 0.35;
    let ground = mix(layer, sand, cover.min(1.0));
    let ground = mix(ground, mix(ground, RUST, 0.5), smoothstep(0.7, 1.0, steep));
    mix(ground, CREAM, 0.45 * smoothstep(0.55, 1.0, v))
}

/// The desert's rock, by the mountain's draw `v`: its strata's five
/// colours (brick, ochre, cream, rust, chocolate in the red rock's
/// country). Deserts differ most in their stone: red rock, pale
/// sandstone, grey and maroon badlands, dark lava.
fn strata(v: f32) -> [Rgb; 5] {
    use ground::*;
    match (v * 11.0).fract() {
        k if k < 0.4 => [BRICK, OCHRE, CREAM, RUST, CHOCOLATE],
        k if k < 0.6 => [
            [0.86, 0.66, 0.56],
            [0.90, 0.82, 0.68],
            [0.96, 0.93, 0.86],
            [0.80, 0.62, 0.50],
            [0.66, 0.52, 0.44],
        ],
        k if k < 0.8 => [
            [0.56, 0.30, 0.28],
            [0.66, 0.62, 0.64],
            [0.80, 0.74, 0.66],
            [0.52, 0.46, 0.56],
            [0.36, 0.30, 0.36],
        ],
        _ => [
            [0.30, 0.26, 0.25],
            [0.62, 0.50, 0.34],
            [0.80, 0.70, 0.52],
            [0.22, 0.20, 0.20],
            [0.15, 0.14, 0.14],
        ],
    }
}

/// White beaches, palms then jungle up the slopes (dry grass and scrub
/// on a dry island), dark basalt on the steepest faces and the volcanic
/// tops.
fn tropical(u: f32, steep: f32, beach: bool, v: f32) -> Rgb {
    use ground::*;
    // The lee of some islands lies in a dry season: golden grass and
    // olive scrub for the palms and the jungle.
    let dry = smoothstep(0.55, 0.9, v);
    // Emerald forest or a yellower green, by the mountain.
    let k = mood(v);
    let (palm, jungle) = (
        mix([0.16, 0.58, 0.24], [0.50, 0.64, 0.12], k),
        mix([0.02, 0.44, 0.26], [0.28, 0.44, 0.06], k),
    );
    let (palm, jungle) = (mix(palm, DRY_GRASS, dry), mix(jungle, SCRUB, dry));
    let green = ramp(
        &[(0.0, palm), (0.12, palm), (0.3, jungle), (1.0, jungle)],
        u,
    );
    let green = match beach {
        true => ramp(&[(0.0, CORAL_SAND), (0.03, CORAL_SAND), (0.06, green)], u),
        false => green,
    };
    let rock = smoothstep(0.6, 0.95, steep) + smoothstep(0.82, 1.0, u) * 0.6;
    mix(green, BASALT, rock.min(0.85))
}

/// Whether `world`'s low ground lies dry (sand and salt in place of the
/// water, see [`water`]): no wind streaks it, and it mirrors nothing.
pub fn dry_basin(world: World) -> bool {
    world == World::Desert
}

/// The water's colour over ground a share `t` (0 at the shore, 1 the
/// deepest) of the deepest depth down, in `world`; `v` the mountain's draw.
pub fn water(world: World, t: f32, v: f32) -> Rgb {
    richer(world, water_drawn(world, t, v))
}

/// [`water`] before the world's richness ([`richer`]).
fn water_drawn(world: World, t: f32, v: f32) -> Rgb {
    let s = t.sqrt();
    match world {
        World::Alpine => mix([0.22, 0.55, 0.58], [0.05, 0.24, 0.32], s),
        World::Winter => {
            // Ice out from the shore over the shallows, dark open water
            // beyond.
            let edge = 0.12 + 0.3 * v;
            let ice = 1.0 - smoothstep(edge, edge + 0.08, t);
            mix(
                mix([0.10, 0.22, 0.34], [0.02, 0.07, 0.16], s),
                [0.82, 0.88, 0.94],
                ice,
            )
        }
        World::Autumn => mix([0.18, 0.40, 0.52], [0.03, 0.10, 0.22], s),
        // The basin lies dry: sand at its edge, salt on its floor.
        World::Desert => ramp(
            &[
                (0.0, ground::DUNE),
                (0.15, [0.90, 0.84, 0.70]),
                (0.5, ground::PLAYA),
                (1.0, ground::PLAYA),
            ],
            t,
        ),
        World::Tropical => ramp(
            &[
                (0.0, [0.55, 0.92, 0.84]),
                (0.1, [0.12, 0.78, 0.78]),
                (0.3, [0.04, 0.45, 0.66]),
                (1.0, [0.02, 0.12, 0.38]),
            ],
            t,
        ),
        COAST | World::Temperate => [0.10, 0.34, 0.66],
    }
}

/// The sky's colours in `world`, top and horizon, from the light's
/// `zenith` and `horizon`: a dusty desert air, a cold winter one, a clear
/// mountain one, an autumn's golden haze, each thicker or thinner by the
/// mountain's draw of its air `v` ([`air_draw`]), its top somewhere
/// between the world's two skies, so two slides of one world at one time
/// of day are apart. `night` (0 to 1) of the night's look turns both
/// towards the world's own night ([`night_air`]), and a twilight's
/// horizon to its afterglow (`dusk.rs`).
pub fn air(world: World, sky: [Rgb; 2], v: f32, night: f32) -> [Rgb; 2] {
    air_drawn(world, sky, v, night).map(|c| richer(world, c))
}

/// [`air`] before the world's richness ([`richer`]).
fn air_drawn(world: World, [zenith, horizon]: [Rgb; 2], v: f32, night: f32) -> [Rgb; 2] {
    // The tint of the horizon and how much of it (least to most), and the
    // two tints of the sky's top (a paler, hazier one and a deeper one)
    // and how much of them at most.
    let (tint, (lo, hi), tops, most) = match world {
        World::Desert => (
            [0.86, 0.74, 0.58],
            (0.15, 0.75),
            [[0.72, 0.70, 0.64], [0.10, 0.24, 0.62]],
            0.75,
        ),
        World::Winter => (
            [0.80, 0.86, 0.94],
            (0.15, 0.8),
            [[0.56, 0.62, 0.72], [0.22, 0.44, 0.74]],
            0.8,
        ),
        World::Tropical => (
            [0.70, 0.88, 0.95],
            (0.0, 0.5),
            [[0.04, 0.34, 0.80], [0.16, 0.58, 0.86]],
            0.75,
        ),
        World::Autumn => (
            [0.88, 0.76, 0.58],
            (0.1, 0.6),
            [[0.40, 0.44, 0.58], [0.14, 0.26, 0.60]],
            0.7,
        ),
        World::Alpine => (
            [0.78, 0.88, 0.98],
            (0.05, 0.5),
            [[0.04, 0.12, 0.42], [0.12, 0.34, 0.78]],
            0.75,
        ),
        COAST | World::Temperate => return [zenith, horizon],
    };
    let day = 1.0 - night;
    let horizon = mix(horizon, tint, (lo + (hi - lo) * v) * day);
    // The top's tint follows draws of its own (the draw's other digits).
    let (w, which) = ((v * 7.0).fract(), (v * 13.0).fract());
    let top = mix(tops[0], tops[1], which);
    let day_sky = [mix(zenith, top, most * (0.3 + 0.7 * w) * day), horizon];
    let dark = night_air(world, v);
    let [top, horizon] = [0, 1].map(|i| mix(day_sky[i], dark[i], night * NIGHT_AIR));
    let glow = super::dusk::afterglow(world, v);
    [top, mix(horizon, glow, super::dusk::glowing(night))]
}

/// How thick the aerial haze is at the back edge (`haze.rs`) on the
/// mountain of air draw `v` ([`air_draw`]) in `world`, within [`HAZE`]
/// (another of the draw's digits): a crisp day whose far ridges keep
/// their colours, or a hazy one that fades them into the sky. None for
/// the temperate world, which keeps its own.
pub fn haze(world: World, v: f32) -> Option<f32> {
    if matches!(world, World::Temperate | COAST) {
        return None;
    }
    Some(HAZE.0 + (HAZE.1 - HAZE.0) * (v * 23.0).fract())
}

/// The thinnest and the thickest haze at the back edge of a world's
/// land ([`haze`]; the temperate world's is `haze.rs`'s 0.45).
pub const HAZE: (f32, f32) = (0.05, 0.6);

/// How far a full night turns the sky to its world's own ([`night_air`]):
/// most of the way, the night's deep blue still under it.
const NIGHT_AIR: f32 = 0.8;

/// The night sky of `world`, top and horizon, with the mountain's draw of
/// its air `v`: somewhere between the world's clearest, darkest night and
/// its hazier, moonlit one (the desert's violet dusk, the glow of moonlit
/// snow under winter's, the tropics' deep teal, autumn's warm haze, the
/// mountains' near-black or their moonlit blue). Each stays dark: no
/// night a black frame, none a bright one.
fn night_air(world: World, v: f32) -> [Rgb; 2] {
    let [dark, moonlit]: [[Rgb; 2]; 2] = match world {
        World::Desert => [
            [[0.025, 0.015, 0.070], [0.15, 0.08, 0.16]],
            [[0.060, 0.040, 0.120], [0.26, 0.15, 0.24]],
        ],
        World::Winter => [
            [[0.030, 0.045, 0.090], [0.16, 0.20, 0.26]],
            [[0.070, 0.100, 0.170], [0.30, 0.35, 0.42]],
        ],
        World::Tropical => [
            [[0.005, 0.040, 0.100], [0.04, 0.17, 0.22]],
            [[0.020, 0.090, 0.170], [0.10, 0.30, 0.34]],
        ],
        World::Autumn => [
            [[0.030, 0.025, 0.045], [0.15, 0.10, 0.08]],
            [[0.060, 0.050, 0.080], [0.26, 0.19, 0.15]],
        ],
        World::Alpine => [
            [[0.004, 0.008, 0.035], [0.04, 0.06, 0.13]],
            [[0.030, 0.070, 0.180], [0.14, 0.22, 0.36]],
        ],
        COAST | World::Temperate => [
            [[0.015, 0.030, 0.085], [0.08, 0.11, 0.20]],
            [[0.015, 0.030, 0.085], [0.08, 0.11, 0.20]],
        ],
    };
    let t = (v * 3.0).fract();
    [0, 1].map(|i| mix(dark[i], moonlit[i], t))
}

/// A number from 0 to 1 drawn from the mountain's `identity` for its air
/// ([`air`]): apart from [`draw`], so a snowier year is not always a
/// hazier one.
pub fn air_draw(identity: u64) -> f32 {
    (crate::terrain::splitmix::mix(identity ^ DRAW_KEY) & 0xff_ffff) as f32 / (1u64 << 24) as f32
}

/// A number from 0 to 1 drawn from the mountain's `identity` for its
/// day's light ([`light`]), apart from [`draw`] and [`air_draw`].
pub fn light_draw(identity: u64) -> f32 {
    ((crate::terrain::splitmix::mix(identity ^ DRAW_KEY) >> 24) & 0xffff) as f32 / 65536.0
}

/// Mixed into a mountain's identity for its day's sun ([`sun`]), so the
/// hour is not another draw's again.
const SUN_KEY: u64 = 0x7375_6e20_6f66_2064;

/// The share of a world's varied days whose sun stands low (below
/// [`LOW_SUN`]): the hours that colour a sky, commoner than an even draw
/// over the day's heights would make them.
const LOW_SHARE: f32 = 0.45;
/// Degrees up below which a sun counts as low.
const LOW_SUN: f32 = 10.0;

/// How low and how high a varied day's sun stands in `world`, in degrees:
/// the alpine and the winter worlds reach down to the horizon (the
/// peaks' last light; a sun below it is a twilight's, `dusk.rs`, so the
/// survey's nights are the nights drawn), winter's sun never stands high, the
/// desert's and the tropics' noon stand highest. None for the temperate
/// world named (its four times are the slide show from before the
/// worlds); the temperate coast of the varied draw (`worlds::COAST` here,
/// `worlds::drawn_world`) draws its hour as the others do.
fn sun_heights(world: World) -> Option<(f32, f32)> {
    match world {
        World::Alpine => Some((0.0, 50.0)),
        World::Winter => Some((0.0, 18.0)),
        World::Autumn => Some((1.0, 35.0)),
        World::Desert => Some((1.0, 65.0)),
        World::Tropical => Some((2.0, 70.0)),
        COAST => Some((1.0, 55.0)),
        World::Temperate => None,
    }
}

/// Where the sun of a varied day over the mountain `identity` stands in
/// `world`: any height in the world's range ([`sun_heights`]), morning or
/// afternoon, from the viewer's side, and half the low suns ahead (the
/// land against a glowing sky), so two slides of one world are seldom lit
/// by one hour (the temperate world's four times lit many alike, and
/// still light it where it is named). None
/// for the temperate world named.
pub fn sun(world: World, identity: u64) -> Option<SunAt> {
    let (lo, hi) = sun_heights(world)?;
    let draw = crate::terrain::splitmix::mix(identity ^ SUN_KEY);
    let unit = |shift: u32| ((draw >> shift) & 0xffff) as f32 / 65535.0;
    let (pick, height, side) = (unit(0), unit(16), unit(32));
    let low = LOW_SUN.min(hi);
    let elevation = match pick < LOW_SHARE {
        true => lo + (low - lo) * height,
        false => low + (hi - low) * height,
    };
    let afternoon = (draw >> 63) == 1;
    let ahead = elevation < LOW_SUN && (draw >> 62) & 1 == 1;
    // Degrees round from the viewer's left: ahead within the view's
    // width, else from the side, anywhere round to over the viewer's
    // shoulder (the land lit full face), never from behind the range (a
    // low sun there leaves the near land in one shadow).
    let azimuth = match (ahead, afternoon) {
        (true, _) => 75.0 + 30.0 * side,
        (false, false) => 35.0 - 95.0 * side,
        (false, true) => 145.0 + 95.0 * side,
    };
    Some(SunAt {
        elevation,
        azimuth,
        afternoon,
    })
}

/// The day's light in `world`, from the time of day's `light`: winter's
/// low, cold sun (lower, paler and bluer, more of its light from the
/// sky); in every world but the temperate named (`worlds::COAST` is the
/// temperate coast of the varied draw) a brighter or duller, warmer or
/// colder day, its shade lighter or deeper, by the mountain's draw `v`
/// ([`light_draw`]), the shade lighter still under a low sun ahead
/// ([`BACKLIT`]); a twilight's land lit [`TWILIGHT_LIFT`] times as
/// bright as the time of day's; a full night's land lit [`MOONLIT`]
/// times as bright as the temperate world's. Seed 000's light is left
/// as it is.
pub fn light(world: World, mut light: Lighting, v: f32) -> Lighting {
    if light.classic || world == World::Temperate {
        return light;
    }
    if light.night >= 1.0 {
        // Its darkest woods (the tropics' jungle, autumn's) otherwise
        // go black under `sun = "night"`'s moon.
        for c in [&mut light.direct, &mut light.ambient] {
            *c = c.map(|x| x * MOONLIT);
        }
        return light;
    }
    if light.night > 0.0 {
        // The afterglow and the blue hour's sky still light the land:
        // the sunset's light dimmed to the night's was a dark land under
        // every world's twilight, and those slides alike.
        for c in [&mut light.direct, &mut light.ambient] {
            *c = c.map(|x| x * TWILIGHT_LIFT);
        }
        return light;
    }
    if world == World::Winter {
        let s = light.sun;
        let el = s.z.clamp(-1.0, 1.0).asin().to_degrees();
        let low = el.min(8.0 + 0.35 * el).to_radians();
        let flat = glam::Vec2::new(s.x, s.y).normalize_or_zero() * low.cos();
        light.sun = glam::Vec3::new(flat.x, flat.y, low.sin()).normalize_or(s);
        light.direct = mix(light.direct, [0.80, 0.86, 0.98], 0.35).map(|c| 0.85 * c);
        light.ambient = mix(light.ambient, [0.42, 0.48, 0.62], 0.3);
    }
    // Two draws from one: how bright, and how warm.
    let (bright, warm) = (v, (v * 5.0).fract());
    let tint = match warm < 0.5 {
        true => mix([1.0; 3], [1.0, 0.84, 0.66], 2.0 * (0.5 - warm)),
        false => mix([1.0; 3], [0.84, 0.92, 1.0], 2.0 * (warm - 0.5)),
    };
    let k = DIRECT.0 + (DIRECT.1 - DIRECT.0) * bright;
    light.direct = [0, 1, 2].map(|i| light.direct[i] * tint[i] * k);
    // A hazy day's sky lights the shade more than a clear one's: how
    // much, a third draw from the one.
    let sky = SKY_LIGHT.0 + (SKY_LIGHT.1 - SKY_LIGHT.0) * (v * 3.0).fract();
    let sky = sky * (1.0 + BACKLIT * backlit(light.sun));
    light.ambient = light.ambient.map(|c| c * sky);
    light.glints = light.direct;
    light
}

/// How bright a world's day's sky light is against its time of day's,
/// least and most ([`light`]): the shade deep under a clear sky, light
/// under a hazy one.
const SKY_LIGHT: (f32, f32) = (0.55, 1.9);

/// How bright a world's day's sunlight is against its time of day's,
/// least and most ([`light`]): a dull day's or a brilliant one's.
const DIRECT: (f32, f32) = (0.85, 1.35);

/// How much of a world's twilight's light ([`light`]) the land keeps
/// against the time of day's: the afterglow's and the blue sky's light
/// on the snow, the rock and the leaves, the land still read.
const TWILIGHT_LIFT: f32 = 1.8;

/// How much more sky light the faces turned to the viewer take under a
/// low sun ahead ([`backlit`]): the glowing sky ahead and the air lit
/// round them fill the shade, which else is one dark silhouette on
/// every such slide of every world.
const BACKLIT: f32 = 0.8;

/// How far the sun at unit vector `sun` (z up, y towards the back)
/// stands low ahead of the viewer: 1 low in the view, 0 from the side,
/// behind or high.
fn backlit(sun: Vec3) -> f32 {
    smoothstep(0.3, 0.9, sun.y) * (1.0 - smoothstep(0.1, 0.3, sun.z))
}

/// How much brighter a world's moonlit land is than `sun = "night"`'s
/// (the temperate world's nights keep their pictures): the land must
/// read against the night sky.
const MOONLIT: f32 = 1.7;

/// A pattern of patches across the heights: 0 to 1, `n` ups and downs
/// over the relief (stands of one tree and another, bands of snow).
fn bands(u: f32, n: f32) -> f32 {
    let x = u * n;
    let a = (x * std::f32::consts::TAU).sin();
    let b = (x * 2.37 * std::f32::consts::TAU + 1.3).sin();
    (0.5 + 0.3 * a + 0.2 * b).clamp(0.0, 1.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::settings::worlds::OWN_LOOKS as DRAWN;

    /// A world of its own cover shows a dull colour stronger at the same
    /// luminance, a grey as grey, a full colour as it is; the temperate
    /// world (and its coast in the varied draw) keeps every colour.
    #[test]
    fn a_world_strengthens_its_dull_colours_and_keeps_greys_and_full_ones() {
        let (dull, grey, full) = (ground::DUNE, [0.5; 3], [1.0, 0.5, 0.0]);
        for world in DRAWN {
            let r = richer(world, dull);
            assert!(
                (luminance(r) - luminance(dull)).abs() < 1e-4,
                "{world:?} {r:?}"
            );
            let gain = spread(r) / spread(dull);
            let most = 1.0 + (VIBRANCE - 1.0) * (1.0 - spread(dull));
            assert!(
                (gain - most).abs() < 1e-3 && gain > 1.2,
                "{world:?}: {gain}"
            );
            assert_eq!(richer(world, grey), grey, "{world:?}");
            assert_eq!(richer(world, full), full, "{world:?}");
        }
        for world in [World::Temperate, COAST] {
            assert_eq!(richer(world, dull), dull, "{world:?}");
        }
    }

    /// What a world's land, water and air give is its pigments made richer:
    /// each more colourful than its colour before [`richer`].
    #[test]
    fn a_worlds_land_water_and_air_are_richer_than_their_pigments() {
        let (zenith, horizon) = ([0.30, 0.50, 0.85], [0.75, 0.82, 0.90]);
        for world in DRAWN {
            let at = (0.3, 0.2, 0.0, 0.0);
            let ground = land_drawn(world, at, true, 0.5);
            assert!(
                spread(land(world, at, true, 0.5)) > spread(ground),
                "{world:?}"
            );
            let lake = water_drawn(world, 0.2, 0.5);
            assert!(spread(water(world, 0.2, 0.5)) > spread(lake), "{world:?}");
            let [top, _] = air(world, [zenith, horizon], 0.5, 0.0);
            let [before, _] = air_drawn(world, [zenith, horizon], 0.5, 0.0);
            assert!(
                spread(top) > spread(before),
                "{world:?}: {top:?} {before:?}"
            );
        }
    }

    /// A varied day's sun stands within its world's heights, over most of
    /// them, and shines from the side, over the viewer's shoulder or,
    /// low, from ahead: never from high behind the range.
    #[test]
    fn a_worlds_sun_stands_within_its_heights_and_never_behind_the_range() {
        // `worlds::COAST`: the temperate coast of the varied draw.
        for world in DRAWN.into_iter().chain([COAST]) {
            let (lo, hi) = sun_heights(world).expect("a world's heights");
            let suns: Vec<SunAt> = (0..2000).filter_map(|i| sun(world, i)).collect();
            assert_eq!(suns.len(), 2000, "{world:?}");
            let (least, most) = suns.iter().fold((f32::MAX, f32::MIN), |(a, b), s| {
                (a.min(s.elevation), b.max(s.elevation))
            });
            assert!(least >= lo && most <= hi, "{world:?}: {least}..{most}");
            assert!(
                most - least >= 0.9 * (hi - lo),
                "{world:?}: {least}..{most}"
            );
            let low = suns.iter().filter(|s| s.elevation < LOW_SUN).count();
            assert!(low * 3 >= suns.len(), "{world:?}: {low} low suns");
            for s in &suns {
                let behind = (35.5..144.5).contains(&s.azimuth);
                let ahead = (75.0..=105.0).contains(&s.azimuth) && s.elevation < LOW_SUN;
                assert!(!behind || ahead, "{world:?}: {s:?}");
            }
        }
        assert_eq!(sun(World::Temperate, 1), None);
    }

    /// A world's moonlit land is lit brighter than the temperate world's
    /// night (which keeps its pictures), its twilights and days as they
    /// were given.
    #[test]
    fn a_worlds_moonlit_land_is_brighter_than_the_temperate_night() {
        use crate::render::base::colour::luminance;
        use crate::settings::Sun;
        let field = crate::terrain::Heightfield::flat(5, 100.0);
        let night = Lighting::new(Sun::Night, &field);
        let temperate = light(World::Temperate, night.clone(), 0.5);
        assert_eq!(temperate.direct, night.direct);
        for world in DRAWN.into_iter().chain([COAST]) {
            let lit = light(world, night.clone(), 0.5);
            for (a, b) in [(lit.direct, night.direct), (lit.ambient, night.ambient)] {
                assert!(luminance(a) >= 1.5 * luminance(b), "{world:?}: {a:?} {b:?}");
            }
            assert_eq!(lit.zenith, night.zenith, "{world:?}: the sky is the air's");
        }
    }

    /// A world's day's sky light is its time of day's times a factor
    /// within [`SKY_LIGHT`], over most of it (winter's own colder sky
    /// light aside); the temperate world's is its time of day's.
    #[test]
    fn a_worlds_sky_light_lies_within_its_range() {
        use crate::settings::Sun;
        let field = crate::terrain::Heightfield::flat(5, 100.0);
        let day = Lighting::new(Sun::Midday, &field);
        let days = [World::Alpine, World::Autumn, World::Desert, World::Tropical];
        for world in days.into_iter().chain([COAST]) {
            let ks: Vec<f32> = (0..500)
                .map(|i| light(world, day.clone(), i as f32 / 500.0).ambient[2] / day.ambient[2])
                .collect();
            let (lo, hi) = ks
                .iter()
                .fold((f32::MAX, f32::MIN), |(a, b), &k| (a.min(k), b.max(k)));
            let (least, most) = SKY_LIGHT;
            assert!(
                lo >= least - 1e-4 && hi <= most + 1e-4,
                "{world:?}: {lo}..{hi}"
            );
            assert!(hi - lo >= 0.9 * (most - least), "{world:?}: {lo}..{hi}");
        }
        assert_eq!(
            light(World::Temperate, day.clone(), 0.3).ambient,
            day.ambient
        );
    }

    /// The mean colour of `world`'s ground over its heights and
    /// steepnesses, dry and wet, for the mountain of draw `v`.
    fn mean_land(world: World, v: f32) -> Rgb {
        let mut sum = [0.0; 3];
        let mut n = 0.0;
        for i in 0..20 {
            for j in 0..10 {
                for wet in [0.0, 1.0] {
                    let (u, steep) = (0.025 + i as f32 / 20.0, j as f32 / 10.0);
                    let c = land(world, (u, steep, 0.0, wet), true, v);
                    (0..3).for_each(|k| sum[k] += c[k]);
                    n += 1.0;
                }
            }
        }
        sum.map(|c| c / n)
    }

    /// Two mountains of one world whose palettes lie at either end of
    /// its range ([`mood`]) are grounded in visibly different colours
    /// (their other draws alike: the two draws 0.06 apart), and each
    /// stays its world's: the winter land pale with snow, autumn's and
    /// the desert's warm, the tropics' green.
    #[test]
    fn a_worlds_palette_differs_by_the_mountain_within_its_world() {
        let (first, last) = (0.001 / 17.0, 0.999 / 17.0);
        assert!(mood(first) < 0.01 && mood(last) > 0.99);
        for world in DRAWN {
            let (a, b) = (mean_land(world, first), mean_land(world, last));
            let apart = (0..3).map(|k| (a[k] - b[k]).powi(2)).sum::<f32>().sqrt();
            assert!(apart >= 0.07, "{world:?}: {a:?} {b:?} {apart}");
            for c in [a, b] {
                match world {
                    World::Autumn | World::Desert => assert!(c[0] > c[2] + 0.1, "{world:?} {c:?}"),
                    World::Tropical => assert!(c[1] > c[0] && c[1] > c[2], "{c:?}"),
                    World::Winter => {
                        let luma = crate::render::base::colour::luminance(c);
                        assert!(luma >= 0.55, "{c:?} {luma}");
                    }
                    _ => {}
                }
            }
        }
    }

    /// A world's haze at the back edge lies within [`HAZE`], over most
    /// of it; the temperate world keeps its own.
    #[test]
    fn a_worlds_haze_lies_within_its_range() {
        for world in DRAWN {
            let hazes: Vec<f32> = (0..500)
                .map(|i| haze(world, i as f32 / 500.0).expect("a world's haze"))
                .collect();
            let (lo, hi) = hazes
                .iter()
                .fold((f32::MAX, f32::MIN), |(a, b), &h| (a.min(h), b.max(h)));
            assert!(lo >= HAZE.0 && hi <= HAZE.1, "{world:?}: {lo}..{hi}");
            assert!(hi - lo >= 0.9 * (HAZE.1 - HAZE.0), "{world:?}: {lo}..{hi}");
        }
        assert_eq!(haze(World::Temperate, 0.3), None);
    }

    /// A world's twilight lights its land [`TWILIGHT_LIFT`] times as bright
    /// as the time of day's, and a low sun ahead fills the shade more
    /// than the same sun from the side; the temperate world's light is
    /// its time of day's.
    #[test]
    fn a_worlds_twilight_and_backlit_shade_are_lifted() {
        let hour = |elevation, azimuth| {
            Lighting::at_hour(SunAt {
                elevation,
                azimuth,
                afternoon: true,
            })
        };
        let dusk = hour(-5.0, 20.0);
        assert!(dusk.night > 0.0 && dusk.night < 1.0);
        for world in DRAWN {
            let lit = light(world, dusk.clone(), 0.5);
            for (a, b) in [(lit.direct, dusk.direct), (lit.ambient, dusk.ambient)] {
                for k in 0..3 {
                    assert!((a[k] - TWILIGHT_LIFT * b[k]).abs() < 1e-5, "{world:?}");
                }
            }
            let (ahead, side) = (hour(3.0, 90.0), hour(3.0, 10.0));
            let (a, s) = (
                light(world, ahead.clone(), 0.5).ambient[2] / ahead.ambient[2],
                light(world, side.clone(), 0.5).ambient[2] / side.ambient[2],
            );
            assert!(a > 1.5 * s, "{world:?}: {a} {s}");
        }
        assert_eq!(
            light(World::Temperate, dusk.clone(), 0.5).direct,
            dusk.direct
        );
    }

    /// Every world's night sky is dark but not black, top and horizon,
    /// at either end of its draw; the horizon lighter than the top.
    #[test]
    fn a_worlds_night_sky_is_dark_but_never_black() {
        let luma = crate::render::base::colour::luminance;
        for world in DRAWN {
            for v in [0.0, 0.33, 0.66, 0.99] {
                let night = [
                    super::super::light::NIGHT.zenith,
                    super::super::light::NIGHT.horizon,
                ];
                let [top, horizon] = air(world, night, v, 1.0);
                let (t, h) = (luma(top), luma(horizon));
                assert!((0.005..0.12).contains(&t), "{world:?} {v}: top {t}");
                assert!((0.04..0.36).contains(&h), "{world:?} {v}: horizon {h}");
                assert!(h > t, "{world:?} {v}");
            }
        }
    }

    /// A slope keeps its facing whichever side the land is seen from. One
    /// quarter turn draws the original's point (n-1-y, x) at (x, y)
    /// (scene.rs's `turned`), so a step (dx, dy) of the turned grid is the
    /// original's (-dy, dx), and an original direction (x, y) is the
    /// turned grid's (y, -x).
    #[test]
    fn the_sunward_side_turns_with_the_land() {
        for identity in [1u64, 7, 42, 1997] {
            let side = sunward(identity, 0);
            for quarters in 1..4 {
                let turned_side = sunward(identity, quarters);
                for k in 0..16 {
                    let (sin, cos) = (k as f32 * 0.4).sin_cos();
                    let normal = Vec3::new(0.5 * cos, 0.5 * sin, 0.866);
                    let turned = (0..quarters).fold(normal, |v, _| Vec3::new(v.y, -v.x, v.z));
                    let (a, b) = (
                        facing_weight(normal, side),
                        facing_weight(turned, turned_side),
                    );
                    assert!((a - b).abs() < 1e-5, "{identity} {quarters} {k}: {a} {b}");
                }
            }
        }
    }
}
