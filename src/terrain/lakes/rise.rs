//! The water rising in every basin at once, from the pits up.
//!
//! Every pit starts a region of water. The points around the regions are
//! taken lowest first, over the whole field, so every region's water
//! stands at the height being taken (or lower, if it has drained). A point
//! taken joins the regions it touches (their waters meet there) unless the
//! water finds a way down from it: the border, the sea, a point lower still
//! that no region holds (its water runs off to an outlet or into a region
//! already drained: a region still filling would hold it by now), or a
//! drained region. Then the regions touching it have drained, at its
//! height, which is their lowest lip. Water only rises where a basin is, so
//! the slopes that drain anyway are never taken.
//!
//! Slower than [`super::spill`], it needs less memory: the lakes of the
//! largest fields are found this way.

use super::bits::Bits;
use super::grid::{Grid, land};
use super::labels::Labels;
use super::open::{Open, entry};
use super::pits::pits;

/// Calls `found(level, points)` for each lake of `heights` (`n` a side) of
/// at least `least` points.
pub(super) fn basins(heights: &[f32], n: usize, least: usize, found: impl FnMut(f32, &mut [u32])) {
    let (pits, lo, hi) = pits(heights, n);
    let mut rise = Rise::new(heights, n, (lo, hi), pits);
    // The pits are taken in their turn from their own list, lowest first,
    // beside the queue (a copy of each in the queue would only wait).
    let mut next = 0;
    loop {
        let pit = rise.pits.get(next).map(|&i| entry(heights, i));
        let i = match (pit, rise.open.peek(heights)) {
            (None, None) => break,
            (Some(p), q) if q.is_none_or(|q| p < q) => {
                next += 1;
                p as u32
            }
            _ => rise.open.pop(heights).expect("a point was waiting"),
        };
        let soon = rise.open.front();
        if let Some(j) = soon.or(rise.pits.get(next).copied()) {
            rise.fetch(j as usize);
        }
        rise.take(i as usize);
    }
    rise.lakes(least, found);
}

/// The state of the rising water.
struct Rise<'a> {
    heights: &'a [f32],
    grid: Grid,
    /// Points under a region's water (or at its surface).
    wet: Bits,
    /// For a point not wet: waiting in `open`. For a wet one: its region
    /// has drained.
    mark: Bits,
    open: Open,
    labels: Labels,
    /// The pits, lowest first (ties by index); region `r` starts (if it
    /// does) at pit `r`.
    pits: Vec<u32>,
    /// Per region: the region it joined (itself if none); for a region
    /// marked in `drained`, the bits of the height its water drained at.
    joined: Vec<u32>,
    /// Per region: drained (a region still filling, or one never started
    /// because its pit joined another before its turn, is not).
    drained: Bits,
    /// Per region: whether its pit still waits to queue all its neighbours
    /// (see [`Rise::start`]).
    lazy: Bits,
    /// Scratch for [`Rise::drain`] and [`Rise::lakes`].
    stack: Vec<u32>,
}

impl<'a> Rise<'a> {
    fn new(heights: &'a [f32], n: usize, (lo, hi): (f32, f32), pits: Vec<u32>) -> Self {
        let regions = pits.len();
        Rise {
            heights,
            grid: Grid::new(n),
            wet: Bits::new(heights.len()),
            mark: Bits::new(heights.len()),
            open: Open::new(lo, hi, heights.len()),
            labels: Labels::new(),
            pits,
            joined: (0..regions as u32).collect(),
            drained: Bits::new(regions),
            lazy: Bits::new(regions),
            stack: Vec::new(),
        }
    }

    /// Asks for the rows around point `j` and its bits, which it will
    /// soon be taken.
    #[inline]
    fn fetch(&self, j: usize) {
        let n = self.grid.n();
        for at in [j.wrapping_sub(n + 1), j.wrapping_sub(1), j + n - 1] {
            super::ahead::fetch(self.heights, at);
        }
        super::ahead::fetch(&self.wet.0, j / 64);
        super::ahead::fetch(&self.mark.0, j / 64);
    }

    /// Queues point `i` unless it waits already (or is wet).
    #[inline]
    fn queue(&mut self, i: usize) {
        if !self.mark.get(i) && !self.wet.get(i) {
            self.mark.set(i);
            self.open.push(self.heights[i], i as u32);
        }
    }

    /// The region starting at point `i`, if it is a pit.
    fn pit(&self, i: usize) -> Option<usize> {
        let at = entry(self.heights, i as u32);
        self.pits
            .binary_search_by_key(&at, |&p| entry(self.heights, p))
            .ok()
    }

    /// The region a point joined, as it stands now.
    fn find(&mut self, mut r: u32) -> u32 {
        loop {
            let up = self.joined[r as usize];
            if self.drained.get(r as usize) || up == r {
                return r;
            }
            if self.drained.get(up as usize) {
                return up;
            }
            // Halving the path: a drained region's slot holds no region.
            let further = self.joined[up as usize];
            self.joined[r as usize] = further;
            r = further;
        }
    }

    /// The region wet point `i` first joined: its own, or that of the
    /// lowest wet neighbour below it, down to a point written down.
    fn region(&mut self, i: usize) -> u32 {
        let mut at = i;
        let region = loop {
            if let Some(region) = self.labels.known(at as u32) {
                break region;
            }
            let h = self.heights[at];
            let (mut lowest, mut below) = (h, usize::MAX);
            for k in self.grid.around(at) {
                let hk = self.heights[k];
                if hk < lowest && self.wet.get(k) {
                    (lowest, below) = (hk, k);
                }
            }
            if below == usize::MAX {
                break match self.pit(at) {
                    Some(region) => region as u32,
                    None => self.labels.root(at as u32),
                };
            }
            at = below;
        };
        self.labels.remember(i as u32, region);
        region
    }

    /// Takes point `i`, the lowest waiting: it joins the regions it
    /// touches, or drains them.
    fn take(&mut self, i: usize) {
        if self.wet.get(i) {
            return;
        }
        // No longer waiting: a region that reaches it later queues it again
        // (on a flat, the drained water it leads to is then found).
        self.mark.clear(i);
        let (around, count) = self.grid.neighbours(i);
        let (mut filling, mut drained) = (false, false);
        for &k in &around[..count] {
            if self.wet.get(k) {
                let d = self.mark.get(k);
                drained |= d;
                filling |= !d;
            }
        }
        if !filling && drained {
            // Only drained water here: nothing left to do.
            return;
        }
        let h = self.heights[i];
        let mut out = drained || count < 8;
        let (mut regions, mut found) = ([0u32; 8], 0);
        let (mut lazy, mut lazies) = ([0u32; 8], 0);
        let mut root = true;
        for &k in &around[..count] {
            let hk = self.heights[k];
            if !land(hk) {
                out = true;
            } else if self.wet.get(k) {
                if self.mark.get(k) {
                    continue;
                }
                root &= hk >= h;
                let first = self.region(k);
                if self.lazy.get(first as usize) && self.pits[first as usize] == k as u32 {
                    lazy[lazies] = first;
                    lazies += 1;
                }
                let r = self.find(first);
                if !regions[..found].contains(&r) {
                    regions[found] = r;
                    found += 1;
                }
            } else if hk < h {
                out = true;
            }
        }
        if out {
            self.drain(&regions[..found], &around[..count], h);
        } else if found == 0 {
            self.start(i);
        } else {
            self.join(i, &regions[..found], root);
            for &first in &lazy[..lazies] {
                self.lazy.clear(first as usize);
                for k in self.grid.around(self.pits[first as usize] as usize) {
                    self.queue(k);
                }
            }
        }
    }

    /// A new region at pit `i`. Only its lowest neighbour is queued: most
    /// pits drain over it, and then the others would only be taken to be
    /// thrown away. The others are queued when it joins the region (none is
    /// lower, so none is taken late).
    fn start(&mut self, i: usize) {
        let region = self
            .pit(i)
            .expect("only a pit is taken with no water beside it");
        self.lazy.set(region);
        self.wet.set(i);
        self.mark.clear(i);
        // A pit's region is found by its place among the pits.
        self.labels.set(i as u32, region as u32, false);
        let lowest = self
            .grid
            .around(i)
            .into_iter()
            .min_by_key(|&k| (super::open::key(self.heights[k]), k))
            .expect("eight neighbours");
        self.queue(lowest);
    }

    /// Point `i` joins `regions` (all filling), which join into one.
    fn join(&mut self, i: usize, regions: &[u32], root: bool) {
        let region = regions[0];
        for &other in &regions[1..] {
            self.joined[other as usize] = region;
        }
        self.wet.set(i);
        self.mark.clear(i);
        self.labels.set(i as u32, region, root);
        for k in self.grid.around(i) {
            self.queue(k);
        }
    }

    /// `regions` (all filling) drain at height `h`, over a point whose
    /// neighbours are `around`: their levels are set, and their points
    /// marked drained.
    fn drain(&mut self, regions: &[u32], around: &[usize], h: f32) {
        for &r in regions {
            self.drained.set(r as usize);
            self.joined[r as usize] = h.to_bits();
        }
        for &k in around {
            if self.wet.get(k) && !self.mark.get(k) {
                self.mark.set(k);
                self.stack.push(k as u32);
            }
        }
        // The wet points still filling that touch each other are one
        // region: all of them drain.
        while let Some(p) = self.stack.pop() {
            for k in self.grid.around(p as usize) {
                if self.wet.get(k) && !self.mark.get(k) {
                    self.mark.set(k);
                    self.stack.push(k as u32);
                }
            }
        }
    }

    /// Calls `found` for each lake of at least `least` points: from each
    /// pit under water, every point joined to it below its region's level
    /// (all of them wet, all at that level). What only the rising needed is
    /// let go first, for the lakes' own lists.
    fn lakes(self, least: usize, mut found: impl FnMut(f32, &mut [u32])) {
        let Rise {
            heights,
            grid,
            mut wet,
            pits,
            joined,
            drained,
            mut stack,
            ..
        } = self;
        let mut basin = Vec::new();
        for (region, &pit) in pits.iter().enumerate() {
            if !wet.get(pit as usize) {
                continue;
            }
            let mut root = region;
            while !drained.get(root) && joined[root] as usize != root {
                root = joined[root] as usize;
            }
            let level = f32::from_bits(joined[root]);
            let pit = pit as usize;
            if !drained.get(root) || heights[pit] >= level {
                continue;
            }
            basin.clear();
            // Wet points leave the set as they join the lake.
            wet.clear(pit);
            stack.push(pit as u32);
            while let Some(p) = stack.pop() {
                basin.push(p);
                let p = p as usize;
                for k in grid.around(p) {
                    if wet.get(k) && heights[k] < level {
                        wet.clear(k);
                        stack.push(k as u32);
                    }
                }
            }
            if basin.len() >= least {
                found(level, &mut basin);
            }
        }
    }
}
