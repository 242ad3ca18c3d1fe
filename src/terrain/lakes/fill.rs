//! The lakes filled from their pits, one after another, each point at most
//! once.

use std::ops::Range;

use super::bits::Bits;

/// Fills lakes on one field. Its lists are kept from lake to lake: most
/// fills are of a few points (a basin with room for a lake whose water
/// covers little of it), and their own lists cost as much as the filling.
pub(super) struct Filler<'a> {
    heights: &'a [f32],
    n: usize,
    /// The points filled so far.
    seen: Bits,
    todo: Vec<usize>,
    /// The runs of the last lake filled.
    runs: Vec<Range<u32>>,
}

impl<'a> Filler<'a> {
    /// Nothing filled yet on `heights` (`n` a side).
    pub(super) fn new(heights: &'a [f32], n: usize) -> Self {
        Filler {
            heights,
            n,
            seen: Bits::new(heights.len()),
            todo: Vec::new(),
            runs: Vec::new(),
        }
    }

    /// Whether point `i` lies in a lake filled already.
    pub(super) fn seen(&self, i: usize) -> bool {
        self.seen.get(i)
    }

    /// Fills the points joined to `pit` below `level`; how many there are.
    /// A run of a row at a time: the whole run of such points a point lies
    /// in, then the runs beside it in the rows above and below, from one
    /// point left of it to one right of it (lakes join across a cell's
    /// diagonals, as the triangles drawn over the cells do); a row is read
    /// in order, where a point at a time would read its eight neighbours.
    pub(super) fn fill(&mut self, pit: usize, level: f32) -> usize {
        let (heights, n) = (self.heights, self.n);
        let wet = |seen: &Bits, i: usize| !seen.get(i) && heights[i] < level;
        self.runs.clear();
        self.todo.clear();
        self.todo.push(pit);
        let mut count = 0;
        while let Some(p) = self.todo.pop() {
            if !wet(&self.seen, p) {
                continue;
            }
            let (y, row) = (p / n, p / n * n);
            let (mut start, mut end) = (p, p + 1);
            while start > row && wet(&self.seen, start - 1) {
                start -= 1;
            }
            while end < row + n && wet(&self.seen, end) {
                end += 1;
            }
            (start..end).for_each(|i| self.seen.set(i));
            self.runs.push(start as u32..end as u32);
            count += end - start;
            let beside = (start - row).saturating_sub(1)..(end - row + 1).min(n);
            for side in [y.wrapping_sub(1), y + 1].into_iter().filter(|&s| s < n) {
                let mut was_wet = false;
                for i in beside.clone().map(|x| side * n + x) {
                    let is_wet = wet(&self.seen, i);
                    if is_wet && !was_wet {
                        self.todo.push(i);
                    }
                    was_wet = is_wet;
                }
            }
        }
        count
    }

    /// Lists the points of the last lake filled in `lake`, in place order.
    pub(super) fn points(&mut self, lake: &mut Vec<u32>) {
        self.runs.sort_unstable_by_key(|r| r.start);
        lake.clear();
        lake.extend(self.runs.iter().cloned().flatten());
    }
}
