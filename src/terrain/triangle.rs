//! Triangle subdivision (Fractal Mountain Climbing, seed 000; FL3, seed 004).
//!
//! The grid is two triangles, split along the diagonal from the back-left
//! corner `(0, 0)` to the front-right corner `(last, last)`, drawn by the
//! renderer as a parallelogram or a square. Each triangle's three edge
//! midpoints are set once, to the mean of the edge's two ends plus a uniform
//! deviation, and the four sub-triangles are split in turn. Level by level,
//! that makes three kinds of new point: horizontal edge midpoints, vertical
//! edge midpoints and diagonal midpoints.
//!
//! Seed 000's `MaxDeviation(ic) = roughness^(ic-1) * 8`, with `ic` starting at
//! `maxIter + 1` whatever the detail, and its profiles start the corners at
//! `q = MaxDeviation(maxIter + 1) / 2`. Dividing every height by
//! `roughness^maxIter` (the result is normalised later anyway) gives the same
//! shape in small numbers: `q = 4` and a deviation of at most
//! `8 / roughness^(k+1)` at depth `k`.

use super::noise::Noise;
use super::subdivide::{CentreRows, EdgeRows, Put, Rule, edge_row_of_ends};
use crate::settings::Profile;

/// Starting corner height of the profiles, in the generator's raw units.
const Q: f32 = 4.0;

/// The triangle generator's rule for one field.
pub(crate) struct Triangle {
    /// Largest deviation per depth, index = depth.
    amplitudes: Vec<f32>,
    /// The starting profile.
    profile: Profile,
}

impl Triangle {
    /// The rule for `roughness` (seed 000's Smoothness base, 1.0-5.0; 0 or
    /// less is its blank item, `roughness = -1`: no point deviated).
    pub(crate) fn new(roughness: f32, profile: Profile) -> Self {
        let r = f64::from(roughness);
        let mut amplitude = if r > 0.0 { 8.0f64 } else { 0.0 };
        let amplitudes = (0..super::heightfield::MAX_EXPONENT)
            .map(|_| {
                if r > 0.0 {
                    amplitude /= r;
                }
                amplitude as f32
            })
            .collect();
        Triangle {
            amplitudes,
            profile,
        }
    }

    /// Sets the corners (seed 000's CalcMountains) and the first level's
    /// five midpoints, except those the profile fixes instead.
    pub(crate) fn first_level<P: Put>(
        &self,
        heights: &mut [f32],
        size: usize,
        noise: &Noise,
        put: &P,
    ) {
        let (last, mid) = (size - 1, (size - 1) / 2);
        let index = |(x, y): (usize, usize)| y * size + x;
        let corners = [(0, 0), (last, 0), (0, last), (last, last)];
        for (&point, value) in corners.iter().zip(corner_heights(self.profile)) {
            put.put(&mut heights[index(point)], value);
        }
        let pins = pins(self.profile, last);
        for &(x, y, value) in &pins {
            put.put(&mut heights[index((x, y))], value);
        }
        // Each new point with the two ends of its edge, in the same order
        // as the row kernels add them (up before down, left before right).
        let midpoints = [
            ((mid, 0), (0, 0), (last, 0)),
            ((0, mid), (0, 0), (0, last)),
            ((mid, mid), (0, 0), (last, last)),
            ((last, mid), (last, 0), (last, last)),
            ((mid, last), (0, last), (last, last)),
        ];
        let amp = self.amplitude(0);
        for ((x, y), p, q) in midpoints {
            if pins.iter().any(|&(px, py, _)| (px, py) == (x, y)) {
                continue;
            }
            let mean = 0.5 * (heights[index(p)] + heights[index(q)]);
            put.put(&mut heights[index((x, y))], mean + amp * noise.at(x, y));
        }
    }
}

/// Corner heights (back-left, back-right, front-left, front-right) of a profile.
fn corner_heights(profile: Profile) -> [f32; 4] {
    match profile {
        Profile::Slope => [Q, 0.0, 0.0, -Q],
        Profile::Peak => [Q, 0.0, 0.0, 0.0],
        Profile::Bay => [0.0, 0.0, 0.0, -Q],
        Profile::Massif => [0.0; 4],
    }
}

/// First-level midpoints a profile fixes instead of deviating them.
fn pins(profile: Profile, last: usize) -> Vec<(usize, usize, f32)> {
    let mid = last / 2;
    match profile {
        // The single peak at the back-left falls to a flat sea elsewhere.
        Profile::Peak => vec![(mid, mid, 0.0), (mid, last, 0.0), (last, mid, 0.0)],
        // A raised centre and raised back and left edge midpoints.
        Profile::Massif => vec![(mid, mid, 0.5 * Q), (mid, 0, Q), (0, mid, Q)],
        Profile::Slope | Profile::Bay => Vec::new(),
    }
}

impl Rule for Triangle {
    /// `8 / roughness^(depth + 1)`: seed 000's MaxDeviation in our units.
    fn amplitude(&self, depth: u32) -> f32 {
        self.amplitudes.get(depth as usize).copied().unwrap_or(0.0)
    }

    fn centre_row<P: Put>(&self, rows: CentreRows<'_>, offsets: &[f32], put: &P) {
        let CentreRows { above, row, below } = rows;
        let (Some((r0, row)), Some((o0, offsets))) = (row.split_first_mut(), offsets.split_first())
        else {
            return;
        };
        put.put(r0, 0.5 * (above[0] + below[0]) + o0);
        // Pairs of (diagonal midpoint 2j+1, vertical edge midpoint 2j+2).
        let mut up_left = above[0];
        let ends = above[1..].chunks_exact(2).zip(below[1..].chunks_exact(2));
        for ((r, (a, b)), o) in row
            .chunks_exact_mut(2)
            .zip(ends)
            .zip(offsets.chunks_exact(2))
        {
            put.put(&mut r[0], 0.5 * (up_left + b[1]) + o[0]);
            put.put(&mut r[1], 0.5 * (a[1] + b[1]) + o[1]);
            up_left = a[1];
        }
    }

    fn edge_row<P: Put>(&self, rows: EdgeRows<'_>, offsets: &[f32], put: &P) {
        edge_row_of_ends(rows.row, offsets, put);
    }
}
