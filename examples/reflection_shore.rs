//! Issue 19's reflection target: in calm water just below a shore, the
//! water's brightness follows the mirrored land above it (a correlation of
//! at least 0.3 along the shore).
//!
//! cargo run --release --example reflection_shore -- [--size 1920x1080] \
//!     [--seeds 1-24] [--window 9] [--set key=value ...]
//!
//! Each seed is drawn with default settings (and any `--set`), and its class
//! picture (`render_classes`) tells land from water. In each column, the
//! shore is the lowest land pixel with water straight below it, at least
//! [`REACH`] pixels of land above and of water below. Its land brightness
//! is the mean luma of the land rows above it, its water brightness the
//! mean of the water rows below (each water row mirrors the land row as far
//! above the shore). Per seed: Pearson's correlation of the two along the
//! shore (column by column), raw and with each series' running mean over
//! `--window` shore columns (9 unless told) taken away: haze lightens far land and far
//! water alike, and gentle shores have both lighter land and shallower,
//! lighter water, so the raw figure is well above 0 without any mirror;
//! the detrended one keeps only what changes from column to column, as a
//! mirror's image does. A seed with fewer than [`FEWEST`] shore columns is
//! left out.
//!
//! That figure holds the water below a shore against the land straight
//! above it, as if every shore were a cliff: a gentle shore seen from above
//! mirrors the land behind it, or the sky, not itself, so even a perfect
//! mirror scores little there. The second figure, "traced", holds the water
//! against the land it mirrors: from each of those water pixels of the sea
//! the sight line is reflected off sea level and followed over the field
//! (marched here, half a grid step at a time, not the renderer's mirror)
//! to the land it meets; where that land is seen in the frame (no nearer
//! land hides it), the pixel showing it is the mirrored land. Per shore
//! column, the mean luma of those land pixels against the mean of their
//! water pixels, correlated along the shore as above. A perfect mirror
//! (the renderer's mirror constants set to all mirror, no streaks, sampled
//! six times finer: docs/benchmarks-history.md, "The reflection figure,
//! traced") scores 0.99 raw and 0.80 detrended there, against 0.80 and
//! 0.32 straight above.
//!
//! Even without reflections the water's own colour follows the land near
//! it (shallow water lies off gentle, lighter shores), so the third
//! figure, "the mirror's part", is the traced one with what the water's
//! brightness without reflections (the same seed drawn with `reflections =
//! false`) explains taken out of both series (partial correlation): how
//! the water follows the land it mirrors beyond its own colour; exactly 0
//! without reflections.

use glam::{Vec2, Vec3};
use mountains::quality::image;
use mountains::render::Size;
use mountains::render::classes::{Class, render_classes};
use mountains::render::facts::{SceneFacts, drawn_field};
use mountains::render::{Frame, detail, render_full};
use mountains::settings::{Settings, load};
use mountains::terrain::{self, Heightfield};

/// Rows of land above a shore and of water below it that are compared.
const REACH: u32 = 12;
/// The rows next to the shore line itself are its anti-aliased coverage.
const SKIP: u32 = 2;
/// Shore columns a seed needs to count.
const FEWEST: usize = 40;
/// Water pixels of a shore column whose mirrored land the traced figure
/// needs to count the column (of `REACH - SKIP`).
const TRACED: usize = 5;

fn main() {
    let (mut w, mut h) = (1920u32, 1080u32);
    let mut seeds: Vec<u64> = (1..=24).collect();
    let mut settings = Settings::default();
    let mut window = 9usize;
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        let mut value = || {
            args.next()
                .unwrap_or_else(|| die(&format!("{a} needs a value")))
        };
        match a.as_str() {
            "--size" => {
                let v = value();
                let (a, b) = v.split_once('x').unwrap_or_else(|| die("--size WxH"));
                (w, h) = (parse(a), parse(b));
            }
            "--seeds" => {
                let v = value();
                seeds = match v.split_once('-') {
                    Some((a, b)) => (parse(a)..=parse(b)).collect(),
                    None => v.split(',').map(parse).collect(),
                };
            }
            "--window" => window = parse(&value()),
            "--set" => {
                let v = value();
                let (key, raw) = v.split_once('=').unwrap_or_else(|| die("--set key=value"));
                load::apply_set(&mut settings, key.trim(), raw)
                    .unwrap_or_else(|p| die(&p.to_string()));
            }
            _ => die(&format!("unknown argument {a}")),
        }
    }
    println!("seed shores raw detrended | traced: columns raw detrended | mirror's part");
    let mut figures = Vec::new();
    let mut traced = Vec::new();
    let mut parts = Vec::new();
    for seed in seeds {
        let s = detail::for_frame(&settings, Size::new(w, h));
        let field = terrain::generate(&s, seed);
        let mut frame = Frame::new(w, h).expect("room for the frame");
        render_full(&field, &s, &mut frame);
        let mut classes = Frame::new(w, h).expect("room for the classes");
        render_classes(&field, &s, &mut classes).unwrap_or_else(|| die("no classes"));
        let (land, water) = shores(&frame, &classes);
        if land.len() < FEWEST {
            println!("{seed} {} - -", land.len());
            continue;
        }
        let raw = pearson(&land, &water);
        let detrended = pearson(&detrend(&land, window), &detrend(&water, window));
        print!("{seed} {} {raw:.3} {detrended:.3}", land.len());
        figures.push((raw, detrended));
        // The ground as drawn (turned by `rotation`, ...), which the
        // facts' sight lines go with.
        let drawn = drawn_field(&field, &s, Size::new(w, h));
        let tracer = Tracer::new(&drawn, SceneFacts::of(&field, &s, Size::new(w, h)), w, h);
        let unmirrored = Settings {
            reflections: false,
            ..s.clone()
        };
        let mut plain = Frame::new(w, h).expect("room for the frame");
        render_full(&field, &unmirrored, &mut plain);
        let [land, water, own] = traced_shores(&frame, &plain, &classes, &tracer);
        if land.len() < FEWEST {
            println!(" | {} - - | - -", land.len());
            continue;
        }
        let raw = pearson(&land, &water);
        let [dl, dw, downs] = [&land, &water, &own].map(|v| detrend(v, window));
        let detrended = pearson(&dl, &dw);
        let part = (partial(&land, &water, &own), partial(&dl, &dw, &downs));
        println!(
            " | {} {raw:.3} {detrended:.3} | {:.3} {:.3}",
            land.len(),
            part.0,
            part.1
        );
        traced.push((raw, detrended));
        parts.push(part);
    }
    summary("straight above", figures);
    summary("traced", traced);
    summary("the mirror's part", parts);
}

/// The medians and means of the seeds' `(raw, detrended)` figures.
fn summary(what: &str, figures: Vec<(f64, f64)>) {
    let median = |mut v: Vec<f64>| {
        v.sort_by(f64::total_cmp);
        v.get(v.len() / 2).copied().unwrap_or(f64::NAN)
    };
    let mean = |v: &[f64]| v.iter().sum::<f64>() / v.len() as f64;
    let (raw, det): (Vec<f64>, Vec<f64>) = figures.into_iter().unzip();
    println!(
        "{what}, {} seeds: raw median {:.3} mean {:.3}; detrended median {:.3} mean {:.3}",
        raw.len(),
        median(raw.clone()),
        mean(&raw),
        median(det.clone()),
        mean(&det)
    );
}

/// The land and the water brightness at each shore, column by column.
fn shores(frame: &Frame, classes: &Frame) -> (Vec<f64>, Vec<f64>) {
    let (mut land, mut water) = (Vec::new(), Vec::new());
    let n = (REACH - SKIP) as f64;
    for (x, y) in shore_pixels(classes) {
        land.push((SKIP..REACH).map(|d| luma(frame, x, y - d)).sum::<f64>() / n);
        water.push(
            (SKIP..REACH)
                .map(|d| luma(frame, x, y + 1 + d))
                .sum::<f64>()
                / n,
        );
    }
    (land, water)
}

/// The brightness of the land the water below each shore mirrors (as
/// `tracer` finds it), of that water, and of that water in `plain` (the
/// frame without reflections), column by column, where at least
/// [`TRACED`] of its water pixels mirror land seen in the frame.
fn traced_shores(frame: &Frame, plain: &Frame, classes: &Frame, tracer: &Tracer) -> [Vec<f64>; 3] {
    let mut out = [Vec::new(), Vec::new(), Vec::new()];
    for (x, y) in shore_pixels(classes) {
        let found: Vec<[f64; 3]> = (SKIP..REACH)
            .filter_map(|d| {
                let (mx, my) = tracer.mirrored(x, y + 1 + d)?;
                let seen = Class::of(classes.pixels()[(my * frame.width() + mx) as usize]);
                let water = (x, y + 1 + d);
                (seen == Class::Land).then(|| {
                    [
                        luma(frame, mx, my),
                        luma(frame, water.0, water.1),
                        luma(plain, water.0, water.1),
                    ]
                })
            })
            .collect();
        if found.len() >= TRACED {
            let n = found.len() as f64;
            for (k, series) in out.iter_mut().enumerate() {
                series.push(found.iter().map(|f| f[k]).sum::<f64>() / n);
            }
        }
    }
    out
}

/// Each column's shore: its lowest land pixel with water straight below
/// it, [`REACH`] pixels of land above and of water below.
fn shore_pixels(classes: &Frame) -> Vec<(u32, u32)> {
    let (w, h) = (classes.width(), classes.height());
    let class = |x: u32, y: u32| Class::of(classes.pixels()[(y * w + x) as usize]);
    (0..w)
        .filter_map(|x| {
            (REACH..h.saturating_sub(REACH + 1)).rev().find_map(|y| {
                let shore = class(x, y) == Class::Land
                    && (0..REACH).all(|d| class(x, y - d) == Class::Land)
                    && (1..=REACH).all(|d| class(x, y + d) == Class::Water);
                shore.then_some((x, y))
            })
        })
        .collect()
}

/// The luma of pixel (`x`, `y`), as the quality measurement takes it.
fn luma(frame: &Frame, x: u32, y: u32) -> f64 {
    let c = frame.pixels()[(y * frame.width() + x) as usize];
    f64::from(image::luma(image::channels(c)))
}

/// Sight lines reflected off the sea and followed over the field.
struct Tracer<'a> {
    field: &'a Heightfield,
    facts: SceneFacts,
    frame: Vec2,
    /// Grid steps a side, a step's width in world units, the highest land.
    cells: f32,
    cell: f32,
    top: f32,
}

impl<'a> Tracer<'a> {
    fn new(field: &'a Heightfield, facts: SceneFacts, w: u32, h: u32) -> Self {
        Tracer {
            field,
            cell: facts.cell(),
            facts,
            frame: Vec2::new(w as f32, h as f32),
            cells: (field.size() - 1) as f32,
            top: field.max(),
        }
    }

    /// The pixel showing the land the sea at pixel (`x`, `y`) mirrors:
    /// `None` where the sight line there meets no sea (land, a lake), its
    /// reflection meets no land, or nearer land hides that land.
    fn mirrored(&self, x: u32, y: u32) -> Option<(u32, u32)> {
        let at = (Vec2::new(x as f32, y as f32) + 0.5) / self.frame;
        let (eye, sight) = self.facts.sight_line(at.x, at.y)?;
        if sight.z >= 0.0 {
            return None;
        }
        let sea = eye + sight * (-eye.z / sight.z);
        if self.height(sea)? > 0.0 {
            return None;
        }
        let up = Vec3::new(sight.x, sight.y, -sight.z);
        let land = self.march(sea, up, f32::INFINITY)?;
        // Seen from the eye: no ground between (followed from a grid step
        // off the land towards the eye, to a grid step short of it).
        let home = (eye - land).normalize();
        let reach = (eye - land).length() - self.cell;
        if self.march(land + home * self.cell, home, reach).is_some() {
            return None;
        }
        let g = Vec2::new(land.x, land.y) / (self.cell * self.cells);
        let p = self.facts.place(g.x, g.y, land.z) * self.frame;
        let inside = p.x >= 0.0 && p.y >= 0.0 && p.x < self.frame.x && p.y < self.frame.y;
        inside.then_some((p.x as u32, p.y as u32))
    }

    /// Where the line from `from` along unit `dir` first meets the ground,
    /// within `reach` of `from` and before it leaves the grid or rises over
    /// the highest land (found half a grid step at a time, then to 1/128th
    /// of one).
    fn march(&self, from: Vec3, dir: Vec3, reach: f32) -> Option<Vec3> {
        let across = Vec2::new(dir.x, dir.y).length() / self.cell;
        let step = 0.5 / across.max(1e-6);
        let above = |p: Vec3| self.height(p).map(|h| p.z > h);
        let mut t = 0.0;
        loop {
            let next = t + step;
            if next > reach {
                return None;
            }
            let p = from + dir * next;
            if (dir.z > 0.0 && p.z > self.top) || self.height(p).is_none() {
                return None;
            }
            if above(p) == Some(false) {
                let (mut lo, mut hi) = (t, next);
                for _ in 0..6 {
                    let mid = 0.5 * (lo + hi);
                    if above(from + dir * mid) == Some(true) {
                        lo = mid
                    } else {
                        hi = mid
                    }
                }
                return Some(from + dir * hi);
            }
            t = next;
        }
    }

    /// The ground's height under world point `p` (bilinear), `None` off
    /// the grid.
    fn height(&self, p: Vec3) -> Option<f32> {
        let g = Vec2::new(p.x, p.y) / self.cell;
        if !(g.x >= 0.0 && g.y >= 0.0 && g.x <= self.cells && g.y <= self.cells) {
            return None;
        }
        let last = self.field.size() - 1;
        let (x0, y0) = ((g.x as usize).min(last - 1), (g.y as usize).min(last - 1));
        let (fx, fy) = (g.x - x0 as f32, g.y - y0 as f32);
        let at = |x, y| self.field.get(x, y);
        let top = at(x0, y0) + (at(x0 + 1, y0) - at(x0, y0)) * fx;
        let bottom = at(x0, y0 + 1) + (at(x0 + 1, y0 + 1) - at(x0, y0 + 1)) * fx;
        Some(top + (bottom - top) * fy)
    }
}

/// `v` less its running mean over `window` items.
fn detrend(v: &[f64], window: usize) -> Vec<f64> {
    let half = window / 2;
    (0..v.len())
        .map(|i| {
            let part = &v[i.saturating_sub(half)..(i + half + 1).min(v.len())];
            v[i] - part.iter().sum::<f64>() / part.len() as f64
        })
        .collect()
}

/// Pearson's correlation of `a` and `b`.
fn pearson(a: &[f64], b: &[f64]) -> f64 {
    let n = a.len() as f64;
    let (ma, mb) = (a.iter().sum::<f64>() / n, b.iter().sum::<f64>() / n);
    let (mut sab, mut saa, mut sbb) = (0.0, 0.0, 0.0);
    for (x, y) in a.iter().zip(b) {
        let (da, db) = (x - ma, y - mb);
        sab += da * db;
        saa += da * da;
        sbb += db * db;
    }
    sab / (saa * sbb).sqrt()
}

/// The correlation of `a` and `b` with what `c` explains of each taken
/// out (partial correlation): how the water follows the mirrored land
/// beyond what its own colour, as drawn without reflections, does. 0
/// where `b` is all `c` (no reflections).
fn partial(a: &[f64], b: &[f64], c: &[f64]) -> f64 {
    let mean = c.iter().sum::<f64>() / c.len() as f64;
    if c.iter().all(|&v| v == mean) {
        // Nothing to take out.
        return pearson(a, b);
    }
    let (ab, ac, bc) = (pearson(a, b), pearson(a, c), pearson(b, c));
    let rest = ((1.0 - ac * ac) * (1.0 - bc * bc)).sqrt();
    if rest < 1e-9 || !rest.is_finite() {
        return 0.0;
    }
    (ab - ac * bc) / rest
}

fn parse<T: std::str::FromStr>(s: &str) -> T {
    s.trim()
        .parse()
        .unwrap_or_else(|_| die(&format!("not a number: {s}")))
}

fn die(message: &str) -> ! {
    eprintln!("reflection_shore: {message}");
    std::process::exit(2)
}
