//! A small radix-2 fast Fourier transform for the Brownian generator.
//!
//! Written here rather than taken from a crate so that a seed gives the same
//! bits on every platform: its twiddle factors come from series in `+`, `-`,
//! `*` and `/` only (no libm `sin`/`cos`), and its butterflies use no SIMD
//! path chosen at run time, whose rounding could differ between machines.

/// The inverse (positive exponent, unnormalised) transform of one length.
pub(crate) struct Fft {
    len: usize,
    /// For each stage of half-width `h` (1, 2, 4, ...): `e^{i pi j / h}` for
    /// `j < h`, interleaved re, im; stage `h` starts at float `2 (h - 1)`.
    twiddles: Vec<f32>,
    /// The bit-reversed index of each position.
    reversed: Vec<u32>,
}

impl Fft {
    /// A transform of `len` points (a power of two, at least 1).
    pub(crate) fn new(len: usize) -> Self {
        assert!(
            len.is_power_of_two(),
            "FFT length {len} is not a power of two"
        );
        let mut twiddles = Vec::with_capacity(2 * len);
        let mut h = 1;
        while h < len {
            for j in 0..h {
                let (s, c) = sin_cos_stable(std::f64::consts::PI * j as f64 / h as f64);
                twiddles.extend([c as f32, s as f32]);
            }
            h *= 2;
        }
        let bits = len.trailing_zeros();
        let reversed = (0..len as u32)
            .map(|i| {
                if bits == 0 {
                    0
                } else {
                    i.reverse_bits() >> (32 - bits)
                }
            })
            .collect();
        Fft {
            len,
            twiddles,
            reversed,
        }
    }

    /// Replaces `data` (`len` complex values, interleaved re, im) with
    /// `x[n] = sum_k data[k] e^{2 pi i k n / len}`.
    pub(crate) fn inverse(&self, data: &mut [f32]) {
        debug_assert_eq!(data.len(), 2 * self.len);
        for (i, &r) in self.reversed.iter().enumerate() {
            let r = r as usize;
            if r > i {
                data.swap(2 * i, 2 * r);
                data.swap(2 * i + 1, 2 * r + 1);
            }
        }
        let mut h = 1;
        while h < self.len {
            let tw = &self.twiddles[2 * (h - 1)..2 * (2 * h - 1)];
            for block in data.chunks_exact_mut(4 * h) {
                let (a, b) = block.split_at_mut(2 * h);
                for ((a, b), w) in a
                    .chunks_exact_mut(2)
                    .zip(b.chunks_exact_mut(2))
                    .zip(tw.chunks_exact(2))
                {
                    let tr = b[0] * w[0] - b[1] * w[1];
                    let ti = b[0] * w[1] + b[1] * w[0];
                    b[0] = a[0] - tr;
                    b[1] = a[1] - ti;
                    a[0] += tr;
                    a[1] += ti;
                }
            }
            h *= 2;
        }
    }
}

/// `(sin x, cos x)` for `0 <= x <= pi` from their Taylor series, in f64 with
/// `+`, `-`, `*`, `/` only: the same bits on every platform, and within
/// 1e-15 of the truth (far below an f32's last bit).
pub(crate) fn sin_cos_stable(x: f64) -> (f64, f64) {
    // Halving the angle to at most pi/2 keeps the series short and exact
    // enough; cos(x) = 1 - 2 sin^2(x/2), sin(x) = 2 sin(x/2) cos(x/2).
    let half = 0.5 * x;
    let (mut s, mut c) = (0.0, 0.0);
    let (mut term_s, mut term_c) = (half, 1.0);
    let h2 = half * half;
    for k in 0..12 {
        s += term_s;
        c += term_c;
        let k = k as f64;
        term_s *= -h2 / ((2.0 * k + 2.0) * (2.0 * k + 3.0));
        term_c *= -h2 / ((2.0 * k + 1.0) * (2.0 * k + 2.0));
    }
    (2.0 * s * c, 1.0 - 2.0 * s * s)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn stable_sin_cos_match_libm() {
        for i in 0..=1000 {
            let x = std::f64::consts::PI * i as f64 / 1000.0;
            let (s, c) = sin_cos_stable(x);
            assert!((s - x.sin()).abs() < 1e-14, "sin {x}");
            assert!((c - x.cos()).abs() < 1e-14, "cos {x}");
        }
    }

    /// The transform agrees with the sum that defines it.
    #[test]
    fn the_fft_is_the_discrete_fourier_sum() {
        for len in [1usize, 2, 4, 8, 64] {
            let input: Vec<f32> = (0..2 * len).map(|i| ((i * 37 % 11) as f32) - 5.0).collect();
            let mut fast = input.clone();
            Fft::new(len).inverse(&mut fast);
            for n in 0..len {
                let (mut re, mut im) = (0.0f64, 0.0f64);
                for k in 0..len {
                    let a = 2.0 * std::f64::consts::PI * (k * n) as f64 / len as f64;
                    let (xr, xi) = (input[2 * k] as f64, input[2 * k + 1] as f64);
                    re += xr * a.cos() - xi * a.sin();
                    im += xr * a.sin() + xi * a.cos();
                }
                assert!((fast[2 * n] as f64 - re).abs() < 1e-3, "len {len} n {n}");
                assert!(
                    (fast[2 * n + 1] as f64 - im).abs() < 1e-3,
                    "len {len} n {n}"
                );
            }
        }
    }
}
