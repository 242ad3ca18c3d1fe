//! The lakes found from the basins and the lips between them.
//!
//! Every point's water runs down, lowest neighbour after lowest neighbour,
//! to a pit or out of the field (over the border or into the sea): the
//! points that end in one pit are its basin. Water rises in a basin until
//! it spills over the lowest lip to a neighbouring basin, and from basin to
//! basin until it reaches an outlet: a basin's level is the least, over
//! every chain of basins to an outlet, of the highest lip crossed, where
//! the lip between two basins is the lowest pair of neighbouring points,
//! one in each, counted at the higher of the two. A point stands under
//! water where it is lower than its basin's level (the water between it and
//! the pit only falls; see [`super`] for why this is the lowest height it
//! must rise to), and every lake is a set of such points joined together.
//!
//! Each pass reads the field in place order, so the memory it touches is
//! in the cache: the basins in one pass (a walk down from each point not
//! yet in one), the lips in one more; the levels then come from the few
//! lips, lowest first, without the points (Kruskal's joining of the
//! basins, until each joins the outlets).

use std::sync::atomic::AtomicU32;
use std::sync::atomic::Ordering::Relaxed;

use super::bits::Bits;
use super::grid::{Grid, land};

/// Most points of a field whose lakes are found here: a 4097 grid's memory
/// has room for the rising water's bits (see [`super::rise`]) but not for
/// a basin number a point.
pub(super) const MOST_POINTS: usize = 1 << 23;

/// The basin of the outlets: the border and the sea.
const OUTLET: u32 = 0;
/// A point not yet in a basin.
const UNSET: u32 = u32::MAX;

/// Calls `found(level, points)` for each lake of `heights` (`n` a side) of
/// at least `least` points.
pub(super) fn lakes(
    heights: &[f32],
    n: usize,
    least: usize,
    found: &mut impl FnMut(f32, &mut [u32]),
) {
    let (basin, pits) = basins(heights, n);
    let lips = lips(heights, n, &basin);
    drop(basin);
    let levels = levels(lips, pits.len() + 1);
    let grid = Grid::new(n);
    let mut seen = Bits::new(heights.len());
    let mut lake = Vec::new();
    for (&pit, &level) in pits.iter().zip(&levels[1..]) {
        let pit = pit as usize;
        if level <= heights[pit] || seen.get(pit) {
            continue;
        }
        fill(heights, grid, pit, level, &mut seen, &mut lake);
        if lake.len() >= least {
            found(level, &mut lake);
        }
    }
}

/// Every point's basin (the outlets' is [`OUTLET`], pit `k`'s `k + 1`),
/// and the pits, in place order (as their basins are numbered). The two
/// halves of the rows at once, each row by row: the rows above are in
/// their basins by then, so a point whose water goes up a row takes its
/// basin from there at once, and the others are walked down to a point in
/// one. A walk may cross into the other half: both halves then write the
/// same basins there.
fn basins(heights: &[f32], n: usize) -> (Vec<u32>, Vec<u32>) {
    let (steps, pits) = first_steps(heights, n);
    let mut basin = vec![UNSET; heights.len()];
    for (k, &pit) in pits.iter().enumerate() {
        basin[pit as usize] = k as u32 + 1;
    }
    let shared = shared(&mut basin);
    let walk = |rows| walk_rows(shared, &steps, n, rows);
    crate::threads::both(|| walk(0..n / 2), || walk(n / 2..n));
    (basin, pits)
}

/// `basin` for two threads to write at once.
fn shared(basin: &mut [u32]) -> &[AtomicU32] {
    // SAFETY: AtomicU32 has the size, alignment and bit validity of u32,
    // and the exclusive borrow of `basin` is held as long as the result.
    unsafe { &*(std::ptr::from_mut(basin) as *const [AtomicU32]) }
}

/// Puts every point of rows `rows` in its basin (see [`basins`]).
fn walk_rows(basin: &[AtomicU32], steps: &[u8], n: usize, rows: std::ops::Range<usize>) {
    let n = n as isize;
    let offsets = [-n - 1, -n, -n + 1, -1, 1, n - 1, n, n + 1];
    // Where a point's basin is first looked for: the neighbour its water
    // goes to where that was put in its basin before it (up a row, or to
    // the left), else itself (a pit is in its own already).
    let earlier = [-n - 1, -n, -n + 1, -1, 0, 0, 0, 0, 0, 0];
    let get = |i: usize| basin[i].load(Relaxed);
    let mut path = Vec::new();
    for start in rows.start * n as usize..rows.end * n as usize {
        let step = steps[start];
        let b = get(start.wrapping_add_signed(earlier[step as usize]));
        let mut b = if step == OUT { OUTLET } else { b };
        if b == UNSET {
            let mut at = start;
            b = loop {
                let b = get(at);
                if b != UNSET {
                    break b;
                }
                path.push(at as u32);
                match steps[at] {
                    OUT => break OUTLET,
                    d => at = at.wrapping_add_signed(offsets[d as usize]),
                }
            };
            for &p in &path {
                basin[p as usize].store(b, Relaxed);
            }
            path.clear();
        }
        basin[start].store(b, Relaxed);
    }
}

/// The first step of a point's water: out of the field.
const OUT: u8 = 8;
/// The first step of a point's water: nowhere (it is a pit).
const PIT: u8 = 9;

/// Per point, where its water goes first: to its lowest lower neighbour
/// (its place 0-7 in [`Grid::around`]'s order; the first of equals), [`OUT`]
/// (on the border, in the sea, or beside the sea or a point without data)
/// or [`PIT`] (no neighbour lower); and the pits, in place order. The two
/// halves of the rows at once.
fn first_steps(heights: &[f32], n: usize) -> (Vec<u8>, Vec<u32>) {
    let mut steps = vec![OUT; heights.len()];
    let (top, bottom) = steps.split_at_mut(n / 2 * n);
    let rows = |out: &mut [u8], first: usize| {
        let mut pits = Vec::new();
        for (r, row_out) in out.chunks_mut(n).enumerate() {
            let y = first + r;
            if y > 0 && y + 1 < n {
                let at = |y: usize| &heights[y * n..(y + 1) * n];
                steps_of_row([at(y - 1), at(y), at(y + 1)], row_out);
                let pit = |(x, &step)| (step == PIT).then_some((y * n + x) as u32);
                pits.extend(row_out.iter().enumerate().filter_map(pit));
            }
        }
        pits
    };
    let (mut pits, theirs) = crate::threads::both(|| rows(top, 0), || rows(bottom, n / 2));
    pits.extend(theirs);
    (steps, pits)
}

/// [`first_steps`] of the points of `row` off the border, branch-free
/// (the compiler keeps it in vector registers).
fn steps_of_row([above, row, below]: [&[f32]; 3], out: &mut [u8]) {
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
    for x in 0..n - 2 {
        let h = row[x + 1];
        let (mut low, mut step, mut out_of) = (h, i32::from(PIT), !land(h));
        for (d, side) in around.iter().enumerate() {
            let hk = side[x];
            out_of |= !land(hk);
            let lower = hk < low;
            low = if lower { hk } else { low };
            step = if lower { d as i32 } else { step };
        }
        out[x + 1] = if out_of { OUT } else { step as u8 };
    }
}

/// A lip between two basins: the bits of its height (a positive float's
/// bits order as the float does), and the two basins.
type Lip = (u32, u32, u32);

/// The lips between the basins: for each pair of basins that touch, at
/// least their lowest (a few more where the pairs alternate; the extra
/// ones are higher and change no level), in two lists, each lowest first.
/// The two halves of the rows at once.
fn lips(heights: &[f32], n: usize, basin: &[u32]) -> [Vec<Lip>; 2] {
    let half = |rows| {
        let mut lips = lips_in(heights, n, basin, rows);
        lips.sort_unstable_by_key(|l| l.0);
        lips
    };
    let (top, bottom) = crate::threads::both(|| half(0..n / 2), || half(n / 2..n - 1));
    [top, bottom]
}

/// [`lips`] between the points of rows `rows` and their neighbours to the
/// right and below, unsorted. Each row's points are compared with those
/// neighbours branch-free first, and only the few on a basin's edge are
/// looked at again.
fn lips_in(heights: &[f32], n: usize, basin: &[u32], rows: std::ops::Range<usize>) -> Vec<Lip> {
    let mut lips = Lips::new();
    let mut edges = vec![0u8; n];
    let offsets = [1, n - 1, n, n + 1];
    for y in rows {
        let at = |y: usize| &basin[y * n..(y + 1) * n];
        edges_of_row(at(y), at(y + 1), &mut edges);
        for (x0, chunk) in edges.chunks(8).enumerate() {
            let mut word = [0u8; 8];
            word[..chunk.len()].copy_from_slice(chunk);
            let mut bits = u64::from_le_bytes(word);
            while bits != 0 {
                let bit = bits.trailing_zeros() as usize;
                let i = y * n + x0 * 8 + bit / 8;
                let j = i + offsets[bit % 8];
                lips.add(basin[i], basin[j], heights[i].max(heights[j]));
                bits &= bits - 1;
            }
        }
    }
    lips.all()
}

/// Per point of row `row` (not the last), bit `d` set where its basin is
/// not that of its neighbour right (0), below left (1), below (2) or
/// below right (3), `below` being the next row's basins.
fn edges_of_row(row: &[u32], below: &[u32], edges: &mut [u8]) {
    let n = row.len();
    for x in 1..n - 1 {
        let a = row[x];
        edges[x] = u8::from(a != row[x + 1])
            | u8::from(a != below[x - 1]) << 1
            | u8::from(a != below[x]) << 2
            | u8::from(a != below[x + 1]) << 3;
    }
    let (first, last) = (row[0], row[n - 1]);
    edges[0] = u8::from(first != row[1])
        | u8::from(first != below[0]) << 2
        | u8::from(first != below[1]) << 3;
    edges[n - 1] = u8::from(last != below[n - 2]) << 1 | u8::from(last != below[n - 1]) << 2;
}

/// The lips found so far, the lowest of each recent pair of basins kept
/// in a small table: neighbouring points mostly pair the same two basins,
/// so most are only compared there.
struct Lips {
    recent: Vec<(u64, u32)>,
    out: Vec<Lip>,
}

/// The lip of a recent table's slot.
fn lip((pair, bits): (u64, u32)) -> Lip {
    (bits, (pair >> 32) as u32, pair as u32)
}

/// Bits of the recent table's slot index.
const RECENT_BITS: u32 = 12;
/// An empty slot of the recent table.
const NO_PAIR: u64 = u64::MAX;

impl Lips {
    fn new() -> Self {
        Lips {
            recent: vec![(NO_PAIR, 0); 1 << RECENT_BITS],
            out: Vec::new(),
        }
    }

    /// A lip between basins `a` and `b` (not equal) at height `h`.
    #[inline]
    fn add(&mut self, a: u32, b: u32, h: f32) {
        let pair = (u64::from(a.min(b)) << 32) | u64::from(a.max(b));
        let bits = h.to_bits();
        let slot = (pair.wrapping_mul(0x9E37_79B9_7F4A_7C15) >> (64 - RECENT_BITS)) as usize;
        let kept = &mut self.recent[slot];
        if kept.0 == pair {
            kept.1 = kept.1.min(bits);
            return;
        }
        if kept.0 != NO_PAIR {
            self.out.push(lip(*kept));
        }
        *kept = (pair, bits);
    }

    /// Every lip kept.
    fn all(mut self) -> Vec<Lip> {
        let kept = self.recent.iter().filter(|k| k.0 != NO_PAIR);
        self.out.extend(kept.copied().map(lip));
        self.out
    }
}

/// Each of `count` basins' level: the height at which its water first
/// reaches the outlets' basin ([`OUTLET`], whose own level is -inf),
/// joining the basins over their lips, lowest first, until every basin
/// has.
fn levels([top, bottom]: [Vec<Lip>; 2], count: usize) -> Vec<f32> {
    let mut levels = vec![f32::NAN; count];
    levels[OUTLET as usize] = f32::NEG_INFINITY;
    let mut left = count - 1;
    let mut sets = Sets::new(count);
    for (bits, a, b) in lowest_first(top, bottom) {
        if left == 0 {
            break;
        }
        let (ra, rb) = (sets.find(a), sets.find(b));
        if ra == rb {
            continue;
        }
        let out = sets.find(OUTLET);
        if ra == out || rb == out {
            for m in sets.members(if ra == out { rb } else { ra }) {
                levels[m as usize] = f32::from_bits(bits);
                left -= 1;
            }
        }
        sets.join(ra, rb);
    }
    levels
}

/// The lips of two lists, each lowest first, lowest first.
fn lowest_first(a: Vec<Lip>, b: Vec<Lip>) -> impl Iterator<Item = Lip> {
    let (mut a, mut b) = (a.into_iter().peekable(), b.into_iter().peekable());
    std::iter::from_fn(move || match (a.peek(), b.peek()) {
        (Some(x), Some(y)) if y.0 < x.0 => b.next(),
        _ => a.next().or_else(|| b.next()),
    })
}

/// Basins joined into sets, each set's members listed.
struct Sets {
    parent: Vec<u32>,
    /// Per member, the next of its set (itself at the end).
    next: Vec<u32>,
    /// Per set (at its root), its last member.
    last: Vec<u32>,
}

impl Sets {
    fn new(count: usize) -> Self {
        let all: Vec<u32> = (0..count as u32).collect();
        Sets {
            parent: all.clone(),
            next: all.clone(),
            last: all,
        }
    }

    fn find(&mut self, mut x: u32) -> u32 {
        while self.parent[x as usize] != x {
            let up = self.parent[self.parent[x as usize] as usize];
            self.parent[x as usize] = up;
            x = up;
        }
        x
    }

    /// The members of the set whose root is `root`.
    fn members(&self, root: u32) -> impl Iterator<Item = u32> + '_ {
        let mut at = Some(root);
        std::iter::from_fn(move || {
            let m = at?;
            let next = self.next[m as usize];
            at = (next != m).then_some(next);
            Some(m)
        })
    }

    /// Joins the sets of roots `a` and `b` (`a` stays the root).
    fn join(&mut self, a: u32, b: u32) {
        let (a, b) = (a as usize, b as usize);
        self.parent[b] = a as u32;
        let tail = self.last[a] as usize;
        self.next[tail] = b as u32;
        self.last[a] = self.last[b];
    }
}

/// Lists in `lake` the points joined to `pit` below `level`, and marks
/// them in `seen`.
fn fill(heights: &[f32], grid: Grid, pit: usize, level: f32, seen: &mut Bits, lake: &mut Vec<u32>) {
    lake.clear();
    seen.set(pit);
    lake.push(pit as u32);
    let mut at = 0;
    while let Some(&p) = lake.get(at) {
        at += 1;
        let (around, count) = grid.neighbours(p as usize);
        for &k in &around[..count] {
            if !seen.get(k) && heights[k] < level {
                seen.set(k);
                lake.push(k as u32);
            }
        }
    }
}
