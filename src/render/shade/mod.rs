//! Light and colour: the sun and the sky's light, shadows, sky light, smooth
//! normals, the palette, haze, ripples on the water and what it mirrors, the sky's gradient and
//! Mono's dither, and the colour arithmetic they share.

pub mod colour;
pub mod dither;
pub(super) mod haze;
pub mod light;
pub(super) mod mirror;
pub(super) mod normals;
pub mod palette;
pub(super) mod ripples;
pub mod shadow;
pub(super) mod sky;
pub(super) mod skylight;
