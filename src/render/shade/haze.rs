//! Aerial haze: distant land fades towards the horizon colour, so depth
//! reads at a glance and the far coast melts into the sky.
//!
//! Computed per grid point from its distance (a fraction of the distance
//! to the back edge) and blended per face: haze changes slowly across a
//! face, so working it out per pixel would cost much and show nothing more.

/// No haze nearer than this fraction of the distance to the back edge.
const CLEAR: f32 = 0.45;
/// Haze at the back edge (0..=1).
const FAR: f32 = 0.45;
/// How quickly the haze thickens with distance beyond [`CLEAR`].
const DENSITY: f32 = 2.2;

/// Haze towards one horizon colour.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Haze {
    /// The packed colour distant land fades to.
    pub colour: u32,
    /// 1 - e^-(DENSITY (1 - CLEAR)): the back edge's unscaled haze.
    norm: f32,
    /// Haze at the back edge (0..=1).
    far: f32,
}

impl Haze {
    /// Haze fading to packed `colour`, as thick at the back edge as
    /// `far` (0..=1) says, or as [`FAR`] without it.
    pub(crate) fn new(colour: u32, far: Option<f32>) -> Self {
        Haze {
            colour,
            norm: 1.0 - (-DENSITY * (1.0 - CLEAR)).exp(),
            far: far.unwrap_or(FAR),
        }
    }

    /// Haze at `distance` (fraction of the back edge's), in 1/256ths.
    #[inline]
    pub(crate) fn amount(&self, distance: f32) -> u32 {
        let d = distance - CLEAR;
        // The nearer half of the land is clear: no `exp` for it (nor for NaN).
        if d.is_nan() || d <= 0.0 {
            return 0;
        }
        let h = self.far * (1.0 - (-DENSITY * d).exp()) / self.norm;
        (h.clamp(0.0, 1.0) * 256.0) as u32
    }
}
