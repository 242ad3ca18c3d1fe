//! A screen triangle's geometry for planes through values at its corners:
//! Gouraud colours (`blend`) and the mirror's outline (`outline`) both
//! read such a plane at pixel centres.

use std::ops::{Mul, Sub};

use crate::render::base::fixed::{Fixed2, SUBPIXEL};

/// The first corner of a triangle in pixels and what turns the other two
/// corners' differences from it into a plane's change per pixel.
pub(crate) struct Gradient {
    /// The first corner's position in pixels.
    pub origin: [f32; 2],
    /// The edges from the first corner to the second and to the third, in
    /// pixels.
    e1: [f32; 2],
    e2: [f32; 2],
    /// One over the edges' determinant (0 for a triangle of no area: its
    /// planes are flat).
    inv: f32,
}

impl Gradient {
    /// The geometry of the triangle of corners `v` (24.8 fixed point).
    #[inline]
    pub(crate) fn new(v: [Fixed2; 3]) -> Self {
        let to_px = 1.0 / SUBPIXEL as f32;
        let origin = [v[0][0] as f32 * to_px, v[0][1] as f32 * to_px];
        let e1 = [
            (v[1][0] - v[0][0]) as f32 * to_px,
            (v[1][1] - v[0][1]) as f32 * to_px,
        ];
        let e2 = [
            (v[2][0] - v[0][0]) as f32 * to_px,
            (v[2][1] - v[0][1]) as f32 * to_px,
        ];
        let det = e1[0] * e2[1] - e2[0] * e1[1];
        let inv = if det != 0.0 { 1.0 / det } else { 0.0 };
        Gradient {
            origin,
            e1,
            e2,
            inv,
        }
    }

    /// The change per pixel to the right and per row down of the plane
    /// whose values at the second and third corners exceed the first's by
    /// `d1` and `d2`.
    #[inline]
    pub(crate) fn slopes<T>(&self, d1: T, d2: T) -> (T, T)
    where
        T: Copy + Mul<f32, Output = T> + Sub<Output = T>,
    {
        let (e1, e2) = (self.e1, self.e2);
        (
            (d1 * e2[1] - d2 * e1[1]) * self.inv,
            (d2 * e1[0] - d1 * e2[0]) * self.inv,
        )
    }
}
