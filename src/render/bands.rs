//! The full frame drawn in bands of columns, shared out among threads.
//!
//! Every band runs the whole painter's order but only touches its own
//! columns, so each pixel receives the same writes in the same order as when
//! one thread draws everything: the result does not depend on the thread
//! count. Bands of columns, not rows: in the vista a strip spans much of the
//! frame's height but only a few cells of it reach a given column, so a band
//! walks and projects only those (`Scene::cells_reaching`).

use std::sync::Mutex;

use super::canvas::Canvas;
use super::frame::Frame;
use super::scene::Scene;
use super::walk::{Rows, draw_strips};

/// Most threads used; more bands would mostly repeat per-strip work.
const MAX_THREADS: usize = 8;
/// Bands per thread: the work is not even across the frame (land in the
/// middle, a plain margin at a side in the classic views), so there are
/// more bands than threads and each thread takes the next band left.
const BANDS_PER_THREAD: usize = 2;
/// Bands narrower than this are not worth a thread.
const MIN_BAND_COLUMNS: u32 = 64;

/// One band: its first column and its part of every frame row.
struct Band<'f> {
    x0: u32,
    rows: Vec<&'f mut [u32]>,
}

/// Draws the sky and every strip of `scene` into `frame`, on all cores.
pub(crate) fn render(scene: &Scene, frame: &mut Frame) {
    let width = frame.width();
    let threads = std::thread::available_parallelism()
        .map_or(1, |n| n.get())
        .min(MAX_THREADS);
    let bands = (threads * BANDS_PER_THREAD).min((width / MIN_BAND_COLUMNS).max(1) as usize);
    if threads < 2 || bands < 2 {
        let canvas = Canvas::new(frame.pixels_mut(), width, 0);
        draw(
            scene,
            &mut canvas_for(scene, canvas),
            &mut Rows::new(),
            width,
        );
        return;
    }
    let cuts: Vec<u32> = (0..=bands)
        .map(|b| (u64::from(width) * b as u64 / bands as u64) as u32)
        .collect();
    let queue = Mutex::new(split(frame, &cuts).into_iter());
    let work = || {
        let mut rows = Rows::new();
        loop {
            // The lock is held only to take the next band.
            let next = queue.lock().map_or(None, |mut q| q.next());
            let Some(band) = next else { break };
            let canvas = Canvas::from_rows(band.rows, band.x0, 0);
            draw(scene, &mut canvas_for(scene, canvas), &mut rows, width);
        }
    };
    let work = &work;
    std::thread::scope(|s| {
        for _ in 1..threads.min(bands) {
            s.spawn(work);
        }
        work();
    });
}

/// The frame cut into bands of columns at `cuts` (first 0, last the width):
/// each band holds its part of every row, so each thread draws straight
/// into the frame and no two touch the same pixel.
fn split<'f>(frame: &'f mut Frame, cuts: &[u32]) -> Vec<Band<'f>> {
    let width = frame.width() as usize;
    let mut bands: Vec<Band> = cuts[..cuts.len() - 1]
        .iter()
        .map(|&x0| Band {
            x0,
            rows: Vec::new(),
        })
        .collect();
    for mut row in frame.pixels_mut().chunks_exact_mut(width) {
        for (band, w) in bands.iter_mut().zip(cuts.windows(2)) {
            let (part, rest) = row.split_at_mut((w[1] - w[0]) as usize);
            band.rows.push(part);
            row = rest;
        }
    }
    bands
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
