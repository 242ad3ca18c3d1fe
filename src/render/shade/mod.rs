//! Light and colour: the sun and the sky's light, shadows, sky light, smooth
//! normals, the palette, haze, ripples on the water and what it mirrors, the
//! sky's gradient, its clouds and the sun's glow, and Mono's dither (their
//! colour arithmetic is the ground floor's: `base/colour.rs`).

pub(super) mod clouds;
pub(super) mod cover;
pub mod dither;
pub(super) mod dusk;
pub mod essay;
pub mod facings;
pub(super) mod haze;
pub mod hour;
pub(super) mod kept_points;
pub mod light;
pub mod listing;
pub(super) mod mirror;
pub(super) mod moonrise;
pub(super) mod night;
pub(super) mod normals;
pub mod palette;
pub(super) mod relief;
pub(super) mod ripples;
pub mod shadow;
pub(super) mod sky;
pub(super) mod skylight;
pub(super) mod stars;
pub(super) mod strata;
pub(super) mod weather;

/// `v` truncated to an index into a grid or a table: NaN and negatives
/// 0, values past `i32::MAX` that (callers take the least with their last
/// index). Through i32: a float to usize conversion is a branchy sequence
/// on x86, and these run per point, per face and per pixel.
#[inline]
pub(crate) fn index(v: f32) -> usize {
    (v as i32).max(0) as usize
}
