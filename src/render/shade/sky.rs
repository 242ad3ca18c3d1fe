//! The sky behind the land: a gradient from the zenith colour at the top to
//! the horizon colour where the land begins, ordered-dithered so that a
//! slow gradient across a large screen shows no bands; in the looks with
//! depth, the weather in it too (the sun's glow and cloud, [`Weather`]).

use std::sync::Arc;

use glam::Vec4;

use super::stars::Stars;
use super::weather::{Weather, WeatherRow};
use crate::render::base::canvas::Canvas;
use crate::render::base::colour::{Rgb, packed_lanes, rgb_lanes, unpack};

/// 4x4 Bayer thresholds, 0..16.
const BAYER: [[u8; 4]; 4] = [[0, 8, 2, 10], [12, 4, 14, 6], [3, 11, 1, 9], [15, 7, 13, 5]];
/// How the blend to the horizon colour speeds up towards the horizon
/// (1 = linear; above 1 keeps the upper sky deep and brightens near the land).
const HORIZON_CURVE: f32 = 1.6;

/// What [`Sky::colour_seen`] keeps of the pixels it has looked at: about
/// 60 kB, whatever the frame (kept in full, the anchors of a 4K frame's
/// skyline took megabytes of a slide show's peak).
#[derive(Default)]
pub(crate) struct SkySeen<'s> {
    /// Without weather: the last row and its four colours.
    phases: Option<(u32, [u32; 4])>,
    /// With weather: rows' gradient colours and weather, a slot each by
    /// the row's low bits, and anchors as lanes, a slot each by row and
    /// anchor; a slot keeps the last one put there.
    rows: Vec<Option<(u32, Rgb, WeatherRow<'s>)>>,
    anchors: Vec<Option<((u32, u32), Vec4)>>,
}

/// Slots of [`SkySeen`]'s rows and anchors (powers of two): the skyline
/// pass looks down one column after another, so what it needs again lies
/// a few rows and anchors away.
const SEEN_ROWS: usize = 64;
const SEEN_ANCHORS: usize = 1024;

/// The background of one frame.
#[derive(Debug, Clone)]
pub(crate) struct Sky {
    top: Rgb,
    horizon: Rgb,
    /// Frame row where the horizon colour is reached.
    horizon_row: f32,
    /// The sun's glow and the clouds over the gradient, where there are any.
    weather: Option<Arc<Weather>>,
    /// The stars of a night sky.
    stars: Option<Stars>,
    /// Where the weather is worked out in full along a row.
    anchors: Anchors,
}

impl Sky {
    /// A gradient from packed `top` to packed `horizon` at row `horizon_row`.
    pub(crate) fn new(top: u32, horizon: u32, horizon_row: f32) -> Self {
        let horizon_row = if horizon_row.is_finite() {
            horizon_row.max(1.0)
        } else {
            1.0
        };
        Sky {
            top: unpack(top),
            horizon: unpack(horizon),
            horizon_row,
            weather: None,
            stars: None,
            anchors: Anchors::for_height(0.0),
        }
    }

    /// This sky with `stars` where it is clear.
    pub(crate) fn with_stars(mut self, stars: Option<Stars>) -> Self {
        self.stars = stars;
        self
    }

    /// This sky with `weather` over its gradient (none if it shows nothing).
    pub(crate) fn with_weather(mut self, weather: Option<Weather>) -> Self {
        self.weather = weather.filter(|w| !w.is_clear()).map(Arc::new);
        if let Some(w) = &self.weather {
            self.anchors = Anchors::for_height(w.frame_height());
        }
        self
    }

    /// The frame row where the horizon colour is reached.
    pub(crate) fn horizon_row(&self) -> f32 {
        self.horizon_row
    }

    /// The weather over the gradient, if any.
    pub(crate) fn weather(&self) -> Option<&Weather> {
        self.weather.as_deref()
    }

    /// Fills every row of `canvas` (on a first-write canvas, what is left).
    pub(crate) fn paint(&self, canvas: &mut Canvas) {
        // Below the horizon row every row is the horizon colour: its four
        // dither rows once, not a power per row (a 1-pixel-wide frame is
        // all rows).
        let below: [[u32; 4]; 4] = std::array::from_fn(|y| self.colours_at(1.0, y as u32));
        let end = canvas.all_written_from();
        // On a canvas that keeps the first write the stars go first, so the
        // gradient leaves them; on one that keeps the last, after it.
        let first = canvas.keeps_first();
        if first {
            self.paint_stars(canvas, end);
            self.paint_disc(canvas, end);
        }
        self.paint_gradient(canvas, end, below);
        if !first {
            self.paint_stars(canvas, end);
            self.paint_disc(canvas, end);
        }
    }

    /// The pixels round the light's disc, of rows above `end` that are
    /// still open: each its own colour (the weather's every few columns
    /// would draw the disc's edge in steps).
    fn paint_disc(&self, canvas: &mut Canvas, end: i64) {
        let Some([(left, right), (top, bottom)]) =
            self.weather.as_ref().and_then(|w| w.disc_bounds())
        else {
            return;
        };
        let clip = *canvas.clip();
        let cols = (
            left.max(clip.x0 as f32) as u32,
            right.min(clip.x1 as f32).max(0.0) as u32,
        );
        let last = (end as f32).min(bottom).min(self.horizon_row.ceil());
        let mut seen = SkySeen::default();
        for y in top.max(clip.y0 as f32).max(0.0) as u32..last.max(0.0) as u32 {
            for x in cols.0..cols.1 {
                let c = self.colour_seen(x, y, &mut seen);
                canvas.fill_with(y, x, x + 1, |_| c);
            }
        }
    }

    /// The stars' pixels of rows above `end` that are still open.
    fn paint_stars(&self, canvas: &mut Canvas, end: i64) {
        let Some(stars) = &self.stars else {
            return;
        };
        let clip = *canvas.clip();
        let (x0, x1) = (clip.x0 as u32, clip.x1 as u32);
        let last = (end as f32).min(self.horizon_row.ceil()).max(0.0) as u32;
        let mut seen = SkySeen::default();
        for y in clip.y0 as u32..last {
            for x in stars.in_row(y, x0, x1) {
                let c = self.colour_seen(x, y, &mut seen);
                canvas.fill_with(y, x, x + 1, |_| c);
            }
        }
    }

    /// The gradient (and the weather over it) of every open pixel of the
    /// rows above `end`; `below` the four dither rows of the horizon colour.
    fn paint_gradient(&self, canvas: &mut Canvas, end: i64, below: [[u32; 4]; 4]) {
        let clip = *canvas.clip();
        let (x0, x1) = (clip.x0 as u32, clip.x1 as u32);
        if let Some(w) = &self.weather {
            // Only where the land left the sky showing: the weather costs.
            let (mut anchors, step) = (Vec::new(), self.anchors);
            for y in clip.y0 as u32..end as u32 {
                let (g, row) = (self.gradient(y as f32 + 0.5), w.row(y as f32 + 0.5));
                let dither = dither_row(y);
                for (a, b) in canvas.open_runs(y) {
                    let first = step.before(a);
                    anchors.clear();
                    let last = step.before(b - 1) + 1;
                    anchors.extend((first..=last).map(|k| step.anchor(&row, g, k)));
                    canvas.fill_with(y, a, b, |x| {
                        let k = (step.before(x) - first) as usize;
                        step.pixel(anchors[k], anchors[k + 1], x, dither)
                    });
                }
            }
            return;
        }
        for y in clip.y0 as u32..end as u32 {
            let phases = match self.blend(y) {
                1.0 => below[(y & 3) as usize],
                t => self.colours_at(t, y),
            };
            canvas.fill_with(y, x0, x1, |x| phases[(x & 3) as usize]);
        }
    }

    /// The packed colours of row `y` at each of the four dither columns
    /// (column `x` has colour `x & 3`), where the sky has no weather.
    fn row_colours(&self, y: u32) -> [u32; 4] {
        self.colours_at(self.blend(y), y)
    }

    /// The packed colour [`Sky::paint`] gives pixel (`x`, `y`).
    #[cfg(test)]
    pub(crate) fn colour(&self, x: u32, y: u32) -> u32 {
        self.colour_seen(x, y, &mut SkySeen::default())
    }

    /// Whether pixel (`x`, `y`) of a frame holds the sky as painted.
    pub(crate) fn shows<'s>(&'s self, px: u32, x: u32, y: u32, seen: &mut SkySeen<'s>) -> bool {
        px == self.colour_seen(x, y, seen)
    }

    /// The packed colour [`Sky::paint`] gives pixel (`x`, `y`), keeping in
    /// `seen` what the pixels looked at next will need again: a row's four
    /// colours without weather; with weather, rows' weather and anchors
    /// (the skyline pass asks for a few pixels down each column, whose
    /// anchors and rows the columns beside share: worked out afresh each
    /// time, they were most of that pass on a cloudy 1080p slide).
    pub(crate) fn colour_seen<'s>(&'s self, x: u32, y: u32, seen: &mut SkySeen<'s>) -> u32 {
        let c = self.gradient_seen(x, y, seen);
        let (px, py) = (x as f32 + 0.5, y as f32 + 0.5);
        let cover = self.weather.as_ref().map_or(0.0, |w| w.disc_cover(px, py));
        let c = match &self.weather {
            Some(w) if cover > 0.0 => {
                crate::render::base::colour::to_u32(w.disc_over(unpack(c), px, py, cover))
            }
            _ => c,
        };
        let Some(star) = self.stars.as_ref().and_then(|s| s.at(x, y)) else {
            return c;
        };
        let clear = self
            .weather
            .as_ref()
            .map_or(1.0, |w| w.clear_at(x as f32 + 0.5, y as f32 + 0.5));
        let [r, g, b] = unpack(c);
        let lit = |v: f32, s: f32| ((v + s * clear) * 255.0 + 0.5).clamp(0.0, 255.0) as u32;
        lit(r, star[0]) << 16 | lit(g, star[1]) << 8 | lit(b, star[2])
    }

    /// [`Sky::colour_seen`] without the stars and the light's disc: the
    /// weather's every few columns, blended.
    fn gradient_seen<'s>(&'s self, x: u32, y: u32, seen: &mut SkySeen<'s>) -> u32 {
        let Some(w) = &self.weather else {
            let phases = match seen.phases {
                Some((at, phases)) if at == y => phases,
                _ => {
                    let phases = self.row_colours(y);
                    seen.phases = Some((y, phases));
                    phases
                }
            };
            return phases[(x & 3) as usize];
        };
        if seen.rows.is_empty() {
            seen.rows.resize_with(SEEN_ROWS, || None);
            seen.anchors.resize(SEEN_ANCHORS, None);
        }
        let slot = y as usize & (SEEN_ROWS - 1);
        if seen.rows[slot].as_ref().is_none_or(|(at, ..)| *at != y) {
            let (g, row) = (self.gradient(y as f32 + 0.5), w.row(y as f32 + 0.5));
            seen.rows[slot] = Some((y, g, row));
        }
        let Some((_, g, row)) = &seen.rows[slot] else {
            unreachable!("the row's slot was just filled");
        };
        let mut at = |k: u32| {
            let i = (y as usize * 31 + k as usize) & (SEEN_ANCHORS - 1);
            match seen.anchors[i] {
                Some((key, c)) if key == (y, k) => c,
                _ => {
                    let c = self.anchors.anchor(row, *g, k);
                    seen.anchors[i] = Some(((y, k), c));
                    c
                }
            }
        };
        let k = self.anchors.before(x);
        self.anchors.pixel(at(k), at(k + 1), x, dither_row(y))
    }

    /// The sky's colour seen at screen point (`x`, `y`), which may lie
    /// outside the frame (above it: the zenith's side), undithered: what
    /// the water mirrors where a reflected sight line meets no land.
    pub(crate) fn colour_at(&self, x: f32, y: f32) -> u32 {
        let c = self.gradient(y);
        let c = match &self.weather {
            Some(w) => w.over(c, x, y),
            None => c,
        };
        crate::render::base::colour::to_u32(c)
    }

    /// The gradient's colour (0..=1) at screen height `y`.
    fn gradient(&self, y: f32) -> Rgb {
        let t = match y / self.horizon_row {
            q if q >= 1.0 => 1.0,
            q => q.max(0.0).powf(HORIZON_CURVE),
        };
        [0, 1, 2].map(|i| self.top[i] + (self.horizon[i] - self.top[i]) * t)
    }

    /// How far row `y` is blended from the top colour (0) to the horizon
    /// colour (1).
    fn blend(&self, y: u32) -> f32 {
        match y as f32 / self.horizon_row {
            q if q >= 1.0 => 1.0,
            q => q.max(0.0).powf(HORIZON_CURVE),
        }
    }

    /// The packed colour of row `y`, blended `t` of the way to the
    /// horizon, at each of the four dither columns.
    fn colours_at(&self, t: f32, y: u32) -> [u32; 4] {
        let c: Rgb = [0, 1, 2].map(|i| (self.top[i] + (self.horizon[i] - self.top[i]) * t) * 255.0);
        let row = &BAYER[(y & 3) as usize];
        row.map(|b| {
            let d = (f32::from(b) + 0.5) / 16.0;
            let ch = |v: f32| ((v + d) as u32).min(255);
            ch(c[0]) << 16 | ch(c[1]) << 8 | ch(c[2])
        })
    }
}

/// The columns where the weather is worked out in full, every `step`
/// (a power of two); the pixels between are blended (glow and cloud change
/// little over a few pixels, and the noise is most of a sky pixel's cost).
#[derive(Clone, Copy, Debug)]
struct Anchors {
    step: u32,
}

impl Anchors {
    /// Every 4 columns in a frame under [`TALL`] pixels tall, every 8 from
    /// it, every 16 from twice it: the clouds' sizes are shares of the
    /// frame's height, so their shapes span as many more pixels (a span of
    /// two 1080p monitors side by side keeps 8). At 1080p and 4K a
    /// sunset's glow and a cloudy sky then changed by about a level (at
    /// most 5) in 1-2% of the pixels, for 2-3% of a cloudy 1080p frame's
    /// instructions.
    fn for_height(height: f32) -> Self {
        let finer = u32::from(height >= TALL) + u32::from(height >= 2.0 * TALL);
        Anchors { step: 4 << finer }
    }

    /// The anchor at or before column `x`.
    #[inline]
    fn before(self, x: u32) -> u32 {
        x / self.step
    }

    /// The weather of `row` over gradient colour `g` at the centre of
    /// anchor `k`'s column, as lanes (blue, green, red, 0; 0..=1).
    #[inline]
    fn anchor(self, row: &WeatherRow, g: Rgb, k: u32) -> Vec4 {
        rgb_lanes(row.over_sky(g, (k * self.step) as f32 + 0.5))
    }

    /// Pixel `x` of a row whose dither steps are `dither`, blended from
    /// the anchors `a` (at or before it) and `b` (the next), dithered as
    /// the plain gradient is.
    #[inline]
    fn pixel(self, a: Vec4, b: Vec4, x: u32, dither: [f32; 4]) -> u32 {
        let t = (x % self.step) as f32 / self.step as f32;
        let c = (a + (b - a) * t) * 255.0 + dither[(x & 3) as usize];
        packed_lanes(c.clamp(Vec4::ZERO, Vec4::splat(255.0)))
    }
}

/// The frame height from which the weather's anchors are twice as far apart.
const TALL: f32 = 1080.0;

/// Row `y`'s steps of the ordered dither, by column `x & 3`, in levels.
#[inline]
fn dither_row(y: u32) -> [f32; 4] {
    BAYER[(y & 3) as usize].map(|b| (f32::from(b) + 0.5) / 16.0)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::base::size::Size;
    use crate::render::framing::tops::RowTops;
    use crate::render::framing::view::View;
    use crate::render::shade::light::Lighting;
    use crate::settings::{Sun, ViewKind};
    use crate::terrain::Heightfield;
    use glam::Vec2;

    #[test]
    fn painted_weather_is_what_colour_says() {
        // Small, and as large as frames whose anchors lie farther apart:
        // the top 90 rows of each painted.
        for (width, height, step) in [(150, 90, 4), (1920, 1080, 8), (3840, 2160, 16)] {
            let field = Heightfield::flat(5, 100.0);
            let tops = RowTops::of(&field);
            let size = Size::new(width, height);
            let view = View::fitted(ViewKind::Vista, 33, 100.0, (tops.rows(), 0.0), size);
            let lighting = Lighting::new(Sun::Evening, &field);
            let frame = Vec2::new(width as f32, height as f32);
            let horizon = height as f32 * 0.66;
            let w = Weather::new(&view, &lighting, |c| c, (frame, horizon), 0.8, 3);
            let sky = Sky::new(0x203060, 0xc0d0e0, horizon).with_weather(w);
            assert!(sky.weather().is_some());
            assert_eq!(sky.anchors.step, step, "{height} tall");
            let mut pixels = vec![0u32; width as usize * 90];
            let mut canvas = Canvas::new(&mut pixels, width, 0);
            sky.paint(&mut canvas);
            for y in (0..90).step_by(if height > 90 { 7 } else { 1 }) {
                for x in 0..width {
                    assert_eq!(
                        pixels[(y * width + x) as usize],
                        sky.colour(x, y),
                        "{height} tall: ({x}, {y})"
                    );
                }
            }
        }
    }

    /// A rising moon's disc is drawn pixel by pixel: its edge crosses from
    /// the sky to the disc within a pixel or two, where the weather's
    /// columns, worked out every 8 at 1080p, would draw it in steps; and
    /// what is painted is what `colour` says.
    #[test]
    fn a_rising_moons_disc_is_drawn_pixel_by_pixel() {
        let (width, height) = (1920u32, 1080u32);
        let field = Heightfield::flat(5, 100.0);
        let tops = RowTops::of(&field);
        let size = Size::new(width, height);
        let view = View::fitted(ViewKind::Vista, 33, 100.0, (tops.rows(), 0.0), size);
        let lighting = Lighting::new(Sun::Night, &field).moon_at(0.3, 90.0);
        let frame = Vec2::new(width as f32, height as f32);
        let horizon = height as f32 * 0.66;
        let w = Weather::new(&view, &lighting, |c| c, (frame, horizon), 0.0, 3);
        let sky = Sky::new(0x101828, 0x303848, horizon).with_weather(w);
        let w = sky.weather().expect("a rising moon's glow");
        let [(left, right), (top, bottom)] = w.disc_bounds().expect("its disc");
        let (cx, cy) = ((left + right) / 2.0, (top + bottom) / 2.0);
        assert!(
            cx > 0.0 && cx < width as f32 && cy > 0.0 && cy < horizon,
            "the moon at ({cx}, {cy}), out of the sky"
        );
        let rows = bottom.ceil() as u32 + 1;
        let mut pixels = vec![0u32; (width * rows) as usize];
        let mut canvas = Canvas::new(&mut pixels, width, 0);
        sky.paint(&mut canvas);
        let y = cy as u32;
        let luma = |c: u32| crate::render::base::colour::luminance(unpack(c));
        let row: Vec<f32> = (0..width)
            .map(|x| luma(pixels[(y * width + x) as usize]))
            .collect();
        for x in left as u32..right as u32 {
            assert_eq!(
                pixels[(y * width + x) as usize],
                sky.colour(x, y),
                "({x}, {y})"
            );
        }
        let inside = luma(sky.colour(cx as u32, y));
        let outside = row[(left as usize).saturating_sub(4)];
        assert!(
            inside > outside + 0.3,
            "disc {inside} over the sky {outside}"
        );
        // Pixels part way between the sky round it and the disc, at each
        // edge (inside, the moon's seas are darker): a pixel or two.
        let part = |l: f32| l > outside + 0.1 * (inside - outside);
        let full = |l: f32| l > outside + 0.6 * (inside - outside);
        let span = &row[left as usize..right as usize];
        for edge in [
            span.iter().collect::<Vec<_>>(),
            span.iter().rev().collect::<Vec<_>>(),
        ] {
            let first = edge.iter().position(|&&l| part(l)).expect("the disc");
            let across = edge[first..].iter().take_while(|&&&l| !full(l)).count();
            assert!(across <= 2, "{across} pixels across an edge");
        }
    }
}
