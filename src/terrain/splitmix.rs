//! SplitMix64 (Steele, Lea and Flood 2014): the one 64-bit mixer behind
//! the terrain's noise, a field's fingerprint and the ridges' layers.
//! Its draws as numbers in a range are [`unit`] and [`signed_unit`].

/// SplitMix64's increment (2^64 / golden ratio).
pub const GOLDEN: u64 = 0x9E37_79B9_7F4A_7C15;

/// SplitMix64's output function: a bijective 64-bit mixer.
#[inline]
pub fn mix(mut z: u64) -> u64 {
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

/// The top 24 bits of `bits` (a [`mix`]'s output) as a number in `0..1`:
/// all that an `f32` holds exactly.
#[inline]
pub fn unit(bits: u64) -> f32 {
    (bits >> 40) as f32 / (1u64 << 24) as f32
}

/// The top 24 bits of `bits` as a number in `-1..1`.
#[inline]
pub fn signed_unit(bits: u64) -> f32 {
    (bits >> 40) as f32 / (1u64 << 23) as f32 - 1.0
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_draw_spans_its_range_and_never_reaches_the_top() {
        assert_eq!((unit(0), signed_unit(0)), (0.0, -1.0));
        assert!(unit(u64::MAX) < 1.0 && signed_unit(u64::MAX) < 1.0);
        let mut z = 1u64;
        let (mut low, mut high) = (0, 0);
        for _ in 0..10_000 {
            z = mix(z);
            let (u, s) = (unit(z), signed_unit(z));
            assert!((0.0..1.0).contains(&u) && (-1.0..1.0).contains(&s));
            // The same draw, one range mapped onto the other exactly.
            assert_eq!(s, u * 2.0 - 1.0);
            low += usize::from(u < 0.1);
            high += usize::from(u >= 0.9);
        }
        assert!((900..1100).contains(&low) && (900..1100).contains(&high));
    }
}
