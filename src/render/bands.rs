//! The full frame drawn in horizontal bands, shared out among threads.
//!
//! Every band runs the whole painter's order but only touches its own rows,
//! so each pixel receives the same writes in the same order as when one
//! thread draws everything: the result does not depend on the thread count.

use std::sync::Mutex;

use super::canvas::Canvas;
use super::frame::Frame;
use super::painter::{Rows, draw_strips};
use super::scene::Scene;

/// Most threads used; more bands would mostly repeat per-strip work.
const MAX_THREADS: usize = 8;
/// Bands per thread. The work is far from even down the frame (a dense
/// mountain above, flat sea below), so the frame is cut into several bands
/// per thread and each thread takes the next band left when it is done.
const BANDS_PER_THREAD: usize = 2;
/// Bands thinner than this are not worth a thread.
const MIN_BAND_ROWS: u32 = 16;

/// Draws every strip of `scene` into `frame`, background first.
pub(crate) fn render(scene: &Scene, frame: &mut Frame) {
    let (width, height) = (frame.width(), frame.height());
    let threads = std::thread::available_parallelism()
        .map_or(1, |n| n.get())
        .min(MAX_THREADS);
    let bands = (threads * BANDS_PER_THREAD).min((height / MIN_BAND_ROWS).max(1) as usize);
    let bands = if threads < 2 { 1 } else { bands };
    let cuts = cut_rows(scene, height, bands);
    let strips = 0..scene.cells();
    let mut rest = frame.pixels_mut();
    let mut pieces = Vec::with_capacity(cuts.len() + 1);
    let mut y0 = 0;
    for &y1 in cuts.iter().chain(std::iter::once(&height)) {
        let (band, tail) = rest.split_at_mut(((y1 - y0) * width) as usize);
        pieces.push((band, y0));
        rest = tail;
        y0 = y1;
    }
    let draw = |(band, y0): (&mut [u32], u32), rows: &mut Rows| {
        let mut canvas = Canvas::new(band, width, y0);
        scene.sky.paint(&mut canvas);
        draw_strips(scene, &mut canvas, rows, strips.clone());
    };
    let workers = threads.min(pieces.len());
    let queue = Mutex::new(pieces.into_iter());
    let work = || {
        let mut rows = Rows::new();
        loop {
            // The lock is held only to take the next band.
            let next = queue.lock().map_or(None, |mut q| q.next());
            match next {
                Some(piece) => draw(piece, &mut rows),
                None => break,
            }
        }
    };
    let work = &work;
    if workers < 2 {
        work();
        return;
    }
    std::thread::scope(|s| {
        for _ in 1..workers {
            s.spawn(work);
        }
        work();
    });
}

/// Rows where the bands meet (ascending, each in `1..height`), chosen so each
/// band holds about as many strips: the strips' middles split into quantiles.
fn cut_rows(scene: &Scene, height: u32, bands: usize) -> Vec<u32> {
    if bands < 2 {
        return Vec::new();
    }
    let mut middles: Vec<i64> = (0..scene.cells())
        .map(|s| {
            let (lo, hi) = scene.strip_rows(s);
            lo / 2 + hi / 2
        })
        .collect();
    middles.sort_unstable();
    let mut cuts: Vec<u32> = (1..bands)
        .map(|b| middles[b * middles.len() / bands].clamp(1, height as i64 - 1) as u32)
        .collect();
    cuts.dedup();
    cuts
}
