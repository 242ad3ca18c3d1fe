//! A rectangle of frame pixels to draw into, with the damage it collects.
//!
//! The parallel full frame gives each thread its own band of columns of the
//! frame (each row's part of the band is a slice of its own, so the threads
//! draw straight into the frame); stepping uses one canvas that is the whole
//! frame. Either way a pixel only ever receives the writes of one canvas, in
//! painter's order, so the results are identical.
//!
//! A canvas either keeps the last write to a pixel (the painter's order,
//! back to front) or the first (the same order reversed, front to back).
//! Both end with the same pixels; the second lets the full frame skip the
//! faces hidden behind what is already drawn.

use super::damage::Damage;
use super::fixed::Clip;
use super::frame::Rect;

/// Columns `x0..x0 + width` of rows `y0..` of a frame, a slice per row.
pub(crate) struct Canvas<'a> {
    rows: Vec<&'a mut [u32]>,
    width: u32,
    x0: u32,
    y0: u32,
    clip: Clip,
    damage: Damage,
    /// Keeping the first write: for each column, the top of the run of
    /// written pixels that reaches the bottom row (`clip.y1` when empty).
    solid: Option<Vec<i64>>,
}

/// What an unwritten pixel of a first-write canvas holds: drawn colours
/// are `0x00RRGGBB`, so none is this.
const UNSET: u32 = 0xff00_0000;

impl<'a> Canvas<'a> {
    /// `pixels` holds rows `y0..` of the frame, whole rows.
    pub(crate) fn new(pixels: &'a mut [u32], width: u32, y0: u32) -> Self {
        let rows = pixels.chunks_exact_mut(width.max(1) as usize).collect();
        Self::from_rows(rows, 0, y0)
    }

    /// `rows` are columns `x0..x0 + width` of frame rows `y0..`, all `width`
    /// long.
    pub(crate) fn from_rows(rows: Vec<&'a mut [u32]>, x0: u32, y0: u32) -> Self {
        let width = rows.first().map_or(0, |r| r.len() as u32);
        let height = rows.len() as u32;
        Canvas {
            rows,
            width,
            x0,
            y0,
            clip: Clip {
                x0: x0 as i64,
                x1: (x0 + width) as i64,
                y0: y0 as i64,
                y1: (y0 + height) as i64,
            },
            damage: Damage::default(),
            solid: None,
        }
    }

    /// This canvas, turned to keep the first colour written to a pixel:
    /// draw front to back. All pixels start unwritten.
    pub(crate) fn keeping_first(mut self) -> Self {
        for row in &mut self.rows {
            row.fill(UNSET);
        }
        self.solid = Some(vec![self.clip.y1; self.width as usize]);
        self
    }

    /// Whether this canvas keeps the first write (is drawn front to back).
    #[inline]
    pub(crate) fn keeps_first(&self) -> bool {
        self.solid.is_some()
    }

    /// The first row from which every row is written in every column (the
    /// canvas's end when nothing is): on a first-write canvas, nothing drawn
    /// below it shows. The canvas's end on one that keeps the last write,
    /// where later writes show anyway.
    pub(crate) fn all_written_from(&self) -> i64 {
        match &self.solid {
            Some(solid) => solid.iter().copied().max().unwrap_or(self.clip.y0),
            None => self.clip.y1,
        }
    }

    /// Whether every pixel of columns `x0..=x1` from row `y0` down is
    /// written already: on a first-write canvas, nothing drawn there shows.
    #[inline]
    pub(crate) fn hidden(&self, x0: i64, x1: i64, y0: i64) -> bool {
        let Some(solid) = &self.solid else {
            return false;
        };
        let (a, b) = ((x0 - self.clip.x0) as usize, (x1 - self.clip.x0) as usize);
        solid[a..=b].iter().all(|&top| top <= y0)
    }

    /// Sets row `y`, columns `x0..x1` (frame coordinates, already clipped)
    /// to `colour(x)`, or on a first-write canvas its unwritten pixels.
    // Always inlined: most spans are one to three pixels, so a call per
    // span would cost more than its writes.
    #[inline(always)]
    pub(crate) fn fill_with(&mut self, y: u32, x0: u32, x1: u32, colour: impl Fn(u32) -> u32) {
        let Some(solid) = &mut self.solid else {
            for (px, x) in self.span_mut(y, x0, x1).iter_mut().zip(x0..) {
                *px = colour(x);
            }
            return;
        };
        let r = (y - self.y0) as usize;
        let (a, b) = ((x0 - self.x0) as usize, (x1 - self.x0) as usize);
        let (upper, rest) = self.rows.split_at_mut(r);
        let (row, solid) = (&mut rest[0][a..b], &mut solid[a..b]);
        let below = i64::from(y) + 1;
        for i in 0..row.len().min(solid.len()) {
            let (px, top, c) = (&mut row[i], &mut solid[i], a + i);
            // A select, not a branch: written and unwritten pixels alternate
            // unpredictably along a ridge.
            let colour = colour(x0 + i as u32);
            *px = if *px == UNSET { colour } else { *px };
            if *top == below {
                // The row joins the column's solid run: lift the run over
                // the written pixels above.
                let mut above = r;
                while above > 0 && upper[above - 1][c] != UNSET {
                    above -= 1;
                }
                *top = i64::from(self.y0) + above as i64;
            }
        }
    }

    /// The runs `x0..x1` of row `y` (frame coordinates, inside the canvas)
    /// a write would change: on a first-write canvas its unwritten pixels,
    /// on one that keeps the last write the whole row.
    pub(crate) fn open_runs(&self, y: u32) -> Vec<(u32, u32)> {
        let (x0, x1) = (self.clip.x0 as u32, self.clip.x1 as u32);
        if self.solid.is_none() {
            return vec![(x0, x1)];
        }
        let row = &self.rows[(y - self.y0) as usize];
        let mut runs = Vec::new();
        let mut start = None;
        for (i, &px) in row.iter().enumerate() {
            match (px == UNSET, start) {
                (true, None) => start = Some(i),
                (false, Some(s)) => {
                    runs.push((x0 + s as u32, x0 + i as u32));
                    start = None;
                }
                _ => {}
            }
        }
        if let Some(s) = start {
            runs.push((x0 + s as u32, x1));
        }
        runs
    }

    /// The first run `a..b` of the pixels `x0..x1` of row `y` (already
    /// clipped) a write would change: on a first-write canvas unwritten
    /// ones, on one that keeps the last write all of them. A pixel whose
    /// colour costs much need not be worked out where it would not show.
    #[inline]
    pub(crate) fn next_open(&self, y: u32, x0: u32, x1: u32) -> Option<(u32, u32)> {
        if self.solid.is_none() {
            return (x0 < x1).then_some((x0, x1));
        }
        let row = &self.rows[(y - self.y0) as usize];
        let open = |x: u32| row[(x - self.x0) as usize] == UNSET;
        let a = (x0..x1).find(|&x| open(x))?;
        Some((a, (a..x1).find(|&x| !open(x)).unwrap_or(x1)))
    }

    /// Sets row `y`, columns `x0..x1` to one colour, as [`Canvas::fill_with`].
    #[inline(always)]
    pub(crate) fn fill(&mut self, y: u32, x0: u32, x1: u32, colour: u32) {
        if self.solid.is_none() {
            self.span_mut(y, x0, x1).fill(colour);
        } else {
            self.fill_with(y, x0, x1, |_| colour);
        }
    }

    /// The pixels this canvas may change.
    #[inline]
    pub(crate) fn clip(&self) -> &Clip {
        &self.clip
    }

    /// What has been drawn so far, in frame coordinates. A canvas that
    /// keeps the first write is drawn whole in one go, sky included, and
    /// answers its whole rectangle (no need to track each write).
    pub(crate) fn damage(&self) -> Damage {
        if self.solid.is_some() {
            let c = self.clip;
            let all = Rect::sized(c.x0 as u32, c.y0 as u32, self.width, (c.y1 - c.y0) as u32);
            return all.into();
        }
        self.damage.clone()
    }

    /// Adds a rectangle to the damage.
    #[inline]
    pub(crate) fn touch(&mut self, x0: u32, y0: u32, x1: u32, y1: u32) {
        self.damage.add(Rect { x0, y0, x1, y1 });
    }

    /// Row `y`, columns `x0..x1` (frame coordinates, already clipped).
    #[inline]
    pub(crate) fn span_mut(&mut self, y: u32, x0: u32, x1: u32) -> &mut [u32] {
        self.touch(x0, y, x1, y + 1);
        let (a, b) = ((x0 - self.x0) as usize, (x1 - self.x0) as usize);
        &mut self.rows[(y - self.y0) as usize][a..b]
    }

    /// Adds the pixels of the fixed-point box `lo..=hi` (the pixels holding
    /// those points and all between), clipped, to the damage.
    #[inline]
    pub(crate) fn touch_box(&mut self, lo: [i64; 2], hi: [i64; 2]) {
        let c = self.clip;
        let (x0, y0) = ((lo[0] >> 8).max(c.x0), (lo[1] >> 8).max(c.y0));
        let (x1, y1) = (((hi[0] >> 8) + 1).min(c.x1), ((hi[1] >> 8) + 1).min(c.y1));
        if x0 < x1 && y0 < y1 {
            self.touch(x0 as u32, y0 as u32, x1 as u32, y1 as u32);
        }
    }

    /// The pixel at (`x`, `y`), frame coordinates inside the canvas.
    #[inline]
    pub(crate) fn get(&self, x: u32, y: u32) -> u32 {
        self.rows[(y - self.y0) as usize][(x - self.x0) as usize]
    }

    /// Sets one pixel (frame coordinates, already clipped) without adding it
    /// to the damage: the caller has covered it with `touch_box`.
    #[inline]
    pub(crate) fn plot(&mut self, x: u32, y: u32, color: u32) {
        self.rows[(y - self.y0) as usize][(x - self.x0) as usize] = color;
    }
}
