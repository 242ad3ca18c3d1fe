//! Seed 002: plain midpoint displacement leaves straight creases along the
//! big squares' edges; diamond-square's ordering removes them.

use crate::common::terrain_setup;

use mountains::settings::Generator;
use mountains::terrain::{Heightfield, generate};
use terrain_setup::settings;

/// Mean |second difference across column x, `d` columns each way| over the rows.
fn bend_across_column(f: &Heightfield, x: usize, d: usize) -> f64 {
    (0..f.size())
        .map(|y| (f.get(x - d, y) as f64 - 2.0 * f.get(x, y) as f64 + f.get(x + d, y) as f64).abs())
        .sum::<f64>()
        / f.size() as f64
}

/// How much sharper the fold along the grid's centre line (the edge of the
/// first level's squares) is than along the odd columns beside it (which
/// no level's squares have as an edge), over seeds.
fn crease(generator: Generator, d: usize) -> f64 {
    let mut ratio = 0.0;
    for seed in 0..40 {
        let f = generate(&settings(generator, 8), seed);
        let mid = f.size() / 2;
        let beside = [mid - 7, mid - 5, mid - 3, mid + 3, mid + 5, mid + 7];
        let ordinary = beside
            .iter()
            .map(|&x| bend_across_column(&f, x, d))
            .sum::<f64>()
            / 6.0;
        ratio += bend_across_column(&f, mid, d) / ordinary;
    }
    ratio / 40.0
}

#[test]
fn diamond_square_softens_the_crease_along_the_first_split() {
    // Every ordering bends more along the coarse lines (their points move
    // further), but midpoint displacement folds there, diamond-square less.
    for d in [2, 4] {
        let (square, diamond) = (crease(Generator::Square, d), crease(Generator::Diamond, d));
        assert!(
            square > 2.0,
            "square subdivision should show its crease: {square}"
        );
        assert!(
            diamond < 0.8 * square,
            "d={d}: diamond {diamond} vs square {square}"
        );
    }
}
