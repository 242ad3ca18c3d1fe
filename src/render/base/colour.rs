//! Colour arithmetic shared by the palette, the sky and the haze.

use glam::Vec4;

/// An sRGB colour with channels in `0.0..=1.0`.
pub type Rgb = [f32; 3];

/// Linear blend from `a` (t = 0) to `b` (t = 1).
#[inline]
pub fn mix(a: Rgb, b: Rgb, t: f32) -> Rgb {
    [0, 1, 2].map(|i| a[i] + (b[i] - a[i]) * t)
}

/// Piecewise-linear colour ramp through `(position, colour)` stops.
pub fn ramp(stops: &[(f32, Rgb)], t: f32) -> Rgb {
    let (mut prev_t, mut prev_c) = stops[0];
    if t.is_nan() || t <= prev_t {
        return prev_c;
    }
    for &(st, sc) in &stops[1..] {
        if t <= st {
            return mix(prev_c, sc, (t - prev_t) / (st - prev_t));
        }
        (prev_t, prev_c) = (st, sc);
    }
    prev_c
}

/// Rec. 709 luminance.
#[inline]
pub fn luminance(c: Rgb) -> f32 {
    0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]
}

pub use crate::terrain::curves::smoothstep;

/// A 0..=1 colour as `0x00RRGGBB`.
pub fn to_u32(c: Rgb) -> u32 {
    pack(c, 255.0, 0.0)
}

/// `base` times `scale` less `offset` (the palette's tone offset, in
/// 0..=255 steps), rounded, clamped and packed as `0x00RRGGBB`.
#[inline]
pub fn pack(base: Rgb, scale: f32, offset: f32) -> u32 {
    let c = base.map(|v| (v * scale - offset + 0.5).clamp(0.0, 255.0) as u32);
    c[0] << 16 | c[1] << 8 | c[2]
}

/// A packed colour times `b` (0..=1), two channels per multiply.
#[inline]
pub fn scale_packed(c: u32, b: f32) -> u32 {
    // 0 ..= 256 in 1/256ths; NaN casts to 0.
    let k = ((b * 256.0 + 0.5) as u32).min(256);
    let red_blue = (((c & 0x00ff_00ff) * k) >> 8) & 0x00ff_00ff;
    let green = (((c & 0x0000_ff00) * k) >> 8) & 0x0000_ff00;
    red_blue | green
}

/// `0x00RRGGBB` as a 0..=1 colour.
pub fn unpack(c: u32) -> Rgb {
    [c >> 16, c >> 8, c].map(|v| (v & 0xff) as f32 / 255.0)
}

/// A packed colour with each channel times its factor (0..=1; more is
/// clamped at white).
#[inline]
pub fn scale_packed3(c: u32, k: Rgb) -> u32 {
    packed_lanes((lanes(c) * rgb_lanes(k) + 0.5).clamp(Vec4::ZERO, Vec4::splat(255.0)))
}

/// Blends packed colour `c` towards packed `to` by `t` (0..=1, in 1/256ths).
#[inline]
pub fn blend_packed(c: u32, to: u32, t: u32) -> u32 {
    let t = t.min(256);
    let lerp = |mask: u32| {
        let (a, b) = (c & mask, to & mask);
        // Per channel pair: a + (b - a) t / 256, written without negatives.
        ((a * (256 - t) + b * t) >> 8) & mask
    };
    lerp(0x00ff_00ff) | lerp(0x0000_ff00)
}

/// Packed colours `a` and `b` mixed `f` (0..=1) of the way to `b`.
#[inline]
pub fn mix_packed(a: u32, b: u32, f: f32) -> u32 {
    let (x, y) = (lanes(a), lanes(b));
    packed_lanes((x + (y - x) * f).clamp(Vec4::ZERO, Vec4::splat(255.0)) + 0.5)
}

/// A packed colour's channels as the lanes of a vector: blue, green, red
/// (0.0..=255.0, a packed colour's bytes in memory order) and 0, so that
/// [`packed_lanes`] packs them again with two instructions.
#[inline]
pub(crate) fn lanes(c: u32) -> Vec4 {
    Vec4::new(
        (c & 0xff) as f32,
        ((c >> 8) & 0xff) as f32,
        ((c >> 16) & 0xff) as f32,
        0.0,
    )
}

/// An [`Rgb`] in [`lanes`]' order: blue, green, red, 0.
#[inline]
pub(crate) fn rgb_lanes(c: Rgb) -> Vec4 {
    Vec4::new(c[2], c[1], c[0], 0.0)
}

/// Lanes blue, green, red (each in 0.0..256.0, truncated; a NaN lane
/// gives 0; callers clamp, as a lane of 2^31 or more would pack as 0)
/// packed `0x00RRGGBB`. On x86-64 the lanes are converted and
/// narrowed together: a channel at a time, the conversion (which Rust
/// saturates) was a fifth of a smooth-shaded pixel's cost and a third of
/// mixing two colours.
#[inline(always)]
pub(crate) fn packed_lanes(c: Vec4) -> u32 {
    #[cfg(target_arch = "x86_64")]
    {
        use std::arch::x86_64::{
            _mm_cvtsi128_si32, _mm_cvttps_epi32, _mm_packs_epi32, _mm_packus_epi16,
        };
        // SAFETY: SSE2 is part of x86-64 itself, so these instructions
        // exist on every machine the build runs on. NaN converts to
        // i32::MIN, which the saturating narrowing takes to 0.
        unsafe {
            let lanes = _mm_cvttps_epi32(c.into());
            let words = _mm_packs_epi32(lanes, lanes);
            _mm_cvtsi128_si32(_mm_packus_epi16(words, words)) as u32
        }
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        let c = c.as_uvec4();
        c.z << 16 | c.y << 8 | c.x
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_lanes_mix_and_scale_as_channel_by_channel() {
        // A channel at a time, as Rust's saturating casts have it.
        let mix_each = |a: u32, b: u32, f: f32| {
            let ch = |shift: u32| {
                let (x, y) = (((a >> shift) & 0xff) as f32, ((b >> shift) & 0xff) as f32);
                ((x + (y - x) * f).clamp(0.0, 255.0) + 0.5) as u32
            };
            ch(16) << 16 | ch(8) << 8 | ch(0)
        };
        let scale_each = |c: u32, k: Rgb| {
            let ch = |shift: u32, k: f32| {
                let v = ((c >> shift) & 0xff) as f32 * k + 0.5;
                (v.clamp(0.0, 255.0) as u32) << shift
            };
            ch(16, k[0]) | ch(8, k[1]) | ch(0, k[2])
        };
        let odd = [f32::NAN, f32::INFINITY, f32::NEG_INFINITY, -0.5, 1.5, 7.0];
        let mut state = 0x9e37_79b9_7f4a_7c15u64;
        for i in 0..20_000 {
            state = crate::terrain::splitmix::mix(state);
            let (a, b) = (
                (state & 0xff_ffff) as u32,
                ((state >> 24) & 0xff_ffff) as u32,
            );
            let f = match i % 10 {
                0 => odd[(state >> 50) as usize % odd.len()],
                _ => crate::terrain::splitmix::unit(state),
            };
            let k = [f, 1.0 - f, f * 0.5];
            assert_eq!(
                mix_packed(a, b, f),
                mix_each(a, b, f),
                "{a:06x} {b:06x} {f}"
            );
            assert_eq!(scale_packed3(a, k), scale_each(a, k), "{a:06x} {k:?}");
        }
    }

    #[test]
    fn mixing_packed_colours() {
        assert_eq!(mix_packed(0x000000, 0xff8040, 0.5), 0x804020);
        assert_eq!(mix_packed(0x123456, 0xabcdef, 0.0), 0x123456);
        assert_eq!(mix_packed(0x123456, 0xabcdef, 1.0), 0xabcdef);
    }
}
