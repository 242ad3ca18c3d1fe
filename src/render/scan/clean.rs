//! A complete frame's edges drawn clean, once every strip is in: the
//! skyline against the sky, then the crests of nearer land against farther
//! land. Both read the frame's geometry (the floating horizon) and its
//! pixels, never the order they were drawn in, so the full frame's bands
//! and the painter's last step end with the same pixels.

use super::horizon::{Edge, Horizon};
use super::{crests, skyline};
use crate::render::damage::Damage;
use crate::render::frame::Frame;
use crate::render::scene::Scene;

/// Mixes the pixels along the skyline and the crests of `frame`, which
/// holds every strip of `scene`; `horizon` is the scene's swept across the
/// frame's width. Returns the pixels it changed.
pub(crate) fn clean_edges(scene: &Scene, horizon: &Horizon, frame: &mut Frame) -> Damage {
    let exact: Vec<Option<Edge>> = (0..frame.width())
        .map(|x| horizon.skyline(scene, x))
        .collect();
    let (mut damage, tops) = skyline::smooth(frame, &scene.sky, &exact);
    crests::smooth(frame, scene, horizon, &tops, &mut damage);
    damage
}
