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
//!
//! On steep rock the slope is also taken across the columns beside the
//! point (`strata::weight`): a cliff is a cell or two tall and hundreds of
//! pixels high, each column's light blended down all of it, and on a
//! rough face the slope of one column alone differs from its neighbours'
//! enough to draw curtains one column wide.

use glam::{Vec2, Vec3};

use super::strata;

use crate::render::framing::tops::finite;
use crate::terrain::Heightfield;

/// Grid steps, towards each side, over which each grid row's slope is taken.
pub(crate) struct Normals {
    /// For each grid row: rows back and forward to its drawn neighbours.
    reach: Vec<[u16; 2]>,
    /// Width of one cell in height units.
    cell: f32,
    /// The palette's steepness reference (`1 - normal.z` at the field's
    /// 90th percentile), which says where rock is steep.
    steep_ref: f32,
}

impl Normals {
    /// Normals for a field of `size` points a side drawn with grid rows
    /// `rows` (ascending, first and last included), cells `cell` units wide,
    /// steep where `1 - normal.z` reaches about `steep_ref` (the palette's).
    pub(crate) fn new(size: usize, rows: &[usize], cell: f32, steep_ref: f32) -> Self {
        let mut reach = vec![[1u16, 1u16]; size];
        for (i, &y) in rows.iter().enumerate() {
            let back = if i > 0 { y - rows[i - 1] } else { 1 };
            let front = rows.get(i + 1).map_or(1, |&next| next - y);
            reach[y] = [back.max(1) as u16, front.max(1) as u16];
        }
        Normals {
            reach,
            cell,
            steep_ref,
        }
    }

    /// Upward unit normal at grid point (`x`, `y`) in the palette's frame
    /// (z up, y towards the back).
    #[inline]
    pub(crate) fn at(&self, field: &Heightfield, x: usize, y: usize) -> Vec3 {
        let own = self.slope(field, x, y);
        let n = normal_of(own);
        let rock = strata::weight((1.0 - n.z) / self.steep_ref);
        if rock == 0.0 {
            return n;
        }
        // The slopes of the two columns on each side too, 1:2:3:2:1 (its
        // own again past the field's edges).
        let last = field.size() - 1;
        let beside = |d: usize| {
            let at = |x: Option<usize>| {
                x.filter(|&x| x <= last)
                    .map_or(own, |x| self.slope(field, x, y))
            };
            at(x.checked_sub(d)) + at(Some(x + d))
        };
        let wide = (own * 3.0 + beside(1) * 2.0 + beside(2)) / 9.0;
        normal_of(own + (wide - own) * rock)
    }

    /// The ground's rise per unit to the right and towards the back at
    /// grid point (`x`, `y`), over the span of its drawn neighbours.
    #[inline]
    fn slope(&self, field: &Heightfield, x: usize, y: usize) -> Vec2 {
        let last = field.size() - 1;
        let h = |x: usize, y: usize| finite(field.get(x, y));
        let (xl, xr) = (x.saturating_sub(1), (x + 1).min(last));
        let [back, front] = self.reach[y].map(usize::from);
        let (yb, yf) = (y.saturating_sub(back), (y + front).min(last));
        // Differences over the whole span, one-sided at the field's edges.
        let dx = (h(xr, y) - h(xl, y)) / ((xr - xl).max(1) as f32 * self.cell);
        // Grid rows run towards the viewer, the palette's y away from it.
        let dy = (h(x, yb) - h(x, yf)) / ((yf - yb).max(1) as f32 * self.cell);
        Vec2::new(dx, dy)
    }
}

/// The upward unit normal of ground rising `slope` (per unit to the right
/// and towards the back).
#[inline]
fn normal_of(slope: Vec2) -> Vec3 {
    Vec3::new(-slope.x, -slope.y, 1.0).normalize_or(Vec3::Z)
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
            let n = Normals::new(size, &rows, f.extent() / (size - 1) as f32, 1.0);
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
        let fine = Normals::new(size, &(0..size).collect::<Vec<_>>(), 1.0, 1.0);
        let merged = Normals::new(size, &[0, 4, 8, 12, 16], 1.0, 1.0);
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

    #[test]
    fn a_steep_rough_face_takes_its_slope_across_its_neighbouring_columns() {
        // A wall rising to the back, each column a little higher than the
        // last or lower: across a column the slope flips from side to side.
        let mut f = Heightfield::flat(4, 16.0);
        let wobble = |x: usize| [0.0, 1.0, 0.0, -1.0][x % 4];
        for y in 0..f.size() {
            for x in 0..f.size() {
                let wall = if y < 8 { 12.0 } else { 0.0 };
                f.set(
                    x,
                    y,
                    wall + wobble(x) * 0.5 * (y as f32 - 8.0).abs().min(1.0),
                );
            }
        }
        let size = f.size();
        let rows: Vec<usize> = (0..size).collect();
        let (own, smoothed) = (
            Normals::new(size, &rows, 1.0, f32::INFINITY),
            Normals::new(size, &rows, 1.0, 0.05),
        );
        let across = |n: &Normals| (4..12).map(|x| n.at(&f, x, 7).x.abs()).sum::<f32>();
        assert!(
            across(&smoothed) < across(&own) * 0.5,
            "sideways lean: smoothed {}, own {}",
            across(&smoothed),
            across(&own)
        );
        // Gentle ground is not steep rock, and keeps its own slope.
        let plane = plane(0.1, 0.05, 1.0);
        let n = Normals::new(plane.size(), &rows, 1.0, 0.05);
        let want = Vec3::new(-0.1, -0.05, 1.0).normalize();
        assert!((n.at(&plane, 5, 5) - want).length() < 1e-4);
    }
}
