//! Which cells of a strip can reach a band of screen columns.
//!
//! A full frame is drawn in bands of columns, one per thread at a time. Each
//! band walks only the cells that can touch its columns, and projects only
//! their points, so no strip is walked or projected twice over (bands of rows
//! did both: in the vista a strip spans much of the frame's height).

use std::ops::Range;

use crate::render::base::canvas::Canvas;
use crate::render::base::fixed::Clip;
use crate::render::scene::Scene;

/// Pixels added on each side of a band: fixed-point rounding and the lines
/// of Sonar and Outline (a pixel either side of their points) stay inside.
const MARGIN_PX: f32 = 2.0;
/// Cells a block of [`StripReach::cells_showing`]'s: the row tops' blocks.
const BLOCK: usize = 16;

impl<'a> Scene<'a> {
    /// How far strip `s`'s cells reach across the screen, if the view is
    /// known to keep the order of grid columns on screen: worked out once
    /// a strip, for both [`StripReach::cells_reaching`] and
    /// [`StripReach::cells_showing`].
    ///
    /// Along one grid row at one height the screen column only grows with
    /// the grid column (a straight line, all of it in front of the camera),
    /// and a point's column lies between its columns at sea level and at
    /// the strip's top. So the columns a cell reaches are bounded by
    /// monotone functions of its grid column.
    pub(crate) fn strip_reach(&self, s: usize) -> Option<StripReach<'_, 'a>> {
        let (y0, y1) = self.strip_grid_rows(s);
        let top = self.row_top.row(y0).max(self.row_top.row(y1));
        let reach = StripReach {
            scene: self,
            s,
            lines: [(y0, 0.0), (y0, top), (y1, 0.0), (y1, top)],
        };
        let cells = self.cells();
        let ordered = (reach.lines.iter()).all(|&l| reach.column(0, l) < reach.column(cells, l));
        ordered.then_some(reach)
    }
}

/// Strip `s` of a scene whose view keeps the order of grid columns on
/// screen ([`Scene::strip_reach`]).
pub(crate) struct StripReach<'s, 'a> {
    scene: &'s Scene<'a>,
    s: usize,
    /// The strip's two grid rows, each at sea level and at the strip's top.
    lines: [(usize, f32); 4],
}

impl StripReach<'_, '_> {
    /// The screen column of grid column `gx` on `line`.
    fn column(&self, gx: usize, (row, h): (usize, f32)) -> f32 {
        self.scene.view.project(gx as f32, row as f32, h).x
    }

    /// The screen columns (least, greatest) grid column `gx` of the strip
    /// can reach, at any height up to the strip's top.
    fn columns(&self, gx: usize) -> (f32, f32) {
        (self.lines.iter()).fold((f32::INFINITY, f32::NEG_INFINITY), |(lo, hi), &l| {
            let x = self.column(gx, l);
            (lo.min(x), hi.max(x))
        })
    }

    /// The strip's cells whose faces, skirts and lines can touch columns
    /// `clip.x0..clip.x1`.
    ///
    /// They are one run, found by bisection, starting from `near` (the run
    /// of the strip before, which is seldom far off): each band walks every
    /// strip, so bisecting the whole row each time would repeat that work
    /// for every strip of every band.
    pub(crate) fn cells_reaching(&self, clip: &Clip, near: &Range<usize>) -> Range<usize> {
        let cells = self.scene.cells();
        let (left, right) = (clip.x0 as f32 - MARGIN_PX, clip.x1 as f32 + MARGIN_PX);
        // Cell gx spans grid columns gx..=gx + 1.
        let start = partition_near(cells, near.start, |gx| self.columns(gx + 1).1 < left);
        let end = partition_near(cells, near.end, |gx| self.columns(gx).0 < right);
        start..end.max(start)
    }

    /// `cells` of the strip less the blocks of [`BLOCK`] cells at either
    /// end that lie wholly behind what `canvas` (drawn front to back)
    /// holds already: their points are then neither projected nor shaded.
    /// Behind a near ridge most cells of a band's strips are hidden (at
    /// 1080p 244 k of the 561 k cells walked), and the ridge mostly hides a
    /// run at one end of a band.
    pub(crate) fn cells_showing(&self, canvas: &Canvas, mut cells: Range<usize>) -> Range<usize> {
        let clip = canvas.clip();
        let hidden = |run: Range<usize>| {
            let top = self.scene.strip_top(self.s, &run);
            let (lo, hi) = (
                self.columns(run.start).0 - MARGIN_PX,
                self.columns(run.end).1 + MARGIN_PX,
            );
            let x0 = (lo.floor() as i64).max(clip.x0);
            let x1 = (hi.ceil() as i64).min(clip.x1 - 1);
            x0 > x1 || canvas.hidden(x0, x1, top)
        };
        while !cells.is_empty() {
            let end = ((cells.start / BLOCK + 1) * BLOCK).min(cells.end);
            if !hidden(cells.start..end) {
                break;
            }
            cells.start = end;
        }
        while !cells.is_empty() {
            let start = ((cells.end - 1) / BLOCK * BLOCK).max(cells.start);
            if !hidden(start..cells.end) {
                break;
            }
            cells.end = start;
        }
        cells
    }
}

/// The first `i` in `0..n` for which `before(i)` is false (`before` holds
/// for a prefix of `0..n`), searched for outwards from `guess` in doubling
/// steps and then by bisection: a few probes when the guess is close.
fn partition_near(n: usize, guess: usize, before: impl Fn(usize) -> bool) -> usize {
    let guess = guess.min(n);
    // The answer lies in lo..=hi.
    let (mut lo, mut hi);
    if guess < n && before(guess) {
        lo = guess + 1;
        let mut step = 1;
        loop {
            hi = (lo + step).min(n);
            if hi == n || !before(hi) {
                break;
            }
            lo = hi + 1;
            step *= 2;
        }
    } else {
        (lo, hi) = (0, guess);
        let mut step = 1;
        while hi > 0 {
            let probe = hi.saturating_sub(step);
            if before(probe) {
                lo = probe + 1;
                break;
            }
            hi = probe;
            step *= 2;
        }
    }
    while lo < hi {
        let mid = lo + (hi - lo) / 2;
        if before(mid) {
            lo = mid + 1;
        } else {
            hi = mid;
        }
    }
    lo
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::base::size::Size;
    use crate::render::scene::FieldRef;
    use crate::settings::{Detail, Settings, World};

    #[test]
    fn blocks_behind_what_a_band_holds_are_left_out() {
        let settings = Settings {
            detail: Detail::Level(7),
            // Seed 42's coast as it was measured (its varied world is another).
            world: World::Temperate,
            ..Settings::default()
        };
        let field = crate::terrain::generate(&settings, 42);
        let (w, h) = (320, 180);
        let scene = Scene::new(FieldRef::Borrowed(&field), &settings, Size::new(w, h));
        let mut pixels = vec![0u32; (w * h) as usize];
        let mut canvas = Canvas::new(&mut pixels, w, 0).keeping_first();
        let clip = *canvas.clip();
        let mut kept = 0;
        // Nothing drawn yet: every cell reaching the frame stays.
        let reach = |s: usize| {
            scene
                .strip_reach(s)
                .expect("the vista keeps columns in order")
        };
        for s in 0..scene.strips() {
            let cells = reach(s).cells_reaching(&clip, &(0..scene.cells()));
            assert_eq!(reach(s).cells_showing(&canvas, cells.clone()), cells);
            kept += cells.len();
        }
        assert!(kept > 1000, "{kept} cells reach the frame");
        // Everything drawn: no cell shows.
        for y in 0..h {
            canvas.fill(y, 0, w, 0x123456);
        }
        for s in 0..scene.strips() {
            let cells = reach(s).cells_reaching(&clip, &(0..scene.cells()));
            assert!(
                reach(s).cells_showing(&canvas, cells).is_empty(),
                "strip {s}"
            );
        }
    }

    #[test]
    fn the_search_from_a_guess_finds_the_end_of_the_prefix() {
        for n in [0usize, 1, 2, 3, 7, 64, 1025] {
            for answer in 0..=n {
                for guess in [
                    0,
                    1,
                    answer.saturating_sub(3),
                    answer,
                    answer + 1,
                    answer + 40,
                    n,
                    n + 5,
                ] {
                    let probes = std::cell::Cell::new(0);
                    let got = partition_near(n, guess, |i| {
                        assert!(i < n, "probed {i} of {n}");
                        probes.set(probes.get() + 1);
                        i < answer
                    });
                    assert_eq!(got, answer, "n {n}, guess {guess}");
                    if guess.abs_diff(answer) <= 1 {
                        assert!(
                            probes.get() <= 4,
                            "{} probes from a guess next to it",
                            probes.get()
                        );
                    }
                }
            }
        }
    }
}
