//! Whole-field passes after the subdivision: sea level, contour, height.
//!
//! Each pass is elementwise (or a min/max), so cutting the field into
//! chunks for threads cannot change a single bit of the result.

use super::coast;
use super::params::Params;
use super::subdivide::Extremes;
use super::{Heightfield, TRIANGLE_PEAK_PER_HEIGHT};
use crate::settings::WaterLine;

/// Fields smaller than this many points are processed on one thread.
const PARALLEL_POINTS: usize = 1 << 18;

/// How much deeper than the land is high the triangle generator's sea may
/// be before the depths, not the peak, set the scale.
const DEPTH_CAP: f32 = 4.0;

/// Square generators: moves the water line and scales the relief by
/// `height / 5` (see `generate` for the units). `extremes` are the field's,
/// if already known.
pub(crate) fn finish_square(
    field: &mut Heightfield,
    p: &Params,
    threads: usize,
    extremes: Option<Extremes>,
) {
    let scale = p.height / 5.0;
    let zero = match p.water_line {
        WaterLine::Coast => coast::reference(field),
        WaterLine::Generator => 0.0,
    };
    let shift = if p.sea_level == 0.0 {
        zero
    } else {
        let e = extremes.unwrap_or_else(|| min_max(field.heights(), threads));
        zero + water_line(p.sea_level, e.lo - zero, e.hi - zero)
    };
    if shift != 0.0 || scale != 1.0 {
        map_in_place(field.heights_mut(), threads, |h| (h - shift) * scale);
    }
    if p.water_line == WaterLine::Coast {
        coast::lower_the_front(field);
    }
}

/// Where `sea_level` puts the water in a field spanning `lo..=hi` around
/// the reference zero: that fraction of the way from the zero up to the highest point
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
/// highest point is `height * TRIANGLE_PEAK_PER_HEIGHT`. `extremes` are
/// the field's, if already known.
pub(crate) fn finish_triangle(
    field: &mut Heightfield,
    p: &Params,
    threads: usize,
    extremes: Option<Extremes>,
) {
    let e = extremes.unwrap_or_else(|| min_max(field.heights(), threads));
    let (lo, hi) = (e.lo, e.hi);
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
        let (inverse, power) = (1.0 / reference, PowTable::new(p.contour));
        map_in_place(field.heights_mut(), threads, |h| {
            let d = h - shift;
            (power.of(d.abs() * inverse) * peak).copysign(d)
        });
    }
}

/// Lowest and highest value of `heights` (both 0 when empty).
pub(crate) fn min_max(heights: &[f32], threads: usize) -> Extremes {
    let parts: Vec<Extremes> = if threads > 1 && heights.len() >= PARALLEL_POINTS {
        let chunk = heights.len().div_ceil(threads);
        std::thread::scope(|scope| {
            let handles: Vec<_> = heights
                .chunks(chunk)
                .map(|c| scope.spawn(move || Extremes::NONE.with_all(c)))
                .collect();
            handles
                .into_iter()
                .map(|h| h.join().expect("min/max thread panicked"))
                .collect()
        })
    } else {
        vec![Extremes::NONE.with_all(heights)]
    };
    let e = parts.into_iter().fold(Extremes::NONE, Extremes::with);
    if e.lo > e.hi {
        Extremes { lo: 0.0, hi: 0.0 }
    } else {
        e
    }
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

/// Mantissa steps per octave in [`PowTable`].
const MANTISSA_STEPS: usize = 256;

/// `x^p` for one `p` and many `x`: `2^(p e)` per binary exponent `e` times
/// `m^p` for the mantissa `m` in `[1, 2)`, interpolated between 257 points.
/// Built with [`pow_stable`], so as platform-stable as it, and far faster
/// over a field. Relative error below 5e-5 (for p = 5; less for smaller p).
pub(crate) struct PowTable {
    /// `2^(p e)` for the f32 exponent field `e + 127` (0..=255).
    octaves: [f32; 256],
    /// `m^p` at `m = 1 + i / MANTISSA_STEPS`.
    mantissas: [f32; MANTISSA_STEPS + 1],
}

impl PowTable {
    /// The table of `x^p`.
    pub(crate) fn new(p: f32) -> Self {
        let octaves = std::array::from_fn(|field| {
            let e = field as f64 - 127.0;
            let v = exp2_stable(f64::from(p) * e);
            v.min(f64::from(f32::MAX)) as f32
        });
        let mantissas =
            std::array::from_fn(|i| pow_stable(1.0 + i as f32 / MANTISSA_STEPS as f32, p));
        PowTable { octaves, mantissas }
    }

    /// `x^p` for `x >= 0` (0 for zero, subnormal, infinite and NaN `x`).
    #[inline]
    pub(crate) fn of(&self, x: f32) -> f32 {
        const FRACTION_BITS: u32 = 23 - MANTISSA_STEPS.trailing_zeros();
        let bits = x.to_bits();
        let field = ((bits >> 23) & 0xFF) as usize;
        // Exponent field 0: zero or subnormal; 255: infinite or NaN. The
        // sign bit is ignored: callers pass magnitudes.
        if field == 0 || field == 255 {
            return 0.0;
        }
        let mantissa = bits & 0x7F_FFFF;
        let i = (mantissa >> FRACTION_BITS) as usize;
        let t = (mantissa & ((1 << FRACTION_BITS) - 1)) as i32 as f32
            * (1.0 / (1 << FRACTION_BITS) as f32);
        let (lo, hi) = (self.mantissas[i], self.mantissas[i + 1]);
        (lo + (hi - lo) * t) * self.octaves[field]
    }
}

/// `x^p` for `x >= 0`, computed with +, -, *, / and bit operations only,
/// so that it gives the same bits on every platform (`f32::powf` calls the
/// platform's libm, whose last bit may differ). Relative error below 1e-9
/// before the final rounding to f32.
pub(crate) fn pow_stable(x: f32, p: f32) -> f32 {
    if x > 0.0 {
        exp2_stable(f64::from(p) * log2_stable(f64::from(x))) as f32
    } else {
        0.0 // also for NaN
    }
}

/// Base-2 logarithm of a positive normal `x` (any positive f32 widened to
/// f64 is normal).
fn log2_stable(x: f64) -> f64 {
    const LOG2_E: f64 = std::f64::consts::LOG2_E;
    let bits = x.to_bits();
    let exponent = ((bits >> 52) & 0x7FF) as i64 - 1023;
    let m = f64::from_bits((bits & 0x000F_FFFF_FFFF_FFFF) | 0x3FF0_0000_0000_0000);
    // Halve mantissas above sqrt(2) so that |t| <= 0.172 below.
    let big = m > std::f64::consts::SQRT_2;
    let m = if big { 0.5 * m } else { m };
    let exponent = exponent + i64::from(big);
    // ln(m) = 2 atanh(t), t = (m - 1) / (m + 1): an odd series in t.
    let t = (m - 1.0) / (m + 1.0);
    let t2 = t * t;
    let series = 1.0 + t2 * (1.0 / 3.0 + t2 * (1.0 / 5.0 + t2 * (1.0 / 7.0 + t2 * (1.0 / 9.0))));
    exponent as f64 + (2.0 * LOG2_E) * t * series
}

/// 2 to the power `y`, saturating far outside the f32 range.
fn exp2_stable(y: f64) -> f64 {
    // ln(2)^k / k!: the Taylor series of 2^f.
    const C: [f64; 9] = [
        1.0,
        std::f64::consts::LN_2,
        0.240_226_506_959_100_72,
        0.055_504_108_664_821_58,
        0.009_618_129_107_628_477,
        0.001_333_355_814_642_844_3,
        0.000_154_035_303_933_816_1,
        1.525_273_380_405_984_1e-5,
        1.321_548_679_014_431e-6,
    ];
    let y = y.clamp(-200.0, 200.0);
    // n = round(y) without libm's floor: truncate, then step down if the
    // truncation went up (negative y).
    let r = y + 0.5;
    let truncated = r as i64;
    let n = truncated - i64::from(r < truncated as f64);
    let f = y - n as f64;
    let poly = C.iter().rev().fold(0.0, |acc, &c| acc * f + c);
    poly * f64::from_bits(((n + 1023) as u64) << 52)
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
                    ((ours - libm) / libm).abs() < 3e-7,
                    "{x}^{p}: {ours} vs {libm}"
                );
            }
        }
        assert_eq!(pow_stable(0.0, 0.5), 0.0);
        assert_eq!(pow_stable(-1.0, 2.0), 0.0);
    }

    #[test]
    fn stable_pow_holds_over_a_sweep() {
        for i in 0..=1200 {
            let x = 10f32.powf(-6.0 + i as f32 / 100.0);
            for j in 0..=19 {
                let p = 0.25 + j as f32 * 0.25;
                let (ours, libm) = (pow_stable(x, p) as f64, (x as f64).powf(p as f64));
                assert!(
                    ((ours - libm) / libm).abs() < 3e-7,
                    "{x}^{p}: {ours} vs {libm}"
                );
            }
        }
    }

    #[test]
    fn the_pow_table_stays_close_to_pow() {
        for &p in &[0.25f32, 0.5, 1.5, 2.0, 3.0, 5.0] {
            let table = PowTable::new(p);
            for i in 0..=4000 {
                let x = 10f32.powf(-4.0 + i as f32 / 1000.0);
                let (ours, libm) = (table.of(x) as f64, (x as f64).powf(p as f64));
                assert!(
                    ((ours - libm) / libm).abs() < 5e-5,
                    "{x}^{p}: {ours} vs {libm}"
                );
            }
            assert_eq!(table.of(0.0), 0.0);
            assert_eq!(table.of(1.0), 1.0);
            assert_eq!(table.of(f32::NAN), 0.0);
        }
    }

    #[test]
    fn min_max_is_the_same_on_one_or_many_threads() {
        let heights: Vec<f32> = (0..300_000u64)
            .map(|i| ((i * 7919) % 1000) as f32 - 400.0)
            .collect();
        let expected = Extremes {
            lo: -400.0,
            hi: 599.0,
        };
        assert_eq!(min_max(&heights, 1), expected);
        assert_eq!(min_max(&heights, 3), expected);
        assert_eq!(min_max(&[], 2), Extremes { lo: 0.0, hi: 0.0 });
    }
}
