//! A complete frame's edges drawn clean: the skyline against the sky and
//! the crests of nearer land against farther land, both found by a floating
//! horizon over the mesh's rows. These passes read the whole scene, so they
//! stand above the painting order, which never calls them: the painter and
//! the full frame run them once every strip is in.

pub(super) mod clean;
mod crests;
pub(super) mod horizon;
mod skyline;
