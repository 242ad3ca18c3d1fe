//! Sonar (black faces, white outlines) and Outline (wire mesh) strips.
//!
//! Every grid edge is drawn once, by the later of the two cells that share
//! it, after that cell is filled: both cells' fills lie beneath it, and no
//! edge gets the double border the Mountain Terrain author regretted. (The
//! few corner pixels a later neighbour's fill covers are put back by
//! `touch_up`.)
//! Both modes draw the surface at its clamped height (sea flat at sea level),
//! ignore shading, and Sonar draws no skirts (seed 003).

use glam::Vec2;

use crate::render::base::canvas::Canvas;
use crate::render::base::fixed::{Clip, Fixed2, SUBPIXEL};
use crate::render::scan::raster::{centre_box, draw_line, draw_line_end, fill_triangle};
use crate::render::scene::{Scene, Vert};
use crate::settings::ColorMode;

/// Which of a cell's edges it draws.
struct CellEdges {
    top: bool,
    left: bool,
    right: bool,
    bottom: bool,
}

impl Scene<'_> {
    /// The edges cell `x` of strip `s` owns: those whose neighbour across was
    /// drawn earlier, and those on the border of the grid.
    fn owned_edges(&self, s: usize, x: usize) -> CellEdges {
        let last = self.cells() - 1;
        CellEdges {
            top: true,
            left: x == 0 || x <= self.split,
            right: x == last || x >= self.split,
            bottom: s == last,
        }
    }

    /// Draws strip `s` in Sonar or Outline; `top`/`bottom` are rows `s`, `s + 1`.
    pub(crate) fn edge_strip(
        &self,
        canvas: &mut Canvas,
        s: usize,
        top: &[Vert],
        bottom: &[Vert],
        sonar: bool,
    ) {
        let cells = self.cells();
        let order = (0..self.split).chain((self.split..cells).rev());
        for x in order {
            let rightward = x < self.split;
            let g = |gx: usize, gy: usize| Vec2::new(gx as f32, gy as f32);
            let (tl, tr) = ((&top[x], g(x, s)), (&top[x + 1], g(x + 1, s)));
            let (bl, br) = ((&bottom[x], g(x, s + 1)), (&bottom[x + 1], g(x + 1, s + 1)));
            if !self.may_touch(canvas.clip(), [tl.0, tr.0, bl.0, br.0], sonar) {
                continue;
            }
            if self.holes() && [tl.0, tr.0, bl.0, br.0].iter().any(|v| v.off) {
                continue;
            }
            let own = self.owned_edges(s, x);
            if sonar {
                self.black_cell(canvas, [tl.0, tr.0, bl.0, br.0], rightward);
                self.touch_up(canvas, s, x, top, bottom, &own);
            }
            let mut edge = |a: (&Vert, Vec2), b: (&Vert, Vec2)| self.edge(canvas, a, b, sonar);
            if own.top {
                edge(tl, tr);
            }
            if own.left {
                edge(tl, bl);
            }
            if own.right {
                edge(tr, br);
            }
            if own.bottom {
                edge(bl, br);
            }
            // The diagonal the filled faces are split on (`fill_cell`).
            if rightward && !self.listing_diagonal {
                edge(tr, bl);
            } else {
                edge(tl, br);
            }
        }
        if !sonar {
            self.outline_skirts(canvas, s, top, bottom);
        } else if self.palette.mode() == ColorMode::Filled {
            self.filled_skirts(canvas, s, top, bottom);
        }
    }

    /// Filled (FL3): "filled vertical quadrilaterals" from the right edge's
    /// points and (in the last strip) the front's down to sea level, in the
    /// land's fill and outlined by the pen, which "obscure the undersides of
    /// the landscape surface". A point under the sea stands at its foot.
    fn filled_skirts(&self, canvas: &mut Canvas, s: usize, top: &[Vert], bottom: &[Vert]) {
        let cells = self.cells();
        let (land, _) = self.palette.fills();
        let pen = self.palette.outline_land();
        let mut quad = |a: &Vert, ga: Vec2, b: &Vert, gb: Vec2| {
            if a.h <= 0.0 && b.h <= 0.0 {
                return;
            }
            let (fa, fb) = (self.project_sea(ga), self.project_sea(gb));
            let pa = if a.h > 0.0 { a.p } else { fa };
            let pb = if b.h > 0.0 { b.p } else { fb };
            let clip = *canvas.clip();
            for v in [[pa, pb, fb], [pa, fb, fa]] {
                fill_triangle(v, &clip, |y, x0, x1| canvas.span_mut(y, x0, x1).fill(land));
            }
            for (p, q) in [(pa, fa), (pb, fb), (fa, fb), (pa, pb)] {
                self.line(canvas, p, q, pen);
            }
        };
        let at = |x: usize, y: usize| Vec2::new(x as f32, y as f32);
        if self.sees_right {
            quad(&top[cells], at(cells, s), &bottom[cells], at(cells, s + 1));
        }
        if self.sees_front && s + 1 == cells {
            for x in 0..cells {
                quad(&bottom[x], at(x, s + 1), &bottom[x + 1], at(x + 1, s + 1));
            }
        }
    }

    /// Whether a cell's lines can reach `clip`: its corners' box, a pixel
    /// wider (line pixels are the ones holding the points). Outline cells that
    /// cross the water line are always drawn: their shore points lie on the
    /// sea plane, outside that box.
    fn may_touch(&self, clip: &Clip, v: [&Vert; 4], sonar: bool) -> bool {
        if !sonar && v.iter().any(|v| v.h < 0.0) && v.iter().any(|v| v.h > 0.0) {
            return true;
        }
        let lo = |i: usize| v[0].p[i].min(v[1].p[i]).min(v[2].p[i]).min(v[3].p[i]) >> 8;
        let hi = |i: usize| v[0].p[i].max(v[1].p[i]).max(v[2].p[i]).max(v[3].p[i]) >> 8;
        lo(0) - 1 < clip.x1 && hi(0) + 1 >= clip.x0 && lo(1) - 1 < clip.y1 && hi(1) + 1 >= clip.y0
    }

    /// Sonar: a one-pixel line leans up to half a pixel off its edge, so near
    /// a shared corner the fill of cell `x` can cover a pixel of an earlier
    /// neighbour's top (or, in the last strip, bottom) edge; put those back.
    /// Only pixels next to the shared corner are redrawn, the same pixels the
    /// line had, so nothing thickens.
    fn touch_up(
        &self,
        canvas: &mut Canvas,
        s: usize,
        x: usize,
        top: &[Vert],
        bottom: &[Vert],
        own: &CellEdges,
    ) {
        let last = self.cells() - 1;
        let white = self.palette.outline_land();
        let mut near = |a: Fixed2, b: Fixed2| {
            let clip = *canvas.clip();
            let one = SUBPIXEL;
            canvas.touch_box([b[0] - one, b[1] - one], [b[0] + one, b[1] + one]);
            draw_line_end(a, b, &clip, |px, py| canvas.plot(px, py, white));
        };
        if own.left && x > 0 {
            near(top[x - 1].p, top[x].p);
            if s == last {
                near(bottom[x - 1].p, bottom[x].p);
            }
        }
        if own.right && x < last {
            near(top[x + 2].p, top[x + 1].p);
            if s == last {
                near(bottom[x + 2].p, bottom[x + 1].p);
            }
        }
    }

    /// Sonar: both triangles of a cell in black; Filled: each in FL3's
    /// flat land colour, or its water colour when no corner is above the sea.
    fn black_cell(&self, canvas: &mut Canvas, [tl, tr, bl, br]: [&Vert; 4], rightward: bool) {
        let clip = *canvas.clip();
        if centre_box([tl.p, tr.p, bl.p, br.p], &clip).is_none() {
            return;
        }
        let (land, water) = self.palette.fills();
        let mut fill = |v: [&Vert; 3]| {
            let wet = v.iter().all(|v| v.h <= 0.0);
            let colour = if wet { water } else { land };
            let p = v.map(|v| v.p);
            fill_triangle(p, &clip, |y, x0, x1| {
                canvas.span_mut(y, x0, x1).fill(colour)
            });
        };
        if rightward && !self.listing_diagonal {
            fill([tl, tr, bl]);
            fill([tr, br, bl]);
        } else {
            fill([tl, tr, br]);
            fill([tl, br, bl]);
        }
    }

    /// One grid edge: white in Sonar; in Outline green over land and blue
    /// over water, changing colour where it crosses the water line.
    fn edge(&self, canvas: &mut Canvas, a: (&Vert, Vec2), b: (&Vert, Vec2), sonar: bool) {
        let (ha, hb) = (a.0.h, b.0.h);
        let (land, water) = (self.palette.outline_land(), self.palette.outline_water());
        if sonar {
            self.line(canvas, a.0.p, b.0.p, land);
        } else if (ha < 0.0) != (hb < 0.0) && ha.max(hb) > 0.0 {
            let f = ha / (ha - hb);
            let m = self.project_sea(a.1 + (b.1 - a.1) * f);
            let colour = |h: f32| if h > 0.0 { land } else { water };
            self.line(canvas, a.0.p, m, colour(ha));
            self.line(canvas, m, b.0.p, colour(hb));
        } else {
            let wet = ha <= 0.0 && hb <= 0.0;
            let colour = if wet { water } else { land };
            self.line(canvas, a.0.p, b.0.p, colour);
        }
    }

    fn line(&self, canvas: &mut Canvas, a: Fixed2, b: Fixed2, colour: u32) {
        let clip = *canvas.clip();
        canvas.touch_box(
            [a[0].min(b[0]), a[1].min(b[1])],
            [a[0].max(b[0]), a[1].max(b[1])],
        );
        draw_line(a, b, &clip, |x, y| canvas.plot(x, y, colour));
    }

    /// Outline: FL3's vertical lines from the edge points down to sea level,
    /// along the right edge and (in the last strip) the front, and the foot line.
    fn outline_skirts(&self, canvas: &mut Canvas, s: usize, top: &[Vert], bottom: &[Vert]) {
        let cells = self.cells();
        let land = self.palette.outline_land();
        let mut drop = |v: &Vert, g: Vec2, next: Option<(&Vert, Vec2)>| {
            if v.h > 0.0 {
                let foot = self.project_sea(g);
                self.line(canvas, v.p, foot, land);
                if let Some((_, gw)) = next.filter(|(w, _)| w.h > 0.0) {
                    self.line(canvas, foot, self.project_sea(gw), land);
                }
            }
        };
        let at = |x: usize, y: usize| Vec2::new(x as f32, y as f32);
        if self.sees_right {
            drop(
                &top[cells],
                at(cells, s),
                Some((&bottom[cells], at(cells, s + 1))),
            );
        }
        if self.sees_front && s + 1 == cells {
            for x in 0..=cells {
                let next = (x < cells).then(|| (&bottom[x + 1], at(x + 1, s + 1)));
                drop(&bottom[x], at(x, s + 1), next);
            }
        }
    }
}
