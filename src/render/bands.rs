//! The full frame drawn in horizontal bands, one thread each.
//!
//! Every band runs the whole painter's order but only touches its own rows,
//! so each pixel receives the same writes in the same order as when one
//! thread draws everything: the result does not depend on the thread count.

use super::canvas::Canvas;
use super::frame::Frame;
use super::painter::{Rows, background, draw_strips};
use super::scene::Scene;

/// Most threads used; more bands would mostly repeat per-strip work.
const MAX_BANDS: usize = 8;
/// Bands thinner than this are not worth a thread.
const MIN_BAND_ROWS: u32 = 16;

/// Draws every strip of `scene` into `frame`, background first.
pub(crate) fn render(scene: &Scene, frame: &mut Frame) {
    let (width, height) = (frame.width(), frame.height());
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
    let bands = threads
        .min(MAX_BANDS)
        .min((height / MIN_BAND_ROWS).max(1) as usize);
    let cuts = cut_rows(scene, height, bands);
    let sky = background(scene);
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
    let draw = |(band, y0): (&mut [u32], u32)| {
        let mut canvas = Canvas::new(band, width, y0);
        canvas.clear(sky);
        draw_strips(scene, &mut canvas, &mut Rows::new(), strips.clone());
    };
    let draw = &draw;
    if pieces.len() == 1 {
        pieces.into_iter().for_each(draw);
        return;
    }
    std::thread::scope(|s| {
        let mut pieces = pieces.into_iter();
        let first = pieces.next();
        for piece in pieces {
            s.spawn(move || draw(piece));
        }
        first.into_iter().for_each(draw);
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
