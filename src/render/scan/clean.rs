//! A complete frame's edges drawn clean, once every strip is in: the
//! skyline against the sky, then the crests of nearer land against farther
//! land. Both read the frame's geometry (the floating horizon) and its
//! pixels, never the order they were drawn in, so the full frame's bands
//! and the painter's last step end with the same pixels.

use super::canvas::Canvas;
use super::horizon::{Edge, Horizon};
use super::{crests, skyline};
use crate::render::damage::Damage;
use crate::render::frame::Frame;
use crate::render::scene::{Scene, joined};

/// Mixes the pixels along the skyline and the crests of `frame`, which
/// holds every strip of `scene`; `horizon` is the scene's swept across the
/// frame's width. Returns the pixels it changed.
pub(crate) fn clean_edges(scene: &Scene, horizon: &Horizon, frame: &mut Frame) -> Damage {
    let exact: Vec<Option<Edge>> = (0..frame.width())
        .map(|x| horizon.skyline(scene, x))
        .collect();
    let (mut damage, tops) = skyline::smooth(frame, &scene.sky, &exact);
    // The crests' pixels are far apart in memory and their mixing waits on
    // it: two threads, a half of the columns each, take half the time.
    let [mut left, mut right] = halves(frame);
    std::thread::scope(|s| {
        let theirs = s.spawn(|| crests::smooth(&mut right, scene, horizon, &tops));
        crests::smooth(&mut left, scene, horizon, &tops);
        joined(theirs);
    });
    for r in [left, right]
        .iter()
        .flat_map(|c| c.damage().rects().collect::<Vec<_>>())
    {
        damage.add(r);
    }
    damage
}

/// The left and the right half of `frame`'s columns as canvases of their own.
fn halves(frame: &mut Frame) -> [Canvas<'_>; 2] {
    let at = (frame.width() / 2) as usize;
    let width = frame.width().max(1) as usize;
    let (mut left, mut right) = (Vec::new(), Vec::new());
    for row in frame.pixels_mut().chunks_exact_mut(width) {
        let (l, r) = row.split_at_mut(at);
        left.push(l);
        right.push(r);
    }
    [
        Canvas::from_rows(left, 0, 0),
        Canvas::from_rows(right, at as u32, 0),
    ]
}
