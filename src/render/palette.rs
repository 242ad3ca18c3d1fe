//! Face colours: Lambert shading, the natural palette, filters, water depth.
//!
//! STUB with the final signatures; the colour work replaces the bodies.

use crate::settings::Settings;
use crate::terrain::Heightfield;
use glam::Vec3;

/// Colours for one mountain under one set of settings.
#[derive(Debug, Clone)]
pub struct Palette {
    light: Vec3,
}

impl Palette {
    /// Prepares the colours for `field` (treeline, depth range) under `settings`.
    pub fn new(_settings: &Settings, _field: &Heightfield) -> Self {
        Palette {
            light: Vec3::new(-0.5, -0.6, 0.62).normalize(),
        }
    }

    /// Unit vector pointing from the ground towards the light (z up, y towards the back).
    pub fn light(&self) -> Vec3 {
        self.light
    }

    /// Colour of a land face: its mean height, unit normal (z up), and how
    /// much direct light reaches it (1 = lit, 0 = in cast shadow).
    pub fn land(&self, _mean_height: f32, normal: Vec3, lit: f32) -> u32 {
        let b = 0.5 + 0.5 * normal.dot(self.light).max(0.0) * lit;
        let g = (200.0 * b) as u32;
        g << 8 | (g / 3) << 16
    }

    /// Colour of water over ground `depth` (>= 0) units below sea level.
    pub fn water(&self, _depth: f32) -> u32 {
        0x0000_40c0
    }

    /// Colour of a skirt face (the cut side of the map) facing `normal`.
    pub fn skirt(&self, mean_height: f32, normal: Vec3) -> u32 {
        self.land(mean_height, normal, 1.0)
    }

    /// Background colour behind the mountain.
    pub fn sky(&self) -> u32 {
        0
    }
}
