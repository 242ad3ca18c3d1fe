//! What each of a window's buffers still shows, so that a present copies
//! only what that buffer lacks.
//!
//! softbuffer hands out a buffer with its age: 0 when it holds nothing of
//! ours, N when it was last shown N presents ago (X11 keeps one buffer, so
//! 1; Wayland swaps two, so 2 once both were shown). A buffer of age N
//! lacks what changed in the last N-1 presents as well as what changes
//! now. softbuffer keeps a buffer's age when the window's size changes
//! (the buffer is remade, its pixels are not ours), so the sizes are kept
//! here too.

use std::collections::VecDeque;

use crate::render::{Damage, Rect};

/// Presents remembered: a buffer older than this is copied whole.
const REMEMBERED: usize = 4;

/// The damage of the last few presents, all at the present frame size.
#[derive(Debug, Clone, Default)]
pub struct BufferHistory {
    /// The frame's bounds the remembered presents had.
    bounds: Rect,
    /// The latest first.
    recent: VecDeque<Damage>,
}

impl BufferHistory {
    /// A history with no present in it: every buffer is copied whole.
    pub fn new() -> Self {
        Self::default()
    }

    /// What to copy into a buffer of `age` so that it shows a frame of
    /// `bounds` in which `damage` changed since the last present; records
    /// this present. The whole frame when the buffer is new, older than
    /// what is remembered, or from before a change of size.
    pub fn what_to_copy(&mut self, age: u8, bounds: Rect, damage: &Damage) -> Damage {
        if bounds != self.bounds {
            self.bounds = bounds;
            self.recent.clear();
        }
        let age = usize::from(age);
        // The buffer was shown `age` presents ago: that present must be one
        // of those remembered at this size.
        let copy = if age == 0 || age > self.recent.len() {
            Damage::from(bounds)
        } else {
            let mut copy = damage.clone();
            for missed in self.recent.iter().take(age - 1) {
                missed.rects().for_each(|r| copy.add(r));
            }
            copy
        };
        self.recent.push_front(damage.clone());
        self.recent.truncate(REMEMBERED);
        copy
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const FRAME: Rect = Rect {
        x0: 0,
        y0: 0,
        x1: 640,
        y1: 480,
    };

    fn strip(y: u32) -> Damage {
        Damage::from(Rect::sized(0, y, 640, 10))
    }

    fn has(d: &Damage, y: u32) -> bool {
        d.contains(5, y)
    }

    #[test]
    fn a_new_buffer_gets_the_whole_frame() {
        let mut h = BufferHistory::new();
        assert_eq!(h.what_to_copy(0, FRAME, &strip(0)), Damage::from(FRAME));
        // Age 1 with nothing remembered: it cannot hold our last frame.
        let mut h2 = BufferHistory::new();
        assert_eq!(h2.what_to_copy(1, FRAME, &strip(0)), Damage::from(FRAME));
    }

    #[test]
    fn one_buffer_needs_only_the_new_damage() {
        let mut h = BufferHistory::new();
        h.what_to_copy(0, FRAME, &Damage::from(FRAME));
        assert_eq!(h.what_to_copy(1, FRAME, &strip(100)), strip(100));
        assert_eq!(h.what_to_copy(1, FRAME, &strip(200)), strip(200));
    }

    #[test]
    fn two_buffers_each_get_the_strip_they_missed() {
        // Wayland: buffers A and B take turns; each present's buffer last
        // showed the frame two presents ago.
        let mut h = BufferHistory::new();
        h.what_to_copy(0, FRAME, &Damage::from(FRAME)); // A
        h.what_to_copy(0, FRAME, &strip(100)); // B, new: whole
        let third = h.what_to_copy(2, FRAME, &strip(200)); // A again
        assert!(has(&third, 200) && has(&third, 100), "A missed B's strip");
        assert!(!has(&third, 300));
        let fourth = h.what_to_copy(2, FRAME, &strip(300)); // B again
        assert!(has(&fourth, 300) && has(&fourth, 200));
        assert!(!has(&fourth, 100), "B drew that strip itself");
    }

    #[test]
    fn a_buffer_older_than_remembered_gets_the_whole_frame() {
        let mut h = BufferHistory::new();
        for y in 0..6 {
            h.what_to_copy(1, FRAME, &strip(y * 10));
        }
        let age = u8::try_from(REMEMBERED).unwrap();
        assert_ne!(h.what_to_copy(age, FRAME, &strip(400)), Damage::from(FRAME));
        assert_eq!(
            h.what_to_copy(age + 1, FRAME, &strip(410)),
            Damage::from(FRAME)
        );
    }

    #[test]
    fn a_new_size_forgets_what_the_buffers_held() {
        let mut h = BufferHistory::new();
        h.what_to_copy(0, FRAME, &Damage::from(FRAME));
        h.what_to_copy(1, FRAME, &strip(100));
        let small = Rect::sized(0, 0, 320, 240);
        // softbuffer says age 2 for a buffer it remade at the new size.
        assert_eq!(h.what_to_copy(2, small, &strip(10)), Damage::from(small));
        let next = h.what_to_copy(2, small, &strip(20));
        assert_eq!(next, Damage::from(small), "the other buffer is remade too");
        let then = h.what_to_copy(2, small, &strip(30));
        assert!(has(&then, 30) && has(&then, 20) && !has(&then, 10));
    }
}
