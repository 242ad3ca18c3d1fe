//! Rasterising: triangles and lines into spans (exact top-left rule), colour
//! blended across a face, the coast's coverage, the canvas the spans are
//! written to, and the skyline's coverage once a frame is complete.

pub(super) mod blend;
pub(super) mod canvas;
pub mod raster;
pub(super) mod shore;
pub(super) mod skyline;
