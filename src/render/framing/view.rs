//! Projection of grid points to the screen, fitted to a frame.
//!
//! Grid coordinates: column `gx` left to right, row `gy` back to front, both
//! in grid steps; heights `z` in the field's own units, with
//! `Heightfield::extent` giving the grid's width in those units, so relief is
//! drawn at its true scale.

use glam::{Vec2, Vec3, Vec4};

use super::aim::{Aim, DOWN_CROPS};
use super::camera::{Camera, RowCamera};
use super::tops::finite;
use super::vista;
use crate::render::base::size::Size;
use crate::settings::{ViewKind, World};
use crate::terrain::Heightfield;

/// The lowest point of `field`'s near edge (its last row), at least sea
/// level: the `near_floor` [`View::fitted`] asks for.
pub fn near_floor(field: &Heightfield) -> f32 {
    let last = field.size().saturating_sub(1);
    let lowest = (field.row(last).iter()).fold(f32::INFINITY, |m, &h| m.min(finite(h)));
    if lowest.is_finite() {
        lowest.max(0.0)
    } else {
        0.0
    }
}

/// The highest point of each row of a grid `extent` units wide whose row
/// tops are `row_top` (spread evenly from back to front), down its
/// middle, as the vista's fit reads them.
fn vista_tops(row_top: &[f32], extent: f32) -> Vec<Vec3> {
    let last = row_top.len().saturating_sub(1).max(1) as f32;
    (row_top.iter().enumerate())
        .map(|(i, &z)| {
            let z = if z.is_finite() { z.max(0.0) } else { 0.0 };
            Vec3::new(0.5 * extent, extent * i as f32 / last, z)
        })
        .collect()
}

/// Sine and cosine of the classic view's tilt: the grid is tipped back 70
/// degrees about the x axis (seed 000's `xTh = -1.396`). Written out rather
/// than computed so no platform's `sin` can move a pixel.
const TILT_SIN_COS: (f32, f32) = (0.939_692_6, 0.342_020_15);
/// Sine and cosine of seed 000's tilt as its code has it, `xTh = -1.396`
/// radians: 80 degrees, where the article's words say 70 (docs/classics.md).
/// `look = "fractal-mountain-climbing"` draws with it, and its light
/// (`sun = "classic"`) is worked through with it.
const LISTING_TILT_SIN_COS: (f32, f32) = (0.984_762, 0.173_907_57);
/// How the oblique view is drawn: ours, or as seed 000's listing draws it
/// (`look = "fractal-mountain-climbing"`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Oblique {
    /// Tipped back by the listing's 80 degrees rather than our 70.
    pub listing_tilt: bool,
    /// Heights drawn this many times their own (1 for ours): the listing's
    /// relief against its grid (see [`listing_relief`]).
    pub relief: f32,
}

impl Oblique {
    /// Our own oblique view.
    pub const OURS: Oblique = Oblique {
        listing_tilt: false,
        relief: 1.0,
    };
}

/// `CalcPoint3`'s relief per Height menu step: a column is `2 xc` wide
/// with `xc = 0.4073 * 2^(maxIter - nIter)` (`maxIter = 9`), so the map
/// is `0.8146 * 512` wide whatever the iterations; heights are `0.00217 z`
/// with the highest point at `normalHeight = 10000 * height`.
const LISTING_PEAK_PER_WIDTH: f32 = 0.00217 * 10_000.0 / (2.0 * 0.4073 * 512.0);

/// How many times its own heights the listing would draw a field `extent`
/// wide whose highest point is `highest`, at Height menu step `height`: its
/// peak stands `0.052 * height` of the map's width high. 1 for a field
/// with no land.
pub fn listing_relief(height: u32, extent: f32, highest: f32) -> f32 {
    let k = LISTING_PEAK_PER_WIDTH * height as f32 * extent / highest;
    if k.is_finite() && k > 0.0 { k } else { 1.0 }
}

/// Seed 000's shear: each row forward moves half a step to the left, which
/// turns the square into a parallelogram seen from the front right.
const SHEAR: f32 = 0.5;
/// Empty border around the fitted mountain, as a fraction of each side
/// (oblique and perspective views).
const MARGIN: f32 = 0.02;

/// A projection fitted to one frame size.
#[derive(Debug, Clone)]
pub struct View {
    cell: f32,
    /// Pixels per unscaled unit across and down the frame (the same but
    /// in a vista stretched sideways).
    scale: Vec2,
    offset: Vec2,
    camera: Option<Camera>,
    size: usize,
    /// Sine and cosine of the tilt.
    tilt: (f32, f32),
    /// The oblique view's heights drawn this many times their own.
    relief: f32,
}

/// A view's projection along one grid row ([`View::along_row`]).
#[derive(Debug, Clone, Copy)]
pub(crate) struct RowView {
    camera: Option<RowCamera>,
    /// The row's world y.
    y: f32,
    cell: f32,
    scale: Vec2,
    offset: Vec2,
    tilt: (f32, f32),
    relief: f32,
}

impl RowView {
    /// Pixel position of the row's point at grid column `gx`, height `z`.
    #[inline]
    pub(crate) fn project(&self, gx: f32, z: f32) -> Vec2 {
        let x = gx * self.cell;
        let unscaled = match &self.camera {
            Some(cam) => cam.project(x, z),
            None => {
                let (sin, cos) = self.tilt;
                Vec2::new(x - SHEAR * self.y, self.y * cos - z * self.relief * sin)
            }
        };
        self.offset + self.scale * unscaled
    }

    /// [`RowView::project`] of four points at once (grid columns `gx`,
    /// heights `z`): their pixel x and y in lanes, the same bits.
    #[inline]
    pub(crate) fn project4(&self, gx: Vec4, z: Vec4) -> [Vec4; 2] {
        let x = gx * self.cell;
        let [ux, uy] = match &self.camera {
            Some(cam) => cam.project4(x, z),
            None => {
                let (sin, cos) = self.tilt;
                [
                    x - Vec4::splat(SHEAR * self.y),
                    Vec4::splat(self.y * cos) - z * self.relief * sin,
                ]
            }
        };
        [
            Vec4::splat(self.offset.x) + self.scale.x * ux,
            Vec4::splat(self.offset.y) + self.scale.y * uy,
        ]
    }

    /// The pixel x and y (in lanes) of up to four `points` (grid column,
    /// height), worked out at once ([`RowView::project4`]; the last point
    /// stands in for the missing ones, none gives 0): a projection is two
    /// divisions, which four points share in lanes.
    #[inline]
    pub(crate) fn project_few(&self, points: &[[f32; 2]]) -> [[f32; 4]; 2] {
        let Some(&last) = points.last() else {
            return [[0.0; 4]; 2];
        };
        let mut lanes = [last; 4];
        let n = points.len().min(4);
        lanes[..n].copy_from_slice(&points[..n]);
        let [a, b, c, d] = lanes;
        let gx = Vec4::new(a[0], b[0], c[0], d[0]);
        let z = Vec4::new(a[1], b[1], c[1], d[1]);
        self.project4(gx, z).map(|v| v.to_array())
    }
}

impl View {
    /// Fits a `size` x `size` grid `extent` units wide, with heights up to
    /// `zmax` above sea level, into a frame of `frame` size.
    pub fn new(kind: ViewKind, size: usize, extent: f32, zmax: f32, frame: Size) -> Self {
        let zmax = if zmax.is_finite() { zmax.max(0.0) } else { 0.0 };
        Self::fitted(kind, size, extent, (&[zmax, zmax], 0.0), frame)
    }

    /// Like [`View::new`], fitted to the mountain itself: `row_top[y]` is
    /// the highest point of grid row `y` (a box with the highest peak over
    /// every corner leaves a wide margin where the peak is not);
    /// `near_floor` the lowest point of the near edge (the last row), which
    /// the vista's camera must stand above to see the land.
    pub fn fitted(
        kind: ViewKind,
        size: usize,
        extent: f32,
        (row_top, near_floor): (&[f32], f32),
        frame: Size,
    ) -> Self {
        Self::fitted_oblique(
            kind,
            Oblique::OURS,
            size,
            extent,
            (row_top, near_floor),
            frame,
        )
    }

    /// [`View::fitted`], the oblique view tipped back by seed 000's code's
    /// 80 degrees and its relief where `oblique` asks (the other views
    /// ignore it).
    pub fn fitted_oblique(
        kind: ViewKind,
        oblique: Oblique,
        size: usize,
        extent: f32,
        (row_top, near_floor): (&[f32], f32),
        frame: Size,
    ) -> Self {
        let tops = (row_top, near_floor);
        let world = (World::Temperate, 0);
        Self::fitted_in(kind, (oblique, world), size, extent, tops, frame)
    }

    /// [`View::fitted_oblique`] for the mountain `identity` in `world`,
    /// whose vista aims as the world draws it for that mountain (the
    /// alpine world's looks down into its valleys; the temperate world's
    /// is [`View::fitted_oblique`]'s).
    pub fn fitted_in(
        kind: ViewKind,
        (oblique, (world, identity)): (Oblique, (World, u64)),
        size: usize,
        extent: f32,
        (row_top, near_floor): (&[f32], f32),
        Size { width, height }: Size,
    ) -> Self {
        let steps = size.saturating_sub(1).max(1) as f32;
        let zmax = row_top
            .iter()
            .copied()
            .filter(|z| z.is_finite())
            .fold(0.0, f32::max);
        let extent = if extent.is_finite() && extent > 0.0 {
            extent
        } else {
            steps
        };
        let mut view = View {
            cell: extent / steps,
            scale: Vec2::ONE,
            offset: Vec2::ZERO,
            camera: None,
            size,
            tilt: if oblique.listing_tilt {
                LISTING_TILT_SIN_COS
            } else {
                TILT_SIN_COS
            },
            relief: oblique.relief,
        };
        match kind {
            ViewKind::Vista => view.frame_vista(
                Aim::of(world, identity),
                steps,
                (row_top, near_floor),
                width as f32,
                height as f32,
            ),
            ViewKind::Perspective => {
                view.camera = Some(Camera::new(extent, zmax));
                view.fit(steps, row_top, width as f32, height as f32);
            }
            ViewKind::Oblique => view.fit(steps, row_top, width as f32, height as f32),
        }
        view
    }

    /// A `size` x `size` grid `extent` units wide seen through `camera`
    /// placed by a seed program's own rules rather than fitted: its
    /// unscaled screen point `u` drawn at pixel `offset + scale * u`.
    pub(crate) fn through(
        camera: Camera,
        size: usize,
        extent: f32,
        scale: f32,
        offset: Vec2,
    ) -> Self {
        let steps = size.saturating_sub(1).max(1) as f32;
        View {
            cell: extent / steps,
            scale: Vec2::splat(scale),
            offset,
            camera: Some(camera),
            size,
            tilt: TILT_SIN_COS,
            relief: 1.0,
        }
    }

    /// Distance of a point in front of the camera, as a fraction of the
    /// distance to the middle of the back edge (0 for the oblique view,
    /// which has no camera): what aerial haze grows with.
    #[inline]
    pub fn distance(&self, gx: f32, gy: f32, z: f32) -> f32 {
        match &self.camera {
            Some(cam) => {
                let p = Vec3::new(gx * self.cell, gy * self.cell, z);
                cam.relative_depth(p)
            }
            None => 0.0,
        }
    }

    /// Places the vista camera, aimed as `aim` says, over the land whose
    /// row tops are `row_top` (spread evenly from back to front); tall land puts the back edge
    /// lower (`vista::fitted`), a world's land still cut off at the top is
    /// looked down on from above its near part ([`Aim::looking_down`]),
    /// and land too tall for the vista at all, or
    /// whose near edge stands above its camera (`near_floor`), is framed as
    /// the perspective view frames it.
    fn frame_vista(
        &mut self,
        aim: Aim,
        steps: f32,
        (row_top, near_floor): (&[f32], f32),
        width: f32,
        height: f32,
    ) {
        let extent = self.cell * steps;
        let tops = vista_tops(row_top, extent);
        let fit = |aim| vista::fitted(aim, extent, (width, height), &tops, near_floor);
        // A world's vista that sees its land only cut off at the top sees
        // one near face: from above the near land, looking down over it,
        // where that frames it (today's vista keeps its pictures).
        let shot = match fit(aim) {
            Some(shot) if shot.cut && aim != Aim::ACROSS => (DOWN_CROPS.into_iter())
                .filter(|&cropped| cropped > aim.cropped)
                .find_map(|cropped| fit(aim.looking_down(cropped)).filter(|down| !down.cut))
                .or(Some(shot)),
            shot => shot,
        };
        let Some(shot) = shot else {
            // Land too tall for a camera low in front of it, or raised above
            // it: the perspective's camera, above it, sees it whole.
            let zmax = tops.iter().map(|p| p.z).fold(0.0, f32::max);
            self.camera = Some(Camera::new(extent, zmax));
            return self.fit(steps, row_top, width, height);
        };
        self.camera = Some(shot.camera);
        self.scale = Vec2::new(shot.focal * shot.stretch, shot.focal);
        self.offset = Vec2::new(width, height) * 0.5;
    }

    /// Chooses scale and offset so the mountain fills the frame: each row's
    /// ends at sea level and at the row's highest point (`row_top`, spread
    /// evenly from back to front when it has fewer entries than rows).
    fn fit(&mut self, steps: f32, row_top: &[f32], width: f32, height: f32) {
        let mut lo = Vec2::splat(f32::INFINITY);
        let mut hi = Vec2::splat(f32::NEG_INFINITY);
        let last = row_top.len().saturating_sub(1).max(1) as f32;
        for (i, &top) in row_top.iter().enumerate() {
            let gy = steps * i as f32 / last;
            let top = if top.is_finite() { top.max(0.0) } else { 0.0 };
            for (gx, z) in [(0.0, 0.0), (steps, 0.0), (0.0, top), (steps, top)] {
                let p = self.unscaled(gx, gy, z);
                lo = lo.min(p);
                hi = hi.max(p);
            }
        }
        let span = (hi - lo).max(Vec2::splat(1e-6));
        let room = Vec2::new(width, height) * (1.0 - 2.0 * MARGIN);
        let scale = (room.x / span.x).min(room.y / span.y);
        self.scale = Vec2::splat(if scale.is_finite() && scale > 0.0 {
            scale
        } else {
            1.0
        });
        let centre = (lo + hi) * 0.5 * self.scale;
        self.offset = Vec2::new(width, height) * 0.5 - centre;
    }

    /// Screen position before fitting.
    #[inline]
    fn unscaled(&self, gx: f32, gy: f32, z: f32) -> Vec2 {
        let (x, y) = (gx * self.cell, gy * self.cell);
        match &self.camera {
            Some(cam) => cam.project(Vec3::new(x, y, z)),
            None => {
                let (sin, cos) = self.tilt;
                Vec2::new(x - SHEAR * y, y * cos - z * self.relief * sin)
            }
        }
    }

    /// Pixel position of grid point (`gx`, `gy`) at height `z`.
    #[inline]
    pub fn project(&self, gx: f32, gy: f32, z: f32) -> Vec2 {
        self.offset + self.scale * self.unscaled(gx, gy, z)
    }

    /// [`View::project`] along grid row `gy`: the same pixels, with what
    /// does not change along a row worked out once.
    #[inline]
    pub(crate) fn along_row(&self, gy: f32) -> RowView {
        let y = gy * self.cell;
        RowView {
            camera: self.camera.map(|c| c.along_row(y)),
            y,
            cell: self.cell,
            scale: self.scale,
            offset: self.offset,
            tilt: self.tilt,
            relief: self.relief,
        }
    }

    /// Grid column the perspective camera stands in front of (the view is
    /// drawn from the outside towards it); `None` for the oblique view, which
    /// is seen from the right and drawn left to right.
    pub fn camera_column(&self) -> Option<f32> {
        self.camera
            .map(|c| c.eye_x() / self.cell)
            .filter(|_| self.size > 0)
    }

    /// Where the perspective camera stands over the ground, in grid steps
    /// (column, row); `None` for the oblique view.
    pub fn camera_ground(&self) -> Option<Vec2> {
        self.camera
            .map(|c| c.eye_ground() / self.cell)
            .filter(|_| self.size > 0 && self.cell > 0.0)
    }

    /// Where the camera's eye is, in world units (x right, y towards the
    /// front, z up); `None` for the oblique view.
    pub(crate) fn eye(&self) -> Option<Vec3> {
        self.camera.map(|c| c.eye())
    }

    /// The pixel (possibly outside the frame) where lines along world
    /// direction `dir` vanish: where the sky in that direction is seen.
    /// `None` without a camera or for directions behind it.
    pub(crate) fn vanishing(&self, dir: Vec3) -> Option<Vec2> {
        let p = self.camera?.vanishing(dir)?;
        Some(self.offset + self.scale * p)
    }

    /// How far each grid row forward moves the land left, in grid steps: the
    /// oblique view's shear (which draws the square as seed 000's
    /// parallelogram), 0 for the views with a camera.
    pub fn shear(&self) -> f32 {
        if self.camera.is_some() { 0.0 } else { SHEAR }
    }

    /// The unit sight line through screen point (`x`, `y`) in pixels, in
    /// the world (x right, y towards the front, z up); `None` for the
    /// oblique view, which has no eye.
    pub(crate) fn sight(&self, x: f32, y: f32) -> Option<Vec3> {
        let cam = self.camera.as_ref()?;
        let u = (Vec2::new(x, y) - self.offset) / self.scale;
        cam.sight(u).try_normalize()
    }

    /// How many times their own the oblique view draws heights (1 but in
    /// seed 000's look; 1 in the views with a camera).
    pub fn relief(&self) -> f32 {
        if self.camera.is_some() {
            1.0
        } else {
            self.relief
        }
    }

    /// How many pixels one grid step spans, seen square on, at grid
    /// position (`gx`, `gy`) and height `z`; 0 for the oblique view
    /// (which draws no relief below its grid).
    pub(crate) fn cell_pixels(&self, gx: f32, gy: f32, z: f32) -> f32 {
        match &self.camera {
            Some(cam) => self.cell * self.scale.y / cam.depth(self.point(gx, gy, z)),
            None => 0.0,
        }
    }

    /// The line from the eye to grid position (`gx`, `gy`) at height `z`,
    /// in world units (x right, y towards the front, z up); `None` for the
    /// oblique view, which has no eye.
    pub(crate) fn sight_to(&self, gx: f32, gy: f32, z: f32) -> Option<Vec3> {
        self.camera.map(|cam| self.point(gx, gy, z) - cam.eye())
    }

    /// Grid position (`gx`, `gy`) at height `z` in world units.
    fn point(&self, gx: f32, gy: f32, z: f32) -> Vec3 {
        Vec3::new(gx * self.cell, gy * self.cell, z)
    }

    /// Width of one grid step in height units.
    pub fn cell(&self) -> f32 {
        self.cell
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `check` for rows at the back, the middle and the front of a small
    /// field in each kind of view.
    fn each_row(mut check: impl FnMut(ViewKind, &View, f32, &RowView)) {
        for kind in [ViewKind::Vista, ViewKind::Perspective, ViewKind::Oblique] {
            let view = View::new(kind, 65, 250.0, 60.0, Size::new(640, 360));
            for gy in [0.0, 17.0, 64.0] {
                check(kind, &view, gy, &view.along_row(gy));
            }
        }
    }

    /// Tall land near the front (a third of the width high over the
    /// nearest third of the rows, low hills behind): a world's vista from
    /// low in front of it saw one near face from edge to edge, no sky (6
    /// of seeds 1-480). It now looks down over the near land, and no
    /// row's top stands more than `vista::OVER_TOP` over the top of the
    /// frame (a peak's tip), at both sizes.
    #[test]
    fn a_worlds_vista_looks_down_over_tall_near_land_rather_than_at_a_wall() {
        let (size, extent) = (65, 250.0);
        let rows: Vec<f32> = (0..size)
            .map(|i| {
                if i >= 44 {
                    0.33 * extent
                } else {
                    0.05 * extent
                }
            })
            .collect();
        let mut looked_down = 0;
        for identity in 0..12 {
            let world = (World::Desert, identity);
            let aim = Aim::of(World::Desert, identity);
            for (w, h) in [(320, 180), (1920, 1080)] {
                let frame = Size::new(w, h);
                let view = View::fitted_in(
                    ViewKind::Vista,
                    (Oblique::OURS, world),
                    size,
                    extent,
                    (&rows, 0.0),
                    frame,
                );
                let top = (0..size)
                    .map(|i| view.project(32.0, i as f32, rows[i]).y / h as f32)
                    .fold(f32::INFINITY, f32::min);
                assert!(
                    top >= -vista::OVER_TOP,
                    "desert {identity} at {w}x{h}: the land's top at {top}"
                );
            }
            let tops = vista_tops(&rows, extent);
            let plain = vista::fitted(aim, extent, (1920.0, 1080.0), &tops, 0.0);
            looked_down += usize::from(plain.is_some_and(|shot| shot.cut));
        }
        assert!(
            looked_down >= 6,
            "{looked_down} of 12 aims cut the land off"
        );
    }

    #[test]
    fn a_row_projects_to_the_same_pixels_as_the_view() {
        each_row(|kind, view, gy, row| {
            for (gx, z) in [(0.0, 0.0), (5.0, 12.5), (64.0, 60.0), (31.0, -3.0)] {
                let (a, b) = (row.project(gx, z), view.project(gx, gy, z));
                assert_eq!(a, b, "{kind:?} at ({gx}, {gy}, {z})");
            }
        });
    }

    #[test]
    fn four_points_at_once_project_to_the_same_bits_as_one_by_one() {
        each_row(|kind, _, gy, row| {
            // Behind the eye, far off the grid and at odd heights too.
            let gx = [0.0, 5.0, 64.0, 31.0, 1e4, -700.0, 13.0, 47.0];
            let z = [0.0, 12.5, 60.0, -3.0, 1e5, 0.1, -1e4, 7.25];
            // Fewer than four: the lanes given, the same bits.
            for n in 1..=4 {
                let points: Vec<[f32; 2]> = (0..n).map(|k| [gx[k], z[k]]).collect();
                let [px, py] = row.project_few(&points);
                for k in 0..n {
                    let one = row.project(gx[k], z[k]);
                    assert_eq!(
                        [px[k].to_bits(), py[k].to_bits()],
                        [one.x.to_bits(), one.y.to_bits()]
                    );
                }
            }
            for k in (0..gx.len()).step_by(4) {
                let lanes = |v: &[f32; 8]| Vec4::from_slice(&v[k..k + 4]);
                let [px, py] = row.project4(lanes(&gx), lanes(&z));
                for lane in 0..4 {
                    let one = row.project(gx[k + lane], z[k + lane]);
                    let four = Vec2::new(px[lane], py[lane]);
                    assert_eq!(
                        (one.x.to_bits(), one.y.to_bits()),
                        (four.x.to_bits(), four.y.to_bits()),
                        "{kind:?} at ({}, {gy}, {})",
                        gx[k + lane],
                        z[k + lane]
                    );
                }
            }
        });
    }
}
