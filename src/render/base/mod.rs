//! The ground floor every stage of the renderer stands on: the frame and
//! its damage, the canvas a stage draws into, colour arithmetic, screen
//! positions in fixed point, and the frame's size. It imports nothing else
//! of `render`.

pub(super) mod canvas;
pub mod colour;
pub mod damage;
pub mod fixed;
pub mod frame;
pub mod size;
