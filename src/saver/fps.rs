//! xscreensaver's `-fps`: the frame rate and the load average in the bottom
//! left corner, over the picture. The pixels underneath are kept, and put
//! back before the painter draws again, so the mountain itself is never
//! marked by it.

use std::collections::VecDeque;
use std::time::{Duration, Instant};

use crate::render::{Frame, Rect};
use crate::settings_ui::font::{self, ADVANCE, GLYPH_H, GLYPH_W};

/// The span the frame rate is counted over.
const WINDOW: Duration = Duration::from_secs(1);
/// Pixels between the text and the frame's edges.
const MARGIN: u32 = 4;
const INK: u32 = 0x00ff_ffff;
const PAPER: u32 = 0x0000_0000;

/// The overlay of one window.
#[derive(Debug, Default)]
pub struct FpsOverlay {
    /// When the recent frames were drawn, oldest first.
    frames: VecDeque<Instant>,
    /// The picture under the overlay, and where it was.
    under: Option<(Rect, Vec<u32>)>,
}

impl FpsOverlay {
    /// An overlay that has counted nothing yet.
    pub fn new() -> Self {
        Self::default()
    }

    /// Puts the picture under the overlay back into `frame`; returns where.
    pub fn lift(&mut self, frame: &mut Frame) -> Rect {
        let Some((r, pixels)) = self.under.take() else {
            return Rect::default();
        };
        let w = frame.width() as usize;
        for (dy, row) in pixels.chunks_exact((r.x1 - r.x0) as usize).enumerate() {
            let start = (r.y0 as usize + dy) * w + r.x0 as usize;
            frame.pixels_mut()[start..start + row.len()].copy_from_slice(row);
        }
        r
    }

    /// Forgets the picture underneath: the frame was replaced or cleared.
    pub fn forget(&mut self) {
        self.under = None;
    }

    /// Counts a frame drawn at `now` and draws the overlay; returns where.
    pub fn draw(&mut self, frame: &mut Frame, now: Instant) -> Rect {
        self.frames.push_back(now);
        while self.frames.front().is_some_and(|&t| now - t > WINDOW) {
            self.frames.pop_front();
        }
        let lines = self.lines();
        let scale = if frame.height() >= 1000 { 2 } else { 1 };
        let cols = lines.iter().map(|l| l.chars().count()).max().unwrap_or(0) as u32;
        let (w, h) = (
            cols * ADVANCE * scale + 2 * MARGIN,
            lines.len() as u32 * (GLYPH_H + 1) * scale + 2 * MARGIN,
        );
        if w > frame.width() || h > frame.height() {
            return Rect::default();
        }
        let r = Rect::sized(0, frame.height() - h, w, h);
        self.under = Some((r, copy(frame, r)));
        fill(frame, r, PAPER);
        for (i, line) in lines.iter().enumerate() {
            let y = r.y0 + MARGIN + i as u32 * (GLYPH_H + 1) * scale;
            text(frame, MARGIN, y, line, scale);
        }
        r
    }

    /// The frame rate over the last second, and the load where known.
    fn lines(&self) -> Vec<String> {
        let fps = match (self.frames.front(), self.frames.back()) {
            (Some(&a), Some(&b)) if b > a => (self.frames.len() - 1) as f64 / (b - a).as_secs_f64(),
            _ => 0.0,
        };
        let mut lines = vec![format!("FPS: {fps:.1}")];
        if let Some(load) = load_average() {
            lines.push(format!("Load: {load:.2}"));
        }
        lines
    }
}

/// The one-minute load average (Linux), as xscreensaver shows it.
fn load_average() -> Option<f64> {
    let text = std::fs::read_to_string("/proc/loadavg").ok()?;
    text.split_whitespace().next()?.parse().ok()
}

/// The pixels of `r`, row by row.
fn copy(frame: &Frame, r: Rect) -> Vec<u32> {
    let w = frame.width() as usize;
    let mut out = Vec::with_capacity(((r.x1 - r.x0) * (r.y1 - r.y0)) as usize);
    for y in r.y0..r.y1 {
        let start = y as usize * w;
        out.extend_from_slice(&frame.pixels()[start + r.x0 as usize..start + r.x1 as usize]);
    }
    out
}

fn fill(frame: &mut Frame, r: Rect, colour: u32) {
    let w = frame.width() as usize;
    for y in r.y0..r.y1 {
        let start = y as usize * w;
        frame.pixels_mut()[start + r.x0 as usize..start + r.x1 as usize].fill(colour);
    }
}

/// `s` in the settings screen's font, top left at (`x`, `y`), `scale` pixels a dot.
fn text(frame: &mut Frame, x: u32, y: u32, s: &str, scale: u32) {
    for (n, c) in s.chars().enumerate() {
        let gx = x + n as u32 * ADVANCE * scale;
        for (row, bits) in font::glyph(c).iter().enumerate() {
            for col in 0..GLYPH_W {
                if bits & (1 << (GLYPH_W - 1 - col)) != 0 {
                    let dot = Rect::sized(gx + col * scale, y + row as u32 * scale, scale, scale);
                    fill(frame, dot, INK);
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn picture() -> Frame {
        let mut f = Frame::new(200, 120).unwrap();
        for (i, p) in f.pixels_mut().iter_mut().enumerate() {
            *p = (i as u32).wrapping_mul(2_654_435_761) & 0x00ff_ffff;
        }
        f
    }

    #[test]
    fn the_overlay_shows_and_the_picture_comes_back() {
        let mut f = picture();
        let before = f.clone();
        let mut o = FpsOverlay::new();
        let t0 = Instant::now();
        let r = o.draw(&mut f, t0);
        assert!(!r.is_empty() && r.x0 == 0 && r.y1 == 120, "{r:?}");
        assert!(f != before, "nothing drawn");
        // Text pixels are white on black within the box, nothing outside it.
        let inside = |i: usize| {
            let (x, y) = ((i % 200) as u32, (i / 200) as u32);
            x >= r.x0 && x < r.x1 && y >= r.y0 && y < r.y1
        };
        for (i, (&a, &b)) in f.pixels().iter().zip(before.pixels()).enumerate() {
            if !inside(i) {
                assert_eq!(a, b, "pixel {i} outside the overlay changed");
            } else {
                assert!(a == INK || a == PAPER);
            }
        }
        assert_eq!(o.lift(&mut f), r);
        assert!(
            f == before,
            "the picture under the overlay was not put back"
        );
    }

    #[test]
    fn the_rate_counts_frames_over_the_last_second() {
        let mut f = picture();
        let mut o = FpsOverlay::new();
        let t0 = Instant::now();
        for i in 0..=30 {
            o.lift(&mut f);
            o.draw(&mut f, t0 + Duration::from_millis(i * 33));
        }
        let fps = &o.lines()[0];
        assert!(
            fps.starts_with("FPS: 30.") || fps.starts_with("FPS: 29."),
            "{fps}"
        );
    }
}
