//! Which grid rows a filled mesh is drawn with: every row where rows stand
//! apart on screen, every second or fourth where they crowd together.
//!
//! In the vista most of a 1080p frame's 1024 rows lie less than a pixel
//! apart towards the horizon (938 of them at sea level): their triangles
//! cover hardly a pixel of their own, yet each costs as much to set up as a
//! large one. Where a run of rows stays within [`CROWDED_PX`] of its first
//! row on screen at sea level, across the whole width, the rows between are
//! left out of the mesh. Whole rows go, so the mesh keeps no cracks, and
//! every column stays.
//!
//! The distance is where the far ridges' shapes and light are, and a row
//! merged away is a ridge redrawn a little lower and lit by its neighbours'
//! mean slope. Measured against the same scene drawn larger
//! (examples/quality.rs), a smaller threshold brings the picture closer
//! while saving less of the frame's work each time: [`CROWDED_PX`] is
//! where the far ridges are already close and most crowded rows still go.

use super::view::View;

/// Rows closer than this on screen (at every sampled column) are merged.
const CROWDED_PX: f32 = 0.75;
/// Most rows merged into one strip.
const MAX_STEP: usize = 4;
/// Columns sampled across a row pair.
const SAMPLES: usize = 64;

/// The grid rows (of `n` a side) to draw, back to front: always the first
/// and the last.
pub(crate) fn kept_rows(n: usize, view: &View) -> Vec<usize> {
    let stride = (n / SAMPLES).max(1);
    let columns: Vec<usize> = (0..n)
        .step_by(stride)
        .chain(std::iter::once(n - 1))
        .collect();
    let screen_y = |x: usize, y: usize| view.project(x as f32, y as f32, 0.0).y;
    let crowded = |y0: usize, y1: usize| {
        columns
            .iter()
            .all(|&x| (screen_y(x, y1) - screen_y(x, y0)).abs() < CROWDED_PX)
    };
    let mut rows = vec![0];
    let mut y = 0;
    while y < n - 1 {
        let mut step = 1;
        while step < MAX_STEP && y + 2 * step < n && crowded(y, y + 2 * step) {
            step *= 2;
        }
        y += step;
        rows.push(y);
    }
    rows
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::base::size::Size;
    use crate::settings::ViewKind;

    #[test]
    fn crowded_rows_merge_and_the_ends_stay() {
        let view = View::new(ViewKind::Vista, 1025, 250.0, 50.0, Size::new(1920, 1080));
        let rows = kept_rows(1025, &view);
        assert_eq!((rows[0], *rows.last().unwrap()), (0, 1024));
        assert!(
            rows.windows(2)
                .all(|w| w[1] > w[0] && w[1] - w[0] <= MAX_STEP)
        );
        // The back crowds, the front does not.
        assert!(rows.len() < 700, "{} rows kept", rows.len());
        assert_eq!(rows[rows.len() - 2], 1023, "the nearest row was merged");
        // A view whose rows stand apart keeps them all.
        let near = View::new(ViewKind::Oblique, 33, 250.0, 50.0, Size::new(1920, 1080));
        assert_eq!(kept_rows(33, &near), (0..33).collect::<Vec<_>>());
    }
}
