//! Text over the picture: xscreensaver's `-fps` (the frame rate and the load
//! in the bottom-left corner) and the window mode's list of keys (H, F1, top
//! left). The pixels underneath are kept, and put back before the painter
//! draws again, so the mountain itself is never marked by them.

use std::collections::VecDeque;
use std::time::{Duration, Instant};

use super::input::WINDOW_KEYS;
use crate::render::{Frame, Rect};
use crate::settings_ui::font::{self, ADVANCE, GLYPH_H, GLYPH_W};

/// The span the frame rate is counted over.
const WINDOW: Duration = Duration::from_secs(1);
/// How long the list of keys stays up unless H hides it first.
pub const HELP_FOR: Duration = Duration::from_secs(10);
/// How long a note about a key's effect (`+`: cragginess 128 next) stays up.
pub const NOTE_FOR: Duration = Duration::from_secs(3);
/// Pixels between the text and the edges of its box.
const MARGIN: u32 = 4;
const INK: u32 = 0x00ff_ffff;
const PAPER: u32 = 0x0000_0000;

/// The text boxes of one window.
#[derive(Debug, Default)]
pub struct Overlay {
    /// When the recent frames were drawn, oldest first; `None` without `-fps`.
    frames: Option<VecDeque<Instant>>,
    /// Until when the list of keys is up.
    help_until: Option<Instant>,
    /// A line saying what a key just did, and until when it is up.
    note: Option<(String, Instant)>,
    /// The picture under each box drawn, and where it was.
    under: Vec<(Rect, Vec<u32>)>,
}

impl Overlay {
    /// An overlay with the frame rate (`fps`) or nothing until H.
    pub fn new(fps: bool) -> Self {
        Overlay {
            frames: fps.then(VecDeque::new),
            ..Self::default()
        }
    }

    /// Puts the picture under the boxes back into `frame`; returns where.
    pub fn lift(&mut self, frame: &mut Frame) -> Rect {
        let mut damage = Rect::default();
        while let Some((r, pixels)) = self.under.pop() {
            let w = frame.width() as usize;
            for (dy, row) in pixels.chunks_exact((r.x1 - r.x0) as usize).enumerate() {
                let start = (r.y0 as usize + dy) * w + r.x0 as usize;
                frame.pixels_mut()[start..start + row.len()].copy_from_slice(row);
            }
            damage = damage.union(&r);
        }
        damage
    }

    /// Forgets the picture underneath: the frame was replaced or cleared.
    pub fn forget(&mut self) {
        self.under.clear();
    }

    /// Counts a frame drawn at `now`, for the frame rate.
    pub fn count_frame(&mut self, now: Instant) {
        if let Some(frames) = self.frames.as_mut() {
            frames.push_back(now);
            while frames.front().is_some_and(|&t| now - t > WINDOW) {
                frames.pop_front();
            }
        }
    }

    /// Shows the list of keys for a while, or hides it if it is up.
    pub fn toggle_help(&mut self, now: Instant) {
        self.help_until = match self.help_until {
            Some(t) if t > now => None,
            _ => Some(now + HELP_FOR),
        };
    }

    /// Shows `line` (what a key just did) for [`NOTE_FOR`] from `now`.
    pub fn note(&mut self, line: String, now: Instant) {
        self.note = Some((line, now + NOTE_FOR));
    }

    /// When the next text box goes (the list of keys or a note), if one is up.
    pub fn help_ends(&self) -> Option<Instant> {
        let note = self.note.as_ref().map(|(_, t)| *t);
        match (self.help_until, note) {
            (Some(a), Some(b)) => Some(a.min(b)),
            (a, b) => a.or(b),
        }
    }

    /// Draws the boxes due at `now` (the picture under them must be lifted
    /// first); returns where.
    pub fn draw(&mut self, frame: &mut Frame, now: Instant) -> Rect {
        if self.help_until.is_some_and(|t| t <= now) {
            self.help_until = None;
        }
        if self.note.as_ref().is_some_and(|(_, t)| *t <= now) {
            self.note = None;
        }
        let mut damage = Rect::default();
        if let Some(lines) = self.frames.as_ref().map(rate_lines) {
            damage = damage.union(&self.text_box(frame, &lines, false));
        }
        if self.help_until.is_some() {
            let lines: Vec<String> = WINDOW_KEYS
                .iter()
                .map(|k| format!("{:<7}{}", k.label, k.doc))
                .collect();
            damage = damage.union(&self.text_box(frame, &lines, true));
        } else if let Some((line, _)) = self.note.clone() {
            damage = damage.union(&self.text_box(frame, &[line], true));
        }
        damage
    }

    /// White `lines` on black at the top (or bottom) left, the picture
    /// under it kept; nothing if it does not fit.
    fn text_box(&mut self, frame: &mut Frame, lines: &[String], top: bool) -> Rect {
        let scale = if frame.height() >= 1000 { 2 } else { 1 };
        let cols = lines.iter().map(|l| l.chars().count()).max().unwrap_or(0) as u32;
        let w = cols * ADVANCE * scale + 2 * MARGIN;
        let h = lines.len() as u32 * (GLYPH_H + 1) * scale + 2 * MARGIN;
        if w > frame.width() || h > frame.height() {
            return Rect::default();
        }
        let y0 = if top { 0 } else { frame.height() - h };
        let r = Rect::sized(0, y0, w, h);
        self.under.push((r, copy(frame, r)));
        fill(frame, r, PAPER);
        for (i, line) in lines.iter().enumerate() {
            let y = r.y0 + MARGIN + i as u32 * (GLYPH_H + 1) * scale;
            text(frame, MARGIN, y, line, scale);
        }
        r
    }
}

/// The frame rate over the last second, and the load where known.
fn rate_lines(frames: &VecDeque<Instant>) -> Vec<String> {
    let fps = match (frames.front(), frames.back()) {
        (Some(&a), Some(&b)) if b > a => (frames.len() - 1) as f64 / (b - a).as_secs_f64(),
        _ => 0.0,
    };
    let mut lines = vec![format!("FPS: {fps:.1}")];
    if let Some(load) = load_average() {
        lines.push(format!("Load: {load:.2}"));
    }
    lines
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
        let mut o = Overlay::new(true);
        let t0 = Instant::now();
        o.count_frame(t0);
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
        let mut o = Overlay::new(true);
        let t0 = Instant::now();
        for i in 0..=30 {
            o.lift(&mut f);
            o.count_frame(t0 + Duration::from_millis(i * 33));
            o.draw(&mut f, t0 + Duration::from_millis(i * 33));
        }
        let fps = &rate_lines(o.frames.as_ref().unwrap())[0];
        assert!(
            fps.starts_with("FPS: 30.") || fps.starts_with("FPS: 29."),
            "{fps}"
        );
    }

    /// H shows the list of keys at the top left until H again or its time
    /// is up; the picture under it comes back.
    #[test]
    fn a_note_shows_for_a_while_then_the_picture_comes_back() {
        let mut f = picture();
        let before = f.clone();
        let mut o = Overlay::new(false);
        let t0 = Instant::now();
        o.note("cragginess 128 next".into(), t0);
        assert_eq!(o.help_ends(), Some(t0 + NOTE_FOR));
        let r = o.draw(&mut f, t0);
        assert!(!r.is_empty() && f != before, "the note is drawn");
        o.lift(&mut f);
        assert!(
            o.draw(&mut f, t0 + NOTE_FOR).is_empty(),
            "gone after NOTE_FOR"
        );
        assert_eq!(f, before);
        assert_eq!(o.help_ends(), None);
    }

    #[test]
    fn the_list_of_keys_comes_and_goes() {
        let mut f = Frame::new(400, 300).unwrap();
        f.clear(0x0012_3456);
        let before = f.clone();
        let mut o = Overlay::new(false);
        let t0 = Instant::now();
        assert!(o.draw(&mut f, t0).is_empty(), "nothing asked for");
        o.toggle_help(t0);
        let r = o.draw(&mut f, t0);
        assert!(
            r.y0 == 0 && r.y1 - r.y0 > 10 * WINDOW_KEYS.len() as u32,
            "{r:?}"
        );
        assert_eq!(o.help_ends(), Some(t0 + HELP_FOR));
        o.lift(&mut f);
        assert!(f == before);
        assert!(
            o.draw(&mut f, t0 + HELP_FOR).is_empty(),
            "still up after its time"
        );
        o.toggle_help(t0);
        o.toggle_help(t0);
        assert_eq!(o.help_ends(), None, "a second H hides it");
    }
}
