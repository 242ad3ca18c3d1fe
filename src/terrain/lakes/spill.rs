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
//! Each pass reads the field in order, so the memory it touches is in the
//! cache: the basins in a few (each point's way down is followed a pass at
//! a time, with and against place order, a way at least halving in each:
//! no pass waits on a walk down), the lips in one more, counting each
//! basin's points as it goes; the levels then come from the few lips,
//! lowest first, without the points (Kruskal's joining of the basins,
//! until each joins the outlets), and the lakes are filled a row's run at
//! a time, only from basins with room for one.

use std::sync::atomic::AtomicU32;
use std::sync::atomic::Ordering::Relaxed;

use super::bits::Bits;
use super::grid::land;

/// Most points of a field whose lakes are found here: a 4097 grid's memory
/// has room for the rising water's bits (see [`super::rise`]) but not for
/// a basin number a point.
pub(super) const MOST_POINTS: usize = 1 << 23;

/// The basin of the outlets: the border and the sea.
const OUTLET: u32 = 0;

/// Calls `found(level, points)` for each lake of `heights` (`n` a side) of
/// at least `least` points.
pub(super) fn lakes(
    heights: &[f32],
    n: usize,
    least: usize,
    found: &mut impl FnMut(f32, &mut [u32]),
) {
    let (basin, pits) = basins(heights, n);
    let (lips, sizes) = lips(heights, n, &basin, pits.len() + 1);
    drop(basin);
    let levels = levels(lips, &sizes);
    let mut seen = Bits::new(heights.len());
    let mut lake = Vec::new();
    for (&pit, &(level, room)) in pits.iter().zip(&levels[1..]) {
        let pit = pit as usize;
        if room < least || level <= heights[pit] || seen.get(pit) {
            continue;
        }
        fill(heights, n, pit, level, &mut seen, &mut lake);
        if lake.len() >= least {
            found(level, &mut lake);
        }
    }
}

/// Every point's basin (the outlets' is [`OUTLET`], pit `k`'s `k + 1`),
/// and the pits, in place order (as their basins are numbered). The two
/// halves of the rows at once, each settling its points' ways (see
/// [`settle`]); a way may lead into the other half, whose points then
/// hold a point further down it or their basin: either leads on to the
/// same basin, whenever it is read.
fn basins(heights: &[f32], n: usize) -> (Vec<u32>, Vec<u32>) {
    let (mut basin, pits) = first_steps(heights, n);
    for (k, &pit) in pits.iter().enumerate() {
        basin[pit as usize] = k as u32 + 1;
    }
    let shared = shared(&mut basin);
    let half = n / 2 * n;
    crate::threads::both(
        || settle(shared, 0..half),
        || settle(shared, half..shared.len()),
    );
    (basin, pits)
}

/// `basin` for two threads to write at once.
fn shared(basin: &mut [u32]) -> &[AtomicU32] {
    // SAFETY: AtomicU32 has the size, alignment and bit validity of u32,
    // and the exclusive borrow of `basin` is held as long as the result.
    unsafe { &*(std::ptr::from_mut(basin) as *const [AtomicU32]) }
}

/// Marks a value of `basin` as the place of a point further down the
/// water's way (in the other bits), its basin not yet known.
const ON_THE_WAY: u32 = 1 << 31;

/// Follows the ways of points `range` until each holds its basin. Each
/// pass replaces a point's way by what the point it leads to holds: that
/// point's basin, or a point further down. The passes go against place
/// order and in it in turn (the first in place order is taken in
/// [`first_steps`]), so a way that runs with the pass is followed to
/// its end at once; and any way at least halves in a pass.
fn settle(basin: &[AtomicU32], range: std::ops::Range<usize>) {
    let get = |i: usize| basin[i].load(Relaxed);
    let mut forward = false;
    loop {
        let mut left = false;
        let mut pass = |i: usize| {
            let v = get(i);
            if v & ON_THE_WAY != 0 {
                let w = get((v & !ON_THE_WAY) as usize);
                basin[i].store(w, Relaxed);
                left |= w & ON_THE_WAY != 0;
            }
        };
        if forward {
            range.clone().for_each(&mut pass);
        } else {
            range.clone().rev().for_each(&mut pass);
        }
        if !left {
            return;
        }
        forward = !forward;
    }
}

/// Per point, where its water goes first: [`ON_THE_WAY`] to its lowest
/// lower neighbour (the first of equals in [`Grid::around`]'s order), to
/// itself if it has none (a pit), or straight into the outlets' basin
/// [`OUTLET`] (on the border, in the sea, or beside the sea or a point
/// without data); and the pits, in place order. The two halves of the
/// rows at once. Each row once the next is known is taken one pass of
/// [`settle`] further while it is in the cache: the passes then start
/// against place order.
fn first_steps(heights: &[f32], n: usize) -> (Vec<u32>, Vec<u32>) {
    let mut ways = vec![OUTLET; heights.len()];
    let (top, bottom) = ways.split_at_mut(n / 2 * n);
    let rows = |out: &mut [u32], first: usize| {
        let mut pits = Vec::new();
        for r in 0..out.len() / n {
            let y = first + r;
            if y > 0 && y + 1 < n {
                let at = |y: usize| &heights[y * n..(y + 1) * n];
                let row_out = &mut out[r * n..(r + 1) * n];
                ways_of_row([at(y - 1), at(y), at(y + 1)], row_out, y * n);
                pits_of_row(row_out, y * n, &mut pits);
            }
            if r >= 2 {
                follow_row(out, first * n, (r - 1) * n..r * n);
            }
        }
        pits
    };
    let (mut pits, theirs) = crate::threads::both(|| rows(top, 0), || rows(bottom, n / 2));
    pits.extend(theirs);
    (ways, pits)
}

/// Adds to `pits` the points of `ways` (a row from point `first` on)
/// whose way leads to themselves. Eight at a time first: pits are few.
fn pits_of_row(ways: &[u32], first: usize, pits: &mut Vec<u32>) {
    for (k, eight) in ways.chunks(8).enumerate() {
        let me = |x: usize| ON_THE_WAY | (first + k * 8 + x) as u32;
        let any = eight
            .iter()
            .enumerate()
            .fold(false, |a, (x, &w)| a | (w == me(x)));
        if any {
            let pit = |(x, &w)| (w == me(x)).then_some(me(x) & !ON_THE_WAY);
            pits.extend(eight.iter().enumerate().filter_map(pit));
        }
    }
}

/// One pass of [`settle`] in place order over points `row` of `ways`, the
/// part of the field from point `first` on, whose rows beside `row` are
/// known.
fn follow_row(ways: &mut [u32], first: usize, row: std::ops::Range<usize>) {
    for i in row {
        let v = ways[i];
        if v & ON_THE_WAY != 0 {
            ways[i] = ways[(v & !ON_THE_WAY) as usize - first];
        }
    }
}

/// [`first_steps`] of the points of `row` off the border, the row's first
/// point being point `first` of the field; branch-free (the compiler keeps
/// it in vector registers).
fn ways_of_row([above, row, below]: [&[f32]; 3], out: &mut [u32], first: usize) {
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
        let (mut low, mut to, mut out_of) = (h, 0, !land(h));
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

/// A lip between two basins: the bits of its height (a positive float's
/// bits order as the float does), and the two basins.
type Lip = (u32, u32, u32);

/// The lips between the basins: for each pair of basins that touch, at
/// least their lowest (a few more where the pairs alternate; the extra
/// ones are higher and change no level), in two lists, each lowest first;
/// and the number of points in each of the `count` basins. The two halves
/// of the rows at once.
fn lips(heights: &[f32], n: usize, basin: &[u32], count: usize) -> ([Vec<Lip>; 2], Vec<u32>) {
    let half = |rows| {
        let (mut lips, sizes) = lips_in(heights, n, basin, rows, count);
        lips.sort_unstable_by_key(|l| l.0);
        (lips, sizes)
    };
    let ((top, mut sizes), (bottom, theirs)) =
        crate::threads::both(|| half(0..n / 2), || half(n / 2..n - 1));
    for (size, their) in sizes.iter_mut().zip(theirs) {
        *size += their;
    }
    ([top, bottom], sizes)
}

/// [`lips`] between the points of rows `rows` and their neighbours to the
/// right and below, unsorted, and the rows' points in each basin. Each
/// row's points are compared with those neighbours branch-free first, and
/// only the few on a basin's edge are looked at again; where a basin's run
/// along the row ends, its points are counted.
fn lips_in(
    heights: &[f32],
    n: usize,
    basin: &[u32],
    rows: std::ops::Range<usize>,
    count: usize,
) -> (Vec<Lip>, Vec<u32>) {
    let mut lips = Lips::new();
    let mut sizes = vec![0; count];
    let mut edges = vec![0u8; n];
    let offsets = [1, n - 1, n, n + 1];
    for y in rows {
        let at = |y: usize| &basin[y * n..(y + 1) * n];
        edges_of_row(at(y), at(y + 1), &mut edges);
        let mut run = y * n;
        for (x0, chunk) in edges.chunks(8).enumerate() {
            let mut word = [0u8; 8];
            word[..chunk.len()].copy_from_slice(chunk);
            let word = u64::from_le_bytes(word);
            let mut bits = word;
            while bits != 0 {
                let bit = bits.trailing_zeros() as usize;
                let i = y * n + x0 * 8 + bit / 8;
                let j = i + offsets[bit % 8];
                lips.add(basin[i], basin[j], heights[i].max(heights[j]));
                bits &= bits - 1;
            }
            // The runs' ends: bit 0 of each byte (the basin to the right
            // is another).
            let mut ends = word & 0x0101_0101_0101_0101;
            while ends != 0 {
                let end = y * n + x0 * 8 + ends.trailing_zeros() as usize / 8 + 1;
                sizes[basin[run] as usize] += (end - run) as u32;
                run = end;
                ends &= ends - 1;
            }
        }
        sizes[basin[run] as usize] += ((y + 1) * n - run) as u32;
    }
    (lips.all(), sizes)
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

/// Each basin's level: the height at which its water first reaches the
/// outlets' basin ([`OUTLET`], whose own level is -inf), joining the
/// basins over their lips, lowest first, until every basin has; and the
/// room its lake has: the points of the basins joined to it then (`sizes`
/// gives each basin's). Its lake lies in them, so one with less room than
/// the least lake need not be looked for.
fn levels([top, bottom]: [Vec<Lip>; 2], sizes: &[u32]) -> Vec<(f32, usize)> {
    let count = sizes.len();
    let mut levels = vec![(f32::NAN, 0); count];
    levels[OUTLET as usize].0 = f32::NEG_INFINITY;
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
            let joined = if ra == out { rb } else { ra };
            let room = sets.members(joined).map(|m| sizes[m as usize] as usize);
            let room = room.sum();
            for m in sets.members(joined) {
                levels[m as usize] = (f32::from_bits(bits), room);
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

/// Lists in `lake` the points joined to `pit` below `level`, in place
/// order, and marks them in `seen`. A run of a row at a time: the whole
/// run of such points a point lies in, then the runs beside it in the rows
/// above and below, from one point left of it to one right of it (lakes
/// join across a cell's diagonals, as the triangles drawn over the cells
/// do); a row is read in order, where a point at a time would read its
/// eight neighbours.
fn fill(heights: &[f32], n: usize, pit: usize, level: f32, seen: &mut Bits, lake: &mut Vec<u32>) {
    let wet = |seen: &Bits, i: usize| !seen.get(i) && heights[i] < level;
    let mut runs = Vec::new();
    let mut todo = vec![pit];
    while let Some(p) = todo.pop() {
        if !wet(seen, p) {
            continue;
        }
        let (y, row) = (p / n, p / n * n);
        let (mut start, mut end) = (p, p + 1);
        while start > row && wet(seen, start - 1) {
            start -= 1;
        }
        while end < row + n && wet(seen, end) {
            end += 1;
        }
        (start..end).for_each(|i| seen.set(i));
        runs.push(start as u32..end as u32);
        let beside = (start - row).saturating_sub(1)..(end - row + 1).min(n);
        for side in [y.wrapping_sub(1), y + 1].into_iter().filter(|&s| s < n) {
            let mut was_wet = false;
            for i in beside.clone().map(|x| side * n + x) {
                let is_wet = wet(seen, i);
                if is_wet && !was_wet {
                    todo.push(i);
                }
                was_wet = is_wet;
            }
        }
    }
    runs.sort_unstable_by_key(|r| r.start);
    lake.clear();
    lake.extend(runs.into_iter().flatten());
}
