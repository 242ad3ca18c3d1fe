//! The painter's order over a mesh: strips from the back to the front,
//! each strip's two grid rows projected once and handed on. Both the
//! strip-by-strip painter and the full frame's bands walk it.

use std::ops::Range;

use super::canvas::Canvas;
use super::scene::{Scene, Style, Vert};

/// Two projected grid rows, reused from strip to strip; only the points a
/// strip's cells need are projected.
pub(crate) struct Rows {
    top: Vec<Vert>,
    bottom: Vec<Vert>,
    /// The grid row `bottom` holds, if any, and which of its points.
    bottom_row: Option<(usize, Range<usize>)>,
}

impl Rows {
    pub(crate) fn new() -> Self {
        Rows {
            top: Vec::new(),
            bottom: Vec::new(),
            bottom_row: None,
        }
    }

    /// Makes `top` and `bottom` hold points `xs` of the grid rows at the
    /// back and the front of strip `s`.
    fn load(&mut self, scene: &Scene, s: usize, xs: Range<usize>) {
        let (back, front) = scene.strip_grid_rows(s);
        let n = scene.cells() + 1;
        self.top.resize(n, Vert::default());
        self.bottom.resize(n, Vert::default());
        match self.bottom_row.take() {
            Some((row, had)) if row == back => {
                std::mem::swap(&mut self.top, &mut self.bottom);
                // Project only the points the last strip did not need.
                let before = xs.start..had.start.clamp(xs.start, xs.end);
                scene.project_points(back, before, &mut self.top);
                let after = had.end.clamp(xs.start, xs.end)..xs.end;
                scene.project_points(back, after, &mut self.top);
            }
            _ => scene.project_points(back, xs.clone(), &mut self.top),
        }
        scene.project_points(front, xs.clone(), &mut self.bottom);
        self.bottom_row = Some((front, xs));
    }
}

/// Draws `strips` of `scene` into `canvas`, skipping strips that cannot
/// touch the canvas's rows. A canvas narrower than the `frame_width` walks
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
    for s in strips {
        let (lo, hi) = scene.strip_rows(s);
        if hi < clip.y0 || lo >= clip.y1 {
            continue;
        }
        let filled = matches!(scene.style, Style::Shaded | Style::Mono);
        let cells = if narrow && filled {
            scene.cells_reaching(s, &clip)
        } else {
            0..scene.cells()
        };
        if cells.is_empty() {
            continue;
        }
        rows.load(scene, s, cells.start..(cells.end + 1).min(n));
        let (top, bottom) = (&rows.top[..], &rows.bottom[..]);
        match scene.style {
            Style::Shaded | Style::Mono => scene.fill_strip(canvas, s, cells, top, bottom),
            Style::Sonar => scene.edge_strip(canvas, s, top, bottom, true),
            Style::Outline => scene.edge_strip(canvas, s, top, bottom, false),
        }
    }
}
