//! The field as the bands follow its water down: each pit of one point
//! (every neighbour land and higher) raised to its lowest neighbour, whose
//! way its water then takes.
//!
//! The lakes stay the same but for lakes of one point. Water at such a pit
//! must rise to its lowest neighbour before it can leave, so the height any
//! point's water must rise to is unchanged: a way through the pit passes
//! two of its neighbours, none lower than the height it is raised to. Only
//! the pit itself may be dry where it was wet, and only where it was a lake
//! of its own (its neighbours stand no lower than its water then). Two such
//! pits are never neighbours, so all are raised at once.
//!
//! It pays: most pits of a fractal field are one point deep (seed 1's
//! 17,146 pits at 1025 become 7,012 basins, the edges between basins a third
//! fewer), and the bands' lips, their sorting and the joining shrink with
//! them.

/// Rows of the field, its pits of one point raised (or not), made a row at
/// a time as a band asks for them, three kept.
pub(super) struct Raised<'a> {
    heights: &'a [f32],
    n: usize,
    /// Whether pits are raised; if not, the rows are the field's own.
    raise: bool,
    /// Row `y` in item `y % 3`.
    ring: [Vec<f32>; 3],
    /// The next row to make.
    next: usize,
}

impl<'a> Raised<'a> {
    /// The rows of `heights` (`n` a side), its pits raised if `raise`.
    pub(super) fn new(heights: &'a [f32], n: usize, raise: bool) -> Self {
        let ring = if raise {
            [vec![0.0; n], vec![0.0; n], vec![0.0; n]]
        } else {
            Default::default()
        };
        Raised {
            heights,
            n,
            raise,
            ring,
            next: 0,
        }
    }

    /// Rows `y - 1`, `y` and `y + 1` (`0 < y < n - 1`), the rows asked for
    /// in order.
    pub(super) fn around(&mut self, y: usize) -> [&[f32]; 3] {
        let n = self.n;
        if !self.raise {
            let at = |y: usize| &self.heights[y * n..(y + 1) * n];
            return [at(y - 1), at(y), at(y + 1)];
        }
        self.next = self.next.max(y - 1);
        while self.next <= y + 1 {
            self.make(self.next);
            self.next += 1;
        }
        let at = |y: usize| self.ring[y % 3].as_slice();
        [at(y - 1), at(y), at(y + 1)]
    }

    /// Row `y` of the field itself.
    pub(super) fn plain(&self, y: usize) -> &'a [f32] {
        &self.heights[y * self.n..(y + 1) * self.n]
    }

    /// Makes row `y`.
    fn make(&mut self, y: usize) {
        let n = self.n;
        let at = |y: usize| &self.heights[y * n..(y + 1) * n];
        let out = &mut self.ring[y % 3];
        out.copy_from_slice(at(y));
        if y > 0 && y + 1 < n {
            raise_pits([at(y - 1), at(y), at(y + 1)], out);
        }
    }
}

/// Raises each pit of one point of `row` (off the border) in `out` to its
/// lowest neighbour; branch-free (the compiler keeps it in vector
/// registers).
fn raise_pits(rows: [&[f32]; 3], out: &mut [f32]) {
    super::wide::wide(
        #[inline(always)]
        || raise_pits_here(rows, out),
    );
}

/// [`raise_pits`], for whichever vector registers it is compiled for.
#[inline(always)]
fn raise_pits_here([above, row, below]: [&[f32]; 3], out: &mut [f32]) {
    let n = row.len();
    for x in 0..n - 2 {
        let v = row[x + 1];
        let around = [
            above[x],
            above[x + 1],
            above[x + 2],
            row[x],
            row[x + 2],
            below[x],
            below[x + 1],
            below[x + 2],
        ];
        // A neighbour without data (NaN) fails `>`: no pit beside it.
        let (mut pit, mut low) = (v > 0.0, f32::INFINITY);
        for h in around {
            pit &= h > v;
            low = if h < low { h } else { low };
        }
        out[x + 1] = if pit { low } else { v };
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_pits_of_one_point_are_raised() {
        let n = 5;
        #[rustfmt::skip]
        let heights = vec![
            9.0, 9.0, 9.0, 9.0, 9.0,
            9.0, 1.0, 4.0, 2.0, 9.0,
            9.0, 5.0, 6.0, 2.0, 9.0,
            9.0, 7.0, 3.0, 1.0, 9.0,
            9.0, 9.0, 9.0, 9.0, 0.0,
        ];
        let mut raised = Raised::new(&heights, n, true);
        let [_, one, two] = raised.around(1);
        // (1, 1) is a pit of one point: raised to 4, its lowest neighbour;
        // (3, 1) has a neighbour as low: a flat, left as it is.
        assert_eq!(one, &[9.0, 4.0, 4.0, 2.0, 9.0]);
        assert_eq!(two, &[9.0, 5.0, 6.0, 2.0, 9.0]);
        // (3, 3) is lower than its neighbours but has the sea beside it:
        // its water leaves there, no pit.
        let [_, three, _] = raised.around(3);
        assert_eq!(three, &[9.0, 7.0, 3.0, 1.0, 9.0]);
        let mut plain = Raised::new(&heights, n, false);
        assert_eq!(plain.around(1)[1], &heights[5..10]);
    }

    #[test]
    fn wide_registers_raise_the_same_pits() {
        let mut raised = 0;
        for seed in 0..20u64 {
            let n = 37 + seed as usize;
            let row = |r: u64| -> Vec<f32> {
                (0..n as u64)
                    .map(|x| {
                        let h = crate::terrain::splitmix::mix(seed ^ (r * 1000 + x));
                        match h % 31 {
                            0 => f32::NAN,
                            1 => 0.0,
                            k => (k % 9) as f32 + 0.5,
                        }
                    })
                    .collect()
            };
            let (above, mid, below) = (row(0), row(1), row(2));
            let (mut wide, mut narrow) = (mid.clone(), mid.clone());
            raise_pits([&above, &mid, &below], &mut wide);
            raise_pits_here([&above, &mid, &below], &mut narrow);
            let bits = |v: &[f32]| v.iter().map(|h| h.to_bits()).collect::<Vec<_>>();
            assert_eq!(bits(&wide), bits(&narrow), "seed {seed}");
            raised += wide.iter().zip(&mid).filter(|(w, m)| w > m).count();
        }
        assert!(raised > 0, "no pit raised");
    }
}
