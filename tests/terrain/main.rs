//! Terrain: the generators' laws, erosion, cliffs, coasts, lakes, determinism, and data sets (heightmaps) read, written and viewed.

#[path = "../common/mod.rs"]
mod common;

mod brownian;
mod cliffs;
mod coast;
mod creases;
mod determinism;
mod erosion;
mod from_settings;
mod heightmap_errors;
mod heightmap_foreign;
mod heightmap_golden;
mod heightmap_looks;
mod heightmap_roundtrip;
mod heightmap_save;
mod heightmap_views;
mod lakes;
mod laws;
mod structure;
mod wetness;
