//! A point's neighbours on the square grid the lakes are found on, and
//! which points are land.

use crate::terrain::neighbours::NEIGHBOURS;

/// Whether height `h` is land: above sea level (NaN, no data, is not).
/// Water leaves the field wherever it reaches a point that is not.
#[inline]
pub(super) fn land(h: f32) -> bool {
    h > 0.0
}

/// The neighbourhood of the points of a grid `n` a side.
#[derive(Clone, Copy)]
pub(super) struct Grid {
    n: usize,
    /// `ceil(2^40 / n)`: a point's row by a multiplication.
    row_of: u64,
}

impl Grid {
    /// The grid of `n` points a side.
    pub(super) fn new(n: usize) -> Self {
        Grid {
            n,
            row_of: (1u64 << 40).div_ceil(n as u64),
        }
    }

    /// Points a side.
    #[inline]
    pub(super) fn n(self) -> usize {
        self.n
    }

    /// The eight neighbours of a point off the border.
    #[inline]
    pub(super) fn around(self, i: usize) -> [usize; 8] {
        let n = self.n;
        [
            i - n - 1,
            i - n,
            i - n + 1,
            i - 1,
            i + 1,
            i + n - 1,
            i + n,
            i + n + 1,
        ]
    }

    /// The neighbours of `i` (lakes join across a cell's diagonals, as the
    /// triangles drawn over the cells do), in the first `count` items:
    /// fewer than eight on the border.
    #[inline]
    pub(super) fn neighbours(self, i: usize) -> ([usize; 8], usize) {
        let n = self.n;
        // i / n without a division: exact for i < 2^25 (a 4097 grid has
        // 2^24 points), as i (2^40/n + e) / 2^40 exceeds i / n by less than
        // 2^-15, and i / n's fraction is at most 1 - 1/n.
        let y = ((i as u64 * self.row_of) >> 40) as usize;
        let x = i - y * n;
        if x > 0 && y > 0 && x + 1 < n && y + 1 < n {
            return (self.around(i), 8);
        }
        let mut out = [0; 8];
        let mut count = 0;
        for (dx, dy) in NEIGHBOURS {
            let (nx, ny) = (x as isize + dx, y as isize + dy);
            if nx >= 0 && ny >= 0 && (nx as usize) < n && (ny as usize) < n {
                out[count] = ny as usize * n + nx as usize;
                count += 1;
            }
        }
        (out, count)
    }
}
