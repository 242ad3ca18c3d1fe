//! The night's colours: rod vision (the Purkinje shift) sees moonlit
//! ground blue-green and nearly colourless, and water turns dark, lit by
//! what it mirrors rather than by its own colour.

use crate::render::base::colour::{Rgb, mix, to_u32, unpack};

/// How much of its colour the land loses under a full night.
const COLOURLESS: f32 = 0.75;
/// What a full night leaves of the water's own colour.
const WATER_LEFT: f32 = 0.3;

/// `c` as rods see it `night` (0..=1) of the way: towards the grey of its
/// scotopic brightness (rods weigh green and blue, hardly red), tinted
/// blue-green.
pub(super) fn rods(c: Rgb, night: f32) -> Rgb {
    if night <= 0.0 {
        return c;
    }
    let y = 0.10 * c[0] + 0.55 * c[1] + 0.35 * c[2];
    mix(c, [0.88 * y, y, 1.06 * y], COLOURLESS * night)
}

/// A table of packed land colours as rods see them (the same table by day).
pub(super) fn land(table: Box<[u32]>, night: f32) -> Box<[u32]> {
    if night <= 0.0 {
        return table;
    }
    table
        .iter()
        .map(|&c| to_u32(rods(unpack(c), night)))
        .collect()
}

/// A water colour (0..=1) under `night` (0..=1).
pub(super) fn water(c: Rgb, night: f32) -> Rgb {
    let k = 1.0 - (1.0 - WATER_LEFT) * night.clamp(0.0, 1.0);
    rods(c, night).map(|v| v * k)
}
