//! The generators do what the source documents say: cragginess halving,
//! the triangle's MaxDeviation, contour, profiles, height and sea level.

use crate::common::terrain_setup;

use mountains::settings::{Generator, Profile, Settings};
use mountains::terrain::{Heightfield, TRIANGLE_PEAK_PER_HEIGHT, generate};
use terrain_setup::{GENERATORS, Kind, new_points, settings};

/// The parents a new point of `kind` averages, for a generator.
fn parents(
    generator: Generator,
    kind: Kind,
    x: usize,
    y: usize,
    h: usize,
    last: usize,
) -> Vec<(usize, usize)> {
    let inside = |p: &(isize, isize)| {
        (0..=last as isize).contains(&p.0) && (0..=last as isize).contains(&p.1)
    };
    let (x, y, h) = (x as isize, y as isize, h as isize);
    let candidates: Vec<(isize, isize)> = match (generator, kind) {
        (Generator::Triangle, Kind::Centre) => vec![(x - h, y - h), (x + h, y + h)],
        (_, Kind::Centre) => vec![
            (x - h, y - h),
            (x + h, y - h),
            (x - h, y + h),
            (x + h, y + h),
        ],
        (Generator::Diamond, _) => vec![(x, y - h), (x, y + h), (x - h, y), (x + h, y)],
        (_, Kind::Vertical) => vec![(x, y - h), (x, y + h)],
        (_, Kind::Horizontal) => vec![(x - h, y), (x + h, y)],
    };
    candidates
        .into_iter()
        .filter(inside)
        .map(|(x, y)| (x as usize, y as usize))
        .collect()
}

/// The largest |offset from the parents' mean| / `bound(depth)` at each
/// depth, over every new point of the field.
fn offset_ratios(f: &Heightfield, generator: Generator, bound: impl Fn(u32) -> f64) -> Vec<f64> {
    let last = f.size() - 1;
    (0..f.exponent())
        .map(|k| {
            let h = (last >> k) / 2;
            new_points(last, k)
                .into_iter()
                .map(|(x, y, kind)| {
                    let ps = parents(generator, kind, x, y, h, last);
                    let mean = ps.iter().map(|&(px, py)| f.get(px, py) as f64).sum::<f64>()
                        / ps.len() as f64;
                    (f.get(x, y) as f64 - mean).abs() / bound(k)
                })
                .fold(0.0, f64::max)
        })
        .collect()
}

#[test]
fn cragginess_halves_at_every_level() {
    for generator in [Generator::Square, Generator::Diamond] {
        for cragginess in [1, 17, 96, 128] {
            let s = Settings {
                cragginess,
                ..settings(generator, 8)
            };
            for seed in 0..3 {
                let f = generate(&s, seed);
                let bound = |k: u32| cragginess as f64 / 2f64.powi(k as i32 + 1);
                let ratios = offset_ratios(&f, generator, bound);
                // The diamond generator starts from a 5x5 lattice of free
                // values: the halving law holds from depth 2 on.
                let first = if generator == Generator::Diamond {
                    2
                } else {
                    0
                };
                for (k, r) in ratios.iter().enumerate().skip(first) {
                    // Within the bound (with room for f32 rounding) ...
                    assert!(
                        *r <= 1.0 + 1e-3,
                        "{generator:?} c={cragginess} depth {k}: {r}"
                    );
                    // ... and using it: with many points some come close.
                    if k >= 3 {
                        assert!(*r > 0.9, "{generator:?} c={cragginess} depth {k}: only {r}");
                    }
                }
            }
        }
    }
}

#[test]
fn diamond_starts_from_a_lattice_within_its_reach() {
    let (elevation, cragginess) = (60.0f32, 96u32);
    let s = Settings {
        elevation,
        cragginess,
        ..settings(Generator::Diamond, 6)
    };
    // 0.3 of half the elevation plus the two coarsest displacements.
    let reach = 0.3 * (elevation / 2.0 + cragginess as f32 * (0.5 + 0.25));
    let mut spread: f32 = 0.0;
    for seed in 0..50 {
        let f = generate(&s, seed);
        let step = (f.size() - 1) / 4;
        for y in (0..f.size()).step_by(step) {
            for x in (0..f.size()).step_by(step) {
                let h = f.get(x, y);
                assert!(h.abs() <= reach, "lattice point ({x}, {y}) at {h}");
                spread = spread.max(h.abs());
            }
        }
    }
    assert!(
        spread > 0.9 * reach,
        "lattice never near its reach: {spread}"
    );
}

#[test]
fn square_corners_start_within_half_the_elevation() {
    // Mountain Terrain's start (the diamond generator starts from a lattice).
    let generator = Generator::Square;
    let s = Settings {
        elevation: 60.0,
        ..settings(generator, 5)
    };
    let mut spread: f32 = 0.0;
    for seed in 0..50 {
        let f = generate(&s, seed);
        let last = f.size() - 1;
        for (x, y) in [(0, 0), (last, 0), (0, last), (last, last)] {
            assert!(
                f.get(x, y).abs() <= 30.0,
                "{generator:?} corner {}",
                f.get(x, y)
            );
            spread = spread.max(f.get(x, y).abs());
        }
    }
    assert!(spread > 25.0, "corners never near ±elevation/2: {spread}");
}

#[test]
fn the_triangle_deviation_shrinks_by_roughness_per_level() {
    for roughness in [1.0f32, 2.0, 3.5] {
        let s = Settings {
            roughness,
            profile: Profile::Slope,
            ..settings(Generator::Triangle, 8)
        };
        for seed in 0..3 {
            let f = generate(&s, seed);
            // Slope starts the back-left corner at q = 4 raw units, which
            // tells us the normalisation factor.
            let scale = f.get(0, 0) as f64 / 4.0;
            let bound = |k: u32| scale * 8.0 / (roughness as f64).powi(k as i32 + 1);
            let ratios = offset_ratios(&f, Generator::Triangle, bound);
            for (k, r) in ratios.iter().enumerate() {
                assert!(*r <= 1.0 + 1e-3, "r={roughness} depth {k}: {r}");
                if k >= 3 && roughness < 3.0 {
                    assert!(*r > 0.9, "r={roughness} depth {k}: only {r}");
                }
            }
        }
    }
}

/// Seed 000's blank Smoothness item (`roughness = 0`): no point deviates,
/// so every new point is the mean of its edge's ends and the seed changes
/// nothing.
#[test]
fn roughness_0_deviates_no_point() {
    let s = Settings {
        roughness: 0.0,
        contour: 1.0,
        profile: Profile::Slope,
        ..settings(Generator::Triangle, 7)
    };
    let f = generate(&s, 1);
    let scale = f.get(0, 0) as f64 / 4.0;
    assert!(scale > 0.0, "the slope's high corner: {}", f.get(0, 0));
    let ratios = offset_ratios(&f, Generator::Triangle, |_| scale * 1e-4);
    for (k, r) in ratios.iter().enumerate() {
        assert!(
            *r <= 1.0,
            "depth {k}: a point {r} * 1e-4 q off its parents' mean"
        );
    }
    assert_eq!(f.heights(), generate(&s, 2).heights());
    let rough = Settings {
        roughness: 1.0,
        ..s
    };
    assert_ne!(generate(&rough, 1).heights(), generate(&rough, 2).heights());
}

#[test]
fn the_triangle_peak_is_the_chosen_height() {
    for height in 1..=10 {
        for contour in [0.5, 1.0, 2.0] {
            let s = Settings {
                height,
                contour,
                ..settings(Generator::Triangle, 6)
            };
            let peak = height as f32 * TRIANGLE_PEAK_PER_HEIGHT;
            let f = generate(&s, height as u64);
            assert!(
                (f.max() - peak).abs() < peak * 1e-5,
                "height {height}: {}",
                f.max()
            );
        }
    }
}

#[test]
fn contour_above_one_lowers_the_middle_heights() {
    let base = settings(Generator::Triangle, 7);
    for seed in 0..5 {
        let linear = generate(&base, seed);
        let convex = generate(
            &Settings {
                contour: 2.0,
                ..base.clone()
            },
            seed,
        );
        let concave = generate(
            &Settings {
                contour: 0.5,
                ..base.clone()
            },
            seed,
        );
        let peak = linear.max();
        let mean_land = |f: &Heightfield| {
            let land: Vec<f32> = f.heights().iter().copied().filter(|&h| h > 0.0).collect();
            land.iter().sum::<f32>() / land.len() as f32
        };
        assert!(mean_land(&convex) < mean_land(&linear), "seed {seed}");
        assert!(mean_land(&concave) > mean_land(&linear), "seed {seed}");
        for ((&l, &c), &v) in linear
            .heights()
            .iter()
            .zip(convex.heights())
            .zip(concave.heights())
        {
            // The sign (land or sea) is kept, and a point halfway up the
            // peak goes to a quarter (contour 2) or 0.71 (contour 0.5).
            assert_eq!(l > 0.0, c > 0.0);
            assert_eq!(l < 0.0, v < 0.0);
            let ratio = l / peak;
            if ratio > 0.01 {
                assert!((c / peak - ratio * ratio).abs() < 1e-3, "{l} -> {c}");
                assert!((v / peak - ratio.sqrt()).abs() < 1e-3, "{l} -> {v}");
            }
        }
    }
}

/// Mean height of a corner quarter of the field, over seeds.
fn quarter_mean(s: &Settings, right: bool, front: bool) -> f32 {
    let mut total = 0.0;
    for seed in 0..10 {
        let f = generate(s, seed);
        let half = f.size() / 2;
        let (x0, y0) = (if right { half } else { 0 }, if front { half } else { 0 });
        let mut sum = 0.0;
        for y in y0..y0 + half {
            for x in x0..x0 + half {
                sum += f.get(x, y);
            }
        }
        total += sum / (half * half) as f32;
    }
    total / 10.0
}

#[test]
fn profile_slope_falls_from_back_left_to_front_right() {
    let s = Settings {
        profile: Profile::Slope,
        ..settings(Generator::Triangle, 6)
    };
    let (back_left, front_right) = (quarter_mean(&s, false, false), quarter_mean(&s, true, true));
    assert!(
        back_left > 0.0 && front_right < 0.0,
        "{back_left} {front_right}"
    );
    let f = generate(&s, 3);
    let last = f.size() - 1;
    assert!(f.get(0, 0) > 0.0 && f.get(last, last) < 0.0);
    assert_eq!(f.get(0, 0), -f.get(last, last), "corners are q and -q");
}

#[test]
fn profile_peak_rises_from_a_sea_level_front() {
    let s = Settings {
        profile: Profile::Peak,
        ..settings(Generator::Triangle, 6)
    };
    let back_left = quarter_mean(&s, false, false);
    for (right, front) in [(true, false), (false, true), (true, true)] {
        assert!(
            back_left > quarter_mean(&s, right, front),
            "{right} {front}"
        );
    }
    let f = generate(&s, 3);
    let (last, mid) = (f.size() - 1, f.size() / 2);
    for (x, y) in [
        (last, 0),
        (0, last),
        (last, last),
        (mid, mid),
        (mid, last),
        (last, mid),
    ] {
        assert_eq!(f.get(x, y), 0.0, "({x}, {y}) is fixed at sea level");
    }
}

#[test]
fn profile_bay_sinks_the_front_right() {
    let s = Settings {
        profile: Profile::Bay,
        ..settings(Generator::Triangle, 6)
    };
    let front_right = quarter_mean(&s, true, true);
    assert!(front_right < quarter_mean(&s, false, false));
    let f = generate(&s, 3);
    let last = f.size() - 1;
    assert!(f.get(last, last) < 0.0);
    assert_eq!([f.get(0, 0), f.get(last, 0), f.get(0, last)], [0.0; 3]);
}

#[test]
fn profile_massif_raises_the_back_and_left_edges_and_the_centre() {
    let s = Settings {
        profile: Profile::Massif,
        ..settings(Generator::Triangle, 6)
    };
    assert!(quarter_mean(&s, false, false) > quarter_mean(&s, true, true));
    let f = generate(&s, 3);
    let (last, mid) = (f.size() - 1, f.size() / 2);
    assert!(f.get(mid, 0) > 0.0);
    assert_eq!(
        f.get(mid, 0),
        f.get(0, mid),
        "both edge midpoints start at q"
    );
    assert_eq!(
        f.get(mid, mid) * 2.0,
        f.get(mid, 0),
        "the centre starts at q/2"
    );
    assert_eq!([f.get(0, 0), f.get(last, last)], [0.0; 2]);
}

#[test]
fn height_scales_the_square_generators_relief() {
    for generator in [Generator::Square, Generator::Diamond] {
        let tall = generate(
            &Settings {
                height: 10,
                ..settings(generator, 6)
            },
            5,
        );
        let usual = generate(&settings(generator, 6), 5);
        for (&t, &u) in tall.heights().iter().zip(usual.heights()) {
            assert_eq!(t, 2.0 * u);
        }
    }
}

#[test]
fn higher_cragginess_makes_taller_square_mountains() {
    for generator in [Generator::Square, Generator::Diamond] {
        let relief = |cragginess| {
            let s = Settings {
                cragginess,
                ..settings(generator, 6)
            };
            (0..20)
                .map(|seed| {
                    let f = generate(&s, seed);
                    f.max() - f.min()
                })
                .sum::<f32>()
        };
        assert!(
            relief(128) > relief(32) && relief(32) > relief(1),
            "{generator:?}"
        );
    }
}

#[test]
fn sea_level_moves_the_water_line() {
    for generator in GENERATORS {
        let base = settings(generator, 6);
        for seed in 0..5 {
            let land = |sea_level| {
                let f = generate(
                    &Settings {
                        sea_level,
                        ..base.clone()
                    },
                    seed,
                );
                f.heights().iter().filter(|&&h| h > 0.0).count()
            };
            let flooded = generate(
                &Settings {
                    sea_level: 1.0,
                    ..base.clone()
                },
                seed,
            );
            assert!(
                flooded.max() <= 0.0,
                "{generator:?}: sea level 1 floods all"
            );
            let drained = generate(
                &Settings {
                    sea_level: -1.0,
                    ..base.clone()
                },
                seed,
            );
            assert!(
                drained.min() >= 0.0,
                "{generator:?}: sea level -1 drains all"
            );
            // Raising the water line floods land where there is land above
            // the generator's zero; lowering it drains sea where there is sea.
            let own = generate(&base, seed);
            let (lower, level, higher) = (land(-0.5), land(0.0), land(0.5));
            assert!(lower >= level && level >= higher, "{generator:?} {seed}");
            assert_eq!(own.min() < 0.0, lower > level, "{generator:?} {seed}");
            assert_eq!(own.max() > 0.0, level > higher, "{generator:?} {seed}");
        }
    }
}

#[test]
fn sea_level_shifts_square_heights_without_rescaling() {
    let base = settings(Generator::Diamond, 6);
    let zero = generate(&base, 8);
    let raised = generate(
        &Settings {
            sea_level: 0.25,
            ..base
        },
        8,
    );
    let shift = 0.25 * zero.max();
    for (&z, &r) in zero.heights().iter().zip(raised.heights()) {
        assert!((z - shift - r).abs() < 1e-4, "{z} - {shift} vs {r}");
    }
}
