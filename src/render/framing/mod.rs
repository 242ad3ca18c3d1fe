//! Camera and framing: where the land sits in the frame (the oblique view,
//! the vista and perspective cameras, `detail = "auto"`), which grid rows are
//! drawn and how high each row reaches on screen; the essay's own camera.

pub(super) mod aim;
pub(super) mod camera;
pub mod detail;
pub(super) mod easel;
pub(super) mod rows;
pub(super) mod tops;
pub mod turn;
pub mod view;
pub(super) mod vista;
