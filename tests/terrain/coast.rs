//! `water_line = "coast"`: every map part land, part sea, with water in
//! front; `"generator"` keeps the subdivision's own zero.

use mountains::settings::{Detail, Generator, Settings, WaterLine};
use mountains::terrain::{self, Heightfield};

fn settings(water_line: WaterLine, sea_level: f32) -> Settings {
    Settings {
        detail: Detail::Level(7),
        water_line,
        sea_level,
        ..crate::common::terrain_setup::temperate()
    }
}

fn sea_share(f: &Heightfield) -> f32 {
    let wet = f.heights().iter().filter(|&&h| h <= 0.0).count();
    wet as f32 / f.heights().len() as f32
}

#[test]
fn every_coast_map_is_part_land_part_sea() {
    let s = settings(WaterLine::Coast, 0.0);
    for seed in 0..200u64 {
        let share = sea_share(&terrain::generate(&s, seed));
        // 30% below the water line, plus the front band lowered into the sea.
        assert!(
            (0.3..0.6).contains(&share),
            "seed {seed}: {share:.3} of the map is sea"
        );
    }
}

#[test]
fn the_generators_zero_still_makes_all_sea_maps() {
    // Mountain Terrain's water line: some maps are (nearly) all sea. This
    // is what the coast fixes, and what `generator` keeps.
    let s = Settings {
        generator: Generator::Square,
        ..settings(WaterLine::Generator, 0.0)
    };
    let shares: Vec<f32> = (0..200u64)
        .map(|seed| sea_share(&terrain::generate(&s, seed)))
        .collect();
    assert!(shares.iter().any(|&x| x > 0.9), "no all-sea map in 200");
    assert!(shares.iter().any(|&x| x < 0.1), "no all-land map in 200");
}

#[test]
fn the_front_edge_is_under_water() {
    let s = settings(WaterLine::Coast, 0.0);
    for seed in 0..50u64 {
        let f = terrain::generate(&s, seed);
        let front = f.row(f.size() - 1);
        assert!(
            front.iter().all(|&h| h < 0.0),
            "seed {seed}: land on the front edge"
        );
    }
}

#[test]
fn behind_the_front_band_the_coast_only_moves_the_water_line() {
    // Same subdivision, one constant shift: the coast does not reshape the land.
    for generator in [Generator::Square, Generator::Diamond] {
        let coast = Settings {
            generator,
            ..settings(WaterLine::Coast, 0.0)
        };
        let own = Settings {
            generator,
            ..settings(WaterLine::Generator, 0.0)
        };
        let (a, b) = (terrain::generate(&coast, 9), terrain::generate(&own, 9));
        let shift = b.get(0, 0) - a.get(0, 0);
        assert!(shift.abs() > 1e-3, "{generator:?}: no shift at all");
        let rows = a.size() * 6 / 10;
        for y in 0..rows {
            for x in 0..a.size() {
                let d = b.get(x, y) - a.get(x, y);
                assert!(
                    (d - shift).abs() < 1e-3,
                    "{generator:?} ({x}, {y}): shifted by {d}, not {shift}"
                );
            }
        }
    }
}

#[test]
fn sea_level_floods_and_drains_from_the_coast() {
    for seed in [1u64, 2, 3] {
        let share = |sea_level| {
            sea_share(&terrain::generate(
                &settings(WaterLine::Coast, sea_level),
                seed,
            ))
        };
        let (low, mid, high) = (share(-0.5), share(0.0), share(0.5));
        assert!(low < mid && mid < high, "seed {seed}: {low} {mid} {high}");
        assert!(share(1.0) > 0.99, "seed {seed}: sea_level 1 is not all sea");
    }
}
