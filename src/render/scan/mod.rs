//! Rasterising: triangles and lines into spans (exact top-left rule), colour
//! blended across a face, the coast's coverage, and the canvas the spans
//! are written to.

pub(super) mod blend;
pub(super) mod canvas;
pub mod raster;
pub(super) mod shore;
