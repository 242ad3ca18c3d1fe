//! The essay's colours (seed 002, its second program, `proceed_fractal`):
//! `look = "essay"` in the natural colours.
//!
//! Each triangle is `hsl(100, 80%, L%)` (its `original_Hue`-style green,
//! `Saturation = 80`), with `L = round(amplitude * cos + amplitude +
//! min_shade)`, `amplitude = (max_shade - min_shade) / 2`, `max_shade = 30`,
//! `min_shade = -10`: 20 cos + 10, so a face square to the sun is 30%
//! light and one turned from it black (CSS clamps a lightness below 0).
//! The sun's rays are `[-5, 5, 0]` in its screen frame (x right, y down):
//! the sun stands up and to the right, 45 degrees, in the plane of the
//! picture. The page behind is `background_color = "#ffffff"`.

use glam::Vec3;

/// Towards the essay's sun, in the palette's frame (x right, y towards
/// the back, z up): its rays `[-5, 5, 0]` reversed, y down made z up.
pub const SUN: Vec3 = Vec3::new(
    std::f32::consts::FRAC_1_SQRT_2,
    0.0,
    std::f32::consts::FRAC_1_SQRT_2,
);

/// The page behind the mountain.
pub const BACKGROUND: u32 = 0x00ff_ffff;

/// The hue, saturation and lightness bounds of `proceed_fractal`.
const HUE: f64 = 100.0;
const SATURATION: f64 = 0.8;
const MAX_SHADE: f64 = 30.0;
const MIN_SHADE: f64 = -10.0;

/// The lightness in percent the essay gives a face of unit normal `normal`
/// (z up).
pub fn lightness(normal: Vec3) -> i64 {
    let cos = f64::from(normal.normalize_or_zero().dot(SUN));
    let amplitude = (MAX_SHADE - MIN_SHADE) / 2.0;
    // JavaScript's Math.round: halves go up.
    (amplitude * cos + amplitude + MIN_SHADE + 0.5).floor() as i64
}

/// A face's colour, packed 0x00RRGGBB.
pub fn colour(normal: Vec3) -> u32 {
    hsl(
        HUE,
        SATURATION,
        lightness(normal).clamp(0, 100) as f64 / 100.0,
    )
}

/// CSS's `hsl()` in 8 bits a channel.
fn hsl(hue: f64, s: f64, l: f64) -> u32 {
    let chroma = (1.0 - (2.0 * l - 1.0).abs()) * s;
    let h = hue / 60.0;
    let x = chroma * (1.0 - (h % 2.0 - 1.0).abs());
    let (r, g, b) = match h as u32 {
        0 => (chroma, x, 0.0),
        1 => (x, chroma, 0.0),
        2 => (0.0, chroma, x),
        3 => (0.0, x, chroma),
        4 => (x, 0.0, chroma),
        _ => (chroma, 0.0, x),
    };
    let m = l - chroma / 2.0;
    let byte = |c: f64| ((c + m) * 255.0).round().clamp(0.0, 255.0) as u32;
    (byte(r) << 16) | (byte(g) << 8) | byte(b)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn faces_are_green_from_black_to_30_percent_light() {
        assert_eq!(lightness(SUN), 30);
        assert_eq!(lightness(-SUN), -10);
        assert_eq!(colour(-SUN), 0);
        // A flat face: cos 45 degrees, 20 * 0.707 + 10 = 24.1, so 24%.
        assert_eq!(lightness(Vec3::Z), 24);
        let c = colour(Vec3::Z);
        let (r, g, b) = (c >> 16, (c >> 8) & 0xff, c & 0xff);
        assert!(g > r && g > b, "{c:06x} is not green");
        // CSS: hsl(100, 80%, 24%) is rgb(44.9, 110.2, 12.2), by hand.
        assert_eq!(c, 0x002d_6e0c);
    }
}
