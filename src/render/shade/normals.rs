//! The ground's normal at each grid point, for smooth shading.
//!
//! A face's own normal changes abruptly from face to face, which at 1:1
//! shows as a mosaic of one-colour triangles and as streaks along the
//! grid's diagonal. Smooth shading lights each grid point from the slope of
//! the ground around it and blends the light across each face.
//!
//! The slope is the height difference across the point's neighbours, as far
//! apart as the drawn mesh's points are: where the mesh skips grid rows in
//! the distance (`rows.rs`), a point's slope spans the rows its strips
//! span, the mean slope over what one face covers. A one-row difference
//! there would light a drawn face by one crease of the fine grid and make
//! far ridges sparkle.

use glam::Vec3;

use crate::render::framing::tops::finite;
use crate::terrain::Heightfield;

/// Grid steps, towards each side, over which each grid row's slope is taken.
pub(crate) struct Normals {
    /// For each grid row: rows back and forward to its drawn neighbours.
    reach: Vec<[u16; 2]>,
    /// Width of one cell in height units.
    cell: f32,
}

impl Normals {
    /// Normals for a field of `size` points a side drawn with grid rows
    /// `rows` (ascending, first and last included), cells `cell` units wide.
    pub(crate) fn new(size: usize, rows: &[usize], cell: f32) -> Self {
        let mut reach = vec![[1u16, 1u16]; size];
        for (i, &y) in rows.iter().enumerate() {
            let back = if i > 0 { y - rows[i - 1] } else { 1 };
            let front = rows.get(i + 1).map_or(1, |&next| next - y);
            reach[y] = [back.max(1) as u16, front.max(1) as u16];
        }
        Normals { reach, cell }
    }

    /// Upward unit normal at grid point (`x`, `y`) in the palette's frame
    /// (z up, y towards the back).
    #[inline]
    pub(crate) fn at(&self, field: &Heightfield, x: usize, y: usize) -> Vec3 {
        let last = field.size() - 1;
        let h = |x: usize, y: usize| finite(field.get(x, y));
        let (xl, xr) = (x.saturating_sub(1), (x + 1).min(last));
        let [back, front] = self.reach[y].map(usize::from);
        let (yb, yf) = (y.saturating_sub(back), (y + front).min(last));
        // Differences over the whole span, one-sided at the field's edges.
        let dx = (h(xr, y) - h(xl, y)) / ((xr - xl).max(1) as f32 * self.cell);
        // Grid rows run towards the viewer, the palette's y away from it.
        let dy = (h(x, yb) - h(x, yf)) / ((yf - yb).max(1) as f32 * self.cell);
        Vec3::new(-dx, -dy, 1.0).normalize_or(Vec3::Z)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A plane rising `sx` per unit to the right and `sy` per unit towards
    /// the back, sampled on a grid of `cell`-unit cells.
    fn plane(sx: f32, sy: f32, cell: f32) -> Heightfield {
        let mut f = Heightfield::flat(4, 16.0 * cell);
        for y in 0..f.size() {
            for x in 0..f.size() {
                let (wx, wy) = (x as f32 * cell, -(y as f32) * cell);
                f.set(x, y, 5.0 + sx * wx + sy * wy);
            }
        }
        f
    }

    #[test]
    fn a_plane_has_its_own_normal_everywhere_whatever_rows_are_drawn() {
        let f = plane(0.5, -0.25, 2.0);
        let want = Vec3::new(-0.5, 0.25, 1.0).normalize();
        let size = f.size();
        let sparse: Vec<usize> = (0..size).step_by(4).chain([size - 1]).collect();
        for rows in [(0..size).collect::<Vec<_>>(), sparse] {
            let n = Normals::new(size, &rows, f.extent() / (size - 1) as f32);
            for &y in &rows {
                for x in [0, 3, size - 1] {
                    let got = n.at(&f, x, y);
                    assert!((got - want).length() < 1e-4, "({x}, {y}): {got} != {want}");
                }
            }
        }
    }

    #[test]
    fn a_drawn_row_takes_its_slope_across_the_rows_its_strips_span() {
        // A step down between rows 7 and 8 (ground rising to the back, so
        // the normal leans to the front): across rows 7-9 it is steep,
        // across the eight rows two merged strips span a quarter as steep.
        let mut f = Heightfield::flat(4, 16.0);
        for y in 0..f.size() {
            for x in 0..f.size() {
                f.set(x, y, if y < 8 { 4.0 } else { 0.0 });
            }
        }
        let size = f.size();
        let fine = Normals::new(size, &(0..size).collect::<Vec<_>>(), 1.0);
        let merged = Normals::new(size, &[0, 4, 8, 12, 16], 1.0);
        let (nf, nm) = (fine.at(&f, 5, 8), merged.at(&f, 5, 8));
        assert!(
            (nf.y / nf.z + 2.0).abs() < 1e-4,
            "fine slope {}",
            nf.y / nf.z
        );
        assert!(
            (nm.y / nm.z + 0.5).abs() < 1e-4,
            "merged slope {}",
            nm.y / nm.z
        );
    }
}
