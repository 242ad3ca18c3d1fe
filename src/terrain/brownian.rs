//! `generator = "brownian"`: fractional Brownian surfaces by spectral
//! synthesis (D. Saupe, "Algorithms for random fractals", ch. 2 of *The
//! Science of Fractal Images*, 1988: `SpectralSynthesisFM2D`). Random
//! Fourier coefficients with amplitudes `|k|^-(H+1)`, i.e. a power spectrum
//! `|k|^-(2H+2)`, are turned into heights by an inverse FFT; the Hurst
//! exponent `H` (the `hurst` key) sets the roughness: the fractal
//! dimension is `3 - H`.
//!
//! The coefficient of frequency `(kx, ky)` is a hash of the seed and the
//! frequency, not of the grid: a coarser detail is the same mountain with
//! its finest frequencies left out. Every coefficient, column and row is
//! worked out on its own, so the bits do not depend on the thread count.
//!
//! The transform runs in place in the heightfield's own memory: the
//! half-spectrum of a real `N x N` field takes `N` rows of `N + 2` floats,
//! one fewer than the `(N + 1)^2` the field holds. The surface is periodic,
//! so the field's last row and column repeat its first.

use super::fft::{Fft, sin_cos_stable};
use super::normalize::PowTable;
use super::splitmix::{GOLDEN, mix};

/// Standard deviation of the heights at `H = REFERENCE_HURST`, in height
/// units, before `height` scales them: about the square generators'
/// relief (90) over six.
const SIGMA: f32 = 16.0;
/// The Hurst exponent whose surface has a standard deviation of [`SIGMA`].
const REFERENCE_HURST: f32 = 0.8;
/// Other exponents keep that surface's height differences across this
/// share of the width: a rough surface of the same overall relief would
/// be a forest of needles (its slopes grow as the lag shrinks, as
/// `lag^(H-1)`), a smooth one the same. So roughness changes the texture,
/// not how much of the picture is mountain.
const LAG_PARTS: i64 = 64;
/// Frequencies up to this (in each direction) set the scale: nearly all of
/// the variance and of the differences at [`LAG_PARTS`] lie there for every
/// allowed `H`, and a fixed set keeps the scale the same at every detail.
const SCALE_FREQUENCIES: i64 = 128;
/// Columns of the spectrum transformed together (gathered into a scratch
/// block of contiguous columns).
const COLUMN_BLOCK: usize = 8;
/// Fields with fewer points than this are made on one thread.
const PARALLEL_POINTS: usize = 1 << 16;

/// Fills `heights` (`2^exponent + 1` points a side) with a fractional
/// Brownian surface of Hurst exponent `hurst` and mean 0, scaled as
/// [`LAG_PARTS`] says.
pub(crate) fn synthesise(
    heights: &mut [f32],
    exponent: u32,
    hurst: f32,
    seed: u64,
    threads: usize,
) {
    let n = 1usize << exponent;
    debug_assert_eq!(heights.len(), (n + 1) * (n + 1));
    let threads = if n * n < PARALLEL_POINTS {
        1
    } else {
        threads.max(1)
    };
    let spectrum = &mut heights[..n * (n + 2)];
    let coefficients = Coefficients::new(seed, hurst);
    for_rows(spectrum, n + 2, threads, |ky, row| {
        coefficients.fill_row(ky, n, row)
    });
    columns_inverse(spectrum, n, threads);
    let rows = RowInverse::new(n);
    for_rows(spectrum, n + 2, threads, |_, row| rows.run(row));
    compact(heights, n);
}

/// The random coefficients of one seed and Hurst exponent.
struct Coefficients {
    key: u64,
    /// `k2^(-(H+1)/2)`, the amplitude at squared frequency `k2`.
    amplitude: PowTable,
    /// Scales the amplitudes (see [`LAG_PARTS`]).
    scale: f32,
}

impl Coefficients {
    fn new(seed: u64, hurst: f32) -> Self {
        let amplitude = amplitudes(hurst);
        let reference = amplitudes(REFERENCE_HURST);
        let (variance, difference) = moments(&reference);
        // The differences at the lag the reference surface has at SIGMA.
        let wanted = f64::from(SIGMA) * (difference / variance).sqrt();
        let scale = (wanted / moments(&amplitude).1.sqrt()) as f32;
        Coefficients {
            key: mix(seed ^ 0x6672_6163_7461_6c21),
            amplitude,
            scale,
        }
    }

    /// Row `ky_index` of the half-spectrum: `kx` from 0 to `n / 2`,
    /// interleaved re, im. The Nyquist row and column are left at zero,
    /// so a coarser grid holds exactly the finer one's lower frequencies;
    /// the `kx = 0` column is Hermitian (its transform is real).
    fn fill_row(&self, ky_index: usize, n: usize, row: &mut [f32]) {
        let m = n / 2;
        row.fill(0.0);
        if ky_index == m {
            return;
        }
        let ky = if ky_index < m {
            ky_index as i64
        } else {
            ky_index as i64 - n as i64
        };
        for (kx, c) in row.chunks_exact_mut(2).enumerate().take(m) {
            let kx = kx as i64;
            if kx == 0 && ky == 0 {
                continue;
            }
            // The kx = 0 column: the coefficient at -ky is the conjugate of +ky's.
            let (mirror, sign) = if kx == 0 && ky < 0 {
                (-ky, -1.0)
            } else {
                (ky, 1.0)
            };
            let (re, im) = self.gaussians(kx, mirror);
            let a = self.scale * self.amplitude.of((kx * kx + ky * ky) as f32);
            c[0] = a * re;
            c[1] = sign * a * im;
        }
    }

    /// Two near-Gaussian numbers (mean 0, variance 1: sums of four uniform
    /// 16-bit draws) for frequency `(kx, ky)`.
    fn gaussians(&self, kx: i64, ky: i64) -> (f32, f32) {
        let index = ((ky + (1 << 20)) as u64) << 21 | kx as u64;
        let h = mix(self.key.wrapping_add(index.wrapping_mul(GOLDEN)));
        let g = mix(h ^ GOLDEN);
        (irwin_hall(h), irwin_hall(g))
    }
}

/// `k2^(-(H+1)/2)`: the amplitude at squared frequency `k2`.
fn amplitudes(hurst: f32) -> PowTable {
    PowTable::new(-(hurst + 1.0) / 2.0)
}

/// The variance of a surface of these amplitudes (unscaled), and the mean
/// square difference of its heights `1 / LAG_PARTS` of the width apart,
/// over the frequencies up to [`SCALE_FREQUENCIES`].
fn moments(amplitude: &PowTable) -> (f64, f64) {
    // A coefficient off the kx = 0 column stands for itself and its mirror
    // image: a cosine of variance 4 a^2 (two unit Gaussians), as does each
    // +-ky pair of the kx = 0 column. A cosine of frequency kx changes by
    // 2 (1 - cos(2 pi kx / LAG_PARTS)) of its variance over the lag.
    let (mut variance, mut difference) = (0.0f64, 0.0f64);
    let mut add = |kx: i64, ky: i64| {
        let a = f64::from(amplitude.of((kx * kx + ky * ky) as f32));
        let phase = (kx.rem_euclid(LAG_PARTS) as f64 / LAG_PARTS as f64)
            .min(1.0 - kx.rem_euclid(LAG_PARTS) as f64 / LAG_PARTS as f64);
        let (_, cos) = sin_cos_stable(2.0 * std::f64::consts::PI * phase);
        variance += 4.0 * a * a;
        difference += 4.0 * a * a * 2.0 * (1.0 - cos);
    };
    for ky in -SCALE_FREQUENCIES..=SCALE_FREQUENCIES {
        for kx in 1..=SCALE_FREQUENCIES {
            add(kx, ky);
        }
        if ky > 0 {
            add(0, ky);
        }
    }
    (variance, difference)
}

/// The sum of the four 16-bit parts of `bits`, as uniforms in `[0, 1)`,
/// centred and scaled to variance 1 (exact in f32 up to the last step).
fn irwin_hall(bits: u64) -> f32 {
    let sum: u64 = (0..4).map(|i| (bits >> (16 * i)) & 0xFFFF).sum();
    const SQRT_3: f32 = 1.732_050_8;
    (sum as f32 * (1.0 / 65536.0) - 2.0) * SQRT_3
}

/// Runs `f(index, row)` on every row of `rows` (rows of `len` floats), in
/// contiguous blocks on up to `threads` threads.
fn for_rows<F>(rows: &mut [f32], len: usize, threads: usize, f: F)
where
    F: Fn(usize, &mut [f32]) + Sync,
{
    let count = rows.len() / len;
    let per = count.div_ceil(threads.max(1)).max(1);
    let f = &f;
    std::thread::scope(|scope| {
        for (b, block) in rows.chunks_mut(per * len).enumerate() {
            scope.spawn(move || {
                for (i, row) in block.chunks_exact_mut(len).enumerate() {
                    f(b * per + i, row);
                }
            });
        }
    });
}

/// Inverse transforms of the spectrum's columns `kx < n / 2` (the Nyquist
/// column is zero), each column's `n` values spread over the rows.
fn columns_inverse(spectrum: &mut [f32], n: usize, threads: usize) {
    let m = n / 2;
    let per = m.div_ceil(threads).max(1);
    // Each thread gets its own columns of every row.
    let mut parts: Vec<Vec<&mut [f32]>> = (0..m.div_ceil(per)).map(|_| Vec::new()).collect();
    for row in spectrum.chunks_exact_mut(n + 2) {
        for (part, cols) in parts.iter_mut().zip(row[..2 * m].chunks_mut(2 * per)) {
            part.push(cols);
        }
    }
    let fft = Fft::new(n);
    let fft = &fft;
    std::thread::scope(|scope| {
        for part in parts {
            scope.spawn(move || columns_of_part(part, n, fft));
        }
    });
}

/// Transforms the columns of one thread's part, [`COLUMN_BLOCK`] at a time.
fn columns_of_part(mut rows: Vec<&mut [f32]>, n: usize, fft: &Fft) {
    let width = rows.first().map_or(0, |r| r.len() / 2);
    let mut scratch = vec![0.0f32; COLUMN_BLOCK * 2 * n];
    for first in (0..width).step_by(COLUMN_BLOCK) {
        let cols = COLUMN_BLOCK.min(width - first);
        for (y, row) in rows.iter().enumerate() {
            for c in 0..cols {
                let from = 2 * (first + c);
                scratch[c * 2 * n + 2 * y..][..2].copy_from_slice(&row[from..from + 2]);
            }
        }
        for column in scratch.chunks_exact_mut(2 * n).take(cols) {
            fft.inverse(column);
        }
        for (y, row) in rows.iter_mut().enumerate() {
            for c in 0..cols {
                let to = 2 * (first + c);
                row[to..to + 2].copy_from_slice(&scratch[c * 2 * n + 2 * y..][..2]);
            }
        }
    }
}

/// The real inverse transform of one row's half-spectrum, through a
/// complex transform of half the length (the even samples as real parts,
/// the odd as imaginary).
struct RowInverse {
    half: Fft,
    /// `e^{2 pi i j / n}` for `j <= n / 4`, interleaved.
    twiddles: Vec<f32>,
}

impl RowInverse {
    fn new(n: usize) -> Self {
        let m = n / 2;
        let twiddles = (0..=m / 2)
            .flat_map(|j| {
                let (s, c) = sin_cos_stable(std::f64::consts::PI * j as f64 / m as f64);
                [c as f32, s as f32]
            })
            .collect();
        RowInverse {
            half: Fft::new(m),
            twiddles,
        }
    }

    /// `row` holds `X[0..=m]` (`m = n / 2`, interleaved); afterwards its
    /// first `n` floats are the real samples `x[0..n]`.
    fn run(&self, row: &mut [f32]) {
        let m = (row.len() - 2) / 2;
        // Z[j] = E[j] + i O[j], E[j] = X[j] + conj X[m-j],
        // O[j] = (X[j] - conj X[m-j]) W^j; Z[m-j] = conj E[j] + i conj O[j].
        for j in 0..=m / 2 {
            let k = m - j;
            let (xr, xi) = (row[2 * j], row[2 * j + 1]);
            let (yr, yi) = (row[2 * k], row[2 * k + 1]);
            let (er, ei) = (xr + yr, xi - yi);
            let (dr, di) = (xr - yr, xi + yi);
            let (wr, wi) = (self.twiddles[2 * j], self.twiddles[2 * j + 1]);
            let (or, oi) = (dr * wr - di * wi, dr * wi + di * wr);
            row[2 * j] = er - oi;
            row[2 * j + 1] = ei + or;
            if k != j && k < m {
                row[2 * k] = er + oi;
                row[2 * k + 1] = or - ei;
            }
        }
        self.half.inverse(&mut row[..2 * m]);
    }
}

/// Moves the `n` rows of `n + 2` floats into rows of `n + 1` points, each
/// ending with a copy of its first point, and repeats the first row as the
/// last: the periodic surface's closing edges.
fn compact(heights: &mut [f32], n: usize) {
    for y in 0..n {
        let first = heights[y * (n + 2)];
        // Rows move towards the start, so a row's source is never overwritten
        // before it is read.
        heights.copy_within(y * (n + 2)..y * (n + 2) + n, y * (n + 1));
        heights[y * (n + 1) + n] = first;
    }
    heights.copy_within(0..n + 1, n * (n + 1));
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The real transform of a half-spectrum agrees with the sum over the
    /// full Hermitian spectrum it stands for.
    #[test]
    fn the_row_transform_is_the_real_fourier_sum() {
        let n = 16;
        let m = n / 2;
        let mut row: Vec<f32> = (0..n + 2).map(|i| ((i * 29 % 13) as f32) - 6.0).collect();
        // X[0] and X[m] of a real signal's spectrum are real.
        row[1] = 0.0;
        row[2 * m + 1] = 0.0;
        let spectrum = row.clone();
        RowInverse::new(n).run(&mut row);
        for (t, &got) in row[..n].iter().enumerate() {
            let mut x = 0.0f64;
            for k in 0..n {
                let (re, im) = if k <= m {
                    (spectrum[2 * k] as f64, spectrum[2 * k + 1] as f64)
                } else {
                    (
                        spectrum[2 * (n - k)] as f64,
                        -spectrum[2 * (n - k) + 1] as f64,
                    )
                };
                let a = 2.0 * std::f64::consts::PI * (k * t) as f64 / n as f64;
                x += re * a.cos() - im * a.sin();
            }
            assert!((got as f64 - x).abs() < 1e-3, "x[{t}] {got} vs {x}");
        }
    }

    #[test]
    fn compacting_closes_the_periodic_edges() {
        let n = 4;
        let mut h: Vec<f32> = (0..(n + 1) * (n + 1)).map(|i| i as f32).collect();
        let rows: Vec<Vec<f32>> = (0..n)
            .map(|y| h[y * (n + 2)..y * (n + 2) + n].to_vec())
            .collect();
        compact(&mut h, n);
        for y in 0..=n {
            let want = &rows[y % n];
            for x in 0..=n {
                assert_eq!(h[y * (n + 1) + x], want[x % n], "({x}, {y})");
            }
        }
    }
}
