//! Everything a person sees, drawn into a `Frame`. Pure: no windows.

mod bands;
mod blend;
mod camera;
mod canvas;
#[doc(hidden)]
pub mod classes;
pub mod colour;
pub mod damage;
pub mod detail;
pub mod dither;
mod edges;
pub mod facts;
pub mod frame;
mod haze;
pub mod light;
mod normals;
pub mod painter;
pub mod palette;
pub mod raster;
mod reach;
pub mod ridges;
mod ripples;
mod rows;
mod scene;
pub mod shadow;
mod shore;
mod sky;
mod skylight;
mod skyline;
mod strip;
mod tops;
pub mod view;
mod vista;
mod walk;

pub use damage::Damage;
pub use frame::{Frame, Rect};
pub use painter::{Painter, render_full};
