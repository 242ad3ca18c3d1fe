//! The Wayland room: the layer-shell mode (`--layer`), its surfaces'
//! raw handles and how each buffer covers its output.

pub(super) mod cover;
pub mod layer;
pub mod power;
pub(super) mod target;
