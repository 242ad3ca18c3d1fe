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
//! The basins and lips are found a band of rows at a time, on both cores
//! ([`super::bands`]): each point's way down is followed a pass at a time
//! over the band, with and against place order, a way at least halving in
//! each, in memory the size of the band that stays in the cache; where a
//! way leaves the band, it is followed on in the band it leads to once all
//! are done. The lips are found in one more pass over each band, counting
//! each basin's points as it goes; the levels then come from the few
//! lips, lowest first, without the points (Kruskal's joining of the
//! basins, until each joins the outlets), and the lakes are filled a row's
//! run at a time, only from basins with room for one. Nothing is kept a
//! point but a bit (the points filled).

use super::band::OUTLET;
use super::bands::basins;
use super::fill::Filler;
use super::lips::Lip;

/// Most points of a field whose lakes are found here; a 4097 grid's are
/// found by the rising water (see [`super::rise`]), whose two bits a point
/// are less than the bands' lips and kept rows there.
pub(super) const MOST_POINTS: usize = 1 << 23;

/// Calls `found(level, points)` for each lake of `heights` (`n` a side) of
/// at least `least` points, the basins found in bands of `rows` rows.
pub(super) fn lakes(
    heights: &[f32],
    n: usize,
    least: usize,
    rows: usize,
    found: &mut impl FnMut(f32, &mut [u32]),
) {
    // A pit of one point raised loses only a lake of one point.
    let (pits, lips, sizes) = basins(heights, n, rows, least > 1);
    let levels = levels(lips, &sizes);
    let mut filler = Filler::new(heights, n);
    let mut lake = Vec::new();
    for (&pit, &(level, room)) in pits.iter().zip(&levels[1..]) {
        let pit = pit as usize;
        if room < least || level <= heights[pit] || filler.seen(pit) {
            continue;
        }
        if filler.fill(pit, level) >= least {
            filler.points(&mut lake);
            found(level, &mut lake);
        }
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
