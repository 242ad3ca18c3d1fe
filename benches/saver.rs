//! The window layer's own cost per frame, without a display: pacing and
//! drawing one mountain at 1080p as the slide show does (240 ticks over a
//! simulated 8 s), and a hold tick (which must do nothing).

use std::hint::black_box;
use std::time::{Duration, Instant};

use criterion::{Criterion, criterion_group, criterion_main};
use mountains::render::Size;
use mountains::saver::show::Show;
use mountains::saver::slideshow::Pacing;
use mountains::settings::Settings;

fn settings() -> Settings {
    Settings {
        seed: Some(1),
        ..Settings::default()
    }
}

fn paced_mountain(c: &mut Criterion) {
    let pacing = Pacing::from_seconds(8.0, 10.0, true);
    c.bench_function("saver/one_mountain_1080p_240_ticks", |b| {
        b.iter_batched(
            || {
                let t0 = Instant::now();
                (
                    Show::new(settings(), None, pacing, Size::new(1920, 1080), t0),
                    t0,
                )
            },
            |(mut show, t0)| {
                for frame in 0..240u32 {
                    let now = t0 + Duration::from_millis(u64::from(frame) * 8000 / 239);
                    black_box(show.tick(now));
                }
                show
            },
            criterion::BatchSize::LargeInput,
        )
    });
}

fn hold_tick(c: &mut Criterion) {
    let pacing = Pacing::from_seconds(0.0, 1000.0, true);
    let t0 = Instant::now();
    let mut show = Show::new(settings(), None, pacing, Size::new(1920, 1080), t0);
    show.tick(t0);
    let later = t0 + Duration::from_secs(5);
    c.bench_function("saver/hold_tick", |b| {
        b.iter(|| black_box(show.tick(later)))
    });
}

criterion_group!(benches, paced_mountain, hold_tick);
criterion_main!(benches);
