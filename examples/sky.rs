//! How much of each slide's sky the clouds change (issue 19): for each seed
//! at the given size, default settings, the share of sky pixels whose
//! colour differs from the same slide drawn with `clouds = 0` by more than
//! CIE76 dE 5, and how many slides are clear and how many cloudy.
//!
//! cargo run --release --example sky -- --size 1920x1080 --seeds 1-24
//!
//! Sky pixels are those the class picture (`render_classes`) marks as sky.
//! A slide is counted clear when under 1% of its sky changes, cloudy when
//! at least 15% does.

use mountains::quality::facets::delta_e;
use mountains::quality::image::channels;
use mountains::render::Size;
use mountains::render::classes::{Class, render_classes};
use mountains::render::{Frame, detail, render_full};
use mountains::settings::{Clouds, Settings};
use mountains::terrain;

fn main() {
    let (mut size, mut seeds) = ((1920, 1080), (1..=24).collect::<Vec<u64>>());
    let args: Vec<String> = std::env::args().skip(1).collect();
    for pair in args.chunks(2) {
        match (pair[0].as_str(), pair.get(1)) {
            ("--size", Some(v)) => {
                let (w, h) = v.split_once('x').expect("--size WxH");
                size = (w.parse().expect("width"), h.parse().expect("height"));
            }
            ("--seeds", Some(v)) => {
                let (a, b) = v.split_once('-').expect("--seeds A-B");
                seeds = (a.parse().expect("first")..=b.parse().expect("last")).collect();
            }
            _ => panic!("usage: --size WxH --seeds A-B"),
        }
    }
    let (mut clear, mut cloudy) = (0, 0);
    for &seed in &seeds {
        let share = changed_sky(seed, size);
        let kind = match share {
            s if s < 0.01 => {
                clear += 1;
                "clear"
            }
            s if s >= 0.15 => {
                cloudy += 1;
                "cloudy"
            }
            _ => "light",
        };
        println!(
            "seed {seed:3}: {:5.1}% of the sky changed ({kind})",
            share * 100.0
        );
    }
    let n = seeds.len();
    println!("{clear} of {n} clear, {cloudy} of {n} cloudy");
}

/// The share of `seed`'s sky pixels (default settings, a frame of `size`)
/// that the clouds change by more than dE 5.
fn changed_sky(seed: u64, (w, h): (u32, u32)) -> f64 {
    let chosen = Settings {
        seed: Some(seed),
        ..Settings::default()
    };
    let settings = detail::for_frame(&chosen, Size::new(w, h));
    let field = terrain::generate(&settings, seed);
    let draw = |clouds| {
        let mut frame = Frame::new(w, h).expect("frame");
        let s = Settings {
            clouds,
            ..settings.clone()
        };
        render_full(&field, &s, &mut frame);
        frame
    };
    let (with, without) = (draw(settings.clouds), draw(Clouds::Amount(0.0)));
    let mut classes = Frame::new(w, h).expect("frame");
    render_classes(&field, &settings, &mut classes).expect("classes");
    let (mut sky, mut changed) = (0u64, 0u64);
    for ((&c, &a), &b) in classes
        .pixels()
        .iter()
        .zip(with.pixels())
        .zip(without.pixels())
    {
        if Class::of(c) != Class::Sky {
            continue;
        }
        sky += 1;
        changed += u64::from(delta_e(channels(a), channels(b)) > 5.0);
    }
    changed as f64 / sky.max(1) as f64
}
