//! Ridges mode: layered 2D midpoint-displacement silhouettes (seed 002's 2D
//! mountain) fading into the distance, back to front, one layer per strip.
//!
//! Everything comes from the field and the frame size, so one mountain gives
//! one picture: the random numbers are a hash of (the field's heights, layer,
//! point), and each layer's roughness and relief are measured on one row of
//! the field (back rows make back layers). Far layers are paler and bluer,
//! nearer ones darker (aerial perspective), and each layer fades into mist
//! below its crest, so the valleys between ranges read as haze.

use super::base::colour::{Rgb, mix, to_u32};
use super::base::frame::{Frame, Rect};
use super::base::size::Size;
use crate::settings::Settings;
use crate::terrain::curves::hermite;
use crate::terrain::{Heightfield, splitmix};

/// Number of ranges, from the horizon to the foreground.
const LAYERS: usize = 8;
/// Most points of a layer's profile; wider frames interpolate between them,
/// so memory does not grow with the frame.
const MAX_PROFILE: usize = 4096;
/// Depth below a crest, in fractions of the frame height, over which the
/// layer fades from its crest colour into the mist.
const MIST_DEPTH: f32 = 0.3;

/// Sky at the top of the frame and at the horizon (a dusk gradient).
const SKY_TOP: Rgb = [0.10, 0.13, 0.27];
const SKY_HORIZON: Rgb = [0.93, 0.76, 0.62];
/// The haze far ranges fade into, and the colour of the nearest range.
const HAZE: Rgb = [0.70, 0.66, 0.74];
const NEAR: Rgb = [0.09, 0.10, 0.17];
/// The mist valleys fade into, before aerial perspective.
const MIST: Rgb = [0.55, 0.52, 0.62];

/// One range: its profile (0 lowest ..= 1 highest point) and placement.
#[derive(Debug, Clone)]
struct Layer {
    profile: Vec<f32>,
    /// Screen row of the profile's lowest point, in frame heights.
    base: f32,
    /// Screen height of the profile's highest point above `base`, in frame heights.
    relief: f32,
    /// Crest colour, and the colour the layer fades to in its mist.
    crest: Rgb,
    mist: Rgb,
}

/// The Ridges picture for one field at one frame size, drawn strip by strip.
#[derive(Debug, Clone)]
pub struct Ridges {
    size: Size,
    layers: Vec<Layer>,
}

impl Ridges {
    /// Plans the ranges of `field` for a frame of `size`.
    /// The height setting (1..=10) makes the ranges lower or taller.
    pub fn new(field: &Heightfield, settings: &Settings, size: Size) -> Self {
        let seed = field.fingerprint();
        let points = profile_points(size.width);
        let tallness = 0.6 + 0.08 * crate::settings::handles::HEIGHT.clamp(settings.height) as f32;
        let layers = (0..LAYERS)
            .map(|i| make_layer(field, seed, i, points, tallness))
            .collect();
        Ridges { size, layers }
    }

    /// How many strips the picture takes (one per range).
    pub fn strips_total(&self) -> usize {
        self.layers.len()
    }

    /// Draws strip `i` (strip 0 paints the sky too) and returns the pixels it
    /// changed; nothing when `i` is past the end or `frame` is another size.
    pub fn draw_strip(&self, frame: &mut Frame, i: usize) -> Rect {
        if frame.size() != self.size {
            return Rect::default();
        }
        let Some(layer) = self.layers.get(i) else {
            return Rect::default();
        };
        let mut damage = Rect::default();
        if i == 0 {
            paint_sky(frame);
            damage = frame.bounds();
        }
        damage.union(&paint_layer(frame, layer))
    }
}

/// One SplitMix64 step: a well-mixed 64-bit hash.
fn mix64(z: u64) -> u64 {
    splitmix::mix(z.wrapping_add(splitmix::GOLDEN))
}

/// A uniform number in -1..1 for point `k` of layer `layer`.
fn random(seed: u64, layer: usize, k: usize) -> f32 {
    let bits = mix64(seed ^ mix64((layer as u64) << 40 ^ k as u64));
    crate::terrain::splitmix::signed_unit(bits)
}

/// Profile length: a power of two plus one, at least the frame width (up to
/// `MAX_PROFILE`), so every column has its own point where it can.
fn profile_points(width: u32) -> usize {
    (width as usize).clamp(2, MAX_PROFILE).next_power_of_two() + 1
}

/// Builds range `i` (0 = farthest) from its row of the field.
/// `tallness` scales every range's relief (1 at height setting 5).
fn make_layer(field: &Heightfield, seed: u64, i: usize, points: usize, tallness: f32) -> Layer {
    let n = field.size();
    let row = field.row(i * (n - 1) / (LAYERS - 1));
    let (persistence, relief) = measure_row(row, field);
    let profile = midpoint_profile(seed, i, points, persistence);
    let depth = i as f32 / (LAYERS - 1) as f32;
    let haze = (1.0 - depth).powf(1.3) * 0.85;
    let crest = mix(NEAR, HAZE, haze);
    let mist = mix(mix(NEAR, MIST, 0.55), HAZE, haze);
    Layer {
        profile,
        base: 0.50 + 0.42 * depth,
        relief: (0.12 + 0.16 * depth) * relief * tallness,
        crest,
        mist,
    }
}

/// The persistence (displacement kept per halving, from the row's fractal
/// dimension) and the relative relief (0.4..=1) of one row of the field.
fn measure_row(row: &[f32], field: &Heightfield) -> (f32, f32) {
    let fine = mean_step(row, 1);
    let coarse = mean_step(row, 16.min(row.len() / 2));
    // For fractional Brownian motion, steps grow as distance^H.
    let hurst = if fine > 0.0 && coarse > fine {
        ((coarse / fine).ln() / 16f32.ln()).clamp(0.45, 0.95)
    } else {
        0.7
    };
    let (lo, hi) = row
        .iter()
        .fold((f32::MAX, f32::MIN), |(lo, hi), &v| (lo.min(v), hi.max(v)));
    let (lowest, highest) = field.min_max();
    let span = highest - lowest;
    let relief = if span > 0.0 && hi >= lo {
        ((hi - lo) / span).clamp(0.4, 1.0)
    } else {
        0.7
    };
    (0.5f32.powf(hurst), relief)
}

/// Mean absolute difference between heights `step` apart (0 for a bad row).
fn mean_step(row: &[f32], step: usize) -> f32 {
    if step == 0 || row.len() <= step {
        return 0.0;
    }
    let sum: f32 = row.windows(step + 1).map(|w| (w[step] - w[0]).abs()).sum();
    let mean = sum / (row.len() - step) as f32;
    if mean.is_finite() { mean } else { 0.0 }
}

/// Seed 002's 2D midpoint displacement over `points` (2^k + 1) points,
/// normalised to 0..=1.
fn midpoint_profile(seed: u64, layer: usize, points: usize, persistence: f32) -> Vec<f32> {
    let mut p = vec![0.0f32; points];
    p[0] = random(seed, layer, 0) * 0.5;
    p[points - 1] = random(seed, layer, points - 1) * 0.5;
    let mut span = points - 1;
    let mut amplitude = 1.0;
    while span > 1 {
        let half = span / 2;
        for left in (0..points - 1).step_by(span) {
            let mid = left + half;
            p[mid] = (p[left] + p[left + span]) / 2.0 + random(seed, layer, mid) * amplitude;
        }
        span = half;
        amplitude *= persistence;
    }
    normalise(&mut p);
    p
}

/// Rescales values to 0..=1 (all zero if they are all equal).
fn normalise(p: &mut [f32]) {
    let (lo, hi) = p
        .iter()
        .fold((f32::MAX, f32::MIN), |(lo, hi), &v| (lo.min(v), hi.max(v)));
    let scale = if hi > lo { 1.0 / (hi - lo) } else { 0.0 };
    p.iter_mut().for_each(|v| *v = (*v - lo) * scale);
}

/// Fills the frame with the dusk sky gradient.
fn paint_sky(frame: &mut Frame) {
    let (w, h) = (frame.width() as usize, frame.height());
    for (y, row) in frame.pixels_mut().chunks_exact_mut(w).enumerate() {
        let t = (y as f32 + 0.5) / (h as f32 * 0.62);
        let c = mix(SKY_TOP, SKY_HORIZON, t.min(1.0).powf(1.6));
        row.fill(to_u32(c));
    }
}

/// Paints one range from its crest down to the bottom of the frame and
/// returns the rectangle it covered.
fn paint_layer(frame: &mut Frame, layer: &Layer) -> Rect {
    let (w, h) = (frame.width(), frame.height());
    let crests = crest_rows(layer, frame.size());
    let top = crests.iter().copied().fold(h as f32, f32::min).max(0.0) as u32;
    if top >= h {
        return Rect::default();
    }
    let shades = mist_shades(layer, h);
    // Mist lies in level bands below the highest crest of the range, so it
    // does not streak down from every notch of the crest.
    let mist_top = (layer.base - layer.relief) * h as f32;
    let pixels = frame.pixels_mut();
    for y in top..h {
        let shade = shades[((y as f32 - mist_top).max(0.0) as usize).min(shades.len() - 1)];
        let start = y as usize * w as usize;
        let row = &mut pixels[start..start + w as usize];
        for (px, &crest) in row.iter_mut().zip(&crests) {
            let depth = y as f32 + 1.0 - crest;
            if depth <= 0.0 {
                continue;
            }
            // The pixel the crest crosses is covered only in part.
            *px = if depth < 1.0 {
                blend(*px, shade, depth)
            } else {
                shade
            };
        }
    }
    Rect {
        x0: 0,
        y0: top,
        x1: w,
        y1: h,
    }
}

/// The screen row of the crest above each column (fractional, may be < 0).
fn crest_rows(
    layer: &Layer,
    Size {
        width: w,
        height: h,
    }: Size,
) -> Vec<f32> {
    let last = (layer.profile.len() - 1) as f32;
    let across = if w > 1 { last / (w - 1) as f32 } else { 0.0 };
    (0..w)
        .map(|x| {
            let at = x as f32 * across;
            let i = (at as usize).min(layer.profile.len() - 2);
            let f = at - i as f32;
            let v = layer.profile[i] * (1.0 - f) + layer.profile[i + 1] * f;
            (layer.base - layer.relief * v) * h as f32
        })
        .collect()
}

/// The layer's colour by whole pixels below its crest: crest colour fading
/// into its mist over `MIST_DEPTH` of the frame.
fn mist_shades(layer: &Layer, h: u32) -> Vec<u32> {
    let depth = ((h as f32 * MIST_DEPTH) as usize).max(1);
    (0..=depth)
        .map(|d| {
            let t = d as f32 / depth as f32;
            to_u32(mix(layer.crest, layer.mist, hermite(t)))
        })
        .collect()
}

/// `under` with `over` laid on it at coverage `a` (0..=1).
fn blend(under: u32, over: u32, a: f32) -> u32 {
    let ch = |c: u32, s: u32| ((c >> s) & 0xff) as f32;
    let one = |s: u32| {
        let v = ch(under, s) + (ch(over, s) - ch(under, s)) * a;
        ((v + 0.5) as u32).min(255) << s
    };
    one(16) | one(8) | one(0)
}
