//! A complete frame's edges drawn clean, once every strip is in: the
//! skyline against the sky, then the crests of nearer land against farther
//! land. Both read the frame's geometry (the floating horizon) and its
//! pixels, never the order they were drawn in, so the full frame's bands
//! and the painter's last step end with the same pixels.

use super::crests;
use super::horizon::{Edge, Horizon};
use super::skyline::{self, Skyline};
use crate::render::base::canvas::Canvas;
use crate::render::base::damage::Damage;
use crate::render::base::frame::Frame;
use crate::render::scene::Scene;
use crate::render::shade::sky::SkySeen;
use crate::threads::both;

/// Columns counted together when the crests are shared out.
const BLOCK: u32 = 16;

/// Mixes the pixels along the skyline and the crests of `frame`, which
/// holds every strip of `scene`; `horizon` is the scene's swept across the
/// frame's width. Returns the pixels it changed.
///
/// Both are mixed column by column (a column's crests after its skyline,
/// each reading only its own column's pixels), so two threads share the
/// work, each a part of the columns holding half of the crests: each finds
/// its part's skyline, and once the skyline's runs are known across the
/// width, mixes its part. The crests' pixels are far apart in memory and
/// their mixing waits on it; the crests crowd where the land does, so
/// halves of the width would leave one thread well behind the other.
pub(crate) fn clean_edges(scene: &Scene, horizon: &Horizon, frame: &mut Frame) -> Damage {
    let (width, height) = (frame.width(), frame.height());
    let at = crests_middle(horizon, width);
    // Each part's sky, as seen along its skyline, is kept for its mixing.
    let read = |xs: std::ops::Range<u32>, frame: &Frame| {
        let mut seen = SkySeen::default();
        let exact: Vec<Option<Edge>> = xs.clone().map(|x| horizon.skyline(scene, x)).collect();
        let tops = skyline::land_tops(frame, &scene.sky, &exact, xs.start as usize, &mut seen);
        (exact, tops, seen)
    };
    let ((mut exact, mut tops, mut left_seen), (right_exact, right_tops, mut right_seen)) = {
        let frame = &*frame;
        both(|| read(0..at, frame), || read(at..width, frame))
    };
    exact.extend(right_exact);
    tops.extend(right_tops);
    let skyline = Skyline::new(tops, &exact, height);
    let mut parts = split_at(frame, at);
    let [left, right] = &mut parts;
    let mix = |canvas: &mut Canvas, seen| {
        skyline.mix(canvas, &scene.sky, seen);
        crests::smooth(canvas, scene, horizon, skyline.tops());
    };
    both(|| mix(left, &mut left_seen), || mix(right, &mut right_seen));
    let mut damage = Damage::default();
    for r in parts
        .iter()
        .flat_map(|c| c.damage().rects().collect::<Vec<_>>())
    {
        damage.add(r);
    }
    damage
}

/// A column that splits `horizon`'s crests about in half: the start of
/// the block of [`BLOCK`] columns where half of them are passed.
fn crests_middle(horizon: &Horizon, width: u32) -> u32 {
    let mut counts = vec![0usize; width.div_ceil(BLOCK) as usize];
    for crest in horizon.crests() {
        if let Some(n) = counts.get_mut((crest.x() / BLOCK) as usize) {
            *n += 1;
        }
    }
    let half = counts.iter().sum::<usize>() / 2;
    let mut passed = 0;
    for (block, n) in counts.iter().enumerate() {
        passed += n;
        if passed > half {
            return block as u32 * BLOCK;
        }
    }
    width / 2
}

/// `frame`'s columns left of `at` and from it on as canvases of their own.
fn split_at(frame: &mut Frame, at: u32) -> [Canvas<'_>; 2] {
    let width = frame.width().max(1) as usize;
    let at = (at as usize).min(width);
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
