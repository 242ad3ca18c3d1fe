//! The essay's turned square cut along its sides: a face on the land's
//! edge (a corner outside the square) is drawn as the part of it inside,
//! so the square's edges run straight, as the essay draws them, instead of
//! stepping from cell to cell.

use super::strip::{Corner, Face};
use crate::render::base::canvas::Canvas;
use crate::render::base::fixed::to_fixed;
use crate::render::scene::{Outline, Scene};

/// Most corners a triangle cut by a square's four sides can have.
const MOST: usize = 7;

impl Scene<'_> {
    /// The part of `face` (at least one corner inside the square) inside
    /// the square of `outline`, in the face's winding, as a fan of faces.
    pub(super) fn fill_cut(&self, canvas: &mut Canvas, outline: &Outline, face: Face) {
        let mut points: Vec<Corner> = face.iter().map(|&&c| c).collect();
        for side in 0..4 {
            points = self.cut_by(outline, &points, side);
            if points.len() < 3 {
                return;
            }
        }
        debug_assert!(points.len() <= MOST);
        for k in 1..points.len() - 1 {
            self.fill_face(canvas, [&points[0], &points[k], &points[k + 1]]);
        }
    }

    /// `points` (a convex polygon) cut by side `side` of the square: the
    /// part on its inner side, with a new corner where an edge crosses it,
    /// on the square's side at its own height.
    fn cut_by(&self, outline: &Outline, points: &[Corner], side: usize) -> Vec<Corner> {
        let inside = |c: &Corner| outline.turn.inside(c.g.x, c.g.y)[side];
        let mut out = Vec::with_capacity(points.len() + 1);
        for (i, a) in points.iter().enumerate() {
            let b = &points[(i + 1) % points.len()];
            let (da, db) = (inside(a), inside(b));
            if da >= 0.0 {
                out.push(*a);
            }
            if (da >= 0.0) != (db >= 0.0) {
                let t = da / (da - db);
                out.push(self.on_side(outline, a, b, t));
            }
        }
        out
    }

    /// The corner `t` of the way from `a` to `b`, on a side of the square:
    /// its height the square's own there, its light and air blended.
    fn on_side(&self, outline: &Outline, a: &Corner, b: &Corner, t: f32) -> Corner {
        let g = a.g + (b.g - a.g) * t;
        let h = outline.scale * outline.turn.height(&outline.square, g.x, g.y);
        let w = a.w.max(b.w);
        let p = self.view.project(g.x, g.y, h.max(w));
        // An outside corner has no light of its own: take the inside one's.
        let from = if a.off { b } else { a };
        Corner {
            g,
            h,
            w,
            p: to_fixed(p.x, p.y),
            off: false,
            ..*from
        }
    }
}
