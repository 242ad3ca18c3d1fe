//! The painter's order over a mesh: strips from the back to the front,
//! each strip's two grid rows projected once and handed on. Both the
//! strip-by-strip painter and the full frame's bands walk it.

use std::ops::Range;

use super::strip::painter_order;
use crate::render::base::canvas::Canvas;
use crate::render::scene::{Scene, Style, Vert};

/// Two projected grid rows, reused from strip to strip; only the points a
/// strip's cells need are projected.
pub(crate) struct Rows {
    top: Vec<Vert>,
    bottom: Vec<Vert>,
    /// The grid rows `top` and `bottom` hold, if any, and which points.
    held: Option<[(usize, Range<usize>); 2]>,
}

impl Rows {
    pub(crate) fn new() -> Self {
        Rows {
            top: Vec::new(),
            bottom: Vec::new(),
            held: None,
        }
    }

    /// Makes `top` and `bottom` hold points `xs` of the grid rows at the
    /// back and the front of strip `s`. Walking back to front, the last
    /// strip's front row is this one's back row; front to back, its back
    /// row is this one's front row: that row is kept, not projected again.
    fn load(&mut self, scene: &Scene, s: usize, xs: Range<usize>) {
        let (back, front) = scene.strip_grid_rows(s);
        let n = scene.cells() + 1;
        self.top.resize(n, Vert::default());
        self.bottom.resize(n, Vert::default());
        let fresh = |row: usize, out: &mut [Vert]| scene.project_points(row, xs.clone(), out);
        match self.held.take() {
            Some([_, (row, had)]) if row == back => {
                std::mem::swap(&mut self.top, &mut self.bottom);
                project_missing(scene, back, &xs, &had, &mut self.top);
                fresh(front, &mut self.bottom);
            }
            Some([(row, had), _]) if row == front => {
                std::mem::swap(&mut self.top, &mut self.bottom);
                project_missing(scene, front, &xs, &had, &mut self.bottom);
                fresh(back, &mut self.top);
            }
            _ => {
                fresh(back, &mut self.top);
                fresh(front, &mut self.bottom);
            }
        }
        self.held = Some([(back, xs.clone()), (front, xs)]);
    }
}

/// Projects the points `xs` of grid `row` into `out`, which holds the
/// points `had` of that row already.
fn project_missing(
    scene: &Scene,
    row: usize,
    xs: &Range<usize>,
    had: &Range<usize>,
    out: &mut [Vert],
) {
    let before = xs.start..had.start.clamp(xs.start, xs.end);
    scene.project_points(row, before, out);
    let after = had.end.clamp(xs.start, xs.end)..xs.end;
    scene.project_points(row, after, out);
}

/// Draws `strips` of `scene` into `canvas` in the painter's order (back to
/// front, or reversed on a canvas that keeps the first write), skipping
/// strips that cannot touch the canvas's rows. A canvas narrower than the `frame_width` walks
/// only the cells that can reach its columns (filled styles; the lines of
/// Sonar and Outline are cheap and walk every cell).
pub(crate) fn draw_strips(
    scene: &Scene,
    canvas: &mut Canvas,
    rows: &mut Rows,
    strips: Range<usize>,
    frame_width: u32,
) {
    let clip = *canvas.clip();
    let narrow = clip.x0 > 0 || clip.x1 < i64::from(frame_width);
    let n = scene.cells() + 1;
    // The cells reaching the band in the strip drawn last, where the next
    // strip's search starts.
    let mut reaching = 0..scene.cells();
    painter_order(canvas, strips, |canvas, s| {
        let (lo, hi) = scene.strip_rows(s);
        if hi < clip.y0 || lo >= clip.y1 {
            return;
        }
        let filled = scene.style.is_filled();
        let reach = (narrow && filled || canvas.keeps_first())
            .then(|| scene.strip_reach(s))
            .flatten();
        let cells = match &reach {
            Some(reach) if narrow && filled => {
                reaching = reach.cells_reaching(&clip, &reaching);
                reaching.clone()
            }
            _ => 0..scene.cells(),
        };
        // Drawing front to back, a strip whose cells here all lie below
        // what the band holds across its width is hidden: not projected.
        if cells.is_empty()
            || (canvas.keeps_first()
                && canvas.hidden(clip.x0, clip.x1 - 1, scene.strip_top(s, &cells)))
        {
            return;
        }
        let cells = match &reach {
            Some(reach) if canvas.keeps_first() => reach.cells_showing(canvas, cells),
            _ => cells,
        };
        if cells.is_empty() {
            return;
        }
        rows.load(scene, s, cells.start..(cells.end + 1).min(n));
        let (top, bottom) = (&mut rows.top[..], &mut rows.bottom[..]);
        match scene.style {
            Style::Shaded | Style::Mono => scene.fill_strip(canvas, s, cells, top, bottom),
            Style::Sonar => scene.edge_strip(canvas, s, top, bottom, true),
            Style::Outline => scene.edge_strip(canvas, s, top, bottom, false),
        }
    });
}
