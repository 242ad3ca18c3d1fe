//! Every user preference, in one `Settings` value.
//!
//! The key table (names, ranges, docs) lives in `settings/keys/`, reading
//! files and `--set` in `settings/load.rs`; this file holds the types.

pub mod handles;
pub mod keys;
pub mod load;
pub mod looks;
pub mod paths;
pub mod save;
pub mod text;
pub mod worlds;

use serde::{Deserialize, Serialize};

/// A unit enum a key chooses among, each variant's name written once: serde
/// reads and writes the variant by that name, `NAMES` lists the names in
/// order for the key table, and `name` gives one back.
macro_rules! choice {
    (
        $(#[$meta:meta])*
        pub enum $name:ident {
            $($(#[$vmeta:meta])* $variant:ident = $text:literal,)*
        }
    ) => {
        $(#[$meta])*
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
        pub enum $name {
            $($(#[$vmeta])* #[serde(rename = $text)] $variant,)*
        }

        impl $name {
            /// Every variant's name, in order: the values its key accepts.
            pub const NAMES: &'static [&'static str] = &[$($text),*];

            /// The variant's name, as its key writes it.
            pub const fn name(self) -> &'static str {
                match self {
                    $($name::$variant => $text,)*
                }
            }
        }
    };
}

choice! {
    /// Whose picture the mountain is drawn as: ours, or one of the seed
    /// programs' (`settings/looks.rs` holds the keys each look sets; the
    /// renderer and the generator read the parts no key can say).
    pub enum Look {
        /// Today's picture: every key at its own default.
        Ours = "ours",
        /// Seed 000, MacTech's *Fractal Mountain Climbing* (1991): its
        /// triangles, HSV ramp, light, tilt and water.
        FractalMountainClimbing = "fractal-mountain-climbing",
        /// Seed 003, *Mountain Terrain 3.0* (1997): a filter colour ANDed with
        /// a darkness from nine facings, pure blue water.
        MountainTerrain = "mountain-terrain",
        /// Seed 004, *3D Fractal Landscapes* (FL3): Filled mode, pseudo-normal
        /// deviations, single-point perspective.
        Fl3 = "fl3",
        /// Seed 002, the essay on recursive subdivision: its view turned in
        /// steps of 11.25 degrees, the square's outer edges undisplaced.
        Essay = "essay",
    }
}

choice! {
    /// Where the mountain stands: the terrain, the ground's cover, the
    /// water and the air of a kind of place (`settings/worlds.rs` holds the
    /// keys each world sets; the palette reads the colours no key says).
    pub enum World {
        /// One of the others per mountain, drawn from its identity as the
        /// varied sun is. In settings drawn for a mountain
        /// (`worlds::drawn`) it stands for the temperate coast that draw
        /// gave, its day drawn (`worlds::drawn_world`), named there
        /// `worlds::COAST`.
        Varied = "varied",
        /// Green islands in blue water: the picture before worlds (drawn
        /// by "varied", lit by an hour and framed by a camera of its own:
        /// `worlds::drawn_world`).
        Temperate = "temperate",
        /// High, jagged ranges, snow and glaciers down to the valleys, lakes.
        Alpine = "alpine",
        /// Snow down to the shore, dark rock on steep faces, ice, low light.
        Winter = "winter",
        /// Forests in gold, red and brown.
        Autumn = "autumn",
        /// Mesas and canyons in red and ochre strata, sand, dry lake beds.
        Desert = "desert",
        /// Steep green volcanic islands, turquoise shallows, white beaches.
        Tropical = "tropical",
    }
}

choice! {
    /// Which fractal generator builds the heightfield.
    pub enum Generator {
        /// Mountain Terrain 3.0: square subdivision, cragginess halved per level.
        Square = "square",
        /// Square subdivision in diamond-square order (edge midpoints from the
        /// neighbouring centres), which removes the straight creases, started
        /// from a 5x5 lattice of heights (xmountains' `-t`) rather than four corners.
        Diamond = "diamond",
        /// Fractal Mountain Climbing: triangle subdivision on a parallelogram.
        Triangle = "triangle",
        /// Fractional Brownian surface of a chosen roughness (`hurst`), by
        /// spectral synthesis: Mountain Terrain 3.0's hoped-for version 4.0.
        Brownian = "brownian",
    }
}

choice! {
    /// The four starting profiles of Fractal Mountain Climbing (seed 000).
    pub enum Profile {
        /// Profile 1: high back corner, low front corner: slopes into the sea.
        Slope = "slope",
        /// Profile 2: one high corner, the rest at sea level.
        Peak = "peak",
        /// Profile 3: one low corner, the rest at sea level.
        Bay = "bay",
        /// Profile 4: raised centre and back edges: an island massif.
        Massif = "massif",
    }
}

choice! {
    /// How faces are coloured.
    pub enum ColorMode {
        /// Water blue, green lowlands, brown, snow above the treeline.
        Natural = "natural",
        /// Colour filter: shaded grey.
        Gray = "gray",
        /// Colour filter: red.
        Red = "red",
        /// Colour filter: green.
        Green = "green",
        /// Colour filter: blue.
        Blue = "blue",
        /// Colour filter: yellow.
        Yellow = "yellow",
        /// Colour filter: cyan.
        Cyan = "cyan",
        /// Colour filter: purple.
        Purple = "purple",
        /// Black faces, one-pixel white outlines.
        Sonar = "sonar",
        /// FL3's Filled mode: land faces one flat green, water faces one flat
        /// blue, no shading, each outlined by the pen (Delphi's default black).
        Filled = "filled",
        /// Wire mesh only: land green, water blue.
        Outline = "outline",
        /// Black and white: seed 000's 17 8x8 patterns (`bwPat`).
        Mono = "mono",
        /// Layered 2D ridge silhouettes fading into the distance.
        Ridges = "ridges",
    }
}

choice! {
    /// The projection used to draw the mountain.
    pub enum ViewKind {
        /// A camera low in front of the land looking across it to the horizon,
        /// fitted per frame so the land spans the whole width (xmountains' view).
        Vista = "vista",
        /// The classic tilted, sheared parallelogram (orthographic).
        Oblique = "oblique",
        /// Single-point perspective.
        Perspective = "perspective",
    }
}

/// How fine the grid is.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Detail {
    /// Chosen per frame, so a cell is a few pixels where the land is nearest.
    Auto,
    /// A grid of 2^n + 1 points a side.
    Level(u32),
}

choice! {
    /// What `sea_level` is measured from.
    pub enum WaterLine {
        /// The height with [`COAST_SEA_SHARE`] of the map below it: every
        /// mountain has land and a coast.
        Coast = "coast",
        /// The generator's own zero (Mountain Terrain 3.0: some maps all sea).
        Generator = "generator",
    }
}

/// Share of the map under water when `water_line = "coast"` and
/// `sea_level = 0`.
pub const COAST_SEA_SHARE: f32 = 0.3;

choice! {
    /// Which light falls on the land.
    pub enum Sun {
        /// Morning, midday, evening, sunset or (in the natural colours of our
        /// own look) night, drawn from each mountain's heights.
        Varied = "varied",
        /// A low, cool light from the left and a pale sky.
        Morning = "morning",
        /// A high white light and a deep blue sky.
        Midday = "midday",
        /// A low, warm light from the right and a glowing horizon.
        Evening = "evening",
        /// Evening looking into the sun: the land against a glowing sky, the
        /// water below the sun glittering.
        Sunset = "sunset",
        /// Seed 000's light as its listing computes it: from the back right,
        /// 28 degrees up, brightness `0.5 + 0.5 cos`.
        Classic = "classic",
        /// Night: the moon lights the land coolly and glitters on the water,
        /// stars show where the sky is clear.
        Night = "night",
        /// The sun where it stands now for `latitude` and `longitude`: dawn,
        /// day, dusk and night follow the clock.
        Clock = "clock",
    }
}

choice! {
    /// How light falls across a land face.
    pub enum Shading {
        /// Light worked out at every grid point and blended across each face,
        /// so slopes read as continuous ground (the vista and perspective view
        /// in colour; the classic looks stay flat).
        Smooth = "smooth",
        /// One colour per face, as the seed programs draw them.
        Flat = "flat",
    }
}

/// How much cloud the sky holds.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Clouds {
    /// Drawn per mountain, like the sun: some slides clear, some cloudy.
    Varied,
    /// From 0 (a clear sky) to 1 (overcast).
    Amount(f32),
}

choice! {
    /// Which monitors the full-screen saver covers.
    pub enum Monitors {
        /// One window, with its own mountain, on every monitor.
        All = "all",
        /// Only the primary monitor; the others are blanked.
        Primary = "primary",
        /// One landscape across every monitor, each showing its part.
        Span = "span",
    }
}

choice! {
    /// What the saver does on battery or in power-saver mode.
    pub enum OnBattery {
        /// Finish the slide being drawn, then hold it, doing no work,
        /// until the power returns.
        Hold = "hold",
        /// Go on, with pauses five times as long between slides.
        Slow = "slow",
        /// Go on as on mains power.
        Same = "same",
    }
}

/// Smallest grid exponent (9x9 points): the `detail` key's least value
/// and the smallest heightfield, generated or loaded. Seed 000's
/// Iterations menu starts at 3.
pub const MIN_GRID_EXPONENT: u32 = 3;
/// Largest grid exponent (4097x4097 points), as [`MIN_GRID_EXPONENT`].
pub const MAX_GRID_EXPONENT: u32 = 12;

/// `low_detail` halves the grids of a detail over this one (the smallest
/// keep their size).
const LOW_DETAIL_FROM: u32 = 4;

/// The detail `"auto"` means where no frame is known (a saved data set):
/// what a 1920x1080 vista gets.
pub const AUTO_DETAIL_FALLBACK: u32 = 10;

/// Every preference a user can set. Ranges are checked in `settings::keys`.
#[derive(Debug, Clone, PartialEq)]
pub struct Settings {
    /// Seed of the next mountain; `None` picks a fresh random one each time.
    pub seed: Option<u64>,
    /// Whose picture: ours, or a seed program's (its keys' defaults and
    /// the parts no key says).
    pub look: Look,
    /// Where the mountain stands, or "varied" (one drawn per mountain).
    pub world: World,
    /// Which generator builds the heights.
    pub generator: Generator,
    /// Square generators: initial random range, halved per level (1-128).
    pub cragginess: u32,
    /// Square generators: range of the corner heights (seed 003 hard-codes 100).
    pub elevation: f32,
    /// Triangle generator: seed 000's "Smoothness" base (1.0-5.0).
    pub roughness: f32,
    /// Triangle generator: power applied to heights (0.25-5.0; 1 = none).
    pub contour: f32,
    /// Triangle generator: starting corner heights.
    pub profile: Profile,
    /// Brownian generator: Hurst exponent, the roughness (0.1 rough to 0.9 smooth).
    pub hurst: f32,
    /// Height of the highest peak (1-10, seed 000's Height menu); also moves the treeline.
    pub height: u32,
    /// Sharp edges: terraces, mesas and cliffs cut into the land (0-1, 0 = none).
    pub cliffs: f32,
    /// Strength of the rain that wears gullies into the slopes (0-1, 0 = none).
    pub erosion: f32,
    /// Grid of 2^detail + 1 points a side (4-12), or chosen per frame.
    pub detail: Detail,
    /// Halve the points per side (a quarter of the data set).
    pub low_detail: bool,
    /// Water line, as a fraction of the relief above or below `water_line` (-1.0 to 1.0).
    pub sea_level: f32,
    /// What `sea_level` is measured from.
    pub water_line: WaterLine,
    /// Fill basins above the sea to their lowest lip and draw them as lakes.
    pub lakes: bool,
    /// Colour mode or filter.
    pub color: ColorMode,
    /// Darken water with the depth of the ground below it.
    pub relative_depth: bool,
    /// Cast shadows from the light direction.
    pub shadows: bool,
    /// The light: time of day, or drawn per mountain.
    pub sun: Sun,
    /// Degrees north of the equator (south negative) for `sun = "clock"`.
    pub latitude: f32,
    /// Degrees east of Greenwich (west negative) for `sun = "clock"`.
    pub longitude: f32,
    /// Faces lit smoothly across or one colour each.
    pub shading: Shading,
    /// Cloud in the sky: drawn per mountain, or an amount from 0 to 1.
    pub clouds: Clouds,
    /// Near land lit from a finer terrain than the grid it is drawn with.
    pub fine_relief: bool,
    /// The land and the sky mirrored in the water.
    pub reflections: bool,
    /// Oblique or perspective projection.
    pub view: ViewKind,
    /// Which side the mountain is seen from, in degrees (0, 90, 180, 270).
    pub rotation: u32,
    /// Start a new mountain after the pause (slide show).
    pub auto_redraw: bool,
    /// Seconds over which one mountain is drawn, strip by strip (0 = at once).
    pub draw_seconds: f32,
    /// Seconds a finished mountain is held before the next.
    pub pause_seconds: f32,
    /// Which monitors the full-screen saver covers.
    pub monitors: Monitors,
    /// On battery or in power-saver mode: hold the slide, slow down, or go on.
    pub on_battery: OnBattery,
    /// Folder of heightmaps (PNG or raw) mixed into the slide show (empty = none).
    pub heightmaps_dir: Option<String>,
}

impl Settings {
    /// The quarter turns `rotation` turns the field by (other angles are
    /// rounded to the nearest quarter).
    pub fn quarter_turns(&self) -> u32 {
        (self.rotation % 360 + 45) / 90 % 4
    }

    /// The seed for the next mountain: the one set, or a fresh random one
    /// (`seed = "random"`). Fresh seeds fit a TOML integer, so a seed shown
    /// in a title or printed by `render` can be pasted into `seed = ...`.
    pub fn next_seed(&self) -> u64 {
        self.seed.unwrap_or_else(|| rand::random::<u64>() >> 1)
    }

    /// Points per side of the grid these settings generate, low detail
    /// included; `detail = "auto"` counts as [`AUTO_DETAIL_FALLBACK`] here
    /// (callers that know the frame resolve it first, see
    /// `render::detail::for_frame`).
    pub fn grid_exponent(&self) -> u32 {
        let detail = match self.detail {
            Detail::Auto => AUTO_DETAIL_FALLBACK,
            Detail::Level(n) => n,
        };
        if self.low_detail && detail > LOW_DETAIL_FROM {
            detail - 1
        } else {
            detail
        }
    }

    /// The detail whose grid is `2^exponent + 1` points a side under these
    /// settings' `low_detail` ([`Settings::grid_exponent`]'s inverse), at
    /// most the finest: a low-detail grid of the finest detail's size has
    /// no detail of its own, and keeps the finest.
    pub fn detail_for_grid(&self, exponent: u32) -> u32 {
        let halved = self.low_detail && exponent + 1 > LOW_DETAIL_FROM;
        (exponent + u32::from(halved)).min(MAX_GRID_EXPONENT)
    }
}
