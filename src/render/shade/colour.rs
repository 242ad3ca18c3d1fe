//! Colour arithmetic shared by the palette, the sky and the haze.

/// An sRGB colour with channels in `0.0..=1.0`.
pub type Rgb = [f32; 3];

/// Linear blend from `a` (t = 0) to `b` (t = 1).
#[inline]
pub fn mix(a: Rgb, b: Rgb, t: f32) -> Rgb {
    [0, 1, 2].map(|i| a[i] + (b[i] - a[i]) * t)
}

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
    let ch = |shift: u32, k: f32| {
        let v = ((c >> shift) & 0xff) as f32 * k + 0.5;
        (v.clamp(0.0, 255.0) as u32) << shift
    };
    ch(16, k[0]) | ch(8, k[1]) | ch(0, k[2])
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
    let ch = |shift: u32| {
        let (x, y) = (((a >> shift) & 0xff) as f32, ((b >> shift) & 0xff) as f32);
        ((x + (y - x) * f).clamp(0.0, 255.0) + 0.5) as u32
    };
    ch(16) << 16 | ch(8) << 8 | ch(0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn mixing_packed_colours() {
        assert_eq!(mix_packed(0x000000, 0xff8040, 0.5), 0x804020);
        assert_eq!(mix_packed(0x123456, 0xabcdef, 0.0), 0x123456);
        assert_eq!(mix_packed(0x123456, 0xabcdef, 1.0), 0xabcdef);
    }
}
