//! What each world costs against the temperate world, measured in turns so
//! a loaded machine weighs on every world alike: each round draws every
//! world's frame once (seed 42, the detail `auto` picks) and makes every
//! world's mountain once at 1025 points a side; the least time of each
//! is kept. (`cargo bench --bench render -- world_` and `--bench terrain
//! -- generate_world` time them one after another.)
//!
//! cargo run --release --example worlds_cost -- [ROUNDS]

use std::time::{Duration, Instant};

use mountains::render::Size;
use mountains::render::{Frame, detail, render_full};
use mountains::settings::{Detail, Settings, World};
use mountains::terrain::{Heightfield, generate};

const WORLDS: [World; 6] = [
    World::Temperate,
    World::Alpine,
    World::Winter,
    World::Autumn,
    World::Desert,
    World::Tropical,
];

fn main() {
    let rounds: usize = std::env::args()
        .nth(1)
        .map_or(7, |r| r.parse().expect("ROUNDS"));
    let sizes = [(1920u32, 1080u32), (3840, 2160)];
    let frames: Vec<Vec<(Settings, Heightfield)>> = sizes
        .iter()
        .map(|&(w, h)| {
            WORLDS
                .iter()
                .map(|&world| {
                    let chosen = Settings {
                        world,
                        ..Settings::default()
                    };
                    let s = detail::for_frame(&chosen, Size::new(w, h));
                    let field = generate(&s, 42);
                    (s, field)
                })
                .collect()
        })
        .collect();
    let mut best = vec![[Duration::MAX; 3]; WORLDS.len()];
    for _ in 0..rounds {
        for (i, &world) in WORLDS.iter().enumerate() {
            for (k, &(w, h)) in sizes.iter().enumerate() {
                let (s, field) = &frames[k][i];
                let mut frame = Frame::new(w, h).expect("frame");
                let t = Instant::now();
                render_full(field, s, &mut frame);
                best[i][k] = best[i][k].min(t.elapsed());
            }
            let s = Settings {
                world,
                detail: Detail::Level(10),
                ..Settings::default()
            };
            let t = Instant::now();
            std::hint::black_box(generate(&s, 7));
            best[i][2] = best[i][2].min(t.elapsed());
        }
    }
    let ms = |d: Duration| d.as_secs_f64() * 1e3;
    println!(
        "least of {rounds} rounds: frame 1080p, frame 2160p, terrain 1025 (ratio to temperate)"
    );
    for (i, world) in WORLDS.iter().enumerate() {
        let r = |k: usize| ms(best[i][k]) / ms(best[0][k]);
        println!(
            "{:9} {:7.1} ms ({:.2})  {:7.1} ms ({:.2})  {:6.1} ms ({:.2})",
            world.name(),
            ms(best[i][0]),
            r(0),
            ms(best[i][1]),
            r(1),
            ms(best[i][2]),
            r(2)
        );
    }
}
