//! The floating horizon of a mesh: in each column, which of the drawn rows
//! forms the top of the land, and every place where nearer land hides
//! farther land (a crest with land, water or sky above it).
//!
//! The kept rows are swept front to back at each column's centre, keeping
//! the highest point seen so far (the horizon). A row that rises above the
//! horizon right behind the row that set it is the same slope going on; a
//! row that rises above it after rows hidden behind it is farther land
//! coming out from behind a crest: the horizon there, before the row lowers
//! it, is a silhouette of near land against far land.
//!
//! Only the frame's geometry is read, never its pixels, so the horizon is
//! the same for the full frame's bands and the painter's strips.

use std::ops::RangeInclusive;

use crate::render::base::size::Size;
use crate::render::framing::tops::finite;
use crate::render::scene::Scene;
use crate::settings::MAX_GRID_EXPONENT;

/// Places across a pixel's width where an edge's height is read.
pub(crate) const SAMPLES: usize = 4;

/// No row yet.
const NONE: u32 = u32::MAX;

/// Segments walked, from a hint, to find where a row crosses a place.
const MAX_WALK: usize = 16;
/// Grid points of a row passed over at once where they lie below the
/// horizon (a block of the rows' tops).
const POINTS: usize = 16;
/// Columns whose lowest top is kept together.
const TILE: usize = 32;

/// An edge across one column: its height at [`SAMPLES`] places across the
/// pixel's width and at its centre, in rows from the frame's top.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Edge {
    pub samples: [f32; SAMPLES],
    pub centre: f32,
}

/// The row forming the horizon in a column: its height there, the kept
/// row (an index into the scene's rows) and the grid point starting the
/// segment that crosses the column's centre.
#[derive(Clone, Copy, Debug)]
struct Top {
    y: f32,
    row: u32,
    point: u32,
}

/// A silhouette of nearer land against farther land in one column, in 8
/// bytes: an alpine mountain at 4K has a quarter of a million of them,
/// all kept until the frame is complete (at 16 bytes they took 4 MB, the
/// largest part of a 4K slide show's peak beside the frames and the field).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Crest {
    x: u16,
    /// The first pixel row the near land covers at the column's centre
    /// (its top there rounded to pixel centres: all the mixing needs of it).
    top: u16,
    /// The near land's kept row (an index into the scene's rows) and the
    /// grid point starting its segment across the column's centre.
    row: u16,
    point: u16,
}

// A grid's rows and points fit a crest's `u16`s.
const _: () = assert!(MAX_GRID_EXPONENT < 16);

/// Columns and rows a crest can name: past them (no window, and no
/// `--size`, is that large) the pixels stay as the strips drew them.
const CREST_SIDE: usize = 1 << 16;

/// Where the land's top is in each column, and where it hides farther land.
pub(crate) struct Horizon {
    sweep: Sweep,
}

impl Horizon {
    /// Sweeps `scene`'s rows front to back across a frame of `size`.
    pub(crate) fn sweep(scene: &Scene, size: Size) -> Self {
        HorizonSweep::new(size).finish(scene)
    }

    /// The places where nearer land hides farther land inside the frame,
    /// front to back in each column.
    pub(crate) fn crests(&self) -> &[Crest] {
        &self.sweep.crests
    }

    /// The land's top edge across column `x` as the mesh's rows draw it
    /// (`None` where no land reaches the column).
    pub(crate) fn skyline(&self, scene: &Scene, x: u32) -> Option<Edge> {
        let tops = &self.sweep;
        let top = tops.top_of(x)?;
        if top.row == NONE || !top.y.is_finite() {
            return None;
        }
        // Beside the column the top may be another row's: the neighbours'
        // rows count too.
        let beside = [x.wrapping_sub(1), x + 1].map(|n| tops.top_of(n).filter(|t| t.row != NONE));
        let mut rows = vec![(top.row, top.point)];
        rows.extend(beside.iter().flatten().map(|t| (t.row, t.point)));
        rows.dedup_by_key(|r| r.0);
        let samples = edge_of(scene, &rows, 1, x)?;
        Some(Edge {
            samples,
            centre: top.y,
        })
    }
}

impl Crest {
    /// The crest's column.
    pub(crate) fn x(&self) -> u32 {
        self.x.into()
    }

    /// The first pixel row the near land covers at the column's centre.
    pub(crate) fn top(&self) -> u32 {
        self.top.into()
    }

    /// The near land's edge across the crest's column: its height at the
    /// [`SAMPLES`] places.
    pub(crate) fn edge(&self, scene: &Scene) -> Option<[f32; SAMPLES]> {
        let rows = [(u32::from(self.row), u32::from(self.point))];
        edge_of(scene, &rows, 0, self.x())
    }
}

/// The edge's heights across column `x` formed by the first of `rows`
/// (kept rows with a grid point near the column), lowered to the highest
/// of them and of their neighbours `reach` rows in front and behind.
/// `None` where one of the rows next to the first ends inside the column:
/// there the mesh's side, which no row's line follows, may be the edge.
fn edge_of(scene: &Scene, rows: &[(u32, u32)], reach: u32, x: u32) -> Option<[f32; SAMPLES]> {
    let last = scene.rows.len() as u32 - 1;
    let mut samples = [f32::INFINITY; SAMPLES];
    for (i, &(row, point)) in rows.iter().enumerate() {
        for r in row.saturating_sub(reach)..=(row + reach).min(last) {
            let gy = scene.rows[r as usize];
            match row_samples(scene, gy, point as usize, x) {
                Some(ys) => {
                    for (s, y) in samples.iter_mut().zip(ys) {
                        *s = s.min(y);
                    }
                }
                None if i == 0 => return None,
                None => {}
            }
        }
    }
    Some(samples)
}

/// A sweep of the horizon under way, so that the painter can spread it
/// over its steps (at a large frame, one step carrying it all would stall).
pub(crate) struct HorizonSweep {
    sweep: Sweep,
    /// Kept rows swept so far, from the front.
    done: usize,
    points: Vec<[f32; 2]>,
}

impl HorizonSweep {
    /// A sweep across a frame of `size`, no row swept yet.
    pub(crate) fn new(size: Size) -> Self {
        HorizonSweep {
            sweep: Sweep::new(size.width as usize, size.height as usize),
            done: 0,
            points: Vec::with_capacity(POINTS + 1),
        }
    }

    /// Sweeps `scene`'s rows until `share` (0..=1) of them are done.
    pub(crate) fn advance_to(&mut self, scene: &Scene, share: f32) {
        let total = scene.rows.len();
        let target = ((total as f32 * share.clamp(0.0, 1.0)).ceil() as usize).min(total);
        while self.done < target {
            let row = total - 1 - self.done;
            self.sweep_row(scene, row);
            self.done += 1;
        }
    }

    /// The horizon, once every row of `scene` is swept.
    pub(crate) fn finish(mut self, scene: &Scene) -> Horizon {
        self.advance_to(scene, 1.0);
        Horizon { sweep: self.sweep }
    }

    /// Lowers the horizon to kept row `row`, block by block of points,
    /// passing over the blocks wholly below it.
    fn sweep_row(&mut self, scene: &Scene, row: usize) {
        let n = scene.cells() + 1;
        let gy = scene.rows[row];
        for first in (0..n.saturating_sub(1)).step_by(POINTS) {
            let last = (first + POINTS).min(n - 1);
            if self.sweep.hides(scene, gy, first, last) {
                continue;
            }
            project_points(scene, gy, first..=last, &mut self.points);
            self.sweep.lower(&self.points, first, row as u32);
        }
        self.sweep.settle();
    }
}

/// The screen positions of grid row `gy`'s points `gxs` (the drawn
/// surface: land at its height, water at its level), into `out`.
fn project_points(scene: &Scene, gy: usize, gxs: RangeInclusive<usize>, out: &mut Vec<[f32; 2]>) {
    let row = scene.field.row(gy);
    let line = scene.view.along_row(gy as f32);
    out.clear();
    scene.surfaces(gy, *gxs.start()..*gxs.end() + 1, |gx, w| {
        out.push([gx as f32, finite(row[gx]).max(w)]);
    });
    for points in out.chunks_mut(4) {
        let [px, py] = line.project_few(points);
        for (k, p) in points.iter_mut().enumerate() {
            *p = [px[k], py[k]];
        }
    }
}

/// The horizon while it is swept: each column's top so far, the lowest
/// top in each tile of [`TILE`] columns (a block of points wholly below
/// it is passed over unprojected), and the crests found inside the frame.
struct Sweep {
    /// Each column's top so far: its height, kept row and grid point (the
    /// three apart, so that the inner loop reads and writes little).
    ys: Vec<f32>,
    rows: Vec<u32>,
    points: Vec<u32>,
    lowest: Vec<f32>,
    /// Tiles whose lowest top may have risen since it was last worked out.
    stale: Vec<bool>,
    crests: Vec<Crest>,
    /// The columns and pixel rows whose crests are kept: the frame's
    /// (a crest off it mixes no pixel), at most [`CREST_SIDE`].
    crest_columns: usize,
    crest_rows: f32,
}

impl Sweep {
    fn new(width: usize, height: usize) -> Self {
        let tiles = width.div_ceil(TILE);
        Sweep {
            crest_columns: width.min(CREST_SIDE),
            crest_rows: height.min(CREST_SIDE) as f32,
            ys: vec![f32::INFINITY; width],
            rows: vec![NONE; width],
            points: vec![0; width],
            lowest: vec![f32::INFINITY; tiles],
            stale: vec![false; tiles],
            crests: Vec::new(),
        }
    }

    /// Column `x`'s top, if the frame has that column.
    fn top_of(&self, x: u32) -> Option<Top> {
        ((x as usize) < self.ys.len()).then(|| self.top(x as usize))
    }

    /// Column `c`'s top.
    fn top(&self, c: usize) -> Top {
        Top {
            y: self.ys[c],
            row: self.rows[c],
            point: self.points[c],
        }
    }

    /// Whether grid row `gy`'s points `first..=last` lie wholly below the
    /// horizon. Screen rows do not depend on the grid column (the cameras
    /// do not roll), and the block's columns lie between its corners'.
    fn hides(&self, scene: &Scene, gy: usize, first: usize, last: usize) -> bool {
        let z = scene.row_top.within(gy, first..=last);
        let line = scene.view.along_row(gy as f32);
        let corner = |gx: usize, z: f32| line.project(gx as f32, z);
        let corners = [
            corner(first, 0.0),
            corner(last, 0.0),
            corner(first, z),
            corner(last, z),
        ];
        let top = corners[2].y;
        let (lo, hi) = corners
            .iter()
            .fold((f32::INFINITY, f32::NEG_INFINITY), |(lo, hi), p| {
                (lo.min(p.x), hi.max(p.x))
            });
        if !(top.is_finite() && lo.is_finite() && hi.is_finite()) {
            return false;
        }
        let width = self.ys.len() as f32;
        let (c0, c1) = (first_centre(lo, width), first_centre(hi, width));
        if c0 >= c1 {
            return true;
        }
        let tiles = c0 / TILE..=(c1 - 1) / TILE;
        self.lowest[tiles].iter().all(|&low| top >= low)
    }

    /// Lowers the horizon to the line through `points` (grid points from
    /// `first` on, of kept row `row`) where it passes above, noting a crest
    /// wherever that row comes out from behind land nearer than the row
    /// just in front of it.
    fn lower(&mut self, points: &[[f32; 2]], first: usize, row: u32) {
        let width = self.ys.len() as f32;
        let Some((&start, rest)) = points.split_first() else {
            return;
        };
        let (mut prev, mut prev_column) = (start, first_centre(start[0], width));
        for (i, &p) in rest.iter().enumerate() {
            let column = first_centre(p[0], width);
            // The columns whose centres lie in [a, b), a left of b.
            let (a, b, c0, c1) = if prev[0] <= p[0] {
                (prev, p, prev_column, column)
            } else {
                (p, prev, column, prev_column)
            };
            (prev, prev_column) = (p, column);
            if c0 >= c1 || !(a[1].is_finite() && b[1].is_finite()) {
                continue;
            }
            let slope = (b[1] - a[1]) / (b[0] - a[0]);
            let point = (first + i) as u32;
            let (ys, rows) = (&mut self.ys[c0..c1], &mut self.rows[c0..c1]);
            for (k, (top_y, top_row)) in ys.iter_mut().zip(rows.iter_mut()).enumerate() {
                let y = a[1] + slope * ((c0 + k) as f32 + 0.5 - a[0]);
                if y >= *top_y {
                    continue;
                }
                // Not the row just in front (a slope going on), nor this
                // row again, nor nothing yet: farther land coming out.
                if top_row.wrapping_sub(row) > 1 && *top_row != NONE {
                    let top = (*top_y - 0.5).ceil();
                    if top >= 0.0 && top < self.crest_rows && c0 + k < self.crest_columns {
                        self.crests.push(Crest {
                            x: (c0 + k) as u16,
                            top: top as u16,
                            row: *top_row as u16,
                            point: self.points[c0 + k] as u16,
                        });
                    }
                }
                (*top_y, *top_row) = (y, row);
                self.points[c0 + k] = point;
            }
            self.stale[c0 / TILE] = true;
            self.stale[(c1 - 1) / TILE] = true;
        }
    }

    /// Works out the lowest top of the tiles a row changed.
    fn settle(&mut self) {
        for (t, stale) in self.stale.iter_mut().enumerate() {
            if std::mem::take(stale) {
                self.lowest[t] =
                    lowest_of(&self.ys[t * TILE..(t * TILE + TILE).min(self.ys.len())]);
            }
        }
    }
}

/// The largest of `ys` (the lowest on screen), in eight lanes so that it
/// compiles to vector instructions: a tile is worked out again after
/// nearly every row.
fn lowest_of(ys: &[f32]) -> f32 {
    let mut lanes = [f32::NEG_INFINITY; 8];
    let chunks = ys.chunks_exact(8);
    let rest = chunks.remainder();
    for chunk in chunks {
        for (l, &y) in lanes.iter_mut().zip(chunk) {
            *l = if y > *l { y } else { *l };
        }
    }
    let most = lanes.iter().fold(f32::NEG_INFINITY, |m, &l| m.max(l));
    rest.iter().fold(most, |m, &y| m.max(y))
}

/// The first column (of a frame `width` wide) whose centre lies at or
/// right of screen x `x`. (Without SSE 4.1, `f32::ceil` is a call: here it
/// was a sixth of the sweep.)
#[inline]
fn first_centre(x: f32, width: f32) -> usize {
    let t = (x - 0.5).clamp(0.0, width);
    // Through i32: a float to usize conversion is a branchy sequence on x86.
    let whole = t as i32;
    whole as usize + usize::from((whole as f32) < t)
}

/// The height on screen of grid row `gy`'s line at the [`SAMPLES`]
/// places across column `x`, looked for from grid point `hint` outwards
/// (`None` when the row does not cross one of them within [`MAX_WALK`]
/// segments).
fn row_samples(scene: &Scene, gy: usize, hint: usize, x: u32) -> Option<[f32; SAMPLES]> {
    let row = scene.field.row(gy);
    let n = row.len();
    if n < 2 {
        return None;
    }
    let point = |gx: usize| {
        scene
            .view
            .project(gx as f32, gy as f32, finite(row[gx]).max(0.0))
    };
    let mut i = hint.min(n - 2);
    let (mut a, mut b) = (point(i), point(i + 1));
    let mut steps = 0;
    let mut out = [0.0; SAMPLES];
    for (k, o) in out.iter_mut().enumerate() {
        let sx = x as f32 + (k as f32 + 0.5) / SAMPLES as f32;
        loop {
            let rising = a.x <= b.x;
            let (lo, hi) = if rising { (a, b) } else { (b, a) };
            // Towards lower screen x is a step back along a rising row.
            let step_back = if sx < lo.x {
                rising
            } else if sx > hi.x {
                !rising
            } else {
                let t = if hi.x > lo.x {
                    (sx - lo.x) / (hi.x - lo.x)
                } else {
                    0.0
                };
                *o = lo.y + (hi.y - lo.y) * t;
                break;
            };
            steps += 1;
            if steps > MAX_WALK {
                return None;
            }
            if step_back {
                i = i.checked_sub(1)?;
                (a, b) = (point(i), a);
            } else if i + 2 < n {
                i += 1;
                (a, b) = (b, point(i + 1));
            } else {
                return None;
            }
        }
    }
    Some(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_row_behind_a_crest_marks_the_crest_and_a_continuing_slope_does_not() {
        let mut s = Sweep::new(10, 20);
        // Front row 3 at height 8, row 2 right behind it higher (a slope
        // going on), row 1 hidden behind it, row 0 far land rising above.
        s.lower(&[[0.0, 8.0], [10.0, 8.0]], 0, 3);
        s.lower(&[[0.0, 6.0], [10.0, 6.0]], 0, 2);
        assert!(s.crests.is_empty());
        s.lower(&[[0.0, 7.0], [10.0, 7.0]], 0, 1);
        assert!(s.crests.is_empty());
        s.lower(&[[0.0, 2.0], [5.0, 2.0], [10.0, 9.0]], 0, 0);
        // Only where the far row passes above the crest (columns 0..8).
        let xs: Vec<u32> = s.crests.iter().map(Crest::x).collect();
        assert_eq!(xs, (0..8).collect::<Vec<u32>>());
        // The crest's top at 6.0: the pixel row whose centre (6.5) is below it.
        assert!(s.crests.iter().all(|c| c.top() == 6 && c.row == 2));
        assert_eq!(s.top(0).row, 0);
        assert_eq!(s.top(9).row, 2);
        assert_eq!(s.top(6).point, 1, "the far row's second segment");
    }

    #[test]
    fn a_crest_takes_8_bytes() {
        // A quarter of a million of them for an alpine mountain at 4K.
        assert_eq!(std::mem::size_of::<Crest>(), 8);
    }

    #[test]
    fn crests_below_the_frame_are_not_kept() {
        let mut s = Sweep::new(10, 7);
        // Near row 3 ending below the frame's 7 rows on the left, inside
        // it on the right; far row 0 rises above it everywhere.
        s.lower(&[[0.0, 9.0], [10.0, 4.0]], 0, 3);
        s.lower(&[[0.0, 1.0], [10.0, 1.0]], 0, 0);
        let kept: Vec<(u32, u32)> = s.crests.iter().map(|c| (c.x(), c.top())).collect();
        // Row 3's top at column x's centre is 9 - (x + 0.5) / 2: in pixel
        // row 7 or lower (off the frame) left of column 5.
        assert_eq!(kept, vec![(5, 6), (6, 6), (7, 5), (8, 5), (9, 4)]);
    }

    #[test]
    fn a_line_falling_right_to_left_lowers_the_same_columns() {
        let (mut a, mut b) = (Sweep::new(8, 8), Sweep::new(8, 8));
        a.lower(&[[0.0, 1.0], [8.0, 5.0]], 0, 0);
        b.lower(&[[8.0, 5.0], [0.0, 1.0]], 0, 0);
        for (p, q) in a.ys.iter().zip(&b.ys) {
            assert_eq!(p, q);
        }
        assert!((a.top(3).y - (1.0 + 3.5 * 0.5)).abs() < 1e-6);
    }

    #[test]
    fn the_lowest_of_a_tile_is_its_largest_height() {
        let ys: Vec<f32> = (0..37).map(|i| ((i * 7) % 37) as f32).collect();
        assert_eq!(lowest_of(&ys), 36.0);
        assert_eq!(lowest_of(&ys[..5]), 28.0);
        assert_eq!(lowest_of(&[f32::INFINITY, 1.0]), f32::INFINITY);
    }

    #[test]
    fn first_centres_are_the_columns_whose_centres_lie_at_or_after_x() {
        for (x, want) in [
            (-3.0, 0),
            (0.0, 0),
            (0.5, 0),
            (0.51, 1),
            (1.5, 1),
            (2.2, 2),
            (9.9, 8),
        ] {
            assert_eq!(first_centre(x, 8.0), want, "x = {x}");
        }
    }

    #[test]
    fn a_tile_keeps_the_lowest_top_of_its_columns() {
        let mut s = Sweep::new(TILE + 4, 16);
        s.lower(&[[0.0, 10.0], [TILE as f32, 10.0]], 0, 1);
        s.settle();
        assert_eq!(s.lowest[0], 10.0);
        assert_eq!(s.lowest[1], f32::INFINITY, "columns nothing reached");
        s.lower(&[[0.0, 4.0], [2.0, 4.0]], 0, 0);
        s.settle();
        assert_eq!(s.lowest[0], 10.0, "most columns still end at 10");
    }
}
