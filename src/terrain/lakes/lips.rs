//! The lips between basins: where two neighbouring points drain to
//! different ends, the higher of the two is a height the water of either
//! can cross at; the lowest such height for each pair of ends is their lip.

use std::ops::Range;

/// A lip between two ends: the bits of its height (a positive float's
/// bits order as the float does), and the two ends.
pub(super) type Lip = (u32, u32, u32);

/// The lips between the ends in `ends` (rows from `first_row` on) of the
/// points of rows `rows` and their neighbours to the right and below: for
/// each pair of ends that touch, at least their lowest (a few more where
/// the pairs alternate; the extra ones are higher and change no level),
/// unsorted; and the rows' points that end in each of the `count` ends.
/// Each row's points are compared with those neighbours branch-free first,
/// and only the few on an end's edge are looked at again; where an end's
/// run along the row ends, its points are counted.
pub(super) fn lips_in(
    heights: &[f32],
    n: usize,
    ends: &[u32],
    first_row: usize,
    rows: Range<usize>,
    count: usize,
) -> (Vec<Lip>, Vec<u32>) {
    let mut lips = Lips::new();
    let mut sizes = vec![0; count];
    let mut edges = vec![0u8; n];
    let offsets = [1, n - 1, n, n + 1];
    let first = first_row * n;
    for y in rows {
        let at = |y: usize| &ends[(y - first_row) * n..(y - first_row + 1) * n];
        edges_of_row(at(y), at(y + 1), &mut edges);
        let start = (y - first_row) * n;
        let mut run = start;
        for (x0, chunk) in edges.chunks(8).enumerate() {
            let mut word = [0u8; 8];
            word[..chunk.len()].copy_from_slice(chunk);
            let word = u64::from_le_bytes(word);
            let mut bits = word;
            while bits != 0 {
                let bit = bits.trailing_zeros() as usize;
                let i = start + x0 * 8 + bit / 8;
                let j = i + offsets[bit % 8];
                let h = heights[first + i].max(heights[first + j]);
                lips.add(ends[i], ends[j], h);
                bits &= bits - 1;
            }
            // The runs' ends: bit 0 of each byte (the end to the right is
            // another).
            let mut run_ends = word & 0x0101_0101_0101_0101;
            while run_ends != 0 {
                let end = start + x0 * 8 + run_ends.trailing_zeros() as usize / 8 + 1;
                sizes[ends[run] as usize] += (end - run) as u32;
                run = end;
                run_ends &= run_ends - 1;
            }
        }
        sizes[ends[run] as usize] += (start + n - run) as u32;
    }
    (lips.all(), sizes)
}

/// Per point of row `row` (not the last), bit `d` set where its basin is
/// not that of its neighbour right (0), below left (1), below (2) or
/// below right (3), `below` being the next row's basins.
fn edges_of_row(row: &[u32], below: &[u32], edges: &mut [u8]) {
    super::wide::wide(
        #[inline(always)]
        || edges_of_row_here(row, below, edges),
    );
}

/// [`edges_of_row`], for whichever vector registers it is compiled for.
#[inline(always)]
fn edges_of_row_here(row: &[u32], below: &[u32], edges: &mut [u8]) {
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
/// so most are only compared there. The last pair is kept before it: the
/// edges of one point, and of the next along the row, mostly part the
/// same two (seed 1 at 1025: four in five of the edges).
struct Lips {
    last: (u64, u32),
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
            last: (NO_PAIR, 0),
            recent: vec![(NO_PAIR, 0); 1 << RECENT_BITS],
            out: Vec::new(),
        }
    }

    /// A lip between basins `a` and `b` (not equal) at height `h`.
    #[inline]
    fn add(&mut self, a: u32, b: u32, h: f32) {
        let pair = (u64::from(a.min(b)) << 32) | u64::from(a.max(b));
        let bits = h.to_bits();
        if pair == self.last.0 {
            self.last.1 = self.last.1.min(bits);
            return;
        }
        let (pair, bits) = std::mem::replace(&mut self.last, (pair, bits));
        if pair != NO_PAIR {
            self.keep(pair, bits);
        }
    }

    /// [`Lips::add`] to the table.
    fn keep(&mut self, pair: u64, bits: u32) {
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
        if self.last.0 != NO_PAIR {
            self.keep(self.last.0, self.last.1);
        }
        let kept = self.recent.iter().filter(|k| k.0 != NO_PAIR);
        self.out.extend(kept.copied().map(lip));
        self.out
    }
}
