//! Crests drawn clean: where nearer land hides farther land (or water),
//! each pixel the near land's edge cuts is mixed from the two by how much
//! of it lies below the edge, so a ridge in front of another is a smooth
//! line, not a staircase, and a peak narrower than a pixel is a faint
//! spike, not a bright one.
//!
//! The edge is the near land's top as the mesh's rows draw it (the
//! floating horizon's crests); the two colours are the frame's own, read
//! just above and just below the edge, so light and haze stay as drawn.

use super::horizon::{Crest, Horizon, SAMPLES};
use crate::render::base::canvas::Canvas;
use crate::render::base::colour::blend_packed;
use crate::render::scene::Scene;

/// Most rows one crest mixes in a column: the rest of a sliver's height
/// stays as drawn.
const MAX_ROWS: f32 = 12.0;
/// Colours closer than this in every channel show no step worth mixing.
const ALIKE: u32 = 2;

/// Mixes the pixels along every crest of `horizon` in the columns of a
/// complete frame of `scene` that `canvas` holds, below the columns'
/// skyline `sky_tops` (first rows of land, which the skyline's own pass
/// mixes); what it changed is the canvas's damage.
pub(crate) fn smooth(canvas: &mut Canvas, scene: &Scene, horizon: &Horizon, sky_tops: &[u32]) {
    let clip = *canvas.clip();
    for crest in horizon.crests() {
        let x = crest.x();
        if !(clip.x0..clip.x1).contains(&i64::from(x)) {
            continue;
        }
        let Some(&sky_top) = sky_tops.get(x as usize) else {
            continue;
        };
        if let Some((y0, y1)) = mix_crest(canvas, scene, crest, sky_top) {
            canvas.touch(x, y0, x + 1, y1);
        }
    }
}

/// Mixes one crest's column; returns the rows changed, if any.
fn mix_crest(frame: &mut Canvas, scene: &Scene, crest: &Crest, sky_top: u32) -> Option<(u32, u32)> {
    let (x, top) = (crest.x(), crest.top());
    // Rows clear of the skyline, with a pixel of far land above the edge
    // and one of near land below it inside the frame.
    if !(top > sky_top + 1 && i64::from(top) < frame.clip().y1) {
        return None;
    }
    let (far, near) = (frame.get(x, top - 1), frame.get(x, top));
    if alike(far, near) {
        return None;
    }
    let edge = crest.edge(scene)?;
    mix_rows(frame, x, top, &edge, [far, near], sky_top + 2)
}

/// Mixes the rows of column `x` that the edge at heights `edge` cuts,
/// from row `first_allowed` down; `top` is the first row the near land
/// covers at the centre, and `[far, near]` the colours above and below it
/// there.
fn mix_rows(
    frame: &mut Canvas,
    x: u32,
    top: u32,
    edge: &[f32; SAMPLES],
    [far, near]: [u32; 2],
    first_allowed: u32,
) -> Option<(u32, u32)> {
    let lo = edge.iter().copied().fold(f32::INFINITY, f32::min);
    let hi = edge.iter().copied().fold(f32::NEG_INFINITY, f32::max);
    let first = (lo.floor().max(first_allowed as f32) as u32).min(top);
    let end = ((hi.min(lo + MAX_ROWS).ceil().max(0.0)) as u32)
        .max(top)
        .min(frame.clip().y1 as u32);
    let mut changed: Option<(u32, u32)> = None;
    for y in first..end {
        let cover: f32 = edge
            .iter()
            .map(|&e| (y as f32 + 1.0 - e).clamp(0.0, 1.0))
            .sum::<f32>()
            / edge.len() as f32;
        let own = frame.get(x, y);
        let (above, below) = if y < top { (own, near) } else { (far, own) };
        let mixed = blend_packed(above, below, (cover * 256.0 + 0.5) as u32);
        if mixed != own {
            frame.plot(x, y, mixed);
            let start = changed.map_or(y, |c| c.0);
            changed = Some((start, y + 1));
        }
    }
    changed
}

/// Whether two packed colours differ by at most [`ALIKE`] in every channel.
fn alike(a: u32, b: u32) -> bool {
    [0, 8, 16].iter().all(|&s| {
        let (p, q) = ((a >> s) & 0xff, (b >> s) & 0xff);
        p.abs_diff(q) <= ALIKE
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::base::frame::Frame;

    const FAR: u32 = 0x0080_8080;
    const NEAR: u32 = 0x0000_4000;

    /// A column of far land above row `top` and near land from it down.
    fn column(top: u32, height: u32) -> Frame {
        let mut f = Frame::new(1, height).unwrap();
        for y in 0..height {
            f.set(0, y, if y < top { FAR } else { NEAR });
        }
        f
    }

    #[test]
    fn a_pixel_half_under_the_edge_is_half_near_half_far() {
        let mut f = column(10, 20);
        let mut cols = Canvas::new(f.pixels_mut(), 1, 0);
        let rows = mix_rows(&mut cols, 0, 10, &[9.5; 4], [FAR, NEAR], 0);
        assert_eq!(rows, Some((9, 10)));
        assert_eq!(f.get(0, 9), blend_packed(FAR, NEAR, 128));
        assert_eq!((f.get(0, 8), f.get(0, 10)), (FAR, NEAR));
    }

    #[test]
    fn a_spike_a_quarter_pixel_wide_is_a_quarter_strong() {
        // Near land up to row 14, with a spike to row 6 at one sample only.
        let mut f = column(6, 20);
        let edge = [14.0, 14.0, 6.0, 14.0];
        let mut cols = Canvas::new(f.pixels_mut(), 1, 0);
        mix_rows(&mut cols, 0, 6, &edge, [FAR, NEAR], 0);
        for y in 6..14 {
            assert_eq!(f.get(0, y), blend_packed(FAR, NEAR, 64), "row {y}");
        }
        assert_eq!(f.get(0, 14), NEAR);
        assert_eq!(f.get(0, 5), FAR);
    }

    #[test]
    fn alike_colours_are_within_two_in_every_channel() {
        assert!(alike(0x0010_2030, 0x0012_1f30));
        assert!(!alike(0x0010_2030, 0x0010_2034));
    }
}
