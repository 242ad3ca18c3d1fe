//! The linear map between 16-bit samples and heights, and why it round-trips.
//!
//! A field is stored with `offset` = its lowest height (an `f32`) and
//! `scale` = (highest - lowest) / 65535 (an `f64`), so the samples use the
//! whole 16-bit range. Decoding computes `offset + scale * sample` in `f64`
//! and rounds once to `f32`. Sample 0 then decodes to exactly the lowest
//! height and sample 65535 to exactly the highest (the `f64` error is far
//! below half an `f32` step), so a decoded field yields the same `offset` and
//! `scale` again, and each height re-quantises to the sample it came from
//! (its `f32` rounding is below half a sample step, or else the `f32` was the
//! stored height already). Hence save -> load -> save is byte-identical.

/// The largest 16-bit sample.
pub const MAX_SAMPLE: u16 = u16::MAX;

/// How samples map to heights: `height = offset + scale * sample`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Quantisation {
    /// Height of sample 0.
    pub offset: f32,
    /// Height units per sample step (> 0).
    pub scale: f64,
}

impl Quantisation {
    /// The map that spreads `min..=max` over the whole 16-bit range.
    ///
    /// A flat field (`min == max`) gets scale 1: every sample is 0.
    pub fn spanning(min: f32, max: f32) -> Self {
        let scale = if max > min {
            (f64::from(max) - f64::from(min)) / f64::from(MAX_SAMPLE)
        } else {
            1.0
        };
        Quantisation { offset: min, scale }
    }

    /// The nearest sample to height `h` (clamped to the 16-bit range).
    #[inline]
    pub fn sample(&self, h: f32) -> u16 {
        let s = ((f64::from(h) - f64::from(self.offset)) / self.scale).round();
        s.clamp(0.0, f64::from(MAX_SAMPLE)) as u16
    }

    /// The height sample `s` stands for.
    #[inline]
    pub fn height(&self, s: u16) -> f32 {
        (f64::from(self.offset) + self.scale * f64::from(s)) as f32
    }
}

/// Lowest and highest of a slice of heights: the field's own.
pub use crate::terrain::heightfield::min_max;

/// Rounds every height to the 16-bit grid a save would store it on, so a
/// loaded field saves and loads back unchanged.
pub fn snap_to_grid(heights: &mut [f32]) {
    let (min, max) = min_max(heights);
    let q = Quantisation::spanning(min, max);
    for h in heights.iter_mut() {
        *h = q.height(q.sample(*h));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ends_of_the_range_decode_exactly() {
        for (lo, hi) in [(-37.25f32, 912.5f32), (0.1, 0.3), (-1e-3, 7e4), (5.0, 5.0)] {
            let q = Quantisation::spanning(lo, hi);
            assert_eq!(q.height(0), lo);
            assert_eq!(q.sample(lo), 0);
            if hi > lo {
                assert_eq!(q.height(MAX_SAMPLE), hi);
                assert_eq!(q.sample(hi), MAX_SAMPLE);
            }
        }
    }

    #[test]
    fn every_sample_survives_decode_and_encode() {
        let q = Quantisation::spanning(-123.456, 789.012);
        for s in 0..=MAX_SAMPLE {
            assert_eq!(q.sample(q.height(s)), s, "sample {s}");
        }
    }

    #[test]
    fn snapping_twice_changes_nothing() {
        let mut a: Vec<f32> = (0..1000)
            .map(|i| (i as f32 * 0.731).sin() * 55.5 + 3.0)
            .collect();
        snap_to_grid(&mut a);
        let b = a.clone();
        snap_to_grid(&mut a);
        assert_eq!(a, b);
    }
}
