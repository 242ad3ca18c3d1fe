//! What the sky holds over its gradient in the looks with depth: the sun's
//! glow where the sun stands in or near the view, and cloud lit by the
//! slide's sun (white at midday, orange and grey at evening, lit from below
//! near the horizon when the sun is low).
//!
//! Everything is a function of a point of the screen measured in frame
//! heights (the glow of the sight line through it, the clouds of the
//! backdrop, see `clouds.rs`), so it is the same at every frame size, and
//! the water mirrors the same sky.

use glam::{Vec2, Vec3};

use super::clouds::{CloudSheet, Cover, SheetRow};
use super::light::Lighting;
use crate::render::base::colour::{Rgb, luminance, mix, smoothstep};
use crate::render::framing::view::View;

/// Sight lines farther from the sun than this (1 - cos of the angle
/// between them: 90 degrees) get no glow at all, so a slide whose sun is
/// behind the viewer keeps its plain gradient. Morning and evening put the
/// sun to the side of the view, 60 to 75 degrees beyond the frame's edge,
/// where the glow's wide part warms that side of the sky; a sunset puts it
/// ahead, a few degrees above the frame, whose top its glow fills.
const GLOW_REACH: f32 = 1.0;
/// The wide part's strength at the sun (it falls to 0 at the reach).
const WIDE: f32 = 0.3;
/// How fast the glow's core and its wide halo fall off, in 1 - cos.
const CORE: f32 = 0.003;
const HALO: f32 = 0.06;
/// The sun's disc: 1 - cos of its radius (about 1 degree).
const DISC: f32 = 0.000_15;
/// What a full night leaves of the light on the clouds' lit edges: with
/// it an overcast night's sky stands two to three stops under an overcast
/// day's, as the night's light stands under the day's. At 0.6 it was
/// 0.3-1.8 stops under, and a cloudy night read as a grey-blue day.
const MOONLIT_CLOUD: f32 = 0.25;
/// The height under which a night's moon is a rising one, in the frame
/// (its unit vector's z: about 6 degrees; `moonrise::HEIGHTS`).
const RISING: f32 = 0.1;
/// A rising moon's disc and glow: a pale, warm white, its glow a share
/// of the sun's (the disc itself as bright).
const MOON: Rgb = [1.0, 0.95, 0.84];
const MOON_GLOW: f32 = 0.35;
/// A rising moon's disc: 1 - cos of its radius (half a degree; the sky's
/// real moon is half as wide, but a frame's few degrees of sky make it a
/// speck).
const MOON_DISC: f32 = 0.000_038;
/// How far (1 - cos) from a rising moon its glow hides the stars.
const MOON_WASH: f32 = 0.03;

/// The weather of one slide, seen through one view.
#[derive(Debug, Clone)]
pub(crate) struct Weather {
    view: View,
    /// Towards the sun, in the view's world frame (y towards the front).
    sun: Vec3,
    /// Whether any sight line of the frame comes within the glow's reach.
    glows: bool,
    /// The frame's middle column and its height, and the sky's horizon
    /// line (rows), which the clouds are measured from.
    middle: f32,
    height: f32,
    horizon_row: f32,
    /// The sun's colour, and the glow's strength (1 for a sun on the
    /// horizon, 0 for a high one).
    light: Rgb,
    glow: f32,
    /// Whether the light is a rising moon's: its glow hides the stars
    /// round it.
    rising: bool,
    /// The light's disc, where its glow shows.
    disc: Option<Disc>,
    clouds: Option<CloudSheet>,
    amount: f32,
    /// Cloud lit by the sun (its edges) and in its own shade (its heart).
    lit: Rgb,
    shade: Rgb,
}

/// Whether the glow round the sun at unit vector `sun` (y to the back)
/// can reach a frame of size `frame` seen through `view`: the sun less
/// than the glow's reach beyond the frame's farthest corner from its
/// centre. `None` for a view without a camera.
fn glow_reaches_frame(view: &View, frame: Vec2, sun: Vec3) -> Option<bool> {
    let centre = view.sight(frame.x * 0.5, frame.y * 0.5)?;
    let corners = [
        (0.0, 0.0),
        (frame.x, 0.0),
        (0.0, frame.y),
        (frame.x, frame.y),
    ];
    let spread = corners
        .iter()
        .filter_map(|&(x, y)| view.sight(x, y))
        .map(|d| d.dot(centre))
        .fold(1.0f32, f32::min);
    // The frame's farthest corner from its centre, and the sun's
    // distance from the centre, as angles.
    let (reach, off) = (
        spread.clamp(-1.0, 1.0).acos(),
        sun.dot(centre).clamp(-1.0, 1.0).acos(),
    );
    Some(off - reach < (1.0 - GLOW_REACH).acos())
}

/// The clouds' colours under `lighting` whose light, at most 1 bright, is
/// `sun_light`: lit by it (their edges) and in their own shade (their
/// hearts, never brighter than their edges), dimmed by the night.
fn cloud_colours(lighting: &Lighting, sun_light: Rgb) -> (Rgb, Rgb) {
    let night = lighting.night;
    let white = mix(sun_light, [1.0; 3], 0.15 * (1.0 - night));
    let lit: Rgb = [0, 1, 2].map(|i| (0.8 * white[i] + 0.35 * lighting.horizon[i]).min(1.0));
    let lit = match night > 0.0 {
        true => lit.map(|c| c * (1.0 - (1.0 - MOONLIT_CLOUD) * night)),
        false => lit,
    };
    let shade: Rgb = [0, 1, 2].map(|i| (lighting.ambient[i] + 0.3 * lighting.zenith[i]) * 1.15);
    (lit, heart_within(shade, lit))
}

impl Weather {
    /// The weather under `lighting` (its colours through `filter`, the
    /// palette's), seen through `view` in a frame of size `frame` whose
    /// sky reaches its horizon colour at row `horizon_row`; cloud covering
    /// `amount` (0..=1) of the sky, drawn from `draw`. `None` for a view
    /// without a camera.
    pub(crate) fn new(
        view: &View,
        lighting: &Lighting,
        filter: impl Fn(Rgb) -> Rgb,
        (frame, horizon_row): (Vec2, f32),
        amount: f32,
        draw: u64,
    ) -> Option<Self> {
        // The palette's frame has y towards the back.
        let sun = lighting.sun * Vec3::new(1.0, -1.0, 1.0);
        let glows = glow_reaches_frame(view, frame, sun)?;
        // A high sun stands far above the frame: its glow is not seen.
        let low = 1.0 - smoothstep(0.3, 0.6, sun.z);
        // The moon's glow is too faint to show beside its cost (every
        // sky pixel and every mirrored one on the weather's path) but
        // where it rises ahead (`moonrise.rs`), its disc in the frame: a
        // clear night under a high moon keeps the plain gradient.
        let moon = lighting.night >= 0.5;
        let rising = moon && sun.z < RISING;
        let glows = glows && low > 0.0 && (!moon || rising);
        // A world's brilliant day or its twilight lifts the sun's light
        // on the land past 1; the clouds take its colour, not the lift.
        let direct = lighting.direct;
        let sun_light = direct.map(|c| c / direct[0].max(direct[1]).max(direct[2]).max(1.0));
        let (lit, shade) = cloud_colours(lighting, sun_light);
        // A rising moon's own colour, glow and disc; a high one's clouds
        // keep the light's.
        let (light, strength, size) = match rising {
            true => (MOON, MOON_GLOW, MOON_DISC),
            false => (sun_light, 1.0, DISC),
        };
        // The disc is never darker than the glow around it: where a
        // world's haze brightens the glow past the disc's colour, the sun
        // reads as a blown-out white, not as a grey coin.
        let disc_colour = filter(mix(light, [1.0; 3], 0.6));
        Some(Weather {
            view: view.clone(),
            sun,
            glows,
            middle: frame.x * 0.5,
            height: frame.y.max(1.0),
            horizon_row,
            light: filter(light),
            glow: low * strength,
            rising,
            disc: glows
                .then(|| Disc::of(view, (sun, size), disc_colour, rising))
                .flatten(),
            clouds: (amount > 0.0).then(|| CloudSheet::new(amount, draw)),
            amount,
            lit: filter(lit),
            shade: filter(shade),
        })
    }

    /// Whether it shows nothing over the gradient: no cloud, no glow.
    pub(crate) fn is_clear(&self) -> bool {
        self.clouds.is_none() && !self.glows
    }

    /// The sky's `gradient` colour at screen point (`x`, `y`) with the
    /// weather over it.
    pub(crate) fn over(&self, gradient: Rgb, x: f32, y: f32) -> Rgb {
        self.row(y).over(gradient, x)
    }

    /// The height of the frame it is seen in, in pixels: the clouds'
    /// sizes are shares of it.
    pub(crate) fn frame_height(&self) -> f32 {
        self.height
    }

    /// The weather along screen row `y` (the clouds' part that does not
    /// change along a row worked out once).
    pub(crate) fn row(&self, y: f32) -> WeatherRow<'_> {
        let up = (self.horizon_row - y) / self.height;
        WeatherRow {
            weather: self,
            y,
            up,
            sheet: self.clouds.as_ref().and_then(|c| c.row(up)),
        }
    }

    /// The glow (a share of the sun's colour) on a sight line `away`
    /// (1 - cos) from the sun. Each part is left out where it would add
    /// less than a tenth of a level.
    fn glow_at(&self, away: f32) -> f32 {
        // A moon's light is too faint to warm a whole side of the sky.
        let wide = if self.rising { 0.0 } else { WIDE };
        let mut g = wide * ((GLOW_REACH - away) / GLOW_REACH).powi(2);
        if away < 0.06 {
            g += 0.6 * (-away / CORE).exp();
        }
        if away < 0.55 {
            g += 0.25 * (-away / HALO).exp();
        }
        self.glow * g
    }

    /// The colour of cloud `cover` seen `up` frame heights above the
    /// horizon line, `away` (1 - cos) from the sun: darker in its heart and
    /// the more of the sky is cloud, brighter towards the sun, warmed from
    /// below near the horizon when the sun is low.
    fn cloud(&self, cover: Cover, up: f32, away: f32) -> Rgb {
        let heart = (0.3 + 0.45 * self.amount) * cover.thickness;
        let mut c = mix(self.lit, self.shade, heart);
        if away < 0.65 {
            let silver = 0.35 * self.glow * (-away / 0.08).exp();
            c = [0, 1, 2].map(|i| c[i] + self.light[i] * silver);
        }
        let below = (1.0 - smoothstep(0.0, 0.3, up)) * (1.0 - smoothstep(0.15, 0.5, self.sun.z));
        // A rising moon lights them from below as faintly as it glows.
        let lift = if self.rising { MOON_GLOW } else { 1.0 };
        mix(c, self.light, 0.45 * lift * below)
    }
}

/// The most a cloud's heart, in its own shade, shows of the brightness of
/// its lit edge (luminance). A world lifts the sky's light on its land
/// (`cover::light`: a twilight's land lit up to 1.8 times, the shade
/// under a low sun ahead more): unbounded, that lift lit an overcast
/// sky's hearts past their edges and past white, a blank sky over 40% of
/// the frame (seed 218, a tropical dawn). The plain day's hearts show
/// 0.55-0.7 of their edges.
const HEART_MOST: f32 = 0.8;

/// The cloud's heart colour `shade` darkened, its hue kept, to at most
/// [`HEART_MOST`] of the lit edge `lit`'s luminance and to no channel
/// over 1.
fn heart_within(shade: Rgb, lit: Rgb) -> Rgb {
    let most = HEART_MOST * luminance(lit);
    let (l, top) = (luminance(shade), shade[0].max(shade[1]).max(shade[2]));
    let k = [1.0, most / l, 1.0 / top]
        .into_iter()
        .filter(|k| k.is_finite() && *k > 0.0)
        .fold(1.0f32, f32::min);
    shade.map(|c| c * k)
}

impl Weather {
    /// How much of the sky at screen point (`x`, `y`) is clear of cloud
    /// and of the light's disc (0..=1): where the stars show (a rising
    /// moon's glow washes them out round it).
    pub(crate) fn clear_at(&self, x: f32, y: f32) -> f32 {
        if self.disc_cover(x, y) > 0.0 {
            return 0.0;
        }
        let washed = match (self.rising && self.glows, self.view.sight(x, y)) {
            (true, Some(dir)) => smoothstep(0.0, MOON_WASH, 1.0 - dir.dot(self.sun)),
            _ => 1.0,
        };
        washed * self.cloud_clear(x, y)
    }

    /// How much of the sky at screen point (`x`, `y`) is clear of cloud.
    fn cloud_clear(&self, x: f32, y: f32) -> f32 {
        let row = self.row(y);
        let Some(sheet) = &row.sheet else {
            return 1.0;
        };
        let opacity = sheet.seen((x - self.middle) / self.height).opacity;
        1.0 - opacity.clamp(0.0, 1.0)
    }

    /// The sky's colour `c` (its gradient, glow and cloud) at screen point
    /// (`x`, `y`), of which the light's disc covers `cover`
    /// ([`Weather::disc_cover`]), with the disc over it, behind the cloud
    /// there.
    pub(crate) fn disc_over(&self, c: Rgb, x: f32, y: f32, cover: f32) -> Rgb {
        let Some(disc) = self.disc.filter(|_| cover > 0.0) else {
            return c;
        };
        let lit = mix(c, disc.colour_at(x, y), 0.9);
        let top = [0, 1, 2].map(|i| lit[i].max(c[i]));
        mix(c, top, cover * self.cloud_clear(x, y))
    }

    /// How much of the pixel round screen point (`x`, `y`) the light's
    /// disc covers: 0 without one, its edge across a pixel.
    pub(crate) fn disc_cover(&self, x: f32, y: f32) -> f32 {
        self.disc.map_or(0.0, |d| d.cover(x, y))
    }

    /// The pixels (columns and rows, each from and to) where the light's
    /// disc may show: the sky's painter draws them one by one.
    pub(crate) fn disc_bounds(&self) -> Option<[(f32, f32); 2]> {
        self.disc.map(|d| d.bounds())
    }
}

/// The weather along one screen row ([`Weather::row`]).
pub(crate) struct WeatherRow<'a> {
    weather: &'a Weather,
    y: f32,
    /// Frame heights above the horizon line.
    up: f32,
    sheet: Option<SheetRow<'a>>,
}

impl WeatherRow<'_> {
    /// The sky's `gradient` colour at column `x` of the row with the
    /// weather over it, the light's disc included.
    pub(crate) fn over(&self, gradient: Rgb, x: f32) -> Rgb {
        let c = self.over_sky(gradient, x);
        let cover = self.weather.disc_cover(x, self.y);
        self.weather.disc_over(c, x, self.y, cover)
    }

    /// [`WeatherRow::over`] without the light's disc: what varies little
    /// over a few pixels (the glow, the clouds), which the sky's painter
    /// works out every few columns and blends between (the disc's edge it
    /// draws at each pixel, [`Weather::disc_over`]).
    pub(crate) fn over_sky(&self, gradient: Rgb, x: f32) -> Rgb {
        let w = self.weather;
        let away = match w.view.sight(x, self.y) {
            Some(dir) => 1.0 - dir.dot(w.sun),
            None => 2.0,
        };
        let mut c = gradient;
        if w.glows && away < GLOW_REACH {
            let g = w.glow_at(away);
            c = [0, 1, 2].map(|i| c[i] + w.light[i] * g);
        }
        let Some(sheet) = &self.sheet else {
            return c;
        };
        let cover = sheet.seen((x - w.middle) / w.height);
        if cover.opacity <= 0.0 {
            return c;
        }
        mix(c, w.cloud(cover, self.up, away), cover.opacity)
    }
}

/// The light's disc on the screen, where the sky holds it ([`Disc::of`]).
#[derive(Debug, Clone, Copy)]
struct Disc {
    /// Its centre (possibly outside the frame) and its radius, in pixels.
    centre: Vec2,
    radius: f32,
    colour: Rgb,
    /// Whether it is the moon's, which shows its seas.
    moon: bool,
}

/// The moon's seas as the eye sees them, each a centre on the disc (in
/// its radii, x right and y down) and a radius: Imbrium, Serenitatis,
/// Tranquillitatis, Crisium, Procellarum and Nubium, in shape and place
/// roughly (a disc of one colour reads as a lamp, not the moon).
const SEAS: [(f32, f32, f32); 6] = [
    (-0.3, -0.35, 0.36),
    (0.12, -0.3, 0.24),
    (0.3, 0.02, 0.28),
    (0.66, -0.18, 0.15),
    (-0.55, 0.1, 0.4),
    (-0.12, 0.45, 0.24),
];
/// How much darker than the highlands a sea is at its middle.
const SEA_DARK: f32 = 0.13;

impl Disc {
    /// The disc of the light towards `sun`, `size` (1 - cos of its
    /// radius) seen through `view`, in `colour`: a circle on the screen (a
    /// degree across is a few pixels' difference from one in perspective at
    /// most). None where the view has no camera or the light stands behind
    /// it.
    fn of(view: &View, (sun, size): (Vec3, f32), colour: Rgb, moon: bool) -> Option<Self> {
        let centre = view.vanishing(sun)?;
        // The angle a pixel spans there, as the chord over a hundred
        // pixels (a cosine this near 1 is lost to rounding).
        let (a, b) = (
            view.sight(centre.x, centre.y)?,
            view.sight(centre.x + 100.0, centre.y)?,
        );
        let per_pixel = a.distance(b) / 100.0;
        let angle = (1.0 - size).acos();
        (per_pixel > 0.0).then(|| Disc {
            centre,
            radius: angle / per_pixel,
            colour,
            moon,
        })
    }

    /// The disc's colour at screen point (`x`, `y`) on it: the moon's
    /// darker over its seas ([`SEAS`]).
    fn colour_at(&self, x: f32, y: f32) -> Rgb {
        if !self.moon {
            return self.colour;
        }
        let p = (Vec2::new(x, y) - self.centre) / self.radius;
        let dark: f32 = SEAS
            .iter()
            .map(|&(sx, sy, r)| 1.0 - smoothstep(0.0, r, p.distance(Vec2::new(sx, sy))))
            .sum();
        self.colour.map(|c| c * (1.0 - SEA_DARK * dark.min(1.0)))
    }

    /// How much of the pixel around screen point (`x`, `y`) the disc
    /// covers: 1 within, 0 outside, the share of a pixel across its edge.
    fn cover(&self, x: f32, y: f32) -> f32 {
        let reach = self.radius + 0.5;
        // Most asking pixels lie far off: no root for them.
        if (x - self.centre.x).abs() > reach || (y - self.centre.y).abs() > reach {
            return 0.0;
        }
        let d = Vec2::new(x, y).distance(self.centre);
        (self.radius + 0.5 - d).clamp(0.0, 1.0)
    }

    /// The pixels (columns, rows, each from and to) of the square round it.
    fn bounds(&self) -> [(f32, f32); 2] {
        let r = self.radius + 1.0;
        [
            (self.centre.x - r, self.centre.x + r),
            (self.centre.y - r, self.centre.y + r),
        ]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::base::size::Size;
    use crate::render::framing::tops::RowTops;
    use crate::settings::{Sun, ViewKind};
    use crate::terrain::Heightfield;

    fn view() -> View {
        let field = Heightfield::flat(5, 100.0);
        let tops = RowTops::of(&field);
        View::fitted(
            ViewKind::Vista,
            33,
            100.0,
            (tops.rows(), 0.0),
            Size::new(960, 540),
        )
    }

    fn weather(sun: Sun, amount: f32) -> Weather {
        let field = Heightfield::flat(5, 100.0);
        let lighting = Lighting::new(sun, &field);
        let frame = (Vec2::new(960.0, 540.0), 300.0);
        Weather::new(&view(), &lighting, |c| c, frame, amount, 7).expect("a camera")
    }

    #[test]
    fn a_clear_sky_under_a_high_sun_is_the_plain_gradient() {
        assert!(weather(Sun::Midday, 0.0).is_clear());
        assert!(!weather(Sun::Midday, 0.5).is_clear());
    }

    #[test]
    fn a_low_sun_warms_its_side_of_the_sky() {
        // The evening sun stands to the right of the view.
        let w = weather(Sun::Evening, 0.0);
        assert!(!w.is_clear());
        let grey = [0.5; 3];
        let (left, right) = (w.over(grey, 0.0, 100.0), w.over(grey, 959.0, 100.0));
        assert!(right[0] > left[0] + 0.01, "{left:?} {right:?}");
        assert!(
            right[0] - right[2] > left[0] - left[2],
            "warmer: {left:?} {right:?}"
        );
    }

    /// A world's brilliant day and bright shade (`cover::light` lifts the
    /// sun's light up to 1.35 times and the sky's up to 1.9 x 1.8 times
    /// under a low sun ahead) light the land, not the clouds: an overcast
    /// morning keeps its hearts darker than their edges, and its sky is not
    /// blown out to white (seed 218's was, over 40% of the frame).
    #[test]
    fn a_worlds_lifted_light_leaves_the_clouds_their_shade() {
        let field = Heightfield::flat(5, 100.0);
        let mut lighting = Lighting::new(Sun::Morning, &field);
        lighting.direct = lighting.direct.map(|c| c * 1.35);
        lighting.ambient = lighting.ambient.map(|c| c * 1.9 * 1.8);
        let frame = (Vec2::new(960.0, 540.0), 300.0);
        let w = Weather::new(&view(), &lighting, |c| c, frame, 0.8, 7).expect("a camera");
        assert!(
            luminance(w.shade) <= HEART_MOST * luminance(w.lit) + 1e-4,
            "heart {:?} against edge {:?}",
            w.shade,
            w.lit
        );
        for c in [w.shade, w.lit, w.light] {
            assert!(c.iter().all(|&v| v <= 1.0 + 1e-6), "{c:?}");
        }
        let sky = [0.55, 0.65, 0.85];
        let (mut white, mut all) = (0, 0);
        for y in (0..300).step_by(10) {
            for x in (0..960).step_by(10) {
                let c = w.over(sky, x as f32, y as f32);
                white += c.iter().all(|&v| v >= 0.99) as usize;
                all += 1;
            }
        }
        assert!(white * 100 <= all, "{white} of {all} sky points white");
    }

    /// A high moon to the side keeps a clear night's plain gradient; one
    /// rising ahead shows its disc, hides the stars behind it and washes
    /// out those round it, and leaves them further off.
    #[test]
    fn a_rising_moon_shows_its_disc_and_hides_the_stars_round_it() {
        assert!(weather(Sun::Night, 0.0).is_clear());
        let field = Heightfield::flat(5, 100.0);
        let lighting = Lighting::new(Sun::Night, &field).moon_at(0.3, 90.0);
        let frame = (Vec2::new(960.0, 540.0), 300.0);
        let w = Weather::new(&view(), &lighting, |c| c, frame, 0.0, 7).expect("a camera");
        assert!(!w.is_clear());
        let disc = w.disc.expect("the moon's disc");
        let (c, r) = (disc.centre, disc.radius);
        assert!(r > 1.0 && r < 20.0, "radius {r} px");
        assert!(w.disc_cover(c.x, c.y) == 1.0 && w.clear_at(c.x, c.y) == 0.0);
        let near = w.clear_at(c.x + 2.0 * r, c.y);
        assert!(near > 0.0 && near < 1.0, "beside the moon: {near}");
        assert_eq!(w.clear_at(c.x + 400.0, c.y - 150.0), 1.0);
        let sky = [0.05, 0.07, 0.12];
        let (lit, dark) = (w.over(sky, c.x, c.y), w.over(sky, c.x + 400.0, c.y));
        assert!(luminance(lit) > luminance(dark) + 0.5, "{lit:?} {dark:?}");
    }

    /// The sun's disc against its own glow over a bright sky (a world's
    /// hazy air): the disc must not read as a darker coin.
    #[test]
    fn the_sun_is_never_darker_than_its_glow() {
        let w = weather(Sun::Sunset, 0.0);
        let bright = [0.9, 0.8, 0.85];
        let luma = |c: Rgb| 0.3 * c[0] + 0.59 * c[1] + 0.11 * c[2];
        let (mut disc, mut ring) = (Vec::new(), Vec::new());
        for y in -600..300 {
            for x in 0..960 {
                let (x, y) = (x as f32, y as f32);
                let Some(dir) = w.view.sight(x, y) else {
                    continue;
                };
                let away = 1.0 - dir.dot(w.sun);
                let c = luma(w.over(bright, x, y));
                if away < DISC {
                    disc.push(c);
                } else if away < 3.0 * DISC {
                    ring.push(c);
                }
            }
        }
        assert!(
            !disc.is_empty() && !ring.is_empty(),
            "the sun is not in sight"
        );
        let mean = |v: &[f32]| v.iter().sum::<f32>() / v.len() as f32;
        assert!(
            mean(&disc) >= mean(&ring),
            "disc {} under its glow {}",
            mean(&disc),
            mean(&ring)
        );
    }

    #[test]
    fn clouds_hang_above_the_horizon_line_only() {
        let w = weather(Sun::Midday, 1.0);
        let grey = [0.5; 3];
        let changed = |y: f32| {
            (0..96)
                .filter(|&i| w.over(grey, i as f32 * 10.0, y) != grey)
                .count()
        };
        assert_eq!(changed(310.0), 0, "below the horizon line");
        assert!(changed(100.0) > 90, "overcast above it");
    }
}
