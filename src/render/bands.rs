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

/// One band: its first column, its width and its own pixels (row by row).
struct Band {
    x0: u32,
    width: u32,
    pixels: Vec<u32>,
}

/// Draws every strip of `scene` into `frame`, background first.
pub(crate) fn render(scene: &Scene, frame: &mut Frame) {
    let (width, height) = (frame.width(), frame.height());
    let threads = std::thread::available_parallelism()
        .map_or(1, |n| n.get())
        .min(MAX_THREADS);
    let bands = (threads * BANDS_PER_THREAD).min((width / MIN_BAND_COLUMNS).max(1) as usize);
    // Each band draws into pixels of its own: a second frame's worth of
    // memory. Without it (a huge frame under a memory limit), one band
    // draws in place.
    let spare = Vec::<u32>::new().try_reserve_exact(width as usize * height as usize);
    if threads < 2 || bands < 2 || spare.is_err() {
        let mut canvas = canvas_for(scene, frame.pixels_mut(), 0, width);
        draw(scene, &mut canvas, &mut Rows::new(), width);
        return;
    }
    let cuts: Vec<u32> = (0..=bands)
        .map(|b| (u64::from(width) * b as u64 / bands as u64) as u32)
        .collect();
    let queue: Vec<(u32, u32)> = cuts.windows(2).map(|w| (w[0], w[1] - w[0])).collect();
    let queue = Mutex::new(queue.into_iter());
    let done = Mutex::new(Vec::with_capacity(bands));
    let work = || {
        let mut rows = Rows::new();
        loop {
            // The lock is held only to take the next band.
            let next = queue.lock().map_or(None, |mut q| q.next());
            let Some((x0, w)) = next else { break };
            let mut pixels = vec![0u32; (w * height) as usize];
            draw(
                scene,
                &mut canvas_for(scene, &mut pixels, x0, w),
                &mut rows,
                width,
            );
            if let Ok(mut done) = done.lock() {
                done.push(Band {
                    x0,
                    width: w,
                    pixels,
                });
            }
        }
    };
    let work = &work;
    std::thread::scope(|s| {
        for _ in 1..threads.min(bands) {
            s.spawn(work);
        }
        work();
    });
    let done = done.into_inner().unwrap_or_default();
    for band in &done {
        copy_band(band, frame);
    }
}

/// A canvas over columns `x0..x0 + width` of whole frame rows: filled faces
/// are drawn front to back keeping the first write, so the faces hidden
/// behind nearer land are skipped (the same pixels as back to front); lines
/// (Sonar, Outline) back to front.
fn canvas_for<'a>(scene: &Scene, pixels: &'a mut [u32], x0: u32, width: u32) -> Canvas<'a> {
    if scene.style.is_filled() {
        Canvas::first_write(pixels, x0, width, 0)
    } else {
        Canvas::window(pixels, x0, width, 0)
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

/// Puts a band's pixels into its columns of `frame`.
fn copy_band(band: &Band, frame: &mut Frame) {
    let width = frame.width() as usize;
    let (x0, w) = (band.x0 as usize, band.width as usize);
    let rows = frame.pixels_mut().chunks_exact_mut(width);
    for (row, from) in rows.zip(band.pixels.chunks_exact(w)) {
        row[x0..x0 + w].copy_from_slice(from);
    }
}
