//! The strip-by-strip painter: a state machine that draws a mountain back to front.

use std::sync::Arc;

use super::base::canvas::Canvas;
use super::base::damage::Damage;
use super::base::frame::{Frame, Rect};
use super::base::size::Size;
use super::edges::clean::clean_edges;
use super::edges::horizon::{Horizon, HorizonSweep};
use super::order::bands;
use super::order::walk::{Rows, draw_strips};
use super::ridges::Ridges;
use super::scene::{FieldRef, Scene};
use super::shade::hour::SunAt;
use crate::settings::{ColorMode, Settings};
use crate::terrain::Heightfield;

/// Draws one mountain into frames of one size, a few strips per `step`.
///
/// A strip is one row of grid cells (the last one also carries the front
/// skirt); the first step also paints the background.
pub struct Painter {
    size: Size,
    next: usize,
    how: How,
}

/// What the strips are made of.
enum How {
    /// The scene, its rows as projected last, and the horizon swept
    /// along with the strips (for the clean edges drawn at the end).
    Mesh(Box<Scene<'static>>, Rows, Option<Box<HorizonSweep>>),
    Ridges(Ridges),
    /// Every one of this many strips drawn: the scene is let go (its share
    /// of the field, its shadow and sky-light maps), as nothing draws again.
    Drawn(usize),
}

impl Painter {
    /// Plans drawing `field` under `settings` into a frame of `size`.
    pub fn new(field: Arc<Heightfield>, settings: &Settings, size: Size) -> Self {
        Self::at_hour(field, settings, size, None)
    }

    /// [`Painter::new`] with the sun of `sun = "clock"` where `hour` puts
    /// it (the saver works it out for now; without one it lights as midday).
    pub fn at_hour(
        field: Arc<Heightfield>,
        settings: &Settings,
        size: Size,
        hour: Option<SunAt>,
    ) -> Self {
        let how = if settings.color == ColorMode::Ridges {
            How::Ridges(Ridges::new(&field, settings, size))
        } else {
            let scene = Scene::at_hour(FieldRef::Shared(field), settings, size, hour);
            let sweep = scene.clean_edges.then(|| Box::new(HorizonSweep::new(size)));
            How::Mesh(Box::new(scene), Rows::new(), sweep)
        };
        Painter { size, next: 0, how }
    }

    /// How many strips the whole mountain takes.
    pub fn strips_total(&self) -> usize {
        match &self.how {
            How::Mesh(scene, ..) => scene.strips(),
            How::Ridges(r) => r.strips_total(),
            How::Drawn(strips) => *strips,
        }
    }

    /// How many strips are drawn so far.
    pub fn strips_done(&self) -> usize {
        self.next
    }

    /// True once every strip is drawn.
    pub fn is_done(&self) -> bool {
        self.next >= self.strips_total()
    }

    /// Draws up to `budget` more strips, back to front, and returns the
    /// pixels it changed (empty when nothing was left, or when `frame` is
    /// not the size this painter was made for).
    pub fn step(&mut self, frame: &mut Frame, budget: usize) -> Damage {
        if frame.size() != self.size {
            return Damage::default();
        }
        let start = self.next;
        let end = start.saturating_add(budget).min(self.strips_total());
        if start >= end && start > 0 {
            return Damage::default();
        }
        self.next = end;
        let damage = self.draw(frame, start, end);
        self.let_go_when_done();
        damage
    }

    /// [`Painter::step`]'s drawing of strips `start..end`.
    fn draw(&mut self, frame: &mut Frame, start: usize, end: usize) -> Damage {
        match &mut self.how {
            How::Mesh(scene, rows, sweep) => {
                let mut canvas = Canvas::new(frame.pixels_mut(), self.size.width, 0);
                if start == 0 {
                    scene.sky.paint(&mut canvas);
                }
                draw_strips(scene, &mut canvas, rows, start..end, self.size.width);
                let mut damage = canvas.damage();
                if let Some(sweep) = sweep {
                    // Front to back while the strips go back to front: the
                    // same share of rows as of strips, so no step stalls.
                    sweep.advance_to(scene, end as f32 / scene.strips() as f32);
                }
                if end == scene.strips()
                    && let Some(sweep) = sweep.take()
                {
                    // The full frame's last touch, once every strip is in;
                    // what only the strips read goes first, so that the
                    // edges' own work is not held beside it (the peak of a
                    // 4K slide show is reached here).
                    scene.let_go_of_faces();
                    *rows = Rows::new();
                    let horizon = sweep.finish(scene);
                    for r in clean_edges(scene, &horizon, frame).rects() {
                        damage.add(r);
                    }
                }
                damage
            }
            How::Ridges(ridges) => {
                let mut damage = Damage::default();
                if start == 0 {
                    frame.clear(0);
                    damage.add(frame.bounds());
                }
                for i in start..end {
                    damage.add(ridges.draw_strip(frame, i));
                }
                damage
            }
            How::Drawn(_) => Damage::default(),
        }
    }

    /// Frees what only drawing needs once every strip is in: a held slide
    /// then keeps only its frame (the peak of a 4K slide show, while the
    /// next mountain is made, is lower by the scene's maps).
    fn let_go_when_done(&mut self) {
        if self.is_done() {
            self.how = How::Drawn(self.strips_total());
        }
    }

    /// Draws every remaining strip and returns the rectangle it changed.
    /// A mesh not begun yet is drawn in horizontal bands on all cores
    /// (the same pixels as stepping to the end): a redraw after a resize
    /// or a colour change takes half the time on two cores.
    pub fn finish(&mut self, frame: &mut Frame) -> Rect {
        let size_fits = frame.size() == self.size;
        match &self.how {
            How::Mesh(scene, ..) if self.next == 0 && size_fits => {
                draw_full(scene, frame);
                self.next = self.strips_total();
                self.let_go_when_done();
                frame.bounds()
            }
            _ => self.step(frame, usize::MAX).bounds(),
        }
    }
}

/// Draws a complete mountain into `frame`: the same pixels as stepping a
/// `Painter` to the end, drawn in horizontal bands on all cores.
pub fn render_full(field: &Heightfield, settings: &Settings, frame: &mut Frame) {
    render_full_at(field, settings, frame, None);
}

/// [`render_full`] with the sun of `sun = "clock"` where `hour` puts it.
pub fn render_full_at(
    field: &Heightfield,
    settings: &Settings,
    frame: &mut Frame,
    hour: Option<SunAt>,
) {
    let size = frame.size();
    if settings.color == ColorMode::Ridges {
        let mut p = Painter::new(Arc::new(field.clone()), settings, size);
        p.step(frame, usize::MAX);
        return;
    }
    let scene = Scene::at_hour(FieldRef::Borrowed(field), settings, size, hour);
    draw_full(&scene, frame);
}

/// [`render_full`] of the scene of a frame `k` times smaller than `frame`
/// (a 1:1 picture's reference, to be averaged down k times): the relief
/// below the grid stops at the smaller frame's pixel, as `settings` fix
/// the grid to the smaller frame's.
pub fn render_full_finer(field: &Heightfield, settings: &Settings, frame: &mut Frame, k: u32) {
    if settings.color == ColorMode::Ridges {
        // Ridges draw no land faces, so no relief either.
        return render_full(field, settings, frame);
    }
    let mut scene = Scene::new(FieldRef::Borrowed(field), settings, frame.size());
    scene.relief = scene.relief.map(|r| r.for_finer(k as f32));
    draw_full(&scene, frame);
}

/// Draws the sky and every strip of `scene` into `frame` in bands on all
/// cores, then its edges clean, from the horizon one thread sweeps beside
/// the bands.
pub(crate) fn draw_full(scene: &Scene, frame: &mut Frame) {
    let size = frame.size();
    let sweep = scene.clean_edges.then_some(|| Horizon::sweep(scene, size));
    if let Some(horizon) = bands::draw_bands(scene, frame, sweep) {
        clean_edges(scene, &horizon, frame);
    }
}
