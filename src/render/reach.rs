//! Which cells of a strip can reach a band of screen columns.
//!
//! A full frame is drawn in bands of columns, one per thread at a time. Each
//! band walks only the cells that can touch its columns, and projects only
//! their points, so no strip is walked or projected twice over (bands of rows
//! did both: in the vista a strip spans much of the frame's height).

use std::ops::Range;

use super::raster::Clip;
use super::scene::Scene;

/// Pixels added on each side of a band: fixed-point rounding and the lines
/// of Sonar and Outline (a pixel either side of their points) stay inside.
const MARGIN_PX: f32 = 2.0;

impl Scene<'_> {
    /// Cells of strip `s` whose faces, skirts and lines can touch columns
    /// `clip.x0..clip.x1`: every cell unless the view is known to keep the
    /// order of grid columns on screen.
    ///
    /// Along one grid row at one height the screen column only grows with
    /// the grid column (a straight line, all of it in front of the camera),
    /// and a point's column lies between its columns at sea level and at
    /// the strip's top. So the columns a cell reaches are bounded by
    /// monotone functions of its grid column, and the cells reaching a band
    /// are one run, found by bisection.
    pub(crate) fn cells_reaching(&self, s: usize, clip: &Clip) -> Range<usize> {
        let cells = self.cells();
        let (y0, y1) = self.strip_grid_rows(s);
        let top = self.row_top[y0].max(self.row_top[y1]);
        let lines = [(y0, 0.0), (y0, top), (y1, 0.0), (y1, top)];
        let column =
            |gx: usize, (row, h): (usize, f32)| self.view.project(gx as f32, row as f32, h).x;
        let ordered = lines.iter().all(|&l| column(0, l) < column(cells, l));
        if !ordered {
            return 0..cells;
        }
        let reach = |gx: usize| {
            lines
                .iter()
                .fold((f32::INFINITY, f32::NEG_INFINITY), |(lo, hi), &l| {
                    let x = column(gx, l);
                    (lo.min(x), hi.max(x))
                })
        };
        let (left, right) = (clip.x0 as f32 - MARGIN_PX, clip.x1 as f32 + MARGIN_PX);
        // Cell gx spans grid columns gx..=gx + 1.
        let start = partition(cells, |gx| reach(gx + 1).1 < left);
        let end = partition(cells, |gx| reach(gx).0 < right);
        start..end.max(start)
    }
}

/// The first `i` in `0..n` for which `before(i)` is false (`before` holds
/// for a prefix of `0..n`).
fn partition(n: usize, before: impl Fn(usize) -> bool) -> usize {
    let (mut lo, mut hi) = (0, n);
    while lo < hi {
        let mid = lo + (hi - lo) / 2;
        if before(mid) {
            lo = mid + 1;
        } else {
            hi = mid;
        }
    }
    lo
}
