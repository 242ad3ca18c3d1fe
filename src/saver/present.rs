//! Putting a `Frame` on a window: softbuffer with damage rectangles, and a
//! fallback for X servers where that fails or cannot work well.

use std::num::NonZeroU32;

use raw_window_handle::{HasDisplayHandle, HasWindowHandle};
use softbuffer::{Context, Surface};

use crate::render::{Damage, Frame, Rect};

use super::buffer_history::BufferHistory;
use crate::platform::images::PlainImages;

/// Presents frames on one window, choosing the path that works on this server.
pub struct Presenter<W: HasWindowHandle + HasDisplayHandle + Clone> {
    /// `None` when softbuffer refused the window and plain images draw instead.
    surface: Option<Surface<W, W>>,
    images: PlainImages,
    /// ORed into every pixel softbuffer gets: 0xff000000 for a 32-bit (ARGB)
    /// window, whose top byte is alpha (0 would be see-through under a
    /// compositor); 0 for a 24-bit one.
    alpha: u32,
    /// What softbuffer's buffers still show, by age.
    history: BufferHistory,
    /// Wait for each present to be taken before returning (see `present_soft`);
    /// not on Wayland, where that wait is for the compositor to release the
    /// other buffer.
    wait_after_present: bool,
}

impl<W: HasWindowHandle + HasDisplayHandle + Clone> Presenter<W> {
    /// Prepares presenting on `window`.
    pub fn new(window: W) -> Result<Self, String> {
        let images = PlainImages::for_window(&window);
        let wayland = is_wayland(&window);
        let surface = Context::new(window.clone())
            .and_then(|context| Surface::new(&context, window))
            .map_err(|e| e.to_string());
        let mut presenter = Presenter {
            surface: None,
            images,
            alpha: 0,
            history: BufferHistory::new(),
            wait_after_present: !wayland,
        };
        match surface {
            Ok(surface) => {
                presenter.surface = Some(surface);
                presenter.avoid_wire_transfers();
            }
            Err(e) => presenter.images.instead_of_softbuffer(e)?,
        }
        Ok(presenter)
    }

    /// Shows the pixels of `damage` (the whole frame if the window lost its
    /// previous contents). Switches to the fallback once, with a warning,
    /// if softbuffer fails.
    pub fn present(&mut self, frame: &Frame, damage: &Damage) -> Result<(), String> {
        if let Some(result) = self.images.present(frame, damage) {
            return result;
        }
        let Some(surface) = self.surface.as_mut() else {
            return Err("nothing to present with".into());
        };
        let how = Soft {
            alpha: self.alpha,
            history: &mut self.history,
            wait: self.wait_after_present,
        };
        match present_soft(surface, frame, damage, how) {
            Ok(()) => Ok(()),
            Err(e) => self.fall_back(frame, e.to_string()),
        }
    }

    /// Plain images where softbuffer would send whole frames over the
    /// wire; the window's depth gives `alpha`.
    fn avoid_wire_transfers(&mut self) {
        let (depth, instead) = self.images.avoid_wire_transfers();
        self.alpha = depth.map_or(0, opaque_alpha);
        if instead {
            self.surface = None;
        }
    }

    /// softbuffer failed: plain images from now on, where there are any.
    fn fall_back(&mut self, frame: &Frame, problem: String) -> Result<(), String> {
        self.images.fall_back(frame, problem)?;
        self.surface = None;
        Ok(())
    }
}

/// True for a window of a Wayland compositor.
fn is_wayland(window: &impl HasWindowHandle) -> bool {
    window
        .window_handle()
        .is_ok_and(|h| matches!(h.as_raw(), raw_window_handle::RawWindowHandle::Wayland(_)))
}

/// How `present_soft` copies: the alpha to OR in, the buffers' history,
/// whether to wait for the present to be taken.
struct Soft<'a> {
    alpha: u32,
    history: &'a mut BufferHistory,
    wait: bool,
}

/// What to OR into pixels for a window of `depth` bits so that it is opaque.
fn opaque_alpha(depth: u8) -> u32 {
    if depth == 32 { 0xff00_0000 } else { 0 }
}

fn present_soft<W: HasWindowHandle + HasDisplayHandle>(
    surface: &mut Surface<W, W>,
    frame: &Frame,
    damage: &Damage,
    how: Soft,
) -> Result<(), softbuffer::SoftBufferError> {
    let (Some(w), Some(h)) = (
        NonZeroU32::new(frame.width()),
        NonZeroU32::new(frame.height()),
    ) else {
        return Ok(());
    };
    surface.resize(w, h)?;
    let mut buffer = surface.buffer_mut()?;
    let bounds = frame.bounds();
    // Nothing to show: no present, so the history must not count one.
    let nothing = damage.rects().all(|r| r.intersect(&bounds).is_empty());
    if nothing && buffer.age() != 0 {
        return Ok(());
    }
    let damage = how.history.what_to_copy(buffer.age(), bounds, damage);
    let rects: Vec<softbuffer::Rect> = damage
        .rects()
        .map(|r| r.intersect(&bounds))
        .filter(|r| !r.is_empty())
        .map(|r| {
            copy_rect(frame, &mut buffer, r, how.alpha);
            softbuffer::Rect {
                x: r.x0,
                y: r.y0,
                width: NonZeroU32::new(r.x1 - r.x0).unwrap_or(w),
                height: NonZeroU32::new(r.y1 - r.y0).unwrap_or(h),
            }
        })
        .collect();
    if rects.is_empty() {
        return Ok(());
    }
    buffer.present_with_damage(&rects)?;
    if !how.wait {
        return Ok(());
    }
    // softbuffer's X11 backend leaves the image request in the connection's
    // output buffer until the next `buffer_mut` waits for it. On a connection
    // nobody else flushes (a foreign window's), the last frame before a hold
    // would stay unsent for the whole hold. Waiting here sends it now.
    surface.buffer_mut().map(drop)
}

/// Copies the rows of `rect` from `frame` into a buffer of the same size,
/// ORing `alpha` into every pixel.
fn copy_rect(frame: &Frame, target: &mut [u32], rect: Rect, alpha: u32) {
    let stride = frame.width() as usize;
    let (x0, x1) = (rect.x0 as usize, rect.x1 as usize);
    for y in rect.y0 as usize..rect.y1 as usize {
        let row = y * stride;
        let (to, from) = (
            &mut target[row + x0..row + x1],
            &frame.pixels()[row + x0..row + x1],
        );
        // The usual 24-bit window takes the plain copy (a memcpy).
        if alpha == 0 {
            to.copy_from_slice(from);
        } else {
            for (t, &p) in to.iter_mut().zip(from) {
                *t = p | alpha;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn copy_rect_copies_only_the_rectangle() {
        let mut frame = Frame::new(4, 3).unwrap();
        for (i, p) in frame.pixels_mut().iter_mut().enumerate() {
            *p = i as u32 + 1;
        }
        let mut target = vec![0u32; 12];
        copy_rect(&frame, &mut target, middle_2x2(), 0);
        assert_eq!(target, vec![0, 0, 0, 0, 0, 6, 7, 0, 0, 10, 11, 0]);
    }

    fn middle_2x2() -> Rect {
        Rect {
            x0: 1,
            y0: 1,
            x1: 3,
            y1: 3,
        }
    }

    #[test]
    fn copy_rect_makes_the_rectangle_opaque_for_32_bit_windows() {
        let mut frame = Frame::new(4, 3).unwrap();
        for (i, p) in frame.pixels_mut().iter_mut().enumerate() {
            *p = 0x0012_3400 + i as u32;
        }
        let mut target = vec![7u32; 12];
        copy_rect(&frame, &mut target, middle_2x2(), opaque_alpha(32));
        let o = 0xff12_3400;
        #[rustfmt::skip]
        let expected = vec![
            7, 7, 7, 7,
            7, o + 5, o + 6, 7,
            7, o + 9, o + 10, 7,
        ];
        assert_eq!(target, expected);
    }

    #[test]
    fn only_32_bit_windows_get_alpha() {
        assert_eq!(opaque_alpha(32), 0xff00_0000);
        assert_eq!(opaque_alpha(24), 0);
    }

    #[test]
    fn damage_is_clipped_to_the_frame() {
        let frame = Frame::new(4, 3).unwrap();
        let damage = Rect {
            x0: 2,
            y0: 1,
            x1: 9,
            y1: 9,
        };
        let r = damage.intersect(&frame.bounds());
        assert_eq!(
            r,
            Rect {
                x0: 2,
                y0: 1,
                x1: 4,
                y1: 3
            }
        );
    }
}
