//! Painting order: strips back to front (or front to back on a canvas that
//! keeps the first write), the faces and lines of one strip, and the full
//! frame in bands of columns with only the cells that reach each band.

pub(super) mod bands;
pub(super) mod cut;
pub(super) mod lines;
pub(super) mod mirrored;
pub(super) mod reach;
pub(super) mod strip;
pub(super) mod walk;
