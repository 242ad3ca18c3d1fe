//! One band of rows: where each of its points' water ends, as far as the
//! band can tell.
//!
//! A band holds its own rows and, below them, the first row of the next
//! band, whose points it needs to pair its last row's with (see
//! [`super::lips`]). Every point's water runs down, lowest neighbour after
//! lowest neighbour, to a pit of the band, into the outlets, or out of the
//! band: to a point of the row above it or of the row below its extra row,
//! or to a pit of the extra row (that row is the next band's). Such a point
//! is an exit of the band; [`super::bands`] later follows it on in the band
//! that owns it, which keeps the ends of its first two rows and of its last
//! for that.
//!
//! The band's ends are numbered as they are found, row by row: the outlets
//! 0, then its pits and its exits. The ways are followed in a buffer the size
//! of the band, which stays in the cache: no memory a point of the field.

use std::ops::Range;

use super::grid::land;
use super::lips::{Lip, lips_in};
use super::raised::Raised;

/// The outlets' number: the border and the sea.
pub(super) const OUTLET: u32 = 0;

/// Marks a value as the place of a point further down the water's way (in
/// the other bits), its end not yet known.
const ON_THE_WAY: u32 = 1 << 31;

/// Marks an end of [`Band::ends`] as an exit, the point it leads to in the
/// other bits (else it is a pit).
pub(super) const EXIT: u32 = 1 << 31;

/// What one band found.
pub(super) struct Band {
    /// Its own rows.
    pub(super) rows: Range<usize>,
    /// Its ends but the outlets (end `k + 1` is item `k`): a pit's point,
    /// or [`EXIT`] and the point an exit leads to. The pits come in place
    /// order.
    pub(super) ends: Vec<u32>,
    /// The ends of its first row, its second and its last (three rows).
    pub(super) kept: Vec<u32>,
    /// The lips between its ends, in its rows and to the next band's first.
    pub(super) lips: Vec<Lip>,
    /// The points of its own rows that end in each of its ends.
    pub(super) sizes: Vec<u32>,
}

impl Band {
    /// The ends of its last row.
    pub(super) fn last_row(&self) -> &[u32] {
        let n = self.kept.len() / 3;
        &self.kept[2 * n..]
    }

    /// The end of point `p` (in its first two rows or its last), in this
    /// band's numbers.
    pub(super) fn end_at(&self, p: usize, n: usize) -> u32 {
        let (y, x) = (p / n, p % n);
        let row = if y == self.rows.start {
            0
        } else if y == self.rows.start + 1 {
            1
        } else {
            assert_eq!(y + 1, self.rows.end, "an exit to a row not kept");
            2
        };
        self.kept[row * n + x]
    }
}

/// Finds the ends of rows `rows` of `heights` (`n` a side) and the lips
/// between them, following the ways in `ways` (reused from band to band).
/// `above` is the last row of the band above, in its numbers, if it is
/// known: the exits to one of its ends are then one exit (or none, where
/// that end is the outlets), so the lips do not part the points of one
/// basin along the band's first row. If `raise`, the ways are those of the
/// field with its pits of one point raised (see [`super::raised`]).
pub(super) fn band(
    heights: &[f32],
    n: usize,
    rows: Range<usize>,
    (above, raise): (Option<&[u32]>, bool),
    ways: &mut Vec<u32>,
) -> Band {
    // The next band's first row, if there is one.
    let last = rows.end.min(n - 1);
    ways.clear();
    ways.resize((last + 1 - rows.start) * n, OUTLET);
    let raised = Raised::new(heights, n, raise);
    let mut ends = first_steps(raised, n, rows.start..last + 1, above, ways);
    settle(ways, rows.start * n);
    let at = |y: usize| &ways[(y - rows.start) * n..(y - rows.start + 1) * n];
    let kept = [at(rows.start), at(rows.start + 1), at(rows.end - 1)].concat();
    let lip_rows = rows.start..rows.end.min(n - 1);
    let (mut lips, sizes) = lips_in(heights, n, ways, rows.start, lip_rows, ends.len() + 1);
    spanning(&mut lips, ends.len() + 1);
    ends.shrink_to_fit();
    Band {
        rows,
        ends,
        kept,
        lips,
        sizes,
    }
}

/// Per point of `rows` (the band's and the next band's first row, `ways`
/// from its first point on), where its water goes first: [`ON_THE_WAY`]
/// to its lowest lower neighbour (the first of equals in
/// [`super::grid::Grid::around`]'s order), [`OUTLET`] on the border, in the
/// sea or beside the sea or a point without data, or its end's number if
/// it is a pit or an exit. Each row once the next is known is taken one
/// pass of [`settle`] further while it is in the cache: the passes then
/// start against place order. Returns the ends.
fn first_steps(
    mut heights: Raised,
    n: usize,
    rows: Range<usize>,
    above: Option<&[u32]>,
    ways: &mut [u32],
) -> Vec<u32> {
    let mut ends = Vec::new();
    let first = rows.start * n;
    // The band's own rows end before the last unless it is the field's.
    let own = if rows.end == n { n } else { rows.end - 1 };
    let mut given = Given::new(n, above);
    for y in rows.clone() {
        let r = y - rows.start;
        let row_out = &mut ways[r * n..(r + 1) * n];
        if y > 0 && y + 1 < n {
            let plain = heights.plain(y);
            ways_of_row(heights.around(y), plain, row_out, y * n);
            row_out[0] = OUTLET;
            row_out[n - 1] = OUTLET;
            if y < own {
                pits_of_row(row_out, y * n, &mut ends);
            }
            if y == rows.start {
                given.leave(row_out, y * n, |_, to| to < first, &mut ends);
            }
            if y >= own {
                let below = rows.end * n;
                given.leave(row_out, y * n, |i, to| to >= below || to == i, &mut ends);
            }
        }
        if r >= 2 {
            follow_row(ways, first, (r - 1) * n..r * n);
        }
    }
    ends
}

/// The exits of a band so far, by where they lead: one for each end of the
/// band above (or point of the row above, where its ends are not known),
/// each point of the row below the band, and each pit of the next band's
/// row. Points that lead to one place share its exit.
struct Given<'a> {
    /// The last row of the band above, in its numbers, if known.
    above: Option<&'a [u32]>,
    /// Per place, its exit's end number (0 until it has one).
    exit: Vec<u32>,
    n: usize,
}

impl<'a> Given<'a> {
    fn new(n: usize, above: Option<&'a [u32]>) -> Self {
        let up = above.map_or(n, |a| a.iter().max().map_or(1, |&e| e as usize + 1));
        Given {
            above,
            exit: vec![0; up + 2 * n],
            n,
        }
    }

    /// The place in [`Given::exit`] of a way from point `i` to point `to`
    /// outside the band (the row above `i`'s, the row below, or `i`
    /// itself), or `None` where that point's water is known to reach the
    /// outlets.
    fn place(&self, i: usize, to: usize) -> Option<usize> {
        let (n, x) = (self.n, to % self.n);
        if to + n / 2 < i {
            return match self.above {
                Some(above) => (above[x] != OUTLET).then_some(above[x] as usize),
                None => Some(x),
            };
        }
        let up = self.exit.len() - 2 * n;
        Some(up + x + n * usize::from(to == i))
    }

    /// Turns the ways of `row` (from point `first` on) that lead `outside`
    /// the band into exits (or into the outlets), numbering new exits on
    /// as `ends` lists them.
    fn leave(
        &mut self,
        row: &mut [u32],
        first: usize,
        outside: impl Fn(usize, usize) -> bool,
        ends: &mut Vec<u32>,
    ) {
        for (x, v) in row.iter_mut().enumerate() {
            if *v & ON_THE_WAY == 0 {
                continue;
            }
            let (i, to) = (first + x, (*v & !ON_THE_WAY) as usize);
            if !outside(i, to) {
                continue;
            }
            *v = match self.place(i, to) {
                None => OUTLET,
                Some(place) => {
                    if self.exit[place] == 0 {
                        ends.push(EXIT | to as u32);
                        self.exit[place] = ends.len() as u32;
                    }
                    self.exit[place]
                }
            };
        }
    }
}

/// Numbers the points of `ways` (a row from point `first` on) whose way
/// leads to themselves, pits, on as `ends` lists them. Eight at a time
/// first: pits are few.
fn pits_of_row(ways: &mut [u32], first: usize, ends: &mut Vec<u32>) {
    for (k, eight) in ways.chunks_mut(8).enumerate() {
        let me = |x: usize| ON_THE_WAY | (first + k * 8 + x) as u32;
        let any = eight
            .iter()
            .enumerate()
            .fold(false, |a, (x, &w)| a | (w == me(x)));
        if any {
            for (x, w) in eight.iter_mut().enumerate() {
                if *w == me(x) {
                    ends.push(me(x) & !ON_THE_WAY);
                    *w = ends.len() as u32;
                }
            }
        }
    }
}

/// Follows the ways of `ways` (the band, from point `first` on) until each
/// holds its end. Each pass replaces a point's way by what the point it
/// leads to holds: that point's end, or a point further down. The passes
/// go against place order and in it in turn (the first in place order is
/// taken in [`first_steps`]), so a way that runs with the pass is followed
/// to its end at once; and any way at least halves in a pass. After the
/// first, a pass looks only at the points not settled yet: a point once
/// settled never changes, so the passes do the same as over the whole band.
fn settle(ways: &mut [u32], first: usize) {
    // Most points settle in the first pass (about one in eight is still on
    // its way after the first steps, one in a hundred after this pass): a
    // plain loop, with no list grown for the settled.
    let mut left = Vec::new();
    for i in (0..ways.len()).rev() {
        if ways[i] & ON_THE_WAY != 0 && step(ways, i, first) {
            left.push(i as u32);
        }
    }
    // `left` is against place order; each pass goes the other way.
    while !left.is_empty() {
        left.reverse();
        left.retain(|&i| step(ways, i as usize, first));
    }
}

/// Takes point `i`'s way one step on (see [`settle`]); whether it is still
/// on its way.
#[inline]
fn step(ways: &mut [u32], i: usize, first: usize) -> bool {
    let v = ways[i];
    if v & ON_THE_WAY == 0 {
        return false;
    }
    let w = ways[(v & !ON_THE_WAY) as usize - first];
    ways[i] = w;
    w & ON_THE_WAY != 0
}

/// One pass of [`settle`] in place order over points `row` of `ways`, the
/// band from point `first` on, whose rows beside `row` are known.
fn follow_row(ways: &mut [u32], first: usize, row: Range<usize>) {
    for i in row {
        let v = ways[i];
        if v & ON_THE_WAY != 0 {
            ways[i] = ways[(v & !ON_THE_WAY) as usize - first];
        }
    }
}

/// [`first_steps`] of the points of `row` off the border, the row's first
/// point being point `first` of the field; branch-free (the compiler keeps
/// it in vector registers). A point raised above its height in `plain`
/// (the field's row) goes to its lowest neighbour.
fn ways_of_row(rows: [&[f32]; 3], plain: &[f32], out: &mut [u32], first: usize) {
    super::wide::wide(
        #[inline(always)]
        || ways_of_row_here(rows, plain, out, first),
    );
}

/// [`ways_of_row`], for whichever vector registers it is compiled for.
#[inline(always)]
fn ways_of_row_here(
    [above, row, below]: [&[f32]; 3],
    plain: &[f32],
    out: &mut [u32],
    first: usize,
) {
    let n = row.len();
    let around = [
        &above[..n - 2],
        &above[1..n - 1],
        &above[2..],
        &row[..n - 2],
        &row[2..],
        &below[..n - 2],
        &below[1..n - 1],
        &below[2..],
    ];
    let w = n as i32;
    let offsets = [-w - 1, -w, -w + 1, -1, 1, w - 1, w, w + 1];
    for x in 0..n - 2 {
        let h = row[x + 1];
        let raised = h > plain[x + 1];
        let low = if raised { f32::INFINITY } else { h };
        let (mut low, mut to, mut out_of) = (low, 0, !land(h));
        for (side, offset) in around.iter().zip(offsets) {
            let hk = side[x];
            out_of |= !land(hk);
            let lower = hk < low;
            low = if lower { hk } else { low };
            to = if lower { offset } else { to };
        }
        let way = ON_THE_WAY | ((first + x + 1) as u32).wrapping_add_signed(to);
        out[x + 1] = if out_of { OUTLET } else { way };
    }
}

/// Keeps only the lips of the band's lowest spanning forest, lowest first:
/// a lip that closes a ring of lower (or equal) lips in the band is never
/// the one water first crosses, as the ring's others join its two sides at
/// no greater height; in the field they still do (the band's ends are
/// parts of the field's basins). The field's lips are most of the memory
/// its lakes take; this keeps at most one for each end.
fn spanning(lips: &mut Vec<Lip>, count: usize) {
    lips.sort_unstable_by_key(|l| l.0);
    let mut parent: Vec<u32> = (0..count as u32).collect();
    lips.retain(|&(_, a, b)| {
        let (ra, rb) = (root(&mut parent, a), root(&mut parent, b));
        parent[rb as usize] = ra;
        ra != rb
    });
    lips.shrink_to_fit();
}

/// The root of `x`'s tree in `parent`, halving the way to it.
fn root(parent: &mut [u32], mut x: u32) -> u32 {
    while parent[x as usize] != x {
        let up = parent[parent[x as usize] as usize];
        parent[x as usize] = up;
        x = up;
    }
    x
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Three rows of `n` heights in a few steps (ties), with sea, no data
    /// and a raised point or two.
    fn rows(n: usize, seed: u64) -> Vec<Vec<f32>> {
        (0..4)
            .map(|r| {
                (0..n as u64)
                    .map(|x| {
                        let h = crate::terrain::splitmix::mix(seed ^ (r * 1000 + x));
                        match h % 23 {
                            0 => f32::NAN,
                            1 => 0.0,
                            k => (k % 7) as f32,
                        }
                    })
                    .collect()
            })
            .collect()
    }

    #[test]
    fn wide_registers_find_the_same_first_steps() {
        for seed in 0..20 {
            let n = 37 + seed as usize;
            let r = rows(n, seed);
            // The fourth row stands for the middle one's field heights:
            // where it is lower, the middle point counts as raised.
            let plain: Vec<f32> = r[1].iter().zip(&r[3]).map(|(a, b)| a.min(*b)).collect();
            let (mut wide, mut narrow) = (vec![0; n], vec![0; n]);
            let three = [r[0].as_slice(), &r[1], &r[2]];
            ways_of_row(three, &plain, &mut wide, 5 * n);
            ways_of_row_here(three, &plain, &mut narrow, 5 * n);
            assert_eq!(wide, narrow, "seed {seed}");
        }
    }
}
