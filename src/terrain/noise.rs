//! One random value per grid point, from a hash of (seed, point).
//!
//! A counter-based generator instead of a stream: a point's value does not
//! depend on the order points are visited, so rows can be split across
//! threads, and a point has the same value at every detail level (its
//! position is taken on the finest, 4097-point grid). A coarser detail level
//! is therefore the same mountain with fewer points, not a different one.

use super::heightfield::MAX_EXPONENT;
use super::splitmix::{GOLDEN, mix};

/// How a point's random value is spread over `[-1, 1]`: each seed
/// program's own numbers (`look = ...`), ours uniform.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Spread {
    /// One uniform number in `[-1, 1)`: ours.
    Uniform,
    /// FL3's pseudo-normal numbers: "Rand := Random(Envelope) +
    /// Random(Envelope) - Envelope", the sum of two uniform numbers, here
    /// halved so they keep the range `[-1, 1)`. Their density is a
    /// triangle, highest at 0 (a "sawtooth" in the article's word,
    /// "vaguely like a normal distribution").
    Triangle,
    /// The essay's `Math.cos(random * Math.PI)` with `random` uniform in
    /// `[0, 1)`: the arcsine law on `[-1, 1]`, densest at its ends
    /// (variance 1/2 where a uniform number's is 1/3).
    Arcsine,
}

/// Random values in `[-1, 1]` (`[-1, 1)` but for [`Spread::Arcsine`])
/// keyed by seed and grid point.
///
/// A row's key comes from a 64-bit mix of (seed, row); the value of a point
/// is a 32-bit hash (Wellons' lowbias32) of the row key and the column. The
/// 32-bit half lets a whole row of values be computed with SIMD lanes.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Noise {
    key: u64,
    shift: u32,
    /// How the values are spread (FL3's and the essay's own numbers).
    spread: Spread,
    /// The last column and row of the grid, when its border's values are
    /// all 0 (the essay's undisplaced edges).
    still_border: Option<usize>,
}

impl Noise {
    /// Values for a grid of `2^exponent + 1` points a side.
    pub(crate) fn new(seed: u64, exponent: u32) -> Self {
        Noise {
            // Mixing the seed first keeps seeds that differ by a multiple of
            // GOLDEN from sharing row keys.
            key: mix(seed ^ 0x6D6F_756E_7461_696E),
            shift: MAX_EXPONENT.saturating_sub(exponent),
            spread: Spread::Uniform,
            still_border: None,
        }
    }

    /// These values, or (`on`) 0 on the grid's border: the essay's "points on
    /// the edge of the original square" with no displacement, so its edges
    /// run straight between its corners, and its corners (all at the base in
    /// the essay) start at 0.
    pub(crate) fn still_edges(self, on: bool) -> Self {
        let last = 1usize << (MAX_EXPONENT - self.shift);
        Noise {
            still_border: on.then_some(last),
            ..self
        }
    }

    /// The same points' values spread as `spread` says: from the same
    /// hashes, so [`Spread::Uniform`] gives these values' bits.
    pub(crate) fn spread(self, spread: Spread) -> Self {
        Noise { spread, ..self }
    }

    /// The value at column `x`, row `y`, in `[-1, 1]`.
    pub(crate) fn at(&self, x: usize, y: usize) -> f32 {
        let mut out = [0.0];
        self.fill_row(y, x, 1, 1.0, &mut out);
        out[0]
    }

    /// `out[i] = scale * value(first + i * stride, y)`.
    #[inline]
    pub(crate) fn fill_row(
        &self,
        y: usize,
        first: usize,
        stride: usize,
        scale: f32,
        out: &mut [f32],
    ) {
        self.fill_values(y, first, stride, scale, out);
        if let Some(last) = self.still_border {
            if y == 0 || y == last {
                out.fill(0.0);
            } else {
                for (i, o) in out.iter_mut().enumerate() {
                    let x = first + i * stride;
                    if x == 0 || x == last {
                        *o = 0.0;
                    }
                }
            }
        }
    }

    /// [`Noise::fill_row`]'s values before the border is stilled.
    #[inline]
    fn fill_values(&self, y: usize, first: usize, stride: usize, scale: f32, out: &mut [f32]) {
        let row_key = self.row_key(y);
        let first = ((first as u64) << self.shift) as u32;
        let stride = ((stride as u64) << self.shift) as u32;
        // The top 24 bits, signed, convert to f32 exactly; `step` is `scale`
        // times a power of two, so `level * step` is `scale * value` rounded
        // once: the same bits on every platform.
        let step = scale * (1.0 / (1u32 << 23) as f32);
        // The hash input `row_key + column * GOLDEN32`, stepped by addition.
        let mut input = row_key.wrapping_add(first.wrapping_mul(GOLDEN32));
        let increment = stride.wrapping_mul(GOLDEN32);
        match self.spread {
            Spread::Uniform => {
                for o in out.iter_mut() {
                    let bits = lowbias32(input);
                    *o = ((bits as i32) >> 8) as f32 * step;
                    input = input.wrapping_add(increment);
                }
            }
            Spread::Triangle => {
                for o in out.iter_mut() {
                    // The second number from the same input, hashed apart.
                    let a = (lowbias32(input) as i32) >> 8;
                    let b = (lowbias32(input ^ SECOND) as i32) >> 8;
                    // Halved in integers: 24 bits, exact in an f32.
                    *o = ((a + b) >> 1) as f32 * step;
                    input = input.wrapping_add(increment);
                }
            }
            Spread::Arcsine => {
                for o in out.iter_mut() {
                    let level = (lowbias32(input) as i32) >> 8;
                    *o = scale * essay_cos(level);
                    input = input.wrapping_add(increment);
                }
            }
        }
    }
    /// The key of row `y`, taken on the finest grid.
    fn row_key(&self, y: usize) -> u32 {
        let gy = (y as u64) << self.shift;
        (mix(self.key.wrapping_add((gy + 1).wrapping_mul(GOLDEN))) >> 32) as u32
    }
}

/// The essay's `cos(random * PI)` for `random = (level / 2^23 + 1) / 2`,
/// a uniform `level` in `-2^23..2^23` (`random` uniform in `[0, 1)`):
/// `cos(PI (v + 1) / 2) = -sin(PI v / 2)` for `v = level / 2^23`. By a
/// series in plain arithmetic rather than `f64::sin`, so no platform's
/// libm can move a height: the terms to `t^15 / 15!` leave an error
/// below 1e-11, far under an f32's step.
fn essay_cos(level: i32) -> f32 {
    let t = std::f64::consts::FRAC_PI_2 * (f64::from(level) / f64::from(1u32 << 23));
    let t2 = t * t;
    // sin t = t (1 - t^2/(2*3) (1 - t^2/(4*5) (1 - ...))).
    let sin = [210.0, 156.0, 110.0, 72.0, 42.0, 20.0, 6.0]
        .iter()
        .fold(1.0, |inner, k| 1.0 - t2 / k * inner)
        * t;
    -sin as f32
}

/// Flips the hash input for a point's second number (FL3's pseudo-normal
/// values, [`Spread::Triangle`]), so its two numbers are independent.
const SECOND: u32 = 0x5bd1_e995;

/// 2^32 / golden ratio, odd: spreads consecutive columns over the hash input.
const GOLDEN32: u32 = 0x9E37_79B9;

/// Chris Wellons' lowbias32 integer hash: full avalanche in 32 bits.
#[inline(always)]
fn lowbias32(mut x: u32) -> u32 {
    x ^= x >> 16;
    x = x.wrapping_mul(0x7FEB_352D);
    x ^= x >> 15;
    x = x.wrapping_mul(0x846C_A68B);
    x ^ (x >> 16)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn values_stay_in_range_and_average_near_zero() {
        let noise = Noise::new(42, 8);
        let mut sum = 0.0f64;
        for y in 0..257 {
            for x in 0..257 {
                let v = noise.at(x, y);
                assert!((-1.0..1.0).contains(&v), "{v} out of range");
                sum += v as f64;
            }
        }
        let mean = sum / (257.0 * 257.0);
        assert!(mean.abs() < 0.01, "mean {mean} is biased");
    }

    #[test]
    fn pseudo_normal_values_stay_in_range_and_leave_ours_alone() {
        let ours = Noise::new(42, 8);
        let fl3 = ours.spread(Spread::Triangle);
        let (mut middle, mut n) = (0, 0);
        for y in 0..257 {
            for x in 0..257 {
                let v = fl3.at(x, y);
                assert!((-1.0..1.0).contains(&v), "{v} out of range");
                middle += usize::from(v.abs() < 0.2);
                n += 1;
            }
        }
        // A triangle density puts 36% within 0.2 of 0 (a uniform one 20%).
        let share = middle as f64 / n as f64;
        assert!((0.33..0.39).contains(&share), "{share}");
        assert_eq!(
            ours.spread(Spread::Uniform).at(5, 9).to_bits(),
            ours.at(5, 9).to_bits()
        );
        assert_ne!(fl3.at(5, 9).to_bits(), ours.at(5, 9).to_bits());
    }

    /// Variance and kurtosis of `noise`'s values on a `2^exponent + 1`
    /// grid.
    fn moments(noise: &Noise, exponent: u32) -> (f64, f64) {
        let n = (1usize << exponent) + 1;
        let (mut m2, mut m4, mut mean) = (0.0f64, 0.0f64, 0.0f64);
        for y in 0..n {
            for x in 0..n {
                let v = noise.at(x, y) as f64;
                assert!((-1.0..=1.0).contains(&v), "{v} out of range");
                (mean, m2, m4) = (mean + v, m2 + v * v, m4 + v.powi(4));
            }
        }
        let count = (n * n) as f64;
        assert!((mean / count).abs() < 0.01, "mean {}", mean / count);
        let var = m2 / count;
        (var, m4 / count / (var * var))
    }

    #[test]
    fn the_essays_values_follow_the_arcsine_law() {
        let ours = Noise::new(42, 10);
        let essay = ours.spread(Spread::Arcsine);
        // A million values: the arcsine law's variance 1/2 and kurtosis
        // 3/2, a uniform number's 1/3 and 9/5.
        let (var, kurtosis) = moments(&essay, 10);
        assert!((var - 0.5).abs() < 0.005, "essay variance {var}");
        assert!((kurtosis - 1.5).abs() < 0.01, "essay kurtosis {kurtosis}");
        let (var, kurtosis) = moments(&ours, 10);
        assert!((var - 1.0 / 3.0).abs() < 0.005, "our variance {var}");
        assert!((kurtosis - 1.8).abs() < 0.01, "our kurtosis {kurtosis}");
        // cos(random * PI) of the same uniform number: its share below
        // any c is acos(-c) / PI (here at c = -0.9, 0 and 0.5).
        let mut below = [0usize; 3];
        for y in 0..257 {
            for x in 0..257 {
                let (u, v) = (ours.at(x, y), essay.at(x, y));
                let random = (u as f64 + 1.0) / 2.0;
                let exact = (random * std::f64::consts::PI).cos();
                assert!((v as f64 - exact).abs() < 1e-6, "{u}: {v} for {exact}");
                for (b, c) in below.iter_mut().zip([-0.9, 0.0, 0.5]) {
                    *b += usize::from(v < c);
                }
            }
        }
        for (b, c) in below.iter().zip([-0.9f64, 0.0, 0.5]) {
            let share = *b as f64 / (257.0 * 257.0);
            let law = (-c).acos() / std::f64::consts::PI;
            assert!((share - law).abs() < 0.01, "below {c}: {share}, law {law}");
        }
    }

    #[test]
    fn filled_rows_match_single_points() {
        for spread in [Spread::Uniform, Spread::Triangle, Spread::Arcsine] {
            let noise = Noise::new(99, 10).spread(spread);
            let mut row = [0.0f32; 9];
            noise.fill_row(5, 3, 4, 2.5, &mut row);
            for (i, &v) in row.iter().enumerate() {
                assert_eq!(v.to_bits(), (2.5 * noise.at(3 + 4 * i, 5)).to_bits());
            }
        }
    }

    #[test]
    fn a_point_keeps_its_value_across_detail_levels() {
        let fine = Noise::new(7, 12);
        let coarse = Noise::new(7, 8);
        assert_eq!(fine.at(16 * 3, 16 * 5).to_bits(), coarse.at(3, 5).to_bits());
        assert_ne!(fine.at(1, 0).to_bits(), coarse.at(1, 0).to_bits());
    }
}
