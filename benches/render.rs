//! Speed of a complete frame (`render_full`), per grid size, frame size and mode.
//!
//! `cargo bench --bench render -- --warm-up-time 1 --measurement-time 3`

use criterion::{Criterion, criterion_group, criterion_main};
use mountains::render::{Frame, render_full};
use mountains::settings::{ColorMode, Settings};
use mountains::terrain::Heightfield;
use rand::{Rng, SeedableRng};
use rand_pcg::Pcg32;

/// A diamond-square mountain, so triangle sizes and overdraw are realistic
/// (the terrain generator is still a smooth stub).
fn mountain(exponent: u32) -> Heightfield {
    let mut f = Heightfield::flat(exponent, 400.0);
    let n = f.size();
    let mut rng = Pcg32::seed_from_u64(3);
    let mut amp = 60.0f32;
    for (x, y) in [(0, 0), (n - 1, 0), (0, n - 1), (n - 1, n - 1)] {
        f.set(x, y, rng.random_range(-amp..amp));
    }
    let mut step = n - 1;
    while step > 1 {
        let h = step / 2;
        for y in (h..n).step_by(step) {
            for x in (h..n).step_by(step) {
                let corners = [
                    (x - h, y - h),
                    (x + h, y - h),
                    (x - h, y + h),
                    (x + h, y + h),
                ];
                let mean = corners.iter().map(|&(i, j)| f.get(i, j)).sum::<f32>() / 4.0;
                f.set(x, y, mean + rng.random_range(-amp..amp));
            }
        }
        for y in (0..n).step_by(h) {
            let start = if (y / h).is_multiple_of(2) { h } else { 0 };
            for x in (start..n).step_by(step) {
                let near = [
                    (x.wrapping_sub(h), y),
                    (x + h, y),
                    (x, y.wrapping_sub(h)),
                    (x, y + h),
                ];
                let vals: Vec<f32> = near
                    .iter()
                    .filter(|&&(i, j)| i < n && j < n)
                    .map(|&(i, j)| f.get(i, j))
                    .collect();
                let mean = vals.iter().sum::<f32>() / vals.len() as f32;
                f.set(x, y, mean + rng.random_range(-amp..amp));
            }
        }
        amp *= 0.55;
        step = h;
    }
    f
}

fn bench(c: &mut Criterion) {
    let small = mountain(8);
    let large = mountain(10);
    let cases: [(&str, &Heightfield, u32, u32, ColorMode); 6] = [
        ("natural_257_1080p", &small, 1920, 1080, ColorMode::Natural),
        ("natural_1025_1080p", &large, 1920, 1080, ColorMode::Natural),
        ("natural_1025_2160p", &large, 3840, 2160, ColorMode::Natural),
        ("sonar_1025_1080p", &large, 1920, 1080, ColorMode::Sonar),
        ("outline_1025_1080p", &large, 1920, 1080, ColorMode::Outline),
        ("mono_1025_1080p", &large, 1920, 1080, ColorMode::Mono),
    ];
    for (name, field, w, h, color) in cases {
        let settings = Settings {
            color,
            shadows: true,
            ..Settings::default()
        };
        let mut frame = Frame::new(w, h).unwrap();
        c.bench_function(name, |b| {
            b.iter(|| render_full(field, &settings, &mut frame))
        });
    }
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(10);
    targets = bench
}
criterion_main!(benches);
