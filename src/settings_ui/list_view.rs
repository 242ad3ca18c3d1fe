//! The settings list seen through its window on the panel: which lines are
//! shown, how the window moves (the wheel, the focus, the scroll bar), and
//! where the scroll bar's parts are. It moves by whole lines, so a row is
//! shown whole or not at all and nothing is drawn over the help below.

use crate::render::Rect;

/// One line of the settings list.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Line {
    /// A section heading.
    Heading(&'static str),
    /// The row of a key (its index in the key table).
    Row(usize),
}

/// A part of the scroll bar.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum BarPart {
    /// The arrow at the top: one line up.
    Up,
    /// The arrow at the bottom: one line down.
    Down,
    /// The track above the thumb: a page up.
    PageUp,
    /// The track below the thumb: a page down.
    PageDown,
    /// The thumb, dragged to move the list.
    Thumb,
}

/// The scroll bar's parts, pixels.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Bar {
    /// The up arrow's box.
    pub up: Rect,
    /// The down arrow's box.
    pub down: Rect,
    /// The track between the arrows.
    pub track: Rect,
    /// The thumb: where the shown lines are in the whole list.
    pub thumb: Rect,
}

/// The lines of the list and the window onto them.
///
/// Planned in logical pixels and multiplied by a whole scale, as the
/// layout is, so the 200% list is the 100% one doubled at every scroll.
#[derive(Debug, Clone, PartialEq)]
pub struct ListView {
    lines: Vec<Line>,
    /// The window, logical pixels: a whole number of lines high, the
    /// scroll bar's column at its right.
    area: Rect,
    line_h: u32,
    bar_w: u32,
    scale: u32,
    first: usize,
}

impl ListView {
    /// `lines` shown in `area`, `line_h` a line, with a scroll bar `bar_w`
    /// wide at the right (logical pixels, `scale` pixels each); the first
    /// line on top.
    pub fn new(lines: Vec<Line>, area: Rect, line_h: u32, bar_w: u32, scale: u32) -> ListView {
        ListView {
            lines,
            area,
            line_h: line_h.max(1),
            bar_w,
            scale: scale.max(1),
            first: 0,
        }
    }

    fn scaled(&self, r: Rect) -> Rect {
        let s = self.scale;
        Rect {
            x0: r.x0 * s,
            y0: r.y0 * s,
            x1: r.x1 * s,
            y1: r.y1 * s,
        }
    }

    /// Every line, top to bottom.
    pub fn lines(&self) -> &[Line] {
        &self.lines
    }

    /// The window on the panel, pixels (the scroll bar's column included).
    pub fn area(&self) -> Rect {
        self.scaled(self.area)
    }

    /// How many lines the window shows at once.
    pub fn shown(&self) -> usize {
        ((self.area.y1 - self.area.y0) / self.line_h) as usize
    }

    /// The first line shown.
    pub fn first(&self) -> usize {
        self.first
    }

    /// The first line shown when the list is scrolled to its end; 0 when
    /// it all fits and nothing scrolls.
    pub fn last_first(&self) -> usize {
        self.lines.len().saturating_sub(self.shown())
    }

    /// Shows line `first` (as far as the end allows) at the top.
    pub fn scroll_to(&mut self, first: usize) {
        self.first = first.min(self.last_first());
    }

    /// Moves the window `delta` lines down (up when negative).
    pub fn scroll_by(&mut self, delta: i64) {
        let to = (self.first as i64).saturating_add(delta).max(0);
        self.scroll_to(usize::try_from(to).unwrap_or(usize::MAX));
    }

    /// Moves the window as little as shows `line` whole; a row that starts
    /// a section brings its heading along when moving up.
    pub fn reveal(&mut self, line: usize) {
        let above = match line.checked_sub(1).map(|l| self.lines.get(l)) {
            Some(Some(Line::Heading(_))) if self.shown() > 1 => line - 1,
            _ => line,
        };
        if above < self.first {
            self.scroll_to(above);
        } else if line >= self.first + self.shown() {
            self.scroll_to(line + 1 - self.shown().max(1));
        }
    }

    /// The line of row `i`.
    pub fn line_of_row(&self, i: usize) -> Option<usize> {
        self.lines.iter().position(|l| *l == Line::Row(i))
    }

    /// The top of `line` on the screen, pixels, while it is shown.
    pub fn top(&self, line: usize) -> Option<u32> {
        let shown = line >= self.first && line < self.first + self.shown();
        shown.then(|| self.line_top(line))
    }

    fn line_top(&self, line: usize) -> u32 {
        (self.area.y0 + (line - self.first) as u32 * self.line_h) * self.scale
    }

    /// The shown lines with their tops, pixels.
    pub fn visible(&self) -> impl Iterator<Item = (u32, Line)> + '_ {
        let end = (self.first + self.shown()).min(self.lines.len());
        (self.first..end).map(|l| (self.line_top(l), self.lines[l]))
    }

    /// Whether `(x, y)` (pixels) is over the window or its scroll bar.
    pub fn contains(&self, x: u32, y: u32) -> bool {
        inside(&self.area(), x, y)
    }

    /// The scroll bar, pixels, while there is more than the window shows.
    pub fn bar(&self) -> Option<Bar> {
        let bar = self.bar_logical()?;
        Some(Bar {
            up: self.scaled(bar.up),
            down: self.scaled(bar.down),
            track: self.scaled(bar.track),
            thumb: self.scaled(bar.thumb),
        })
    }

    fn bar_logical(&self) -> Option<Bar> {
        let last = self.last_first();
        if last == 0 || self.bar_w == 0 {
            return None;
        }
        let a = self.area;
        let (x0, w) = (a.x1 - self.bar_w, self.bar_w);
        let up = Rect::sized(x0, a.y0, w, w);
        let down = Rect::sized(x0, a.y1.saturating_sub(w).max(up.y1), w, w);
        let track = Rect {
            x0,
            y0: up.y1,
            x1: a.x1,
            y1: down.y0,
        };
        let (span, thumb_h) = self.thumb_travel(&track);
        let y = track.y0 + (span as u64 * self.first as u64 / last as u64) as u32;
        let thumb = Rect::sized(x0, y, w, thumb_h);
        Some(Bar {
            up,
            down,
            track,
            thumb,
        })
    }

    /// How far the thumb travels in `track`, and its length: the share of
    /// the list shown, but never shorter than the bar is wide.
    fn thumb_travel(&self, track: &Rect) -> (u32, u32) {
        let len = track.y1 - track.y0;
        let whole = self.lines.len().max(1) as u64;
        let share = (len as u64 * self.shown() as u64 / whole) as u32;
        let h = share.max(self.bar_w.min(len / 2)).min(len);
        (len - h, h)
    }

    /// The part of the scroll bar at `(x, y)` (pixels), if any.
    pub fn bar_part(&self, x: u32, y: u32) -> Option<BarPart> {
        let bar = self.bar()?;
        if inside(&bar.up, x, y) {
            Some(BarPart::Up)
        } else if inside(&bar.down, x, y) {
            Some(BarPart::Down)
        } else if inside(&bar.thumb, x, y) {
            Some(BarPart::Thumb)
        } else if inside(&bar.track, x, y) && y < bar.thumb.y0 {
            Some(BarPart::PageUp)
        } else if inside(&bar.track, x, y) {
            Some(BarPart::PageDown)
        } else {
            None
        }
    }

    /// The first line to show when the thumb, grabbed while `from` was
    /// first, has been dragged `dy` pixels down (up when negative).
    pub fn dragged(&self, from: usize, dy: f64) -> usize {
        let Some(bar) = self.bar_logical() else {
            return 0;
        };
        let (span, _) = self.thumb_travel(&bar.track);
        let per_pixel = self.last_first() as f64 / f64::from(span.max(1) * self.scale);
        let to = (from as f64 + dy * per_pixel).round();
        if to.is_finite() && to > 0.0 {
            (to as usize).min(self.last_first())
        } else {
            0
        }
    }
}

fn inside(r: &Rect, x: u32, y: u32) -> bool {
    x >= r.x0 && x < r.x1 && y >= r.y0 && y < r.y1
}

#[cfg(test)]
mod tests {
    use super::*;

    fn view(rows: usize, shown: u32) -> ListView {
        let mut lines = vec![Line::Heading("A")];
        lines.extend((0..rows).map(Line::Row));
        ListView::new(lines, Rect::sized(0, 10, 100, shown * 17), 17, 14, 1)
    }

    #[test]
    fn revealing_moves_the_window_as_little_as_shows_the_line() {
        let mut v = view(20, 5);
        assert_eq!((v.shown(), v.last_first()), (5, 16));
        v.reveal(7);
        assert_eq!(v.first(), 3, "line 7 is the last shown");
        v.reveal(5);
        assert_eq!(v.first(), 3, "a shown line moves nothing");
        v.reveal(1);
        assert_eq!(v.first(), 0, "the first row brings its heading");
        v.scroll_by(100);
        assert_eq!(v.first(), 16, "no further than the end");
        v.scroll_by(-100);
        assert_eq!(v.first(), 0);
    }

    #[test]
    fn the_bar_is_there_only_when_the_list_does_not_fit() {
        assert!(view(4, 5).bar().is_none());
        let mut v = view(20, 5);
        let bar = v.bar().unwrap();
        assert_eq!(bar.thumb.y0, bar.track.y0, "at the top");
        assert_eq!(v.bar_part(90, bar.down.y0 + 1), Some(BarPart::Down));
        assert_eq!(v.bar_part(90, bar.thumb.y1 + 1), Some(BarPart::PageDown));
        assert_eq!(v.bar_part(50, bar.thumb.y1 + 1), None, "left of the bar");
        v.scroll_to(16);
        let bar = v.bar().unwrap();
        assert_eq!(bar.thumb.y1, bar.track.y1, "at the bottom");
        assert_eq!(v.bar_part(90, bar.up.y1 + 1), Some(BarPart::PageUp));
        let travel = f64::from(bar.track.y1 - bar.track.y0 - (bar.thumb.y1 - bar.thumb.y0));
        assert_eq!(v.dragged(16, -travel), 0, "dragged all the way up");
        assert_eq!(v.dragged(0, travel / 2.0), 8);
        assert_eq!(v.dragged(0, f64::NAN), 0);
    }
}
