//! Rasterising: triangles and lines into spans (exact top-left rule), colour
//! blended across a face, the coast's coverage, the canvas the spans are
//! written to, and the coverage of the skyline and the crests once a frame
//! is complete (found by a floating horizon over the mesh's rows).

pub(super) mod blend;
pub(super) mod canvas;
pub(super) mod clean;
mod crests;
pub(super) mod horizon;
pub mod raster;
pub(super) mod shore;
mod skyline;
