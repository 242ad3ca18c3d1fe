//! Rasterising: triangles and lines into spans (exact top-left rule), colour
//! blended across a face, and the coast's coverage. It knows nothing of the
//! scene: the painting order hands it fixed-point positions and colours.

pub(super) mod banded;
pub(super) mod blend;
pub(super) mod fine;
pub(super) mod gradient;
pub(super) mod outline;
pub mod raster;
pub(super) mod shore;
