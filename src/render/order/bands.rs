//! The full frame drawn in bands of columns, shared out among threads.
//!
//! Every band runs the whole painter's order but only touches its own
//! columns, so each pixel receives the same writes in the same order as when
//! one thread draws everything: the result does not depend on the thread
//! count. Bands of columns, not rows: in the vista a strip spans much of the
//! frame's height but only a few cells of it reach a given column, so a band
//! walks and projects only those (`StripReach::cells_reaching`).

use std::sync::Mutex;

use super::walk::{Rows, draw_strips};
use crate::render::base::canvas::Canvas;
use crate::render::base::frame::Frame;
use crate::render::scene::Scene;

/// Most threads used; more bands would mostly repeat per-strip work.
const MAX_THREADS: usize = 8;
/// The narrowest band. Each band walks every strip and finds the cells
/// reaching it, so a narrower one is not worth a thread; yet the other
/// threads wait for the last band, so a wider floor keeps them waiting.
const MIN_BAND_COLUMNS: u32 = 16;

/// One band: its first column and its part of every frame row.
struct Band<'f> {
    x0: u32,
    rows: Vec<&'f mut [u32]>,
}

/// The columns of the frame no thread has taken yet, handed out left to
/// right in bands that shrink as they run out.
///
/// The work is not even across the frame (a seed's land may crowd one
/// side) and two cores are not always equally fast, so with equal bands
/// one thread sat idle at the end. Each thread takes a share of what is
/// left (guided scheduling), so the last bands are narrow and the threads
/// finish close together. A band is not free: it walks every strip again
/// and draws the cells on its edges twice, whatever its width. So each
/// takes a `threads`-th of what is left, not half that: about half as many
/// bands, for threads that still finish together.
struct Columns<'f> {
    x0: u32,
    width: u32,
    rows: Vec<&'f mut [u32]>,
    threads: u32,
}

impl<'f> Columns<'f> {
    fn new(frame: &'f mut Frame, threads: usize) -> Self {
        let width = frame.width();
        let rows = frame
            .pixels_mut()
            .chunks_exact_mut(width as usize)
            .collect();
        Columns {
            x0: 0,
            width,
            rows,
            threads: threads as u32,
        }
    }

    /// The next band: a `threads`-th of the columns left, at least
    /// [`MIN_BAND_COLUMNS`] and never leaving a narrower rest.
    fn take(&mut self) -> Option<Band<'f>> {
        let left = self.width - self.x0;
        if left == 0 {
            return None;
        }
        let mut w = (left / self.threads).max(MIN_BAND_COLUMNS);
        if left < w + MIN_BAND_COLUMNS {
            w = left;
        }
        let rows = self
            .rows
            .iter_mut()
            .map(|row| {
                let (part, rest) = std::mem::take(row).split_at_mut(w as usize);
                *row = rest;
                part
            })
            .collect();
        let band = Band { x0: self.x0, rows };
        self.x0 += w;
        Some(band)
    }
}

/// Draws the sky and every strip of `scene` into `frame`, on all cores,
/// the edges left as drawn; and runs `beside` (if given) on the first
/// thread to start while the others take the bands, returning what it
/// returned. (On a thread of its own beside a thread per core, a job
/// beside the bands had three threads share two cores.)
pub(crate) fn draw_bands<T: Send>(
    scene: &Scene,
    frame: &mut Frame,
    beside: Option<impl FnOnce() -> T + Send>,
) -> Option<T> {
    let width = frame.width();
    let threads = crate::cores::cores()
        .min(MAX_THREADS)
        .min((width / MIN_BAND_COLUMNS) as usize);
    if threads < 2 {
        let canvas = Canvas::new(frame.pixels_mut(), width, 0);
        draw(
            scene,
            &mut canvas_for(scene, canvas),
            &mut Rows::new(),
            width,
        );
        return beside.map(|job| job());
    }
    let queue = Mutex::new(Columns::new(frame, threads));
    let beside = Mutex::new(beside);
    let done = Mutex::new(None);
    let work = || {
        // The first thread to start takes the job; the others find none.
        let job = beside.lock().map_or(None, |mut b| b.take());
        if let Some(result) = job.map(|job| job())
            && let Ok(mut done) = done.lock()
        {
            *done = Some(result);
        }
        let mut rows = Rows::new();
        loop {
            // The lock is held only to take the next band.
            let next = queue.lock().map_or(None, |mut q| q.take());
            let Some(band) = next else { break };
            let canvas = Canvas::from_rows(band.rows, band.x0, 0);
            draw(scene, &mut canvas_for(scene, canvas), &mut rows, width);
        }
    };
    let work = &work;
    std::thread::scope(|s| {
        for _ in 1..threads {
            s.spawn(work);
        }
        work();
    });
    done.into_inner().ok().flatten()
}

/// `canvas` made ready for `scene`: filled faces are drawn front to back
/// keeping the first write, so the faces hidden behind nearer land are
/// skipped (the same pixels as back to front); lines (Sonar, Outline) back
/// to front.
fn canvas_for<'a>(scene: &Scene, canvas: Canvas<'a>) -> Canvas<'a> {
    if scene.style.is_filled() {
        canvas.keeping_first()
    } else {
        canvas
    }
}

/// The sky, then every strip, into `canvas`; on a canvas that keeps the
/// first write, the strips front to back and then the sky where they left
/// the canvas unwritten.
fn draw(scene: &Scene, canvas: &mut Canvas, rows: &mut Rows, frame_width: u32) {
    if !canvas.keeps_first() {
        scene.sky.paint(canvas);
    }
    draw_strips(scene, canvas, rows, 0..scene.strips(), frame_width);
    if canvas.keeps_first() {
        scene.sky.paint(canvas);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Band widths taken from a frame `width` columns wide by `threads`.
    fn widths(width: u32, threads: usize) -> Vec<u32> {
        let mut frame = Frame::new(width, 3).unwrap();
        let mut columns = Columns::new(&mut frame, threads);
        let mut next_x0 = 0;
        let mut widths = Vec::new();
        while let Some(band) = columns.take() {
            assert_eq!(band.x0, next_x0, "bands leave a gap or overlap");
            assert_eq!(band.rows.len(), 3);
            let w = band.rows[0].len() as u32;
            assert!(band.rows.iter().all(|r| r.len() as u32 == w));
            next_x0 += w;
            widths.push(w);
        }
        assert_eq!(next_x0, width, "the bands do not cover the frame");
        widths
    }

    #[test]
    fn bands_cover_the_frame_and_shrink_towards_its_end() {
        for (width, threads) in [(1920, 2), (3840, 2), (1920, 8), (152, 2), (100, 2)] {
            let w = widths(width, threads);
            assert!(
                w.windows(2)
                    .all(|p| p[1] <= p[0] || p[1] < 2 * MIN_BAND_COLUMNS)
            );
            assert!(w.iter().all(|&b| b >= MIN_BAND_COLUMNS), "{width}: {w:?}");
            assert!(*w.last().unwrap() < 2 * MIN_BAND_COLUMNS, "{width}: {w:?}");
        }
        // Each band is a `threads`-th of what is left.
        assert_eq!(widths(1920, 2)[..3], [960, 480, 240]);
        assert_eq!(widths(1920, 8)[..2], [240, 210]);
    }
}
