//! The strip-by-strip painter: a state machine that draws a mountain back to front.
//!
//! STUB with the final signatures; the renderer work replaces the bodies.

use std::sync::Arc;

use super::frame::{Frame, Rect};
use super::palette::Palette;
use crate::settings::Settings;
use crate::terrain::Heightfield;

/// Draws one mountain into frames of one size, a few strips per `step`.
pub struct Painter {
    field: Arc<Heightfield>,
    palette: Palette,
    width: u32,
    height: u32,
    next: usize,
}

impl Painter {
    /// Plans drawing `field` under `settings` into a `width` x `height` frame.
    pub fn new(field: Arc<Heightfield>, settings: &Settings, width: u32, height: u32) -> Self {
        let palette = Palette::new(settings, &field);
        Painter {
            field,
            palette,
            width,
            height,
            next: 0,
        }
    }

    /// How many strips the whole mountain takes.
    pub fn strips_total(&self) -> usize {
        self.field.size()
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
    /// rectangle of pixels it changed (empty when nothing was left).
    pub fn step(&mut self, frame: &mut Frame, budget: usize) -> Rect {
        let mut damage = Rect::default();
        if frame.width() != self.width || frame.height() != self.height {
            return damage;
        }
        let total = self.strips_total();
        let end = (self.next + budget).min(total);
        for strip in self.next..end {
            let y0 = (strip as u64 * self.height as u64 / total as u64) as u32;
            let y1 = ((strip + 1) as u64 * self.height as u64 / total as u64) as u32;
            let h = self.field.get(self.field.size() / 2, strip);
            let c = self.palette.land(h, glam::Vec3::Z, 1.0);
            for y in y0..y1 {
                let row = (y * self.width) as usize;
                frame.pixels_mut()[row..row + self.width as usize].fill(c);
            }
            damage = damage.union(&Rect {
                x0: 0,
                y0,
                x1: self.width,
                y1,
            });
        }
        self.next = end;
        damage
    }
}

/// Draws a complete mountain into `frame` (the same pixels as stepping to the end).
pub fn render_full(field: &Heightfield, settings: &Settings, frame: &mut Frame) {
    let mut p = Painter::new(
        Arc::new(field.clone()),
        settings,
        frame.width(),
        frame.height(),
    );
    p.step(frame, usize::MAX);
}
