//! Square subdivision with cragginess halving (Mountain Terrain 3.0), in
//! two orderings: plain midpoint displacement and diamond-square.
//!
//! Mountain Terrain sets each square's "four midpoints of the edges and the
//! center ... to the average of the four elevations plus or minus half of
//! Cragginess". Taken literally, an edge midpoint would average all four
//! corners of whichever square reached it first, and the two squares that
//! share the edge would disagree. We read it the way that leaves no crease:
//! - [`Ordering::Midpoint`]: the centre averages the square's four corners,
//!   an edge midpoint averages the two ends of its own edge. Shared points
//!   therefore depend only on the shared edge. The faint straight ridges
//!   along the big squares' edges that seed 002 describes remain.
//! - [`Ordering::Diamond`]: the centre as above; an edge midpoint averages
//!   the two ends of its edge *and* the centres of the two squares beside it
//!   (three points on the border): seed 002's diamond-square, which breaks
//!   up those straight ridges.
//!
//! In both, a new point at depth `k` (0 = the first split of the whole grid)
//! moves by a uniform amount in `[-c/2^(k+1), c/2^(k+1))` for cragginess `c`.

use super::noise::Noise;
use super::subdivide::{CentreRows, EdgeRows, Put, Rule, edge_row_of_ends};

/// Which points an edge midpoint averages.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Ordering {
    /// The two ends of its edge.
    Midpoint,
    /// The two ends and the centres of the squares beside it.
    Diamond,
}

/// The square generators' rule for one field.
pub(crate) struct Square {
    /// How edge midpoints are averaged.
    pub(crate) ordering: Ordering,
    /// The initial random range, halved per level.
    pub(crate) cragginess: f32,
    /// Edge midpoints' displacements against centres' (see
    /// `Params::edge_share`); the same when `None`.
    pub(crate) edge_share: Option<f32>,
}

/// Depth of the diamond generator's starting lattice: 2^depth + 1 points
/// a side (5x5), as xmountains starts from a coarse lattice (`-t`). Four
/// corners make one tilted plane with a hill on it; a lattice makes
/// several ranges, bays and valleys across the width.
pub(crate) const LATTICE_DEPTH: u32 = 2;

impl Square {
    /// Sets the starting points and returns the depth the subdivision goes
    /// on from. The midpoint generator (seed 003), and grids too coarse
    /// for a lattice, start from the four corners, uniform in
    /// `[-elevation/2, elevation/2)`. The diamond generator starts from the
    /// [`LATTICE_DEPTH`] lattice, uniform in `[-a, a)` with `a` half the
    /// elevation plus the displacements the levels above the lattice would
    /// have added, times [`LATTICE_SPREAD`].
    pub(crate) fn start<P: Put>(
        &self,
        heights: &mut [f32],
        size: usize,
        elevation: f32,
        noise: &Noise,
        put: &P,
    ) -> u32 {
        let last = size - 1;
        let step = last >> LATTICE_DEPTH;
        let (step, reach, depth) = if self.ordering == Ordering::Midpoint || step < 2 {
            (last, 0.5 * elevation, 0)
        } else {
            let above: f32 = (0..LATTICE_DEPTH).map(|d| self.amplitude(d)).sum();
            (
                step,
                LATTICE_SPREAD * (0.5 * elevation + above),
                LATTICE_DEPTH,
            )
        };
        for y in (0..=last).step_by(step) {
            for x in (0..=last).step_by(step) {
                put.put(&mut heights[y * size + x], reach * noise.at(x, y));
            }
        }
        depth
    }
}

/// The lattice's values use this share of their full reach: independent
/// neighbours a quarter of the width apart would otherwise make cliffs.
const LATTICE_SPREAD: f32 = 0.3;

impl Rule for Square {
    /// `cragginess / 2^(depth + 1)`, halved by exact powers of two.
    fn amplitude(&self, depth: u32) -> f32 {
        (0..=depth).fold(self.cragginess, |a, _| a * 0.5)
    }

    fn centre_row<P: Put>(&self, rows: CentreRows<'_>, offsets: &[f32], put: &P) {
        match self.ordering {
            Ordering::Midpoint => midpoint_centre_row(rows, offsets, put),
            Ordering::Diamond => diamond_centre_row(rows, offsets, put),
        }
    }

    fn edge_row<P: Put>(&self, rows: EdgeRows<'_>, offsets: &[f32], put: &P) {
        if let Some(share) = self.edge_share {
            let scaled: Vec<f32> = offsets.iter().map(|o| o * share).collect();
            return self.edges(rows, &scaled, put);
        }
        self.edges(rows, offsets, put)
    }
}

impl Square {
    /// [`Rule::edge_row`] with the offsets as given.
    fn edges<P: Put>(&self, rows: EdgeRows<'_>, offsets: &[f32], put: &P) {
        let EdgeRows { above, row, below } = rows;
        if self.ordering == Ordering::Midpoint || (above.is_none() && below.is_none()) {
            return edge_row_of_ends(row, offsets, put);
        }
        let Some((first, rest)) = row.split_first_mut() else {
            return;
        };
        // Each pair is (new point 2j+1, old point 2j+2); `left` is point 2j.
        let mut left = *first;
        let pairs = rest.chunks_exact_mut(2).zip(offsets);
        match (above, below) {
            (Some(a), Some(b)) => {
                let sides = a[1..].chunks_exact(2).zip(b[1..].chunks_exact(2));
                for ((r, o), (a, b)) in pairs.zip(sides) {
                    let right = r[1];
                    put.put(&mut r[0], 0.25 * ((left + right) + (a[0] + b[0])) + o);
                    left = right;
                }
            }
            (Some(side), None) | (None, Some(side)) => {
                for ((r, o), s) in pairs.zip(side[1..].chunks_exact(2)) {
                    let right = r[1];
                    put.put(&mut r[0], ((left + right) + s[0]) / 3.0 + o);
                    left = right;
                }
            }
            (None, None) => {} // handled above
        }
    }
}

/// A centre row where each vertical edge point is the mean of its edge's ends.
fn midpoint_centre_row<P: Put>(rows: CentreRows<'_>, offsets: &[f32], put: &P) {
    let CentreRows { above, row, below } = rows;
    let (Some((r0, row)), Some((o0, offsets))) = (row.split_first_mut(), offsets.split_first())
    else {
        return;
    };
    let mut here = above[0] + below[0];
    put.put(r0, 0.5 * here + o0);
    // Pairs of (centre 2j+1, edge point 2j+2); `here` is the ends of 2j.
    let ends = above[1..].chunks_exact(2).zip(below[1..].chunks_exact(2));
    for ((r, (a, b)), o) in row
        .chunks_exact_mut(2)
        .zip(ends)
        .zip(offsets.chunks_exact(2))
    {
        let next = a[1] + b[1];
        put.put(&mut r[0], 0.25 * (here + next) + o[0]);
        put.put(&mut r[1], 0.5 * next + o[1]);
        here = next;
    }
}

/// A centre row where each vertical edge point also averages the two
/// centres beside it, so it is set one pair late.
fn diamond_centre_row<P: Put>(rows: CentreRows<'_>, offsets: &[f32], put: &P) {
    let CentreRows { above, row, below } = rows;
    let (Some((r0, row)), Some((&o0, offsets))) = (row.split_first_mut(), offsets.split_first())
    else {
        return;
    };
    // The edge point waiting for the centre on its right.
    let (mut pending, mut pending_offset) = (r0, o0);
    let mut here = above[0] + below[0];
    let mut left = None;
    let ends = above[1..].chunks_exact(2).zip(below[1..].chunks_exact(2));
    for ((r, (a, b)), o) in row
        .chunks_exact_mut(2)
        .zip(ends)
        .zip(offsets.chunks_exact(2))
    {
        let [centre_slot, edge_slot] = r else {
            continue;
        };
        let next = a[1] + b[1];
        let centre = 0.25 * (here + next) + o[0];
        put.put(centre_slot, centre);
        put.put(
            pending,
            diamond_mean(here, left, Some(centre)) + pending_offset,
        );
        (pending, pending_offset) = (edge_slot, o[1]);
        (here, left) = (next, Some(centre));
    }
    put.put(pending, diamond_mean(here, left, None) + pending_offset);
}

/// Diamond-square's mean of a vertical edge point: its edge's two ends
/// (summing to `ends`) and the centres beside it, three on the border.
#[inline]
fn diamond_mean(ends: f32, left: Option<f32>, right: Option<f32>) -> f32 {
    match (left, right) {
        (Some(l), Some(r)) => 0.25 * (ends + (l + r)),
        (Some(c), None) | (None, Some(c)) => (ends + c) / 3.0,
        (None, None) => 0.5 * ends,
    }
}
