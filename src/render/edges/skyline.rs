//! The skyline drawn clean: where the land meets the sky, each pixel is
//! mixed from the sky and the land by how much of it lies under the edge,
//! so the skyline is a smooth line, not a staircase of whole pixels.
//!
//! The land's top in each column is where the frame stops showing the sky
//! (the sky is a known gradient, and in the views with depth the land runs
//! from there to the bottom). Columns with the same top form runs; the true
//! edge passes through each run's middle at its top, and between the
//! middles of neighbouring runs it is taken to be straight. A run higher
//! (or lower) than both its neighbours is a peak (or a notch): the edge is
//! kept level across it, so a sharp peak keeps its tip and a narrow notch
//! stays open. Each pixel's share of land is the mean of the edge's height
//! at four places across its width.
//!
//! This runs once the frame is complete (it needs each column's
//! neighbours), on the full frame and at the painter's last step alike, so
//! both end with the same pixels. Only the runs and the edges' middles need
//! the whole width: the columns' tops are found, and their pixels mixed,
//! column by column, so parts of the frame's width can do both at once.

use crate::render::base::colour::blend_packed;
use crate::render::base::frame::Frame;
use crate::render::shade::sky::{Sky, SkySeen};

use super::horizon::{Edge, SAMPLES};
use crate::render::base::canvas::Canvas;
#[cfg(test)]
use crate::render::base::damage::Damage;

/// A run of columns whose land starts at the same row.
#[derive(Clone, Copy)]
struct Run {
    /// First and last column.
    x0: u32,
    x1: u32,
    /// The first row of land.
    top: u32,
}

impl Run {
    /// The run's middle, in pixels from the frame's left.
    fn middle(&self) -> f32 {
        (self.x0 + self.x1 + 1) as f32 / 2.0
    }
}

/// The skyline of a complete frame, ready to be mixed column by column:
/// each column's first row of land, the runs of columns that share it, and
/// the edge across each column of land.
pub(crate) struct Skyline {
    tops: Vec<u32>,
    runs: Vec<Run>,
    /// The mesh's edge where it agrees with the column's top (see
    /// [`Skyline::new`]).
    exact: Vec<Option<Edge>>,
    middles: Vec<f32>,
    level: Vec<bool>,
}

impl Skyline {
    /// The skyline of a frame `height` rows high whose columns' first rows
    /// of land are `tops` ([`land_tops`]). `exact` is the land's top edge as
    /// the mesh draws it, per column where it is known: where a column's
    /// top is where that edge puts it, the edge is taken as it is (a
    /// straight sea horizon or a peak narrower than a pixel has no
    /// staircase to tell its height by).
    pub(crate) fn new(tops: Vec<u32>, exact: &[Option<Edge>], height: u32) -> Self {
        let runs = runs_of(&tops, height);
        let exact: Vec<Option<Edge>> = (0..tops.len())
            .map(|x| {
                exact
                    .get(x)
                    .copied()
                    .flatten()
                    .filter(|e| agrees(e, tops[x]))
            })
            .collect();
        let (mut middles, level) = middles(&runs, tops.len());
        for (x, e) in exact.iter().enumerate() {
            if let Some(e) = e {
                middles[x] = e.centre;
            }
        }
        Skyline {
            tops,
            runs,
            exact,
            middles,
            level,
        }
    }

    /// Each column's first row of land (the height where it has none).
    pub(crate) fn tops(&self) -> &[u32] {
        &self.tops
    }

    /// Mixes the pixels along the skyline in `canvas`'s columns, whose sky
    /// is `sky` (as seen so far along them: `seen`); what it changed is the
    /// canvas's damage. Each column is mixed from its own pixels alone, so
    /// canvases of different columns can be mixed at once.
    pub(crate) fn mix<'s>(&self, canvas: &mut Canvas, sky: &'s Sky, seen: &mut SkySeen<'s>) {
        let clip = *canvas.clip();
        let (x0, x1) = (clip.x0 as u32, clip.x1 as u32);
        for run in &self.runs {
            for x in run.x0.max(x0)..(run.x1 + 1).min(x1) {
                let edge: [f32; SAMPLES] = self.exact[x as usize].map_or_else(
                    || {
                        std::array::from_fn(|k| {
                            let at = (k as f32 + 0.5) / SAMPLES as f32;
                            edge_in(&self.middles, &self.level, x as usize, at)
                        })
                    },
                    |e| e.samples,
                );
                if let Some(rows) = mix_column(canvas, (sky, seen), x, run.top, &edge) {
                    canvas.touch(x, rows.0, x + 1, rows.1);
                }
            }
        }
    }
}

/// The whole skyline of `frame` mixed on this thread: what the tests
/// look at.
#[cfg(test)]
fn smooth(frame: &mut Frame, sky: &Sky, exact: &[Option<Edge>]) -> (Damage, Vec<u32>) {
    let (width, height) = (frame.width(), frame.height());
    let known = |x: u32| exact.get(x as usize).copied().flatten();
    let exact: Vec<Option<Edge>> = (0..width).map(known).collect();
    let mut seen = SkySeen::default();
    let tops = land_tops(frame, sky, &exact, 0, &mut seen);
    let skyline = Skyline::new(tops, &exact, height);
    let mut canvas = Canvas::new(frame.pixels_mut(), width, 0);
    skyline.mix(&mut canvas, sky, &mut seen);
    (canvas.damage(), skyline.tops)
}

/// Whether `edge` puts a column's first row of land at `top`: the first
/// pixel centre below the edge's centre.
fn agrees(edge: &Edge, top: u32) -> bool {
    (edge.centre - 0.5).ceil() == top as f32
}

/// The edge's height at the middle of each column (NaN where the column
/// has no land), and whether the column lies in a peak or a notch, where
/// the edge stays level. A middle is held within half a row of the
/// column's own top: the edge cannot pass where the column's pixel centres
/// say it does not.
fn middles(runs: &[Run], width: usize) -> (Vec<f32>, Vec<bool>) {
    let mut middle = vec![f32::NAN; width];
    let mut level = vec![false; width];
    for (i, run) in runs.iter().enumerate() {
        let (left, right) = (neighbour(runs, i, -1), neighbour(runs, i, 1));
        let extreme = match (left, right) {
            (Some(l), Some(r)) => (l.top > run.top) == (r.top > run.top),
            _ => false,
        };
        let top = run.top as f32;
        for x in run.x0..=run.x1 {
            let e = if extreme {
                top
            } else {
                edge_at(run, left, right, x as f32 + 0.5)
            };
            middle[x as usize] = e.clamp(top - 0.5, top + 0.5);
            level[x as usize] = extreme;
        }
    }
    (middle, level)
}

/// The edge's height `at` (0..1) across column `x`: straight between the
/// middles of neighbouring columns, level in a peak or a notch.
fn edge_in(middles: &[f32], level: &[bool], x: usize, at: f32) -> f32 {
    let own = middles[x];
    if level[x] {
        return own;
    }
    let (other, t) = if at < 0.5 {
        (x.checked_sub(1).and_then(|l| middles.get(l)), 0.5 - at)
    } else {
        (middles.get(x + 1), at - 0.5)
    };
    match other {
        Some(&o) if !o.is_nan() => own + (o - own) * t,
        _ => own,
    }
}

/// The first row of each column that is not the sky (the height when the
/// whole column is sky), for the columns from `x0` on that `exact` holds.
/// Where the mesh's edge across a column is known (`exact`), the search
/// starts just above it: no land is drawn higher (a pixel is land when its
/// centre is covered), which its first pixel, checked to be the sky,
/// confirms; elsewhere it starts at the top. A sky with weather costs a
/// lot a pixel to tell.
pub(crate) fn land_tops<'s>(
    frame: &Frame,
    sky: &'s Sky,
    exact: &[Option<Edge>],
    x0: usize,
    seen: &mut SkySeen<'s>,
) -> Vec<u32> {
    let (w, h) = (frame.width() as usize, frame.height());
    let pixels = frame.pixels();
    let mut shows = |x: usize, y: u32| sky.shows(pixels[y as usize * w + x], x as u32, y, seen);
    let mut tops = vec![h; exact.len()];
    let mut from_top = Vec::new();
    for (i, (top, edge)) in tops.iter_mut().zip(exact).enumerate() {
        let x = x0 + i;
        let above = edge.map(|e| {
            let least = e.samples.iter().fold(e.centre, |m, &s| m.min(s));
            (least - 2.0).floor()
        });
        match above {
            Some(y0) if y0 >= 0.0 && y0 < h as f32 && shows(x, y0 as u32) => {
                *top = (y0 as u32 + 1..h).find(|&y| !shows(x, y)).unwrap_or(h);
            }
            Some(y0) if y0 < 0.0 => *top = (0..h).find(|&y| !shows(x, y)).unwrap_or(h),
            _ => from_top.push(i),
        }
    }
    // The rest row by row, as the plain sky's colours come a row at a time.
    let mut open = from_top.len();
    for y in 0..h {
        if open == 0 {
            break;
        }
        for &i in &from_top {
            if tops[i] == h && !shows(x0 + i, y) {
                tops[i] = y;
                open -= 1;
            }
        }
    }
    tops
}

/// Runs of neighbouring columns with the same top; columns with no land
/// belong to none.
fn runs_of(tops: &[u32], height: u32) -> Vec<Run> {
    let mut runs: Vec<Run> = Vec::new();
    for (x, &top) in tops.iter().enumerate() {
        let x = x as u32;
        match runs.last_mut() {
            Some(r) if r.top == top && r.x1 + 1 == x => r.x1 = x,
            _ if top < height => runs.push(Run { x0: x, x1: x, top }),
            _ => {}
        }
    }
    runs
}

/// The run beside run `i` (`step` -1 left, 1 right), if it touches it.
fn neighbour(runs: &[Run], i: usize, step: isize) -> Option<&Run> {
    let j = i.checked_add_signed(step)?;
    let other = runs.get(j)?;
    let touches = if step < 0 {
        other.x1 + 1 == runs[i].x0
    } else {
        runs[i].x1 + 1 == other.x0
    };
    touches.then_some(other)
}

/// The edge's height (rows from the top) at `x` (pixels) within `run`:
/// straight between the middles of the neighbouring runs.
fn edge_at(run: &Run, left: Option<&Run>, right: Option<&Run>, x: f32) -> f32 {
    let top = run.top as f32;
    let middle = run.middle();
    let other = if x < middle { left } else { right };
    match other {
        Some(n) => {
            let t = (x - middle) / (n.middle() - middle);
            top + (n.top as f32 - top) * t
        }
        None => top,
    }
}

/// Mixes column `x` where the edge (its height at each sample across the
/// column) cuts pixels; `top` is the column's first row of land. Returns
/// the rows changed, if any.
fn mix_column<'s>(
    canvas: &mut Canvas,
    (sky, seen): (&'s Sky, &mut SkySeen<'s>),
    x: u32,
    top: u32,
    edge: &[f32; SAMPLES],
) -> Option<(u32, u32)> {
    let lo = edge.iter().copied().fold(f32::INFINITY, f32::min);
    let hi = edge.iter().copied().fold(f32::NEG_INFINITY, f32::max);
    let first = (lo.floor().max(0.0) as u32).min(top);
    // Rows between the edge and the column's top are land all across.
    let end = (hi.ceil().max(0.0) as u32)
        .max(top)
        .min(canvas.clip().y1 as u32);
    let land = canvas.get(x, top);
    let mut changed = None;
    for y in first..end {
        let cover: f32 = edge
            .iter()
            .map(|&e| (y as f32 + 1.0 - e).clamp(0.0, 1.0))
            .sum::<f32>()
            / SAMPLES as f32;
        let now = canvas.get(x, y);
        let own = if y >= top { now } else { land };
        let mixed = blend_packed(
            sky.colour_seen(x, y, seen),
            own,
            (cover * 256.0 + 0.5) as u32,
        );
        if mixed != now {
            canvas.plot(x, y, mixed);
            let (a, _) = changed.get_or_insert((y, y + 1));
            changed = Some((*a, y + 1));
        }
    }
    changed
}

#[cfg(test)]
mod tests {
    use super::*;

    const LAND: u32 = 0x0020_4010;

    /// A frame of `w` x `h` sky with land from row `tops[x]` down.
    fn framed(tops: &[u32], h: u32, sky: &Sky) -> Frame {
        let w = tops.len() as u32;
        let mut f = Frame::new(w, h).unwrap();
        for y in 0..h {
            for x in 0..w {
                let c = if y >= tops[x as usize] {
                    LAND
                } else {
                    sky.colour(x, y)
                };
                f.set(x, y, c);
            }
        }
        f
    }

    /// A level edge at height `y` known across `width` columns.
    fn level(y: f32, width: usize) -> Vec<Option<Edge>> {
        let edge = Edge {
            samples: [y; SAMPLES],
            centre: y,
        };
        vec![Some(edge); width]
    }

    fn sky() -> Sky {
        Sky::new(0x0000_0080, 0x0080_00ff, 40.0)
    }

    /// Land's share of pixel (`x`, `y`) in 1/64ths: its green (the sky has none).
    fn green(f: &Frame, x: u32, y: u32) -> u32 {
        (f.get(x, y) >> 8) & 0xff
    }

    #[test]
    fn a_gentle_staircase_becomes_a_ramp() {
        // Land one row higher every 8 columns: a slope of 1/8.
        let tops: Vec<u32> = (0..48).map(|x| 20 - x / 8).collect();
        let sky = sky();
        let mut f = framed(&tops, 30, &sky);
        let before = f.clone();
        let (damage, _) = smooth(&mut f, &sky, &[]);
        assert!(!damage.is_empty());
        // Above each run's right half a pixel of sky takes some land, more
        // the nearer the step: a blend, not a stair.
        let shares: Vec<u32> = (8..16).map(|x| green(&f, x, 18)).collect();
        assert!(shares[0] == 0 && shares[7] > 0, "{shares:?}");
        assert!(shares.windows(2).all(|w| w[0] <= w[1]), "{shares:?}");
        let blends = (0..48).filter(|&x| {
            let c = f.get(x, 18);
            c != before.get(x, 18) && c != LAND
        });
        assert!(blends.count() >= 8);
        // The land below the edge stays land.
        assert_eq!(f.get(12, 25), LAND);
    }

    #[test]
    fn a_peak_keeps_its_tip_and_a_flat_skyline_is_left_alone() {
        let mut tops = vec![20u32; 16];
        tops[8] = 12;
        let sky = sky();
        let mut f = framed(&tops, 30, &sky);
        smooth(&mut f, &sky, &[]);
        assert_eq!(f.get(8, 12), LAND, "the tip");
        for x in [0, 1, 2, 13, 14, 15] {
            for y in 0..30 {
                let want = if y >= 20 { LAND } else { sky.colour(x, y) };
                assert_eq!(f.get(x, y), want, "({x}, {y})");
            }
        }
        // Its flanks grow a little land into the sky beside the tip.
        assert!(green(&f, 7, 17) > 0 || green(&f, 9, 17) > 0);
    }

    #[test]
    fn a_level_edge_known_exactly_is_mixed_by_its_true_height() {
        // Land from row 20 down, its true edge at 19.75: row 19 is a quarter
        // land, which no staircase of whole rows could tell.
        let tops = vec![20u32; 16];
        let sky = sky();
        let mut f = framed(&tops, 30, &sky);
        smooth(&mut f, &sky, &level(19.75, 16));
        for x in 0..16 {
            let want = blend_packed(sky.colour(x, 19), LAND, 64);
            assert_eq!(f.get(x, 19), want, "column {x}");
            assert_eq!(f.get(x, 20), LAND);
        }
        // An edge the tops contradict (the land's top is not where it says)
        // is not taken.
        let mut g = framed(&tops, 30, &sky);
        smooth(&mut g, &sky, &level(12.3, 16));
        assert_eq!(g.get(5, 19), sky.colour(5, 19));
    }

    #[test]
    fn a_peak_narrower_than_a_pixel_known_exactly_is_faint() {
        // The drawn tip is a whole column from row 12; the mesh says only a
        // quarter of that column's width rises above row 20.
        let mut tops = vec![20u32; 16];
        tops[8] = 12;
        let sky = sky();
        let mut f = framed(&tops, 30, &sky);
        let mut exact = vec![None; 16];
        exact[8] = Some(Edge {
            samples: [20.0, 20.0, 12.0, 20.0],
            centre: 12.0,
        });
        smooth(&mut f, &sky, &exact);
        for y in 12..20 {
            let want = blend_packed(sky.colour(8, y), LAND, 64);
            assert_eq!(f.get(8, y), want, "row {y}: a quarter land");
        }
        assert_eq!(f.get(8, 20), LAND);
    }

    #[test]
    fn a_frame_of_sky_only_is_unchanged() {
        let sky = sky();
        let tops = vec![30u32; 10];
        let mut f = framed(&tops, 30, &sky);
        let before = f.clone();
        assert!(smooth(&mut f, &sky, &[]).0.is_empty());
        assert_eq!(f.pixels(), before.pixels());
    }
}
