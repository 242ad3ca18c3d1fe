//! Mountain lakes: basins above the sea filled to their lowest lip
//! (Priority-Flood, R. Barnes, C. Lehman and D. Mulla, "Priority-Flood: An
//! optimal depression-filling and watershed-labeling algorithm for digital
//! elevation models", Computers & Geosciences 62, 2014, with its plain
//! queue for the cells of a depression).
//!
//! Water drains off the grid's border and into the sea (every point at or
//! below sea level, 0). The flood starts from the land on those outlets and
//! always goes on from the lowest point reached: a point lower than the
//! point it is reached from lies in a basin whose lowest lip is that point,
//! and the basin, every point below the lip joined to it, is found at once.
//! So a lake's surface is its lip's height, exactly; no lake point stands
//! above it; and the sea is an outlet, never a lake. Basins of fewer than
//! [`MIN_AREA_SHARE`] of the points are left dry (a pit a few points wide
//! does not read as water).

use std::cmp::Reverse;
use std::collections::{BinaryHeap, VecDeque};

/// Least share of the grid's points a basin covers to be drawn as a lake.
pub const MIN_AREA_SHARE: f64 = 1e-4;

/// The lakes of one field: their surfaces, and which points of each row
/// lie under them.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Lakes {
    size: usize,
    levels: Vec<f32>,
    /// Per row, the runs of lake points, left to right.
    rows: Vec<Vec<Run>>,
}

/// Points `start..end` of a row, under lake `lake`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Run {
    /// First column under water.
    pub start: u32,
    /// One past the last column under water.
    pub end: u32,
    /// Which lake (an index into [`Lakes::level`]).
    pub lake: u32,
}

impl Lakes {
    /// The lakes of a field of `size` points a side (`heights`, row-major):
    /// basins above the sea of at least [`MIN_AREA_SHARE`] of its points
    /// (and at least 4), filled to their lip.
    pub fn of(heights: &[f32], size: usize) -> Self {
        let least = ((heights.len() as f64 * MIN_AREA_SHARE).ceil() as usize).max(4);
        Lakes::at_least(heights, size, least)
    }

    /// [`Lakes::of`] keeping basins of at least `least` points.
    pub fn at_least(heights: &[f32], size: usize, least: usize) -> Self {
        assert_eq!(heights.len(), size * size, "a square field");
        assert!(
            heights.len() <= 1 << 25,
            "at most 2^25 points (a 4097 grid has 2^24)"
        );
        Flood::new(heights, size).run(least.max(1))
    }

    /// Points per side of the field these lakes belong to.
    pub fn size(&self) -> usize {
        self.size
    }

    /// How many lakes there are.
    pub fn count(&self) -> usize {
        self.levels.len()
    }

    /// The surface height of lake `lake`: its basin's lowest lip.
    pub fn level(&self, lake: u32) -> f32 {
        self.levels[lake as usize]
    }

    /// The runs of lake points in row `y`, left to right.
    pub fn row(&self, y: usize) -> &[Run] {
        self.rows.get(y).map_or(&[], |r| r.as_slice())
    }

    /// The lake over point (`x`, `y`), if any.
    pub fn lake_at(&self, x: usize, y: usize) -> Option<u32> {
        let runs = self.row(y);
        let i = runs.partition_point(|r| (r.end as usize) <= x);
        runs.get(i)
            .filter(|r| r.start as usize <= x)
            .map(|r| r.lake)
    }

    /// The water surface over point (`x`, `y`): its lake's level, or sea
    /// level (0) where there is no lake.
    pub fn surface_at(&self, x: usize, y: usize) -> f32 {
        self.lake_at(x, y).map_or(0.0, |l| self.level(l))
    }

    /// Points under each lake.
    pub fn areas(&self) -> Vec<usize> {
        let mut areas = vec![0; self.count()];
        for run in self.rows.iter().flatten() {
            areas[run.lake as usize] += (run.end - run.start) as usize;
        }
        areas
    }

    /// These lakes on the field turned `quarters` quarter turns as
    /// `render`'s turned view turns it: point (x, y) of the turned field
    /// is point `source(x, y)` of this one.
    pub fn turned(&self, source: impl Fn(usize, usize) -> (usize, usize)) -> Self {
        let n = self.size;
        let mut rows = vec![Vec::new(); n];
        for (y, row) in rows.iter_mut().enumerate() {
            let mut open: Option<Run> = None;
            for x in 0..n {
                let (sx, sy) = source(x, y);
                match (self.lake_at(sx, sy), &mut open) {
                    (Some(l), Some(r)) if r.lake == l && r.end as usize == x => r.end += 1,
                    (lake, open) => {
                        row.extend(open.take());
                        *open = lake.map(|lake| Run {
                            start: x as u32,
                            end: x as u32 + 1,
                            lake,
                        });
                    }
                }
            }
            row.extend(open);
        }
        Lakes {
            size: n,
            levels: self.levels.clone(),
            rows,
        }
    }
}

/// Whether height `h` is land: above sea level (NaN is not).
#[inline]
fn land(h: f32) -> bool {
    h > 0.0
}

/// The state of one flood.
struct Flood<'a> {
    heights: &'a [f32],
    size: usize,
    /// One bit a point: reached (or sea).
    seen: Vec<u64>,
    open: Open,
    /// Points reached that cannot be a lip (see [`Flood::reach`]), waiting
    /// to be flooded from in any order.
    slope: Vec<u32>,
    /// `ceil(2^40 / size)`: a point's row by a multiplication (see `around`).
    row_of: u64,
}

impl<'a> Flood<'a> {
    fn new(heights: &'a [f32], size: usize) -> Self {
        Flood {
            heights,
            size,
            seen: vec![0; heights.len().div_ceil(64)],
            open: Open::new(heights),
            slope: Vec::new(),
            row_of: (1u64 << 40).div_ceil(size as u64),
        }
    }

    #[inline]
    fn seen(&self, i: usize) -> bool {
        self.seen[i / 64] & (1u64 << (i % 64)) != 0
    }

    /// A point just reached, not in a basin of the point it was reached
    /// from (Zhou, Sun and Fu 2016, "An efficient variant of the
    /// Priority-Flood algorithm"): only a point with a lower neighbour not
    /// yet reached can be the lowest lip of a basin, so only such points
    /// wait their turn in height order. From the others the flood can go on
    /// at once (every neighbour it finds is at least as high, so no basin
    /// is found through them): most of a mountain's slopes never touch the
    /// priority queue.
    #[inline]
    fn reach(&mut self, j: usize) {
        let h = self.heights[j];
        let (around, count) = self.around(j);
        // Without short cuts: the comparisons are the flood's least
        // predictable branches, cheaper folded than taken one by one.
        let lip = around[..count].iter().fold(false, |lip, &k| {
            lip | ((self.heights[k] < h) & !self.seen(k))
        });
        if lip {
            self.open.push(self.heights, j as u32);
        } else {
            self.slope.push(j as u32);
        }
    }

    /// Floods on from every point waiting in [`Flood::slope`]; called
    /// before the next point leaves the queue, which it must not overtake.
    fn climb(&mut self) {
        while let Some(t) = self.slope.pop() {
            let (around, count) = self.around(t as usize);
            for &k in &around[..count] {
                if self.see(k) {
                    self.reach(k);
                }
            }
        }
    }

    /// Marks point `i` reached; whether it was not before.
    #[inline]
    fn see(&mut self, i: usize) -> bool {
        let (word, bit) = (i / 64, 1u64 << (i % 64));
        let new = self.seen[word] & bit == 0;
        self.seen[word] |= bit;
        new
    }

    /// The points around `i` (its eight neighbours: lakes join across a
    /// cell's diagonals, as the triangles drawn over the cells do), in the
    /// first `count` items.
    #[inline]
    fn around(&self, i: usize) -> ([usize; 8], usize) {
        let n = self.size;
        // i / n without a division, the flood's hottest step: exact for
        // i < 2^25 (a 4097 grid has 2^24 points), as i (2^40/n + e) / 2^40
        // exceeds i / n by less than 2^-15, and i / n's fraction is at
        // most 1 - 1/n.
        let y = ((i as u64 * self.row_of) >> 40) as usize;
        let x = i - y * n;
        if x > 0 && y > 0 && x + 1 < n && y + 1 < n {
            let all = [
                i - n - 1,
                i - n,
                i - n + 1,
                i - 1,
                i + 1,
                i + n - 1,
                i + n,
                i + n + 1,
            ];
            return (all, 8);
        }
        let mut out = [0; 8];
        let mut count = 0;
        for (dx, dy) in [
            (-1, -1),
            (0, -1),
            (1, -1),
            (-1, 0),
            (1, 0),
            (-1, 1),
            (0, 1),
            (1, 1),
        ] {
            let (nx, ny) = (x as isize + dx, y as isize + dy);
            if nx >= 0 && ny >= 0 && (nx as usize) < n && (ny as usize) < n {
                out[count] = ny as usize * n + nx as usize;
                count += 1;
            }
        }
        (out, count)
    }

    /// Marks the sea (and NaN) as reached, and opens the land on the outlets:
    /// the border, and every point next to the sea.
    fn start(&mut self) {
        let n = self.size;
        for (i, &h) in self.heights.iter().enumerate() {
            if !land(h) {
                self.see(i);
            }
        }
        for (i, &h) in self.heights.iter().enumerate() {
            if !land(h) {
                continue;
            }
            let (x, y) = (i % n, i / n);
            let border = x == 0 || y == 0 || x == n - 1 || y == n - 1;
            let outlet = border || {
                let (around, count) = self.around(i);
                around[..count]
                    .iter()
                    .fold(false, |sea, &j| sea | !land(self.heights[j]))
            };
            if outlet && self.see(i) {
                self.reach(i);
                self.climb();
            }
        }
    }

    fn run(mut self, least: usize) -> Lakes {
        self.start();
        let mut lakes = Lakes {
            size: self.size,
            ..Lakes::default()
        };
        let mut basin: Vec<u32> = Vec::new();
        let mut pit: VecDeque<u32> = VecDeque::new();
        while let Some(c) = self.open.pop(self.heights) {
            let c = c as usize;
            let lip = self.heights[c];
            let (around, count) = self.around(c);
            for &j in &around[..count] {
                if !self.see(j) {
                    continue;
                }
                if self.heights[j] >= lip {
                    self.reach(j);
                    continue;
                }
                // A basin whose lowest lip is `c`: all of it, at once.
                basin.clear();
                pit.push_back(j as u32);
                while let Some(p) = pit.pop_front() {
                    basin.push(p);
                    let (around, count) = self.around(p as usize);
                    for &q in &around[..count] {
                        if self.see(q) {
                            if self.heights[q] < lip {
                                pit.push_back(q as u32);
                            } else {
                                self.reach(q);
                            }
                        }
                    }
                }
                if basin.len() >= least {
                    lakes.add(&mut basin, lip);
                }
            }
            self.climb();
        }
        lakes
    }
}

/// The points waiting to be flooded from, lowest first: a bucket per slice
/// of the land's heights, and the current bucket in a binary heap, which
/// gives the exact order. The flood never asks for a height below the last
/// one taken (its heights only rise), so a bucket, once passed, stays empty;
/// with slices this thin the heap stays small, and a point costs a push and
/// a pop on a short heap instead of on one holding the whole shore.
struct Open {
    lo: f32,
    scale: f32,
    buckets: Vec<Vec<u32>>,
    current: usize,
    /// `key << 32 | point`: one comparison orders by height.
    heap: BinaryHeap<Reverse<u64>>,
}

impl Open {
    fn new(heights: &[f32]) -> Self {
        let (lo, hi) = heights
            .iter()
            .filter(|h| **h > 0.0 && h.is_finite())
            .fold((f32::INFINITY, 0.0f32), |(lo, hi), &h| {
                (lo.min(h), hi.max(h))
            });
        let count = (heights.len() / 64).clamp(256, 1 << 16);
        let span = hi - lo;
        let scale = if span > 0.0 && span.is_finite() {
            (count - 1) as f32 / span
        } else {
            0.0
        };
        Open {
            lo,
            scale,
            buckets: vec![Vec::new(); count],
            current: 0,
            heap: BinaryHeap::new(),
        }
    }

    /// The bucket of height `h` (monotone in `h`).
    #[inline]
    fn bucket(&self, h: f32) -> usize {
        (((h - self.lo) * self.scale) as usize).min(self.buckets.len() - 1)
    }

    /// Adds point `i` (its height not below the last taken).
    #[inline]
    fn push(&mut self, heights: &[f32], i: u32) {
        let h = heights[i as usize];
        let b = self.bucket(h);
        if b <= self.current {
            self.heap
                .push(Reverse(u64::from(key(h)) << 32 | u64::from(i)));
        } else {
            self.buckets[b].push(i);
        }
    }

    /// A point of the lowest height, or `None` when none is left.
    fn pop(&mut self, heights: &[f32]) -> Option<u32> {
        loop {
            if let Some(Reverse(entry)) = self.heap.pop() {
                return Some(entry as u32);
            }
            let next =
                (self.current + 1..self.buckets.len()).find(|&b| !self.buckets[b].is_empty())?;
            self.current = next;
            let points = std::mem::take(&mut self.buckets[next]);
            self.heap.extend(points.iter().map(|&i| entry(heights, i)));
        }
    }
}

impl Lakes {
    /// The same lakes with their levels multiplied by `f` (for a field
    /// whose heights are).
    pub(crate) fn scaled(&self, f: f32) -> Lakes {
        Lakes {
            levels: self.levels.iter().map(|l| l * f).collect(),
            ..self.clone()
        }
    }

    /// Adds the lake over `points` (grid indices) at `level`.
    fn add(&mut self, points: &mut [u32], level: f32) {
        let n = self.size;
        if self.rows.is_empty() {
            self.rows = vec![Vec::new(); n];
        }
        let lake = self.levels.len() as u32;
        self.levels.push(level);
        points.sort_unstable();
        let mut runs = points.chunk_by(|&a, &b| b == a + 1 && !(b as usize).is_multiple_of(n));
        for run in &mut runs {
            let first = run[0] as usize;
            let (x, y) = (first % n, first / n);
            let row = &mut self.rows[y];
            let at = row.partition_point(|r| (r.start as usize) < x);
            row.insert(
                at,
                Run {
                    start: x as u32,
                    end: (x + run.len()) as u32,
                    lake,
                },
            );
        }
    }
}

/// Point `i` in the heap: its height's key above its index.
#[inline]
fn entry(heights: &[f32], i: u32) -> Reverse<u64> {
    Reverse(u64::from(key(heights[i as usize])) << 32 | u64::from(i))
}

/// A height as a key that sorts as the heights do (positive heights only
/// reach the heap, but any finite one would sort right).
#[inline]
fn key(h: f32) -> u32 {
    let b = h.to_bits();
    if b >> 31 == 1 { !b } else { b | 0x8000_0000 }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_open_points_come_lowest_first() {
        let heights: Vec<f32> = (0..5000u32)
            .map(|i| 1.0 + (i.wrapping_mul(2_654_435_761) >> 8) as f32 * 1e-6)
            .collect();
        let mut open = Open::new(&heights);
        for i in 0..heights.len() as u32 {
            open.push(&heights, i);
        }
        let mut last = 0.0;
        let mut count = 0;
        while let Some(i) = open.pop(&heights) {
            let h = heights[i as usize];
            assert!(h >= last, "{h} after {last}");
            last = h;
            count += 1;
        }
        assert_eq!(count, heights.len());
    }

    #[test]
    fn keys_sort_as_heights() {
        let hs = [-5.0f32, -0.5, 0.0, 1e-9, 0.5, 3.0, 1e6];
        for w in hs.windows(2) {
            assert!(key(w[0]) < key(w[1]), "{w:?}");
        }
    }
}
