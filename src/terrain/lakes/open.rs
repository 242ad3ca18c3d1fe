//! The points waiting to be flooded, lowest first.

use std::cmp::Reverse;
use std::collections::BinaryHeap;

/// The points waiting to be flooded, lowest first (ties by index): a
/// bucket per slice of the land's heights, and the current bucket in a
/// binary heap, which gives the exact order. The flood never asks for a
/// height below the last one taken (its water only rises), so a bucket,
/// once passed, stays empty, and the heap holds one thin slice at a time.
pub(super) struct Open {
    lo: f32,
    scale: f32,
    buckets: Vec<Vec<u32>>,
    current: usize,
    /// `key << 32 | point`: one comparison orders by height, then index.
    heap: BinaryHeap<Reverse<u64>>,
}

impl Open {
    /// An empty queue for land heights from `lo` to `hi`, on a grid of
    /// `points` points.
    pub(super) fn new(lo: f32, hi: f32, points: usize) -> Self {
        let count = (points / 256).clamp(256, 1 << 12);
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

    /// Adds point `i` of height `h` (not below the last taken).
    #[inline]
    pub(super) fn push(&mut self, h: f32, i: u32) {
        let b = self.bucket(h);
        if b <= self.current {
            self.heap
                .push(Reverse(u64::from(key(h)) << 32 | u64::from(i)));
        } else {
            self.buckets[b].push(i);
        }
    }

    /// A point of the lowest height (the lowest index of those), or `None`
    /// when none is left.
    pub(super) fn pop(&mut self, heights: &[f32]) -> Option<u32> {
        self.peek(heights)?;
        self.heap.pop().map(|Reverse(e)| e as u32)
    }

    /// The point at the front of the current slice, if any: the next one
    /// taken unless a lower one comes first.
    #[inline]
    pub(super) fn front(&self) -> Option<u32> {
        self.heap.peek().map(|&Reverse(e)| e as u32)
    }

    /// The [`entry`] [`Open::pop`] would take next.
    pub(super) fn peek(&mut self, heights: &[f32]) -> Option<u64> {
        loop {
            if let Some(&Reverse(entry)) = self.heap.peek() {
                return Some(entry);
            }
            let next =
                (self.current + 1..self.buckets.len()).find(|&b| !self.buckets[b].is_empty())?;
            self.current = next;
            let points = std::mem::take(&mut self.buckets[next]);
            self.heap
                .extend(points.iter().map(|&i| Reverse(entry(heights, i))));
        }
    }
}

/// Point `i` as the queue orders it: its height's key above its index.
#[inline]
pub(super) fn entry(heights: &[f32], i: u32) -> u64 {
    u64::from(key(heights[i as usize])) << 32 | u64::from(i)
}

/// A height as a key that sorts as the heights do (positive heights only
/// reach the queue, but any finite one would sort right).
#[inline]
pub(super) fn key(h: f32) -> u32 {
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
        let (lo, hi) = heights
            .iter()
            .fold((f32::INFINITY, 0.0f32), |(lo, hi), &h| {
                (lo.min(h), hi.max(h))
            });
        let mut open = Open::new(lo, hi, heights.len());
        for (i, &h) in heights.iter().enumerate() {
            open.push(h, i as u32);
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
