//! How much fine detail the near land shows, against a `detail = 12` grid
//! of the same field (issue 33's measure): the mean |Laplacian| of the
//! luminance over rows 55-95% of the frame, with clouds and reflections
//! off, for each seed at each size, and the ratio to `detail = 12` (its
//! grid's own land: `fine_relief = false` there).
//!
//! cargo run --release --example near_detail -- --sizes 1920x1080,3840x2160 --seeds 1-8 [--set KEY=VALUE]
//!
//! A ratio under 1 means the default grid shows less of the land's fine
//! structure near the viewer than the finest grid would.

#[path = "shared/flags.rs"]
mod flags;

use mountains::quality::image::channels;
use mountains::render::{Frame, Size, detail, render_full};
use mountains::settings::{Settings, load};
use mountains::terrain;

fn main() {
    let mut sizes = vec![Size::new(1920, 1080), Size::new(3840, 2160)];
    let mut seeds: Vec<u64> = (1..=8).collect();
    let mut prefs = Settings::default();
    load::apply_set(&mut prefs, "clouds", "0").expect("clouds");
    load::apply_set(&mut prefs, "reflections", "false").expect("reflections");
    let args: Vec<String> = std::env::args().skip(1).collect();
    for pair in args.chunks(2) {
        match (pair[0].as_str(), pair.get(1)) {
            ("--sizes", Some(v)) => sizes = v.split(',').map(size).collect(),
            ("--seeds", Some(v)) => seeds = flags::seeds(v),
            ("--set", Some(v)) => flags::set(&mut prefs, v),
            _ => panic!("usage: --sizes WxH,... --seeds A-B [--set KEY=VALUE]..."),
        }
    }
    for &at in &sizes {
        let mut ratios: Vec<f64> = seeds
            .iter()
            .map(|&seed| {
                let drawn = near_detail(&prefs, seed, at, None);
                let finest = near_detail(&prefs, seed, at, Some(12));
                println!(
                    "{at} seed {seed:3}: {drawn:.4} of {finest:.4} = {:.2}",
                    drawn / finest
                );
                drawn / finest
            })
            .collect();
        ratios.sort_by(f64::total_cmp);
        let n = ratios.len();
        let median = (ratios[(n - 1) / 2] + ratios[n / 2]) / 2.0;
        println!("{at}: median {median:.2} over {n} seeds");
    }
}

/// The size `WxH` names.
fn size(text: &str) -> Size {
    let (w, h) = flags::size(text);
    Size::new(w, h)
}

/// Mean |Laplacian| of the luminance (0..=1) over rows 55-95% of the
/// slide of `seed` at `at`, drawn at its own grid or at `grid`.
fn near_detail(prefs: &Settings, seed: u64, at: Size, grid: Option<u32>) -> f64 {
    let mut chosen = Settings {
        seed: Some(seed),
        ..prefs.clone()
    };
    if let Some(level) = grid {
        load::apply_set(&mut chosen, "detail", &level.to_string()).expect("detail");
        // The finer grid's own land, not a relief below it.
        load::apply_set(&mut chosen, "fine_relief", "false").expect("fine_relief");
    }
    let settings = detail::for_frame(&chosen, at);
    let field = terrain::generate(&settings, seed);
    let mut frame = Frame::new(at.width, at.height).expect("frame");
    render_full(&field, &settings, &mut frame);
    let (w, h) = (at.width as usize, at.height as usize);
    let luma: Vec<f64> = frame
        .pixels()
        .iter()
        .map(|&p| {
            let [r, g, b] = channels(p);
            (0.2126 * r as f64 + 0.7152 * g as f64 + 0.0722 * b as f64) / 255.0
        })
        .collect();
    let (top, bottom) = (h * 55 / 100, h * 95 / 100);
    let (mut sum, mut count) = (0.0, 0usize);
    for y in top.max(1)..bottom.min(h - 1) {
        for x in 1..w - 1 {
            let i = y * w + x;
            let lap = luma[i - 1] + luma[i + 1] + luma[i - w] + luma[i + w] - 4.0 * luma[i];
            sum += lap.abs();
            count += 1;
        }
    }
    sum / count.max(1) as f64
}
