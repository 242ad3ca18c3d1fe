//! Fitting an image of any size to a `2^n + 1` grid.
//!
//! The method, in order:
//! 1. **Crop** a non-square image to its central square (side = the shorter
//!    side). Padding would add flat shelves that read as cliffs and plains;
//!    a crop keeps the terrain's own shape, as a "fill" wallpaper does.
//! 2. **Size**: a side of exactly `2^n + 1` (17..=4097) is kept; a side of
//!    `2^n` (16..=4096, the other common heightmap size) is extended by one by
//!    repeating its last row and column, which blurs nothing; any other side
//!    goes to the nearest `2^n + 1` on a log scale (so 300 -> 257, 400 -> 513),
//!    never above 4097 nor below 17.
//! 3. **Resample** (other sides only) with a separable linear filter whose
//!    grid corners land on the image corners: plain bilinear interpolation
//!    when enlarging, and a tent widened to the reduction ratio when
//!    shrinking, so every source pixel counts and nothing aliases.
//!
//! Rows are consumed one at a time as the PNG decoder yields them, so memory
//! is the output grid plus one row, whatever the source size.

use std::fmt;

use crate::terrain::heightfield::MAX_EXPONENT;

/// The smallest grid an image is fitted to (17x17): smaller images are
/// enlarged. Generated fields go down to 9x9 (`detail = 3`, seed 000's
/// fewest iterations), but a data set that small reads as a few slabs.
const LEAST_FITTED_EXPONENT: u32 = 4;

/// What was done to the image to make it a `2^n + 1` grid.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FitMethod {
    /// The square was already `2^n + 1` a side.
    Exact,
    /// A `2^n` square got its last row and column repeated.
    RepeatEdge,
    /// The square was resampled with the linear filter.
    Resampled,
}

/// How an image was fitted to the grid.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Fit {
    /// Width of the image in the file.
    pub source_width: u32,
    /// Height of the image in the file.
    pub source_height: u32,
    /// Left column of the central square used.
    pub crop_x: u32,
    /// Top row of the central square used.
    pub crop_y: u32,
    /// Side of the central square used.
    pub crop_side: u32,
    /// Points per side of the resulting grid.
    pub size: usize,
    /// How the square became the grid.
    pub method: FitMethod,
}

impl Fit {
    /// The plan for a `width` x `height` image (both at least 2).
    pub fn plan(width: u32, height: u32) -> Fit {
        let side = width.min(height);
        let (size, method) = grid_for(side as usize);
        Fit {
            source_width: width,
            source_height: height,
            crop_x: (width - side) / 2,
            crop_y: (height - side) / 2,
            crop_side: side,
            size,
            method,
        }
    }

    /// Whether the image was cropped to its central square.
    pub fn cropped(&self) -> bool {
        self.source_width != self.source_height
    }
}

impl fmt::Display for Fit {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let (w, h, s, n) = (
            self.source_width,
            self.source_height,
            self.crop_side,
            self.size,
        );
        write!(f, "{w}x{h} image")?;
        if self.cropped() {
            write!(f, ", central {s}x{s} square")?;
        }
        match self.method {
            FitMethod::Exact => write!(f, " used as a {n}x{n} grid"),
            FitMethod::RepeatEdge => {
                write!(
                    f,
                    " extended to {n}x{n} by repeating the last row and column"
                )
            }
            FitMethod::Resampled => write!(f, " resampled (linear filter) to {n}x{n}"),
        }
    }
}

/// The grid side for a square of `side` pixels, and how to get there.
fn grid_for(side: usize) -> (usize, FitMethod) {
    let sizes = (LEAST_FITTED_EXPONENT..=MAX_EXPONENT).map(|n| (1usize << n) + 1);
    if sizes.clone().any(|n| n == side) {
        return (side, FitMethod::Exact);
    }
    if sizes.clone().any(|n| n == side + 1) {
        return (side + 1, FitMethod::RepeatEdge);
    }
    let log_distance = |n: usize| ((n as f64).ln() - (side as f64).ln()).abs();
    let best = sizes
        .min_by(|&a, &b| log_distance(a).total_cmp(&log_distance(b)))
        .unwrap_or(17);
    (best, FitMethod::Resampled)
}

/// The filter taps of one axis: for each output point, the source indices
/// and weights (summing to 1) that make it.
#[derive(Debug, Clone)]
pub struct Taps {
    /// First source index of each output point.
    start: Vec<usize>,
    /// Weights of each output point, from `start` on.
    weights: Vec<Vec<f64>>,
}

impl Taps {
    /// Taps taking `source` points to `target` points by `method`.
    pub fn new(source: usize, target: usize, method: FitMethod) -> Taps {
        let (start, weights) = match method {
            FitMethod::Exact | FitMethod::RepeatEdge => {
                (0..target).map(|i| (i.min(source - 1), vec![1.0])).unzip()
            }
            FitMethod::Resampled => (0..target).map(|i| tent(source, target, i)).unzip(),
        };
        Taps { start, weights }
    }

    /// Output point `i` from the `source` values.
    #[inline]
    pub fn apply(&self, i: usize, source: &[f64]) -> f64 {
        let from = &source[self.start[i]..];
        self.weights[i].iter().zip(from).map(|(w, v)| w * v).sum()
    }

    /// The last source index output point `i` reads.
    pub fn last(&self, i: usize) -> usize {
        self.start[i] + self.weights[i].len() - 1
    }

    /// For each source index, the output points it feeds and with what weight.
    pub fn inverted(&self, source: usize) -> Vec<Vec<(usize, f64)>> {
        let mut inv = vec![Vec::new(); source];
        for (i, (&start, ws)) in self.start.iter().zip(&self.weights).enumerate() {
            for (k, &w) in ws.iter().enumerate() {
                inv[start + k].push((i, w));
            }
        }
        inv
    }
}

/// Corner-aligned linear filter weights for output point `i`.
fn tent(source: usize, target: usize, i: usize) -> (usize, Vec<f64>) {
    let ratio = (source - 1) as f64 / (target - 1) as f64;
    let centre = i as f64 * ratio;
    let radius = ratio.max(1.0);
    let first = ((centre - radius).ceil().max(0.0)) as usize;
    let last = ((centre + radius).floor() as usize).min(source - 1);
    let raw: Vec<f64> = (first..=last)
        .map(|j| (1.0 - (j as f64 - centre).abs() / radius).max(0.0))
        .collect();
    let total: f64 = raw.iter().sum();
    (first, raw.iter().map(|w| w / total).collect())
}

/// Builds the fitted grid from source rows fed one at a time.
///
/// Sums run in `f64` and each output point is rounded to `f32` once, so a
/// constant area stays exactly constant (no filter noise that a later
/// normalisation could blow up into relief).
pub struct Resampler {
    fit: Fit,
    columns: Taps,
    row_targets: Vec<Vec<(usize, f64)>>,
    last_source: Vec<usize>,
    scratch: Vec<f64>,
    row: Vec<f64>,
    open: Vec<(usize, Vec<f64>)>,
    spare: Vec<Vec<f64>>,
    out: Vec<f32>,
}

impl Resampler {
    /// A resampler for `fit`, its output all zeros.
    pub fn new(fit: Fit) -> Resampler {
        let side = fit.crop_side as usize;
        let columns = Taps::new(side, fit.size, fit.method);
        let row_taps = Taps::new(side, fit.size, fit.method);
        let last_source = (0..fit.size).map(|t| row_taps.last(t)).collect();
        Resampler {
            fit,
            columns,
            row_targets: row_taps.inverted(side),
            last_source,
            scratch: vec![0.0; side],
            row: vec![0.0; fit.size],
            open: Vec::new(),
            spare: Vec::new(),
            out: vec![0.0; fit.size * fit.size],
        }
    }

    /// Takes image row `y` (all `source_width` samples).
    pub fn push_row(&mut self, y: u32, samples: impl Iterator<Item = f32>) {
        let Some(r) = y.checked_sub(self.fit.crop_y) else {
            return;
        };
        let r = r as usize;
        if r >= self.row_targets.len() {
            return;
        }
        let side = self.fit.crop_side as usize;
        let used = samples.skip(self.fit.crop_x as usize).take(side);
        for (slot, s) in self.scratch.iter_mut().zip(used) {
            *slot = f64::from(s);
        }
        for (x, v) in self.row.iter_mut().enumerate() {
            *v = self.columns.apply(x, &self.scratch);
        }
        let row = std::mem::take(&mut self.row);
        for i in 0..self.row_targets[r].len() {
            let (t, w) = self.row_targets[r][i];
            let acc = self.accumulator(t);
            for (a, v) in acc.iter_mut().zip(&row) {
                *a += w * v;
            }
        }
        self.row = row;
        self.close_rows_ending_at(r);
    }

    /// The running sum of output row `t`, opened at zero when first touched.
    fn accumulator(&mut self, t: usize) -> &mut Vec<f64> {
        let k = match self.open.iter().position(|(row, _)| *row == t) {
            Some(k) => k,
            None => {
                let mut acc = self.spare.pop().unwrap_or_default();
                acc.clear();
                acc.resize(self.fit.size, 0.0);
                self.open.push((t, acc));
                self.open.len() - 1
            }
        };
        &mut self.open[k].1
    }

    /// Output rows whose last source row was `r` are complete: store them.
    fn close_rows_ending_at(&mut self, r: usize) {
        let n = self.fit.size;
        let mut k = 0;
        while k < self.open.len() {
            let t = self.open[k].0;
            if self.last_source[t] == r {
                let (_, acc) = self.open.swap_remove(k);
                for (o, a) in self.out[t * n..(t + 1) * n].iter_mut().zip(&acc) {
                    *o = *a as f32;
                }
                self.spare.push(acc);
            } else {
                k += 1;
            }
        }
    }

    /// The grid, row-major, in sample units.
    pub fn finish(self) -> Vec<f32> {
        self.out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn grid_sizes_follow_the_documented_rule() {
        let cases = [
            (2, 17, FitMethod::Resampled),
            (16, 17, FitMethod::RepeatEdge),
            (17, 17, FitMethod::Exact),
            (200, 257, FitMethod::Resampled),
            (300, 257, FitMethod::Resampled),
            (400, 513, FitMethod::Resampled),
            (512, 513, FitMethod::RepeatEdge),
            (1025, 1025, FitMethod::Exact),
            (4096, 4097, FitMethod::RepeatEdge),
            (8192, 4097, FitMethod::Resampled),
            (16384, 4097, FitMethod::Resampled),
        ];
        for (side, size, method) in cases {
            assert_eq!(grid_for(side), (size, method), "side {side}");
        }
    }

    #[test]
    fn tent_weights_sum_to_one_and_keep_ramps() {
        for (s, t) in [(300, 257), (200, 257), (16384, 4097), (2, 17)] {
            let taps = Taps::new(s, t, FitMethod::Resampled);
            let ratio = (s - 1) as f64 / (t - 1) as f64;
            let ramp: Vec<f64> = (0..s).map(|j| j as f64).collect();
            for i in 0..t {
                let sum: f64 = taps.weights[i].iter().sum();
                assert!((sum - 1.0).abs() < 1e-5, "{s}->{t} point {i}: {sum}");
                // A symmetric filter reproduces a ramp wherever it is not cut
                // by the edge; at the edges it averages inwards.
                let want = i as f64 * ratio;
                let got = taps.apply(i, &ramp);
                let slack = if ratio <= 1.0 { 1e-2 } else { ratio / 2.0 };
                assert!(
                    (got - want).abs() <= slack,
                    "{s}->{t} point {i}: {got} vs {want}"
                );
            }
            if ratio <= 1.0 {
                assert_eq!(taps.apply(0, &ramp), 0.0);
                assert!((taps.apply(t - 1, &ramp) - (s - 1) as f64).abs() < 1e-3);
            }
        }
    }

    #[test]
    fn constants_stay_exactly_constant() {
        for (w, h) in [(40, 40), (300, 200), (2, 3), (1500, 1500)] {
            let fit = Fit::plan(w, h);
            let mut r = Resampler::new(fit);
            for y in 0..h {
                r.push_row(y, std::iter::repeat_n(1234.0, w as usize));
            }
            assert!(r.finish().iter().all(|&v| v == 1234.0), "{w}x{h}");
        }
    }

    #[test]
    fn crop_is_central() {
        let fit = Fit::plan(300, 200);
        assert_eq!((fit.crop_x, fit.crop_y, fit.crop_side), (50, 0, 200));
        let fit = Fit::plan(100, 301);
        assert_eq!((fit.crop_x, fit.crop_y, fit.crop_side), (0, 100, 100));
    }
}
