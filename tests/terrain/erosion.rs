//! Erosion: rain moves soil downhill, the same way on any thread count.

use crate::common::terrain_setup;

use mountains::settings::{Generator, Settings};
use mountains::terrain::{Heightfield, generate_with_threads};
use terrain_setup::settings;

fn eroded(generator: Generator, erosion: f32, seed: u64, threads: usize) -> Heightfield {
    let s = Settings {
        erosion,
        ..settings(generator, 8)
    };
    generate_with_threads(&s, seed, threads)
}

fn bits(f: &Heightfield) -> Vec<u32> {
    f.heights().iter().map(|h| h.to_bits()).collect()
}

#[test]
fn erosion_is_the_same_on_any_thread_count() {
    for generator in terrain_setup::GENERATORS {
        let one = bits(&eroded(generator, 0.5, 7, 1));
        for threads in [2, 3, 8] {
            assert!(
                one == bits(&eroded(generator, 0.5, 7, threads)),
                "{generator:?}: {threads} threads differ from one"
            );
        }
    }
}

#[test]
fn rain_moves_soil_downhill_without_raising_spikes() {
    for seed in [1, 2, 3] {
        let before = eroded(Generator::Diamond, 0.0, seed, 2);
        let after = eroded(Generator::Diamond, 1.0, seed, 2);
        let change: Vec<f64> = after
            .heights()
            .iter()
            .zip(before.heights())
            .map(|(a, b)| f64::from(a - b))
            .collect();
        assert!(after.heights().iter().all(|h| h.is_finite()), "seed {seed}");
        let moved: f64 = change.iter().map(|c| c.abs()).sum();
        let net: f64 = change.iter().sum();
        assert!(moved > 0.0, "seed {seed}: nothing moved");
        // Rain only wears land down overall (what droplets still carry when
        // they dry up or leave goes with them)...
        assert!(net < 0.0, "seed {seed}: net {net}");
        // ...and lays silt in hollows, not in heaps: no point stands out
        // above all its neighbours much more than the tallest did before.
        let relief = before.max() - before.min();
        let (spike_before, spike_after) = (spike(&before), spike(&after));
        eprintln!("seed {seed}: spike {spike_before} -> {spike_after} of {relief}");
        assert!(
            spike_after < 0.06 * relief,
            "seed {seed}: a point stands {spike_after} above its neighbours (was {spike_before})"
        );
        assert!(after.max() <= before.max(), "seed {seed}: the top rose");
        // High ground loses, low ground gains: the change falls with height.
        let n = change.len() as f64;
        let mean_h = before.heights().iter().map(|&h| f64::from(h)).sum::<f64>() / n;
        let mean_c = net / n;
        let cov: f64 = before
            .heights()
            .iter()
            .zip(&change)
            .map(|(&h, c)| (f64::from(h) - mean_h) * (c - mean_c))
            .sum();
        assert!(
            cov < 0.0,
            "seed {seed}: soil moved uphill (covariance {cov})"
        );
    }
}

/// How far the most outstanding point rises above the highest of its
/// eight neighbours.
fn spike(f: &Heightfield) -> f32 {
    let n = f.size();
    let mut most = 0.0f32;
    for y in 1..n - 1 {
        for x in 1..n - 1 {
            let mut around = f32::MIN;
            for (dx, dy) in [
                (0, 1),
                (2, 1),
                (1, 0),
                (1, 2),
                (0, 0),
                (2, 2),
                (0, 2),
                (2, 0),
            ] {
                around = around.max(f.get(x + dx - 1, y + dy - 1));
            }
            most = most.max(f.get(x, y) - around);
        }
    }
    most
}

#[test]
fn more_rain_moves_more_soil_and_none_moves_none() {
    let base = eroded(Generator::Square, 0.0, 11, 2);
    let moved = |e: f32| -> f64 {
        let f = eroded(Generator::Square, e, 11, 2);
        f.heights()
            .iter()
            .zip(base.heights())
            .map(|(a, b)| f64::from((a - b).abs()))
            .sum()
    };
    assert_eq!(moved(0.0), 0.0);
    let (some, more) = (moved(0.3), moved(1.0));
    assert!(
        some > 0.0 && more > some,
        "0.3 moved {some}, 1.0 moved {more}"
    );
}

#[test]
fn a_seed_chooses_where_the_rain_falls() {
    let a = eroded(Generator::Diamond, 0.5, 21, 2);
    let b = eroded(Generator::Diamond, 0.5, 21, 2);
    assert!(bits(&a) == bits(&b));
    let plain_a = eroded(Generator::Diamond, 0.0, 21, 2);
    let other = eroded(Generator::Diamond, 0.5, 22, 2);
    let plain_other = eroded(Generator::Diamond, 0.0, 22, 2);
    let change = |e: &Heightfield, p: &Heightfield| -> Vec<f32> {
        e.heights()
            .iter()
            .zip(p.heights())
            .map(|(x, y)| x - y)
            .collect()
    };
    assert!(change(&a, &plain_a) != change(&other, &plain_other));
}
