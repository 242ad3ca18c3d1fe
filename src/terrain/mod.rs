//! Everything that makes a mountain's heights. Pure: no windows, no clocks.

pub mod heightfield;
pub mod heightmap;

pub use heightfield::Heightfield;

use crate::settings::Settings;

/// Builds the mountain the settings describe from one seed, bit for bit the
/// same on every platform, build and thread count.
///
/// STUB: a smooth dome; the terrain work replaces it.
pub fn generate(settings: &Settings, seed: u64) -> Heightfield {
    let n = settings.grid_exponent();
    let mut field = Heightfield::flat(n, 400.0);
    let size = field.size();
    let phase = (seed % 7) as f32;
    for y in 0..size {
        for x in 0..size {
            let u = x as f32 / (size - 1) as f32 - 0.5;
            let v = y as f32 / (size - 1) as f32 - 0.5;
            let h = 60.0 * (1.0 - 4.0 * (u * u + v * v)) + 5.0 * (u * 20.0 + phase).sin();
            field.set(x, y, h - 10.0);
        }
    }
    field
}
