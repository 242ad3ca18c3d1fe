//! Everything a person sees, drawn into a `Frame`. Pure: no windows.

pub mod dither;
pub mod frame;
pub mod painter;
pub mod palette;
pub mod ridges;
pub mod shadow;

pub use frame::{Frame, Rect};
pub use painter::{Painter, render_full};
