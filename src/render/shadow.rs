//! Cast shadows: which grid points see the light (a horizon sweep).
//!
//! STUB with the final signatures; the colour work replaces the bodies.

use crate::terrain::Heightfield;
use glam::Vec3;

/// Per grid point, how much direct light arrives (1 lit, 0 shadowed).
#[derive(Debug, Clone)]
pub struct ShadowMap {
    size: usize,
    lit: Vec<f32>,
}

impl ShadowMap {
    /// Every point lit (shadows off).
    pub fn all_lit(field: &Heightfield) -> Self {
        ShadowMap {
            size: field.size(),
            lit: vec![1.0; field.size() * field.size()],
        }
    }

    /// Light reaching the grid point at column `x`, row `y`.
    #[inline]
    pub fn lit(&self, x: usize, y: usize) -> f32 {
        self.lit[y * self.size + x]
    }
}

/// Computes which points of `field` the light from direction `light` reaches.
pub fn cast(field: &Heightfield, _light: Vec3) -> ShadowMap {
    ShadowMap::all_lit(field)
}
