//! Softening the stair-steps of 8-bit heightmaps.
//!
//! 256 levels are too few for gentle slopes: each level becomes a flat
//! terrace, and the shading shows the terrace edges as stripes. We look for
//! a smoother surface that still agrees with the samples: repeated
//! `[1 2 1] / 4` blurs in both directions, each point then clamped to within
//! half a level of its own value. Steps of one level melt into slopes; real
//! shapes (differences of several levels) stay where they were.

/// Blur-and-clamp rounds; a step spreads over about `sqrt(ROUNDS / 2)` cells
/// on each side.
pub const ROUNDS: usize = 12;

/// Softens the steps of `grid` (`size` x `size`, in 8-bit sample units).
pub fn soften_steps(grid: &mut [f32], size: usize) {
    let original = grid.to_vec();
    let mut above = vec![0.0f32; size];
    let mut here = vec![0.0f32; size];
    for _ in 0..ROUNDS {
        for row in grid.chunks_exact_mut(size) {
            blur_row(row, &mut here);
        }
        blur_columns(grid, size, &mut above, &mut here);
        for (v, o) in grid.iter_mut().zip(&original) {
            *v = v.clamp(o - 0.5, o + 0.5);
        }
    }
}

/// `[1 2 1] / 4` along one row, the ends repeated.
fn blur_row(row: &mut [f32], copy: &mut [f32]) {
    copy.copy_from_slice(row);
    let last = row.len() - 1;
    for (x, v) in row.iter_mut().enumerate() {
        let left = copy[x.saturating_sub(1)];
        let right = copy[(x + 1).min(last)];
        *v = 0.25 * left + 0.5 * copy[x] + 0.25 * right;
    }
}

/// `[1 2 1] / 4` down the columns, in place, with two rows of memory.
fn blur_columns(grid: &mut [f32], size: usize, above: &mut [f32], here: &mut [f32]) {
    above.copy_from_slice(&grid[..size]);
    for y in 0..size {
        here.copy_from_slice(&grid[y * size..(y + 1) * size]);
        let below_y = (y + 1).min(size - 1);
        for x in 0..size {
            let below = grid[below_y * size + x];
            grid[y * size + x] = 0.25 * above[x] + 0.5 * here[x] + 0.25 * below;
        }
        above.copy_from_slice(here);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_level_steps_become_slopes_within_half_a_level() {
        let n = 33;
        // Terraces four cells wide rising to the right.
        let mut grid: Vec<f32> = (0..n * n).map(|i| ((i % n) / 4) as f32).collect();
        let original = grid.clone();
        soften_steps(&mut grid, n);
        let row = &grid[10 * n..11 * n];
        let mut distinct: Vec<f32> = row.to_vec();
        distinct.dedup();
        assert!(distinct.len() > 2 * 9, "still terraced: {row:?}");
        assert!(
            row.windows(2).all(|w| w[1] >= w[0]),
            "not monotonic: {row:?}"
        );
        for (v, o) in grid.iter().zip(&original) {
            assert!((v - o).abs() <= 0.5);
        }
    }

    #[test]
    fn constants_and_big_features_keep_their_values() {
        let n = 17;
        let mut flat = vec![7.0f32; n * n];
        soften_steps(&mut flat, n);
        assert!(flat.iter().all(|&v| v == 7.0));
        let mut cliff: Vec<f32> = (0..n * n)
            .map(|i| if i % n < 8 { 0.0 } else { 200.0 })
            .collect();
        soften_steps(&mut cliff, n);
        assert!(cliff[5 * n + 7] <= 0.5 && cliff[5 * n + 8] >= 199.5);
    }
}
