//! Where water runs over a field: the rain that falls on each point
//! gathers downhill (the erosion carved its gullies and valleys; this
//! follows them), so a valley floor or a gully drains much ground and is
//! wet, a ridge drains only itself and is dry. The ground's cover reads
//! it (greener along the streams, barer on the ridges).
//!
//! Worked out on the lattice every detail shares (at most
//! `2^SHARED_EXPONENT + 1` points a side), so a mountain's streams are the
//! same at every detail, and read between its points bilinearly. Each
//! point's rain is shared among its lower neighbours by the square of the
//! drop to each (a multiple-flow-direction spread: streams a few points
//! wide, not the single lines of the steepest descent alone), the highest
//! points first. Only `+`, `*`, `/` and the float's own exponent bits: the
//! same on every platform.

use super::Heightfield;
use super::SHARED_EXPONENT;
use super::curves::smoothstep;
use super::neighbours::NEIGHBOURS;

/// The wetness of most of a mountain's slopes: neither a ridge (0) nor a
/// stream (1). What the cover is drawn with where no map is at hand.
pub const ORDINARY: f32 = 0.3;

/// The drained ground, in lattice points (log 2), at which a point counts
/// as dry (0) and as a stream (1).
const DRAINS: (f32, f32) = (0.0, 5.0);

/// Where water runs over one field: 0 on the driest ridges, 1 along the
/// streams.
#[derive(Debug, Clone)]
pub struct Wetness {
    /// Lattice points a side.
    side: usize,
    /// Field points per lattice step.
    stride: usize,
    /// Wetness at each lattice point, row by row.
    values: Vec<f32>,
}

impl Wetness {
    /// Where water runs over `field`.
    pub fn of(field: &Heightfield) -> Self {
        let stride = 1usize << field.exponent().saturating_sub(SHARED_EXPONENT);
        let side = (field.size() - 1) / stride + 1;
        let heights: Vec<f32> = (0..side * side)
            .map(|k| field.get(k % side * stride, k / side * stride))
            .map(|h| if h.is_finite() { h } else { 0.0 })
            .collect();
        let drained = drained(&heights, side);
        let values = heights
            .iter()
            .zip(&drained)
            .map(|(&h, &a)| match h > 0.0 {
                true => smoothstep(DRAINS.0, DRAINS.1, log2(a)),
                false => ORDINARY,
            })
            .collect();
        Wetness {
            side,
            stride,
            values: softened(values, side),
        }
    }

    /// The wetness at field point (`x`, `y`), between the lattice's points.
    #[inline]
    pub fn at(&self, x: usize, y: usize) -> f32 {
        let last = self.side - 1;
        let between = |i: usize| {
            let i0 = (i / self.stride).min(last);
            (
                i0,
                (i0 + 1).min(last),
                (i % self.stride) as f32 / self.stride as f32,
            )
        };
        let ((x0, x1, tx), (y0, y1, ty)) = (between(x), between(y));
        let v = |i: usize, j: usize| self.values[j * self.side + i];
        let top = v(x0, y0) + (v(x1, y0) - v(x0, y0)) * tx;
        let bottom = v(x0, y1) + (v(x1, y1) - v(x0, y1)) * tx;
        top + (bottom - top) * ty
    }
}

/// The lattice points each point of `heights` (`side` a side) drains,
/// itself included: each point's own rain and all that reached it, shared
/// among its lower neighbours by the square of the drop to each (over the
/// step's length), the highest first. Water reaching the sea or a pit
/// stays there (filling the pits to their lips drew the flow across each
/// basin's floor in straight parallel lines).
fn drained(heights: &[f32], side: usize) -> Vec<f32> {
    let mut order: Vec<usize> = (0..heights.len()).collect();
    order.sort_unstable_by(|&a, &b| heights[b].total_cmp(&heights[a]).then(a.cmp(&b)));
    let mut water = vec![1.0f32; heights.len()];
    let mut shares = [(0usize, 0.0f32); 8];
    for i in order {
        let h = heights[i];
        if h <= 0.0 {
            continue;
        }
        let (x, y) = ((i % side) as isize, (i / side) as isize);
        let (mut n, mut total) = (0, 0.0);
        for (dx, dy) in NEIGHBOURS {
            // The drop over the step's length, squared.
            let inverse_square_length = if dx != 0 && dy != 0 { 0.5 } else { 1.0 };
            let (nx, ny) = (x + dx, y + dy);
            if nx < 0 || ny < 0 || nx >= side as isize || ny >= side as isize {
                continue;
            }
            let j = ny as usize * side + nx as usize;
            let drop = h - heights[j];
            if drop > 0.0 {
                let weight = drop * drop * inverse_square_length;
                shares[n] = (j, weight);
                n += 1;
                total += weight;
            }
        }
        if total > 0.0 {
            let w = water[i] / total;
            for &(j, weight) in &shares[..n] {
                water[j] += w * weight;
            }
        }
    }
    water
}

/// `values` (`side` a side) blurred by one pass of a 1-2-1 kernel each
/// way: a stream's edge fades rather than steps.
fn softened(values: Vec<f32>, side: usize) -> Vec<f32> {
    let pass = |v: &[f32], along: bool| -> Vec<f32> {
        (0..side * side)
            .map(|k| {
                let (x, y) = (k % side, k / side);
                let at = |i: usize| match along {
                    true => v[y * side + i],
                    false => v[i * side + x],
                };
                let c = if along { x } else { y };
                let (a, b) = (c.saturating_sub(1), (c + 1).min(side - 1));
                (at(a) + 2.0 * at(c) + at(b)) * 0.25
            })
            .collect()
    };
    let across = pass(&values, true);
    pass(&across, false)
}

/// Base-2 logarithm of `a` (>= 1), from its float's exponent and a
/// straight line through its mantissa: within 0.09 of the true one, and
/// the same bits on every platform.
fn log2(a: f32) -> f32 {
    let bits = a.max(1.0).to_bits();
    let exponent = ((bits >> 23) & 0xff) as f32 - 127.0;
    let mantissa = f32::from_bits((bits & 0x007f_ffff) | 0x3f80_0000);
    exponent + mantissa - 1.0
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_quick_logarithm_is_near_the_true_one() {
        for k in 0..2000 {
            let a = 1.0 + k as f32 * 3.7;
            assert!((log2(a) - a.log2()).abs() < 0.09, "{a}");
        }
    }
}
