//! The pits whose water is settled near them, before it rises everywhere.
//!
//! Most pits of a fractal mountain are small hollows on its slopes: their
//! water rises a little, spills over a lip, maybe fills a hollow or two
//! below, and runs off to the sea. Each pit's water is found here near the
//! pit, in the cache, instead of in the rising water's one height order
//! over the whole field (see [`super::rise`]), where every point taken
//! waits on memory.
//!
//! From a pit the water is flooded lowest point first (height, then index,
//! the rising water's own order), through whatever hollows lie below the
//! highest point taken so far, until a point is taken from which water
//! leaves: over the border, into the sea, beside water already settled, or
//! down a lower point known to stay dry (its water only falls, to one of
//! those). The highest point taken is then the least height the pit's
//! water must rise to before it can leave: its level, exactly as the
//! rising water finds it. Its lake is every point taken joined to the pit
//! below that level; they are written down as drained water (wet and
//! marked, as the rising water writes them), and the pits among them leave
//! the list.
//!
//! A pit is left to the rising water, untouched, where the rising water's
//! order among equal heights would decide (a point at the level beside the
//! lake may join it or not), and where the flood grows past a share of the
//! field ([`MOST_SHARE`]). The rising water then meets a settled lake as it
//! would have met it: every point beside the lake stands above its level,
//! so it reaches the lake only once the lake has drained.

use std::cmp::Reverse;
use std::collections::BinaryHeap;

use super::bits::Bits;
use super::grid::{Grid, land};
use super::open::entry;

/// Most points a flood here takes, as a share of the field's: a larger
/// lake is left to the rising water.
const MOST_SHARE: usize = 8;

/// Most points of a field settled here: a 4097 grid's memory has room for
/// the rising water's bits but not for these beside them (its pits are all
/// left to the rising water, as they were before).
pub(super) const MOST_POINTS: usize = 1 << 23;

/// Settles the water of the pits of `pits` (lowest first) where it can be
/// found near them: their lakes' points set in `wet` and `mark`, each lake
/// of at least `least` points given to `found` with its level, and the
/// pits under them taken out of `pits`.
pub(super) fn settle(
    heights: &[f32],
    n: usize,
    pits: &mut Vec<u32>,
    (wet, mark): (&mut Bits, &mut Bits),
    least: usize,
    found: &mut impl FnMut(f32, &mut [u32]),
) {
    let mut s = Settle {
        heights,
        grid: Grid::new(n),
        wet,
        mark,
        dry: Bits::new(heights.len()),
        sunk: Bits::new(heights.len()),
        sunk_list: Vec::new(),
        most: heights.len() / MOST_SHARE,
        tried: Bits::new(heights.len()),
        seen: Vec::new(),
        edge: Vec::new(),
        open: BinaryHeap::new(),
        path: Vec::new(),
    };
    let mut lake = Vec::new();
    for &pit in pits.iter() {
        if s.wet.get(pit as usize) || s.tried.get(pit as usize) {
            continue;
        }
        let level = s.flood(pit as usize);
        for &i in &s.sunk_list {
            s.sunk.clear(i as usize);
        }
        s.sunk_list.clear();
        for &i in &s.edge {
            s.mark.clear(i as usize);
        }
        if let Some(level) = level {
            s.lake(pit as usize, level, &mut lake);
        }
        for &i in &s.seen {
            if !s.mark.get(i as usize) {
                s.wet.clear(i as usize);
                if level.is_none() {
                    s.tried.set(i as usize);
                }
            }
        }
        if let Some(level) = level.filter(|_| lake.len() >= least) {
            found(level, &mut lake);
        }
        lake.clear();
    }
    let wet = &*s.wet;
    pits.retain(|&p| !wet.get(p as usize));
}

/// The state of the settling.
struct Settle<'a> {
    heights: &'a [f32],
    grid: Grid,
    /// The points the running flood has taken (wet, not marked), and the
    /// settled lakes (wet and marked).
    wet: &'a mut Bits,
    /// Points waiting at the running flood's edge (marked, not wet).
    mark: &'a mut Bits,
    /// Points known to fall to the border, the sea or settled water.
    dry: Bits,
    /// Points whose water falls into a pit or into the running flood, for
    /// the running flood only (a pit's water may settle later), and the
    /// list of them to clear.
    sunk: Bits,
    sunk_list: Vec<u32>,
    /// Most points a flood takes.
    most: usize,
    /// Points a flood that was given up took: a flood that reaches one
    /// is given up too (it would only grow into the same water).
    tried: Bits,
    /// The points the flood has taken (wet while it runs).
    seen: Vec<u32>,
    /// The points it has waiting (marked while it runs).
    edge: Vec<u32>,
    open: BinaryHeap<Reverse<u64>>,
    path: Vec<u32>,
}

impl Settle<'_> {
    /// Floods from `pit`, lowest point first, until the water finds a
    /// way out: the level it leaves at (the highest point taken), or
    /// `None` where the flood's order among equal heights would decide or
    /// the flood grows past its most points. The points taken are listed
    /// in `seen` (wet), those waiting in `edge` (marked).
    fn flood(&mut self, pit: usize) -> Option<f32> {
        self.seen.clear();
        self.edge.clear();
        self.open.clear();
        self.wait(pit);
        let mut level = f32::NEG_INFINITY;
        // A height taken twice as the highest so far (the first flood's
        // order among them decides which of the two drains, if that
        // height is the level).
        let mut tied = f32::NAN;
        while let Some(Reverse(e)) = self.open.pop() {
            let i = e as u32 as usize;
            let h = self.heights[i];
            if self.seen.len() >= self.most || self.tried.get(i) {
                return None;
            }
            if h == level {
                tied = level;
            }
            level = level.max(h);
            self.mark.clear(i);
            self.wet.set(i);
            self.seen.push(i as u32);
            if self.leaves(i, h) {
                // Water at the level waiting beside the lake would join it
                // or not by the flood's order among equal heights.
                let (heights, mark) = (self.heights, &*self.mark);
                let tie = tied == level
                    || (self.edge.iter())
                        .any(|&k| heights[k as usize] == level && mark.get(k as usize));
                return (i != pit && !tie).then_some(level);
            }
            let (around, count) = self.grid.neighbours(i);
            for &k in &around[..count] {
                if !self.wet.get(k) && !self.mark.get(k) {
                    self.wait(k);
                }
            }
        }
        None
    }

    /// Whether water at point `i` (of height `h`) leaves the field or
    /// reaches settled water from there: over the border, into the sea,
    /// beside settled water, or down a lower point whose water only falls.
    fn leaves(&mut self, i: usize, h: f32) -> bool {
        let (around, count) = self.grid.neighbours(i);
        if count < 8 {
            return true;
        }
        let mut lower = ([0usize; 8], 0);
        for &k in &around {
            let hk = self.heights[k];
            if !land(hk) || (self.wet.get(k) && self.mark.get(k)) {
                return true;
            }
            if hk < h && !self.wet.get(k) && !self.mark.get(k) {
                lower.0[lower.1] = k;
                lower.1 += 1;
            }
        }
        lower.0[..lower.1].iter().any(|&k| self.falls(k))
    }

    /// Writes down the lake of `pit` at `level` as settled water: the
    /// points taken joined to the pit below the level (wet and marked),
    /// listed in `lake`.
    fn lake(&mut self, pit: usize, level: f32, lake: &mut Vec<u32>) {
        self.mark.set(pit);
        lake.push(pit as u32);
        let mut at = 0;
        while let Some(&p) = lake.get(at) {
            at += 1;
            let (around, count) = self.grid.neighbours(p as usize);
            for &k in &around[..count] {
                if self.wet.get(k) && !self.mark.get(k) && self.heights[k] < level {
                    self.mark.set(k);
                    lake.push(k as u32);
                }
            }
        }
    }

    /// Puts point `i` at the flood's edge.
    fn wait(&mut self, i: usize) {
        self.mark.set(i);
        self.edge.push(i as u32);
        self.open.push(Reverse(entry(self.heights, i as u32)));
    }

    /// Whether the water at `start` (beside the flood, lower than the point
    /// taken) only falls from there to the border, the sea or settled
    /// water: then it never stands there, and the flood's water leaves
    /// over it. The points walked are written down in `dry`, or else in
    /// `sunk`.
    fn falls(&mut self, start: usize) -> bool {
        self.path.clear();
        let mut at = start;
        let falls = loop {
            if self.dry.get(at) {
                break true;
            }
            if self.sunk.get(at) {
                break false;
            }
            self.path.push(at as u32);
            let (around, count) = self.grid.neighbours(at);
            if count < 8 || self.path.len() > self.grid.n() {
                break count < 8;
            }
            let lowest = around
                .into_iter()
                .min_by(|&a, &b| self.heights[a].total_cmp(&self.heights[b]))
                .expect("eight neighbours");
            let hl = self.heights[lowest];
            if !land(hl) {
                break true;
            }
            if hl >= self.heights[at] {
                break false;
            }
            if self.wet.get(lowest) {
                // Settled water (marked) lies lower than this point, which
                // stands at its edge, so at or above its level: the water
                // here falls into a lake that has drained. Water of the
                // flood still running (not marked) is no way out.
                break self.mark.get(lowest);
            }
            at = lowest;
        };
        let known = if falls { &mut self.dry } else { &mut self.sunk };
        for &p in &self.path {
            known.set(p as usize);
        }
        if !falls {
            self.sunk_list.extend_from_slice(&self.path);
        }
        falls
    }
}
