//! Everything a person sees, drawn into a `Frame`. Pure: no windows.
//!
//! The folders are the pipeline's stages: `framing/` (camera, view, which
//! rows), `shade/` (light and colour), `order/` (painting order: strips,
//! bands), `scan/` (triangles and lines into pixels). The files at the top
//! tie them together: `scene.rs` (everything fixed for one frame),
//! `painter.rs` (the slide show's steps), `frame.rs` and `damage.rs` (the
//! output), `ridges.rs` (Ridges mode, its own look), `facts.rs` and
//! `classes.rs` (what tests and measurements read).

#[doc(hidden)]
pub mod classes;
pub mod damage;
pub mod facts;
pub mod frame;
mod framing;
mod order;
pub mod painter;
pub mod ridges;
mod scan;
mod scene;
mod shade;

// The public paths from before the rooms (`render::palette`, ...) stay.
pub use framing::{detail, turn, view};
pub use scan::raster;
pub use shade::{colour, dither, essay, facings, light, listing, palette, shadow};

pub use damage::Damage;
pub use frame::{Frame, Rect};
pub use painter::{Painter, render_full};
