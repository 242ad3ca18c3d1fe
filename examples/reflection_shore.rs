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

use mountains::render::classes::{Class, render_classes};
use mountains::render::{Frame, detail, render_full};
use mountains::settings::{Settings, load};
use mountains::terrain;

/// Rows of land above a shore and of water below it that are compared.
const REACH: u32 = 12;
/// The rows next to the shore line itself are its anti-aliased coverage.
const SKIP: u32 = 2;
/// Shore columns a seed needs to count.
const FEWEST: usize = 40;

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
    println!("seed shores raw detrended");
    let mut figures = Vec::new();
    for seed in seeds {
        let s = detail::for_frame(&settings, w, h);
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
        println!("{seed} {} {raw:.3} {detrended:.3}", land.len());
        figures.push((raw, detrended));
    }
    let median = |mut v: Vec<f64>| {
        v.sort_by(f64::total_cmp);
        v.get(v.len() / 2).copied().unwrap_or(f64::NAN)
    };
    let mean = |v: &[f64]| v.iter().sum::<f64>() / v.len() as f64;
    let (raw, det): (Vec<f64>, Vec<f64>) = figures.into_iter().unzip();
    println!(
        "{} seeds: raw median {:.3} mean {:.3}; detrended median {:.3} mean {:.3}",
        raw.len(),
        median(raw.clone()),
        mean(&raw),
        median(det.clone()),
        mean(&det)
    );
}

/// The land and the water brightness at each shore, column by column.
fn shores(frame: &Frame, classes: &Frame) -> (Vec<f64>, Vec<f64>) {
    let (w, h) = (frame.width(), frame.height());
    let class = |x: u32, y: u32| Class::of(classes.pixels()[(y * w + x) as usize]);
    let luma = |x: u32, y: u32| {
        let c = frame.pixels()[(y * w + x) as usize];
        let (r, g, b) = ((c >> 16) & 0xff, (c >> 8) & 0xff, c & 0xff);
        0.299 * r as f64 + 0.587 * g as f64 + 0.114 * b as f64
    };
    let (mut land, mut water) = (Vec::new(), Vec::new());
    for x in 0..w {
        for y in (REACH..h.saturating_sub(REACH + 1)).rev() {
            let shore = class(x, y) == Class::Land && class(x, y + 1) == Class::Water;
            if !shore
                || !(0..REACH).all(|d| class(x, y - d) == Class::Land)
                || !(1..=REACH).all(|d| class(x, y + d) == Class::Water)
            {
                continue;
            }
            let rows = SKIP..REACH;
            let n = rows.len() as f64;
            land.push(rows.clone().map(|d| luma(x, y - d)).sum::<f64>() / n);
            water.push(rows.map(|d| luma(x, y + 1 + d)).sum::<f64>() / n);
            break;
        }
    }
    (land, water)
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

fn parse<T: std::str::FromStr>(s: &str) -> T {
    s.trim()
        .parse()
        .unwrap_or_else(|_| die(&format!("not a number: {s}")))
}

fn die(message: &str) -> ! {
    eprintln!("reflection_shore: {message}");
    std::process::exit(2)
}
