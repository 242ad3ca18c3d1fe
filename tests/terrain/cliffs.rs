//! `cliffs`: level terraces with steep faces above the first step, the
//! shore and everything at 0 untouched (the pinned bits of
//! tests/terrain/determinism.rs and the golden pictures hold at 0).

use mountains::settings::{Detail, Generator, Settings};
use mountains::terrain::{CLIFF_STEP_SHARE, Heightfield, Strata, generate, generate_with_threads};

fn settings(generator: Generator, cliffs: f32) -> Settings {
    Settings {
        generator,
        cliffs,
        detail: Detail::Level(8),
        ..crate::common::terrain_setup::temperate()
    }
}

/// The largest height difference between neighbouring points, and the
/// 99th percentile of them, over the land.
fn slopes(f: &Heightfield) -> (f32, f32) {
    let n = f.size();
    let mut steps = Vec::new();
    for y in 0..n - 1 {
        for x in 0..n - 1 {
            let h = f.get(x, y);
            if h > 0.0 {
                steps.push((f.get(x + 1, y) - h).abs());
                steps.push((f.get(x, y + 1) - h).abs());
            }
        }
    }
    steps.sort_by(f32::total_cmp);
    (steps[steps.len() - 1], steps[steps.len() * 99 / 100])
}

/// The share of the land above the first step lying in the lower half of
/// its bed, as `bed` tells the bed of a height: a terrace is mostly level
/// bench, its rise in a short face.
fn bench_share(f: &Heightfield, bed: impl Fn(f32) -> (f32, f32)) -> f64 {
    let step = CLIFF_STEP_SHARE * f.extent();
    let above: Vec<f32> = f.heights().iter().copied().filter(|&h| h > step).collect();
    let low = above
        .iter()
        .filter(|&&h| {
            let (bottom, top) = bed(h);
            h - bottom < 0.5 * (top - bottom)
        })
        .count();
    low as f64 / above.len() as f64
}

/// [`bench_share`] in the rock beds the cliffs cut into `f` (drawn from
/// its seed).
fn share_in_beds(f: &Heightfield) -> f64 {
    let strata = Strata::of(f.seed().expect("a generated field"), f.extent());
    bench_share(f, |h| strata.bed(h))
}

/// [`bench_share`] in even steps of [`CLIFF_STEP_SHARE`]: for the land
/// without cliffs, which has no beds of its own.
fn share_in_steps(f: &Heightfield) -> f64 {
    let step = CLIFF_STEP_SHARE * f.extent();
    bench_share(f, |h| {
        let bottom = (h / step).floor() * step;
        (bottom, bottom + step)
    })
}

const GENERATORS: [Generator; 4] = [
    Generator::Square,
    Generator::Diamond,
    Generator::Triangle,
    Generator::Brownian,
];

#[test]
fn cliffs_make_steeper_faces_and_level_benches() {
    for generator in GENERATORS {
        for seed in [1, 2, 3] {
            let plain = generate(&settings(generator, 0.0), seed);
            let sheer = generate(&settings(generator, 1.0), seed);
            let (max0, p0) = slopes(&plain);
            let (max1, p1) = slopes(&sheer);
            let case = format!("{generator:?} seed {seed}");
            assert!(max1 > 1.2 * max0, "{case}: steepest {max0} -> {max1}");
            assert!(p1 > 2.0 * p0, "{case}: 99th percentile {p0} -> {p1}");
            let (b0, b1) = (share_in_steps(&plain), share_in_beds(&sheer));
            assert!(b0 < 0.65 && b1 > 0.9, "{case}: benches {b0:.2} -> {b1:.2}");
        }
    }
}

#[test]
fn more_cliffs_sharpen_the_faces_step_by_step() {
    let share = |cliffs| share_in_beds(&generate(&settings(Generator::Diamond, cliffs), 4));
    let (a, b, c) = (share(0.25), share(0.5), share(1.0));
    assert!(a < b && b < c, "{a} {b} {c}");
}

/// The shore and the lowlands (the first step), and the sea, keep their
/// heights bit for bit; above them nearly every point moves.
#[test]
fn the_first_step_and_the_sea_are_left_as_they_are() {
    for generator in GENERATORS {
        let plain = generate(&settings(generator, 0.0), 5);
        let sheer = generate(&settings(generator, 0.8), 5);
        let step = CLIFF_STEP_SHARE * plain.extent();
        let (mut moved, mut above) = (0, 0);
        for (a, b) in plain.heights().iter().zip(sheer.heights()) {
            if *a <= step {
                assert_eq!(a.to_bits(), b.to_bits(), "{generator:?}: {a} moved to {b}");
            } else {
                above += 1;
                moved += usize::from(a != b);
                assert!(
                    *b >= step,
                    "{generator:?}: {a} fell to {b}, below the first step"
                );
            }
        }
        assert!(
            moved * 10 > above * 9,
            "{generator:?}: {moved} of {above} moved"
        );
    }
}

#[test]
fn cliffs_are_the_same_on_any_thread_count() {
    let s = Settings {
        detail: Detail::Level(10),
        ..settings(Generator::Diamond, 0.7)
    };
    let one = generate_with_threads(&s, 8, 1);
    let two = generate_with_threads(&s, 8, 2);
    let bits = |f: &Heightfield| f.heights().iter().map(|h| h.to_bits()).collect::<Vec<_>>();
    assert!(bits(&one) == bits(&two));
    assert_eq!(one.lakes(), two.lakes());
}
