//! The lakes as the first flood found them (a priority-flood from the
//! outlets over the whole land, with a bit set and a bucketed heap), kept
//! to check the program's flood against: the same lakes, bit for bit (the
//! order the lakes are numbered in aside).

use std::cmp::Reverse;
use std::collections::{BinaryHeap, VecDeque};

use mountains::terrain::Lakes;

/// Lakes as plain data: each lake's level, and per row its runs
/// `(start, end, lake)`.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Reference {
    size: usize,
    pub levels: Vec<f32>,
    pub rows: Vec<Vec<(u32, u32, u32)>>,
}

impl Reference {
    /// The same data read from `lakes`.
    pub fn from_lakes(lakes: &Lakes) -> Self {
        let n = lakes.size();
        let levels = (0..lakes.count() as u32).map(|l| lakes.level(l)).collect();
        let rows = if lakes.count() == 0 {
            Vec::new()
        } else {
            (0..n)
                .map(|y| {
                    lakes
                        .row(y)
                        .iter()
                        .map(|r| (r.start, r.end, r.lake))
                        .collect()
                })
                .collect()
        };
        Reference {
            size: n,
            levels,
            rows,
        }
    }
}

impl Reference {
    /// The same lakes numbered by their first point (row by row), so two
    /// floods that meet the lakes in another order compare equal.
    pub fn numbered_by_first_point(&self) -> Self {
        let mut first = vec![usize::MAX; self.levels.len()];
        for (y, row) in self.rows.iter().enumerate() {
            for &(start, _, lake) in row {
                let at = &mut first[lake as usize];
                *at = (*at).min(y * self.size + start as usize);
            }
        }
        let mut order: Vec<usize> = (0..self.levels.len()).collect();
        order.sort_by_key(|&l| first[l]);
        let mut new_index = vec![0u32; order.len()];
        for (new, &old) in order.iter().enumerate() {
            new_index[old] = new as u32;
        }
        Reference {
            size: self.size,
            levels: order.iter().map(|&l| self.levels[l]).collect(),
            rows: self
                .rows
                .iter()
                .map(|row| {
                    row.iter()
                        .map(|&(s, e, l)| (s, e, new_index[l as usize]))
                        .collect()
                })
                .collect(),
        }
    }
}

/// The lakes of `heights` (`size` a side) keeping basins of `least` points.
pub fn lakes(heights: &[f32], size: usize, least: usize) -> Reference {
    assert_eq!(heights.len(), size * size, "a square field");
    Flood::new(heights, size).run(least.max(1))
}

/// The least basin [`Lakes::of`] keeps on a grid of `len` points.
pub fn least(len: usize) -> usize {
    ((len as f64 * mountains::terrain::lakes::MIN_AREA_SHARE).ceil() as usize).max(4)
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

    fn run(mut self, least: usize) -> Reference {
        self.start();
        let mut lakes = Reference {
            size: self.size,
            ..Reference::default()
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

impl Reference {
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
            let at = row.partition_point(|r| (r.0 as usize) < x);
            row.insert(at, (x as u32, (x + run.len()) as u32, lake));
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
