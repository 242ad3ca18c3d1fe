//! One landscape across every monitor (`monitors = "span"`): one slide
//! show whose frame is the desktop's bounding rectangle of the monitors,
//! and each monitor's window showing its part of it, where the desktop's
//! coordinates put that monitor (a gap between monitors is a strip of the
//! picture nobody sees, as through a window frame).

use std::time::Instant;

use super::heads::Head;
use super::screen::Screen;
use super::show::Show;
use crate::render::{Damage, Frame, Rect, Size};

/// The smallest rectangle of the desktop holding every head: where the
/// span's frame lies. `None` without heads.
pub fn bounds(heads: &[Head]) -> Option<Head> {
    let x0 = heads.iter().map(|h| i64::from(h.x)).min()?;
    let y0 = heads.iter().map(|h| i64::from(h.y)).min()?;
    let x1 = heads.iter().map(|h| i64::from(h.x) + i64::from(h.width));
    let y1 = heads.iter().map(|h| i64::from(h.y) + i64::from(h.height));
    let (x1, y1) = (x1.max()?, y1.max()?);
    Some(Head {
        x: i32::try_from(x0).ok()?,
        y: i32::try_from(y0).ok()?,
        width: u32::try_from(x1 - x0).ok()?,
        height: u32::try_from(y1 - y0).ok()?,
        primary: false,
    })
}

/// `head`'s part of the frame of the span lying at `whole` on the desktop.
pub fn crop(whole: &Head, head: &Head) -> Rect {
    let x = u32::try_from(i64::from(head.x) - i64::from(whole.x)).unwrap_or(0);
    let y = u32::try_from(i64::from(head.y) - i64::from(whole.y)).unwrap_or(0);
    Rect::sized(x, y, head.width, head.height)
}

/// Every head's part of the span's frame, in the order of `heads`.
pub fn crops(heads: &[Head]) -> Vec<Rect> {
    bounds(heads).map_or_else(Vec::new, |whole| {
        heads.iter().map(|h| crop(&whole, h)).collect()
    })
}

/// Copies the part of `damage` (in the span's frame) that falls in `crop`
/// from `span` into `window`, whose top left pixel is the crop's; the
/// copied part in the window's coordinates. A window smaller than its crop
/// (a compositor that gave it another size) gets what fits.
pub fn copy(span: &Frame, crop: Rect, damage: Rect, window: &mut Frame) -> Rect {
    let fits = Rect::sized(crop.x0, crop.y0, window.width(), window.height());
    let part = damage
        .intersect(&crop)
        .intersect(&fits)
        .intersect(&span.bounds());
    if part.is_empty() {
        return Rect::default();
    }
    let (sw, ww) = (span.width() as usize, window.width() as usize);
    let width = (part.x1 - part.x0) as usize;
    let (from_x, to_x) = (part.x0 as usize, (part.x0 - crop.x0) as usize);
    for y in part.y0..part.y1 {
        let from = y as usize * sw + from_x;
        let to = (y - crop.y0) as usize * ww + to_x;
        window.pixels_mut()[to..to + width].copy_from_slice(&span.pixels()[from..from + width]);
    }
    Rect {
        x0: part.x0 - crop.x0,
        y0: part.y0 - crop.y0,
        x1: part.x1 - crop.x0,
        y1: part.y1 - crop.y0,
    }
}

/// Each head's part of `span` as a picture of its own, as its monitor
/// shows it.
pub fn cut(span: &Frame, crops: &[Rect]) -> Vec<Frame> {
    crops
        .iter()
        .filter_map(|&c| {
            let mut part = Frame::new(c.x1 - c.x0, c.y1 - c.y0)?;
            copy(span, c, c, &mut part);
            Some(part)
        })
        .collect()
}

/// The span's slide show and where its frame lies on the desktop; the
/// windows (or `--layer`'s surfaces) keep black shows of their own that it
/// copies its pixels into.
pub(crate) struct Span {
    show: Show,
    whole: Head,
    /// The heads it was laid for.
    heads: Vec<Head>,
}

impl Span {
    /// A span over `heads` drawing `show`, made for their bounding rectangle.
    pub(crate) fn new(heads: &[Head], make: impl FnOnce(Size) -> Show) -> Option<Span> {
        let whole = bounds(heads)?;
        let show = make(Size::new(whole.width, whole.height));
        let heads = heads.to_vec();
        Some(Span { show, whole, heads })
    }

    /// True when it was laid for exactly `heads`.
    pub(crate) fn laid_for(&self, heads: &[Head]) -> bool {
        self.heads == heads
    }

    /// Number of the slide the span shows.
    pub(crate) fn slide(&self) -> u64 {
        self.show.slide()
    }

    /// Moves the show on: what changed in the span's frame.
    pub(crate) fn tick(&mut self, now: Instant) -> Damage {
        self.show.tick(now)
    }

    /// Makes the span's show follow the power and the display's state:
    /// the pixels that changed in its frame.
    pub(crate) fn follow(&mut self, seen: super::watch::Seen, now: Instant) -> Rect {
        super::watch::apply(seen, &mut self.show, now)
    }

    /// When the show wants to be woken.
    pub(crate) fn wake_at(&self, now: Instant) -> Option<Instant> {
        self.show.wake_at(now)
    }

    /// Copies `damage`'s pixels into `screen`'s frame: what changed there.
    pub(super) fn paint(&self, screen: &mut Screen, damage: &Damage) -> Damage {
        match screen.head {
            Some(head) => self.paint_to(&head, &mut screen.show, damage),
            None => Damage::default(),
        }
    }

    /// Copies the whole of `screen`'s part (a window that is new or was
    /// resized): what changed there.
    pub(super) fn paint_all(&self, screen: &mut Screen) -> Damage {
        self.paint(screen, &self.everything())
    }

    /// The whole span, as damage: what a window that is new or was resized
    /// needs copied.
    pub(crate) fn everything(&self) -> Damage {
        self.show
            .frame()
            .map(Frame::bounds)
            .unwrap_or_default()
            .into()
    }

    /// Copies `damage`'s pixels into the frame of `window`, the black show
    /// of the monitor at `head`: what changed there.
    pub(crate) fn paint_to(&self, head: &Head, window: &mut Show, damage: &Damage) -> Damage {
        let (Some(span), Some(window)) = (self.show.frame(), window.frame_mut()) else {
            return Damage::default();
        };
        let crop = crop(&self.whole, head);
        let mut changed = Damage::default();
        for r in damage.rects() {
            changed.add(copy(span, crop, r, window));
        }
        changed
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn head(x: i32, y: i32, width: u32, height: u32) -> Head {
        Head {
            x,
            y,
            width,
            height,
            primary: false,
        }
    }

    #[test]
    fn bounds_hold_every_head_wherever_the_desktop_starts() {
        let heads = [head(-1080, -300, 1080, 1920), head(0, 0, 2560, 1440)];
        assert_eq!(bounds(&heads), Some(head(-1080, -300, 3640, 1920)));
        assert_eq!(bounds(&[]), None);
        assert_eq!(
            crops(&heads),
            vec![
                Rect::sized(0, 0, 1080, 1920),
                Rect::sized(1080, 300, 2560, 1440)
            ]
        );
    }

    #[test]
    fn copy_moves_the_damaged_part_of_the_crop_to_the_window_origin() {
        let mut span = Frame::new(8, 4).unwrap();
        for y in 0..4 {
            for x in 0..8 {
                span.set(x, y, y * 8 + x);
            }
        }
        let mut window = Frame::new(4, 3).unwrap();
        let crop = Rect::sized(4, 1, 4, 3);
        let changed = copy(&span, crop, Rect::sized(0, 0, 6, 2), &mut window);
        assert_eq!(changed, Rect::sized(0, 0, 2, 1));
        assert_eq!((window.get(0, 0), window.get(1, 0)), (12, 13));
        assert_eq!(window.get(2, 0), 0, "outside the damage");
    }
}
