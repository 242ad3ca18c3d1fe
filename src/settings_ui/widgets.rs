//! The settings screen's widget kit: a classic bevelled look drawn into a
//! frame (boxes, text, a caret, a tick, a focus rectangle, a scroll bar),
//! scaled by the layout; what goes where is `draw.rs`'s business.

use super::font::{self, ADVANCE, GLYPH_H, GLYPH_W};
use super::layout::{Layout, ROW_H};
use super::list_view::Bar;
use crate::render::{Frame, Rect};

/// The classic palette: button face, bevel light and shadow, text, the
/// selection, fields and alerts.
pub(super) const FACE: u32 = 0xC0C0C0;
pub(super) const LIGHT: u32 = 0xFFFFFF;
pub(super) const SHADOW: u32 = 0x808080;
pub(super) const DARK: u32 = 0x000000;
pub(super) const TEXT: u32 = 0x000000;
pub(super) const DIM: u32 = 0x808080;
pub(super) const HINT: u32 = 0x404040;
pub(super) const SELECT: u32 = 0x000080;
pub(super) const SELECT_TEXT: u32 = 0xFFFFFF;
pub(super) const FIELD: u32 = 0xFFFFFF;
pub(super) const ALERT: u32 = 0xA00000;

/// Fills `r`, clipped to the frame.
pub(super) fn fill(frame: &mut Frame, r: Rect, color: u32) {
    let r = r.intersect(&frame.bounds());
    if r.is_empty() {
        return;
    }
    let w = frame.width();
    let px = frame.pixels_mut();
    for y in r.y0..r.y1 {
        let row = (y * w) as usize;
        px[row + r.x0 as usize..row + r.x1 as usize].fill(color);
    }
}

/// Draws `s` with its top-left at `(x, y)`, one font pixel per `scale` pixels.
pub(super) fn text(frame: &mut Frame, layout: &Layout, x: u32, y: u32, s: &str, color: u32) {
    let k = layout.scale;
    for (n, c) in s.chars().enumerate() {
        let gx = x + n as u32 * ADVANCE * k;
        if gx >= frame.width() {
            break;
        }
        for (row, bits) in font::glyph(c).iter().enumerate() {
            for col in 0..GLYPH_W {
                if bits & (1 << (GLYPH_W - 1 - col)) != 0 {
                    let r = Rect::sized(gx + col * k, y + row as u32 * k, k, k);
                    fill(frame, r, color);
                }
            }
        }
    }
}

/// A raised (or, with `sunken`, pressed-in) bevelled box.
pub(super) fn bevel(frame: &mut Frame, layout: &Layout, r: Rect, sunken: bool) {
    let t = layout.px(1);
    let (tl, br) = if sunken {
        (SHADOW, LIGHT)
    } else {
        (LIGHT, DARK)
    };
    fill(frame, Rect::sized(r.x0, r.y0, r.x1 - r.x0, t), tl);
    fill(frame, Rect::sized(r.x0, r.y0, t, r.y1 - r.y0), tl);
    fill(frame, Rect::sized(r.x0, r.y1 - t, r.x1 - r.x0, t), br);
    fill(frame, Rect::sized(r.x1 - t, r.y0, t, r.y1 - r.y0), br);
}

pub(super) fn outline(frame: &mut Frame, r: Rect, t: u32, color: u32) {
    fill(frame, Rect::sized(r.x0, r.y0, r.x1 - r.x0, t), color);
    fill(frame, Rect::sized(r.x0, r.y1 - t, r.x1 - r.x0, t), color);
    fill(frame, Rect::sized(r.x0, r.y0, t, r.y1 - r.y0), color);
    fill(frame, Rect::sized(r.x1 - t, r.y0, t, r.y1 - r.y0), color);
}

/// Centres in logical pixels, so a 200% screen is exactly the 100% one doubled.
pub(super) fn centred_text(frame: &mut Frame, layout: &Layout, r: Rect, s: &str, color: u32) {
    let k = layout.scale;
    let w = font::text_width(s);
    let x = r.x0 + layout.px(((r.x1 - r.x0) / k).saturating_sub(w) / 2);
    let y = r.y0 + layout.px(((r.y1 - r.y0) / k).saturating_sub(7) / 2);
    text(frame, layout, x, y, s, color);
}

pub(super) fn blit(frame: &mut Frame, pic: &Frame, x: u32, y: u32) {
    let fw = frame.width();
    let w = pic.width().min(fw.saturating_sub(x));
    let h = pic.height().min(frame.height().saturating_sub(y));
    for row in 0..h {
        let src = &pic.pixels()[(row * pic.width()) as usize..][..w as usize];
        let at = ((y + row) * fw + x) as usize;
        frame.pixels_mut()[at..at + w as usize].copy_from_slice(src);
    }
}

/// A white field with typed text and a caret.
pub(super) fn typed_text(frame: &mut Frame, layout: &Layout, x: u32, y: u32, w: u32, t: &str) {
    let r = Rect::sized(x - layout.px(2), y + layout.px(1), w, layout.px(ROW_H - 2));
    fill(frame, r, FIELD);
    bevel(frame, layout, r, true);
    let chars = ((w / layout.scale).saturating_sub(10) / ADVANCE) as usize;
    let n = t.chars().count();
    let shown: String = t.chars().skip(n.saturating_sub(chars)).collect();
    let ty = y + layout.px(5);
    text(frame, layout, x, ty, &shown, TEXT);
    let cx = x + layout.px(font::text_width(&shown)) + layout.px(1);
    fill(
        frame,
        Rect::sized(cx, ty - layout.px(1), layout.px(1), layout.px(GLYPH_H)),
        TEXT,
    );
}

/// A check mark, 7 by 5 font pixels, two pixels thick.
pub(super) fn tick(frame: &mut Frame, layout: &Layout, x: u32, y: u32) {
    let k = layout.scale;
    let cols: [u32; 7] = [2, 3, 4, 3, 2, 1, 0];
    for (c, top) in cols.iter().enumerate() {
        fill(
            frame,
            Rect::sized(x + c as u32 * k, y + top * k, k, 2 * k),
            TEXT,
        );
    }
}

/// A classic scroll bar: arrow buttons at its ends, a dithered track, and
/// a raised thumb as long as the share of the list shown.
pub(super) fn scroll_bar(frame: &mut Frame, layout: &Layout, bar: &Bar) {
    dithered(frame, layout, bar.track);
    for (r, up) in [(bar.up, true), (bar.down, false)] {
        fill(frame, r, FACE);
        bevel(frame, layout, r, false);
        arrow(frame, layout, r, up);
    }
    fill(frame, bar.thumb, FACE);
    bevel(frame, layout, bar.thumb, false);
}

/// The track's checkerboard of face and light, one square a logical pixel.
fn dithered(frame: &mut Frame, layout: &Layout, r: Rect) {
    let k = layout.scale;
    fill(frame, r, FACE);
    for y in (r.y0..r.y1).step_by(k as usize) {
        for x in (r.x0..r.x1).step_by(k as usize) {
            if ((x - r.x0) / k + (y - r.y0) / k).is_multiple_of(2) {
                fill(frame, Rect::sized(x, y, k, k), LIGHT);
            }
        }
    }
}

/// A solid triangle, 7 logical pixels wide and 4 high, centred in `r`,
/// pointing up or down.
fn arrow(frame: &mut Frame, layout: &Layout, r: Rect, up: bool) {
    let k = layout.scale;
    let x = r.x0 + layout.px(((r.x1 - r.x0) / k).saturating_sub(7) / 2);
    let y = r.y0 + layout.px(((r.y1 - r.y0) / k).saturating_sub(4) / 2);
    for row in 0..4u32 {
        let half = if up { row } else { 3 - row };
        let r = Rect::sized(
            x + layout.px(3 - half),
            y + layout.px(row),
            layout.px(2 * half + 1),
            k,
        );
        fill(frame, r, TEXT);
    }
}

/// A line cut into the face: shadow over light, `w` pixels long.
pub(super) fn etched(frame: &mut Frame, layout: &Layout, x: u32, y: u32, w: u32) {
    let t = layout.px(1);
    fill(frame, Rect::sized(x, y, w, t), SHADOW);
    fill(frame, Rect::sized(x, y + t, w, t), LIGHT);
}

/// The classic dotted focus rectangle.
pub(super) fn dotted(frame: &mut Frame, r: Rect, k: u32) {
    let mut x = r.x0;
    while x + k <= r.x1 {
        fill(frame, Rect::sized(x, r.y0, k, k), DARK);
        fill(frame, Rect::sized(x, r.y1 - k, k, k), DARK);
        x += 2 * k;
    }
    let mut y = r.y0;
    while y + k <= r.y1 {
        fill(frame, Rect::sized(r.x0, y, k, k), DARK);
        fill(frame, Rect::sized(r.x1 - k, y, k, k), DARK);
        y += 2 * k;
    }
}
