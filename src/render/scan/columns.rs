//! A frame cut into columns that threads can write at once: each part is
//! the same columns of every row, as a slice per row.

use crate::render::frame::Frame;

/// Columns `x0..x0 + width` of every row of a frame.
pub(crate) struct ColumnsMut<'a> {
    rows: Vec<&'a mut [u32]>,
    x0: u32,
}

impl<'a> ColumnsMut<'a> {
    /// `frame` cut at column `at` (clamped to its width): the columns left
    /// of it and the rest.
    pub(crate) fn split(frame: &'a mut Frame, at: u32) -> [ColumnsMut<'a>; 2] {
        let width = frame.width().max(1);
        let at = at.min(width);
        let (mut left, mut right) = (Vec::new(), Vec::new());
        for row in frame.pixels_mut().chunks_exact_mut(width as usize) {
            let (l, r) = row.split_at_mut(at as usize);
            left.push(l);
            right.push(r);
        }
        [
            ColumnsMut { rows: left, x0: 0 },
            ColumnsMut {
                rows: right,
                x0: at,
            },
        ]
    }

    /// Whether frame column `x` is one of these.
    pub(crate) fn holds(&self, x: u32) -> bool {
        let width = self.rows.first().map_or(0, |r| r.len() as u32);
        x >= self.x0 && x - self.x0 < width
    }

    /// How many rows.
    pub(crate) fn height(&self) -> u32 {
        self.rows.len() as u32
    }

    /// Pixel (`x`, `y`) in frame coordinates; the column must be held.
    #[inline]
    pub(crate) fn get(&self, x: u32, y: u32) -> u32 {
        self.rows[y as usize][(x - self.x0) as usize]
    }

    /// Sets pixel (`x`, `y`) in frame coordinates; the column must be held.
    #[inline]
    pub(crate) fn set(&mut self, x: u32, y: u32, colour: u32) {
        self.rows[y as usize][(x - self.x0) as usize] = colour;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_two_parts_are_the_frame_cut_at_a_column() {
        let mut f = Frame::new(5, 3).unwrap();
        for y in 0..3 {
            for x in 0..5 {
                f.set(x, y, 10 * y + x);
            }
        }
        let [mut left, right] = ColumnsMut::split(&mut f, 2);
        assert!(left.holds(1) && !left.holds(2) && right.holds(2) && right.holds(4));
        assert!(!right.holds(5));
        assert_eq!(
            (left.get(1, 2), right.get(3, 1), right.height()),
            (21, 13, 3)
        );
        left.set(0, 1, 99);
        assert_eq!(f.get(0, 1), 99);
    }
}
