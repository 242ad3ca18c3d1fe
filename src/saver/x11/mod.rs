//! The X11 room: the saver's talk with an X server (foreign windows, the
//! monitors and their changes, the input grab and its pointer, frames put
//! as plain images, the server going away).

pub mod bands;
pub mod dpms;
pub mod embed;
pub mod grab;
pub mod heads;
pub(super) mod motion;
mod placed;
pub(super) mod pointer;
pub mod server_gone;
