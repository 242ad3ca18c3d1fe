//! Whole-field passes after the subdivision: sea level, contour, height.
//!
//! Each pass is elementwise (or a min/max), so cutting the field into
//! chunks for threads cannot change a single bit of the result.

use super::params::Params;
use super::{Heightfield, TRIANGLE_PEAK_PER_HEIGHT};

/// Fields smaller than this many points are processed on one thread.
const PARALLEL_POINTS: usize = 1 << 18;

/// How much deeper than the land is high the triangle generator's sea may
/// be before the depths, not the peak, set the scale.
const DEPTH_CAP: f32 = 4.0;

/// Square generators: moves the water line and scales the relief by
/// `height / 5` (see `generate` for the units).
pub(crate) fn finish_square(field: &mut Heightfield, p: &Params, threads: usize) {
    let scale = p.height / 5.0;
    let shift = if p.sea_level == 0.0 {
        0.0
    } else {
        let (lo, hi) = min_max(field.heights(), threads);
        water_line(p.sea_level, lo, hi)
    };
    if shift != 0.0 || scale != 1.0 {
        map_in_place(field.heights_mut(), threads, |h| (h - shift) * scale);
    }
}

/// Where `sea_level` puts the water in a field spanning `lo..=hi`: that
/// fraction of the way from the generator's zero up to the highest point
/// (`sea_level > 0`) or down to the lowest (`sea_level < 0`).
fn water_line(sea_level: f32, lo: f32, hi: f32) -> f32 {
    if sea_level >= 0.0 {
        sea_level * hi.max(0.0)
    } else {
        -sea_level * lo.min(0.0)
    }
}

/// Triangle generator: moves the water line, then seed 000's NormalizeMap:
/// heights raised to the contour power (sign kept) and scaled so the
/// highest point is `height * TRIANGLE_PEAK_PER_HEIGHT`.
pub(crate) fn finish_triangle(field: &mut Heightfield, p: &Params, threads: usize) {
    let (lo, hi) = min_max(field.heights(), threads);
    let shift = water_line(p.sea_level, lo, hi);
    let (top, bottom) = (hi - shift, lo - shift);
    let mut reference = top.max(-bottom / DEPTH_CAP);
    if !(reference > 0.0 && reference.is_finite()) {
        reference = 1.0;
    }
    let peak = p.height * TRIANGLE_PEAK_PER_HEIGHT;
    if p.contour == 1.0 {
        let scale = peak / reference;
        map_in_place(field.heights_mut(), threads, |h| (h - shift) * scale);
    } else {
        let (inverse, contour) = (1.0 / reference, p.contour);
        map_in_place(field.heights_mut(), threads, |h| {
            let d = h - shift;
            let v = pow_stable(d.abs() * inverse, contour) * peak;
            if d < 0.0 { -v } else { v }
        });
    }
}

/// Lowest and highest value of `heights` (`(0, 0)` when empty).
pub(crate) fn min_max(heights: &[f32], threads: usize) -> (f32, f32) {
    let fold = |chunk: &[f32]| {
        // Eight independent lanes, so the compiler can use SIMD min/max.
        let (mut lo, mut hi) = ([f32::INFINITY; 8], [f32::NEG_INFINITY; 8]);
        let mut lanes = chunk.chunks_exact(8);
        for c in &mut lanes {
            for i in 0..8 {
                lo[i] = if c[i] < lo[i] { c[i] } else { lo[i] };
                hi[i] = if c[i] > hi[i] { c[i] } else { hi[i] };
            }
        }
        let rest = lanes.remainder().iter();
        lo.iter()
            .zip(&hi)
            .map(|(&l, &h)| (l, h))
            .chain(rest.map(|&h| (h, h)))
            .fold((f32::INFINITY, f32::NEG_INFINITY), |(lo, hi), (l, h)| {
                (lo.min(l), hi.max(h))
            })
    };
    let parts: Vec<(f32, f32)> = if threads > 1 && heights.len() >= PARALLEL_POINTS {
        let chunk = heights.len().div_ceil(threads);
        std::thread::scope(|scope| {
            let handles: Vec<_> = heights
                .chunks(chunk)
                .map(|c| scope.spawn(move || fold(c)))
                .collect();
            handles
                .into_iter()
                .map(|h| h.join().expect("min/max thread panicked"))
                .collect()
        })
    } else {
        vec![fold(heights)]
    };
    let (lo, hi) = parts
        .into_iter()
        .fold((f32::INFINITY, f32::NEG_INFINITY), |(lo, hi), (a, b)| {
            (lo.min(a), hi.max(b))
        });
    if lo > hi { (0.0, 0.0) } else { (lo, hi) }
}

/// Replaces every height `h` with `f(h)`.
pub(crate) fn map_in_place<F>(heights: &mut [f32], threads: usize, f: F)
where
    F: Fn(f32) -> f32 + Sync,
{
    let apply = |chunk: &mut [f32]| chunk.iter_mut().for_each(|h| *h = f(*h));
    if threads > 1 && heights.len() >= PARALLEL_POINTS {
        let chunk = heights.len().div_ceil(threads);
        std::thread::scope(|scope| {
            let mut chunks = heights.chunks_mut(chunk);
            let first = chunks.next();
            for c in chunks {
                scope.spawn(|| apply(c));
            }
            if let Some(c) = first {
                apply(c);
            }
        });
    } else {
        apply(heights);
    }
}

/// `x^p` for `x >= 0`, computed with +, -, *, / only so that it gives the
/// same bits on every platform (`f32::powf` calls the platform's libm,
/// whose last bit may differ). Accurate to about 1e-12 relative.
pub(crate) fn pow_stable(x: f32, p: f32) -> f32 {
    if x <= 0.0 || x.is_nan() {
        return 0.0;
    }
    exp2_stable(f64::from(p) * log2_stable(f64::from(x))) as f32
}

/// Base-2 logarithm of a positive, finite `x`.
fn log2_stable(x: f64) -> f64 {
    const LOG2_E: f64 = std::f64::consts::LOG2_E;
    let bits = x.to_bits();
    let mut exponent = ((bits >> 52) & 0x7FF) as i64 - 1023;
    let mut m = f64::from_bits((bits & 0x000F_FFFF_FFFF_FFFF) | 0x3FF0_0000_0000_0000);
    if exponent == -1023 {
        // Subnormal: normalise through a multiplication by 2^64.
        return log2_stable(x * 18_446_744_073_709_551_616.0) - 64.0;
    }
    if m > std::f64::consts::SQRT_2 {
        m *= 0.5;
        exponent += 1;
    }
    // ln(m) = 2 atanh(t), t = (m - 1) / (m + 1), |t| <= 0.172.
    let t = (m - 1.0) / (m + 1.0);
    let t2 = t * t;
    let series = 1.0
        + t2 * (1.0 / 3.0
            + t2 * (1.0 / 5.0
                + t2 * (1.0 / 7.0 + t2 * (1.0 / 9.0 + t2 * (1.0 / 11.0 + t2 * (1.0 / 13.0))))));
    exponent as f64 + 2.0 * t * series * LOG2_E
}

/// 2 to the power `y`, saturating far outside the f32 range.
fn exp2_stable(y: f64) -> f64 {
    let y = y.clamp(-200.0, 200.0);
    let n = (y + 0.5).floor();
    let g = (y - n) * std::f64::consts::LN_2;
    // e^g for |g| <= 0.347 by its Taylor series to g^12.
    let mut term = 1.0;
    let mut sum = 1.0;
    for k in 1..=12 {
        term *= g / k as f64;
        sum += term;
    }
    sum * f64::from_bits(((n as i64 + 1023) as u64) << 52)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn stable_pow_matches_libm_closely() {
        for &x in &[1e-6f32, 0.001, 0.1, 0.5, 0.9999, 1.0, 1.5, 3.0, 77.0, 1e6] {
            for &p in &[0.25f32, 0.5, 1.0, 1.5, 2.0, 3.0, 5.0] {
                let ours = pow_stable(x, p) as f64;
                let libm = (x as f64).powf(p as f64);
                assert!(
                    ((ours - libm) / libm).abs() < 1e-6,
                    "{x}^{p}: {ours} vs {libm}"
                );
            }
        }
        assert_eq!(pow_stable(0.0, 0.5), 0.0);
        assert_eq!(pow_stable(-1.0, 2.0), 0.0);
    }

    #[test]
    fn min_max_is_the_same_on_one_or_many_threads() {
        let heights: Vec<f32> = (0..300_000u64)
            .map(|i| ((i * 7919) % 1000) as f32 - 400.0)
            .collect();
        assert_eq!(min_max(&heights, 1), (-400.0, 599.0));
        assert_eq!(min_max(&heights, 3), (-400.0, 599.0));
        assert_eq!(min_max(&[], 2), (0.0, 0.0));
    }
}
