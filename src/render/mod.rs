//! Everything a person sees, drawn into a `Frame`. Pure: no windows.

mod bands;
mod canvas;
pub mod dither;
mod edges;
pub mod frame;
pub mod painter;
pub mod palette;
pub mod raster;
pub mod ridges;
mod scene;
pub mod shadow;
mod strip;
pub mod view;

pub use frame::{Frame, Rect};
pub use painter::{Painter, render_full};
