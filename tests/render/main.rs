//! Rendering: the painter, the scene, rasterising, views, water, reflections, the colour modes and the classic looks (golden pictures).

#[path = "../common/mod.rs"]
mod common;

mod classic_listing;
mod classic_looks;
mod colour_dither;
mod colour_palette;
mod colour_ridges;
mod colour_shadow;
mod edges;
mod lakes;
mod mirror_outline;
mod night;
mod painter;
mod raster;
mod reflections;
mod relief;
mod rock;
mod scene;
mod skirts;
mod smooth;
mod solar;
mod span;
mod view;
mod vista;
mod water;
mod wire_density;
mod worlds;
