//! The grid itself: every point set exactly once, every detail level,
//! low detail, and detail levels that refine rather than rescale.

use crate::common::terrain_setup;

use mountains::settings::Generator;
use mountains::terrain::{SQUARE_EXTENT, TRIANGLE_EXTENT, generate, generate_audited};
use terrain_setup::{GENERATORS, PROFILES, settings};

#[test]
fn every_point_is_written_exactly_once() {
    // The audit starts the field as NaN and counts stores onto points that
    // are already set: a second write is how cracks between neighbouring
    // squares or triangles appear (seed 004's floating triangles).
    for generator in GENERATORS {
        for detail in 4..=9 {
            for threads in [1, 3] {
                let audit = generate_audited(&settings(generator, detail), 31, threads);
                assert_eq!(audit.rewrites, 0, "{generator:?} detail {detail}: rewrites");
                assert_eq!(
                    audit.unset, 0,
                    "{generator:?} detail {detail}: unset points"
                );
            }
        }
    }
}

#[test]
fn triangle_profiles_write_their_fixed_points_once() {
    for profile in PROFILES {
        let mut s = settings(Generator::Triangle, 6);
        s.profile = profile;
        let audit = generate_audited(&s, 8, 1);
        assert_eq!((audit.rewrites, audit.unset), (0, 0), "{profile:?}");
    }
}

#[test]
fn finished_fields_hold_only_finite_heights() {
    for generator in GENERATORS {
        for seed in 0..20 {
            let f = generate(&settings(generator, 5), seed);
            assert!(f.heights().iter().all(|h| h.is_finite()), "{generator:?}");
        }
    }
}

#[test]
fn every_detail_level_works() {
    for generator in GENERATORS {
        for detail in 4..=12 {
            let f = generate(&settings(generator, detail), 11);
            let size = (1usize << detail) + 1;
            assert_eq!(f.size(), size, "{generator:?} detail {detail}");
            assert_eq!(f.heights().len(), size * size);
            assert!(
                f.heights().iter().all(|h| h.is_finite()),
                "{generator:?} {detail}"
            );
            assert!(f.max() > f.min(), "{generator:?} detail {detail} is flat");
            let extent = match generator {
                Generator::Triangle => TRIANGLE_EXTENT,
                _ => SQUARE_EXTENT,
            };
            assert_eq!(f.extent(), extent);
        }
    }
}

#[test]
fn low_detail_is_a_quarter_of_the_points() {
    for generator in GENERATORS {
        for detail in 5..=9 {
            let mut s = settings(generator, detail);
            let full = generate(&s, 4);
            s.low_detail = true;
            let low = generate(&s, 4);
            // A quarter of the cells (the points of a 2^n + 1 grid are a
            // quarter plus a thin edge).
            let cells = |n: usize| (n - 1) * (n - 1);
            assert_eq!(cells(low.size()) * 4, cells(full.size()), "{generator:?}");
            assert_eq!(low.extent(), full.extent(), "low detail must not rescale");
        }
    }
}

#[test]
fn a_coarser_detail_is_the_same_square_mountain_with_fewer_points() {
    for generator in [Generator::Square, Generator::Diamond] {
        let fine = generate(&settings(generator, 9), 21);
        let coarse = generate(&settings(generator, 6), 21);
        for y in 0..coarse.size() {
            for x in 0..coarse.size() {
                assert_eq!(
                    coarse.get(x, y).to_bits(),
                    fine.get(8 * x, 8 * y).to_bits(),
                    "{generator:?} at ({x}, {y})"
                );
            }
        }
    }
}

#[test]
fn a_coarser_detail_is_the_same_triangle_mountain_up_to_its_normalisation() {
    // The highest point of the finer grid may be one the coarse grid lacks,
    // so the two are scaled differently, but only by one factor.
    let fine = generate(&settings(Generator::Triangle, 9), 21);
    let coarse = generate(&settings(Generator::Triangle, 6), 21);
    let ratio = fine.get(0, 0) / coarse.get(0, 0);
    assert!((0.9..=1.0).contains(&ratio), "scale ratio {ratio}");
    for y in 0..coarse.size() {
        for x in 0..coarse.size() {
            let (c, f) = (coarse.get(x, y), fine.get(8 * x, 8 * y));
            assert!(
                (c * ratio - f).abs() < 1e-3,
                "({x}, {y}): {c} * {ratio} vs {f}"
            );
        }
    }
}
