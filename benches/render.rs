//! Speed of a complete frame (`render_full`, what `mountains render` and
//! the saver's redraws run), per grid size, frame size and mode; and of the
//! PNG encoding `render` and the P key's screenshots run.
//!
//! `cargo bench --bench render -- --warm-up-time 1 --measurement-time 4`

use criterion::{Criterion, criterion_group, criterion_main};
use mountains::render::Size;
use mountains::render::{Frame, detail, render_full};
use mountains::settings::{Clouds, ColorMode, Settings, Shading, Sun, World};
use mountains::terrain::{Heightfield, generate};

/// The real generator's mountain (seed 42), so triangle sizes, water and
/// overdraw are what the saver draws.
fn mountain(detail: u32) -> Heightfield {
    generate(
        &Settings {
            detail: mountains::settings::Detail::Level(detail),
            ..temperate()
        },
        42,
    )
}

fn bench(c: &mut Criterion) {
    let small = mountain(8);
    let large = mountain(10);
    let cases: [(&str, &Heightfield, u32, u32, ColorMode); 7] = [
        ("natural_257_1080p", &small, 1920, 1080, ColorMode::Natural),
        ("natural_1025_1080p", &large, 1920, 1080, ColorMode::Natural),
        ("natural_1025_2160p", &large, 3840, 2160, ColorMode::Natural),
        ("sonar_257_1080p", &small, 1920, 1080, ColorMode::Sonar),
        ("sonar_1025_1080p", &large, 1920, 1080, ColorMode::Sonar),
        ("outline_1025_1080p", &large, 1920, 1080, ColorMode::Outline),
        ("mono_1025_1080p", &large, 1920, 1080, ColorMode::Mono),
    ];
    for (name, field, w, h, color) in cases {
        let settings = Settings {
            color,
            shadows: true,
            ..temperate()
        };
        let mut frame = Frame::new(w, h).unwrap();
        c.bench_function(name, |b| {
            b.iter(|| render_full(field, &settings, &mut frame))
        });
    }
}

/// The default frame as the program draws it: default settings with the
/// detail `auto` picks for this frame size; the same with flat shading
/// (one colour a face), which smooth shading's cost is held against; and
/// the same with a clear sky and plain water (`clouds = 0`, `reflections =
/// false`: the frame before the sky and water had weather and mirrors),
/// which their cost is held against.
fn bench_default(c: &mut Criterion) {
    for (name, w, h, shading, weather) in [
        ("default_auto_1080p", 1920, 1080, Shading::Smooth, true),
        ("default_auto_2160p", 3840, 2160, Shading::Smooth, true),
        ("flat_auto_1080p", 1920, 1080, Shading::Flat, true),
        ("flat_auto_2160p", 3840, 2160, Shading::Flat, true),
        ("plain_auto_1080p", 1920, 1080, Shading::Smooth, false),
        ("plain_auto_2160p", 3840, 2160, Shading::Smooth, false),
    ] {
        let defaults = temperate();
        let chosen = Settings {
            shading,
            clouds: if weather {
                defaults.clouds
            } else {
                Clouds::Amount(0.0)
            },
            reflections: weather && defaults.reflections,
            ..defaults
        };
        let settings = detail::for_frame(&chosen, Size::new(w, h));
        let field = generate(&settings, 42);
        let mut frame = Frame::new(w, h).unwrap();
        c.bench_function(name, |b| {
            b.iter(|| render_full(&field, &settings, &mut frame))
        });
        c.bench_function(&format!("{name}_png"), |b| {
            // The frame drawn, as `render` encodes it, even when a filter
            // left out the frame's own bench (a black frame packs to
            // nothing); into memory kept between runs: the encoding, not
            // the disk.
            render_full(&field, &settings, &mut frame);
            let mut out = Vec::new();
            b.iter(|| {
                out.clear();
                mountains::snapshot::encode_png(&frame, &mut out).unwrap()
            })
        });
    }
}

/// A night frame against a day frame of the same mountain, frame size and
/// weather (seed 42 at the detail `auto` picks): the stars, the moon and
/// the night's colours must cost little beside the day's light.
fn bench_night(c: &mut Criterion) {
    for (w, h, size) in [(1920, 1080, "1080p"), (3840, 2160, "2160p")] {
        for (time, sun) in [("day", Sun::Midday), ("night", Sun::Night)] {
            let chosen = Settings { sun, ..temperate() };
            let settings = detail::for_frame(&chosen, Size::new(w, h));
            let field = generate(&settings, 42);
            let mut frame = Frame::new(w, h).unwrap();
            c.bench_function(&format!("{time}_auto_{size}"), |b| {
                b.iter(|| render_full(&field, &settings, &mut frame))
            });
        }
    }
}

/// Each world's frame at 1080p and 4K (seed 42, the detail `auto` picks),
/// against the temperate world's: a world costs at most 1.1 times as much.
fn bench_worlds(c: &mut Criterion) {
    for world in [
        World::Temperate,
        World::Alpine,
        World::Winter,
        World::Autumn,
        World::Desert,
        World::Tropical,
    ] {
        for (w, h) in [(1920, 1080), (3840, 2160)] {
            let chosen = Settings {
                world,
                ..Settings::default()
            };
            let settings = detail::for_frame(&chosen, Size::new(w, h));
            let field = generate(&settings, 42);
            let mut frame = Frame::new(w, h).unwrap();
            c.bench_function(&format!("world_{}_{h}p", world.name()), |b| {
                b.iter(|| render_full(&field, &settings, &mut frame))
            });
        }
    }
}

/// The default settings in the temperate world: the figures before the
/// worlds measured this mountain (the seed's varied world is another; the
/// worlds are timed on their own).
fn temperate() -> Settings {
    Settings {
        world: World::Temperate,
        ..Settings::default()
    }
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(10);
    targets = bench, bench_default, bench_night, bench_worlds
}
criterion_main!(benches);
