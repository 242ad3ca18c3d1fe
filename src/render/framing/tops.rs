//! The highest point of each grid row, whole and per block of columns:
//! how high a strip can reach on screen, for the view's fit and for
//! skipping strips hidden behind nearer land. Heights that are not
//! numbers count as sea level, here and wherever a point is drawn.

use std::ops::RangeInclusive;

use crate::terrain::Heightfield;

/// Heights that are not numbers are drawn at sea level.
#[inline]
pub(crate) fn finite(h: f32) -> f32 {
    if h.is_finite() { h } else { 0.0 }
}

/// Grid points per block.
const BLOCK: usize = 16;

/// Each row's highest point (at least sea level), and its highest point in
/// each block of [`BLOCK`] points.
pub(crate) struct RowTops {
    whole: Vec<f32>,
    blocks: Vec<f32>,
    per_row: usize,
}

impl RowTops {
    /// The tops of `field`'s rows, in one pass over it. A lake's surface
    /// counts as its points' height: a block of columns inside a lake
    /// reaches the surface drawn over them, not the ground below it.
    pub(crate) fn of(field: &Heightfield) -> Self {
        let size = field.size();
        let per_row = size.div_ceil(BLOCK).max(1);
        let mut blocks = Vec::with_capacity(size * per_row);
        let whole = (0..size)
            .map(|y| {
                let row = field
                    .row(y)
                    .chunks(BLOCK)
                    .map(|b| b.iter().fold(0.0f32, |m, &h| finite(h).max(m)));
                let start = blocks.len();
                blocks.extend(row);
                if let Some(lakes) = field.lakes() {
                    for run in lakes.row(y) {
                        let level = lakes.level(run.lake);
                        let (a, b) = (run.start as usize / BLOCK, (run.end as usize - 1) / BLOCK);
                        for top in &mut blocks[start + a..=start + b] {
                            *top = top.max(level);
                        }
                    }
                }
                blocks[start..].iter().copied().fold(0.0f32, f32::max)
            })
            .collect();
        RowTops {
            whole,
            blocks,
            per_row,
        }
    }

    /// The highest point of each row.
    pub(crate) fn rows(&self) -> &[f32] {
        &self.whole
    }

    /// The highest point of row `y`.
    #[inline]
    pub(crate) fn row(&self, y: usize) -> f32 {
        self.whole[y]
    }

    /// The highest of points `points` of row `y` (perhaps a little higher:
    /// whole blocks are looked at).
    #[inline]
    pub(crate) fn within(&self, y: usize, points: RangeInclusive<usize>) -> f32 {
        let first = (*points.start() / BLOCK).min(self.per_row - 1);
        let last = (*points.end() / BLOCK).min(self.per_row - 1);
        let row = &self.blocks[y * self.per_row..][..self.per_row];
        row[first..=last.max(first)]
            .iter()
            .copied()
            .fold(0.0f32, f32::max)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tops_are_the_highest_points_of_rows_and_blocks() {
        let mut f = Heightfield::flat(6, 64.0);
        f.set(40, 3, 9.0);
        f.set(2, 3, 4.0);
        f.set(5, 7, f32::INFINITY);
        f.set(6, 7, -3.0);
        let tops = RowTops::of(&f);
        assert_eq!((tops.row(3), tops.row(7), tops.row(0)), (9.0, 0.0, 0.0));
        assert_eq!(tops.rows().len(), 65);
        // Point 40 lies in the block of points 32..=47.
        assert_eq!(tops.within(3, 0..=31), 4.0);
        assert_eq!(tops.within(3, 30..=33), 9.0);
        assert_eq!(tops.within(3, 48..=64), 0.0);
        assert_eq!(tops.within(7, 0..=64), 0.0, "not a number, or under water");
    }
}
