//! `detail = "auto"`: the grid chosen per frame, so a cell is a few pixels
//! wide where the land is nearest to the viewer.
//!
//! Finer grids cost time and show nothing more; coarser ones show their
//! facets in the foreground. The rule measures the view itself (a flat grid
//! in the frame), so it holds for every view and frame shape: about 1025
//! points a side at 1920x1080 in the vista, 2049 at 3840x2160, far fewer in
//! a 152x112 preview.
//!
//! At this rule's ~4 px a face is a grain of the land's texture (seen at
//! 1:1): under smooth shading (the default in the vista and the
//! perspective) its corners' colours blend across it; the classic looks,
//! the seed programs' and `shading = "flat"` keep one colour a face.
//! Larger faces come only from a detail the user picks or from
//! `low_detail`, whose big facets are the look Mountain Terrain asks for.

use super::view::View;
use crate::render::base::size::Size;
use crate::settings::{Detail, Settings};
use crate::terrain::heightfield::MAX_EXPONENT;

/// The width a cell should have where the land is nearest, in pixels.
const TARGET_CELL_PX: f32 = 4.0;
/// Grid exponent of the flat reference grid the view is measured on.
const REFERENCE_EXPONENT: u32 = 10;
/// The coarsest grid `"auto"` picks (17x17): a 9x9 grid (`detail = 3`,
/// seed 000's fewest iterations) is there to be asked for, but even the
/// smallest preview is better served by the finer one.
const AUTO_LEAST_EXPONENT: u32 = 4;
/// Relief assumed when fitting the reference grid, as a fraction of its
/// width (the oblique and perspective fits include the peaks).
const REFERENCE_RELIEF: f32 = 0.2;

/// `settings` with `detail = "auto"` replaced by the level for a
/// frame of `size` (other settings unchanged).
pub fn for_frame(settings: &Settings, size: Size) -> Settings {
    let mut s = settings.clone();
    if s.detail == Detail::Auto {
        s.detail = Detail::Level(auto_level(settings, size));
    }
    s
}

/// The detail level whose nearest cells are about `TARGET_CELL_PX` wide
/// in this frame, before `low_detail` halves it.
pub fn auto_level(settings: &Settings, size: Size) -> u32 {
    let cells = (1usize << REFERENCE_EXPONENT) as f32;
    let extent = cells;
    let view = View::new(
        settings.view,
        cells as usize + 1,
        extent,
        REFERENCE_RELIEF * extent,
        Size::new(size.width.max(1), size.height.max(1)),
    );
    let px = nearest_cell_px(&view, cells);
    let wanted = cells * px / TARGET_CELL_PX;
    let level = if wanted.is_finite() && wanted >= 1.0 {
        wanted.log2().round() as u32
    } else {
        AUTO_LEAST_EXPONENT
    };
    level.clamp(AUTO_LEAST_EXPONENT, MAX_EXPONENT)
}

/// Width in pixels of the cell at the middle of the near edge.
fn nearest_cell_px(view: &View, cells: f32) -> f32 {
    let mid = (cells / 2.0).floor();
    let a = view.project(mid, cells, 0.0);
    let b = view.project(mid + 1.0, cells, 0.0);
    (b - a).length()
}
