//! Everything a person sees, drawn into a `Frame`. Pure: no windows.
//!
//! The folders are the pipeline's rooms, each standing on those below it
//! and importing nothing from those above (tests/architecture.rs checks),
//! from the bottom:
//!
//! - `base/`, the ground floor: the frame and its damage, the canvas,
//!   colour arithmetic, fixed-point screen positions, the frame's `Size`;
//! - `framing/`: camera, view, which rows;
//! - `shade/`: light and colour;
//! - `scene.rs`: everything fixed for one frame, made from the two above;
//! - `scan/`: triangles and lines into pixels;
//! - `order/`: painting order (strips, bands), the scene's faces and lines
//!   handed to `scan/`;
//! - `edges/`: the skyline and the crests drawn clean once the frame is
//!   complete, the passes that need the whole scene.
//!
//! The files at the top tie them together: `painter.rs` (the slide show's
//! steps and the full frame), `ridges.rs` (Ridges mode, its own look),
//! `facts.rs` and `classes.rs` (what tests and measurements read).

mod base;
#[doc(hidden)]
pub mod classes;
mod edges;
pub mod facts;
mod framing;
mod order;
pub mod painter;
pub mod ridges;
mod scan;
mod scene;
mod shade;

// The public paths from before the rooms (`render::palette`, ...) stay.
pub use base::{colour, damage, frame, size};
pub use framing::{detail, turn, view};
pub use scan::raster;
pub use shade::{dither, essay, facings, hour, light, listing, palette, shadow};

pub use damage::Damage;
pub use frame::{Frame, Rect};
pub use painter::{Painter, render_full, render_full_at, render_full_finer};
pub use size::Size;
