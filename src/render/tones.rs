//! What each grid point's light and air are, worked out once per scene.
//!
//! A full frame is drawn in horizontal bands, and every band projects each
//! grid row its strips touch; in the vista a row spans most of the frame's
//! height, so it was projected once per band. The sky's share (a bilinear
//! sample) and the haze (a camera depth and an `exp`) were a third of a
//! 1080p frame's time: here they are computed once per point, rows shared
//! out among the cores, and a row's projection only looks them up.

use super::haze::Haze;
use super::scene::finite;
use super::skylight::SkyLight;
use super::view::View;
use crate::terrain::Heightfield;

/// Rows fewer than this are not worth a second thread.
const MIN_ROWS_PER_THREAD: usize = 64;

/// Per grid point (row-major, like the field): the sky it sees and its haze.
pub(crate) struct Tones {
    /// Share of the sky seen (0..=1); empty when the scene has no sky light.
    sky: Vec<f32>,
    /// Haze in 1/256ths; empty when the scene has no haze.
    haze: Vec<u16>,
}

impl Tones {
    /// Works out the tones of every point of `field` seen through `view`.
    pub(crate) fn new(
        field: &Heightfield,
        view: &View,
        skylight: Option<&SkyLight>,
        haze: Option<&Haze>,
    ) -> Self {
        let n = field.size();
        let mut sky = vec![0.0f32; if skylight.is_some() { n * n } else { 0 }];
        let mut mist = vec![0u16; if haze.is_some() { n * n } else { 0 }];
        let fill_rows = |y0: usize, sky: &mut [f32], mist: &mut [u16]| {
            if let Some(s) = skylight {
                for (dy, row) in sky.chunks_mut(n).enumerate() {
                    s.fill_row(y0 + dy, row);
                }
            }
            if let Some(h) = haze {
                for (dy, row) in mist.chunks_mut(n).enumerate() {
                    let y = y0 + dy;
                    for ((x, out), &z) in row.iter_mut().enumerate().zip(field.row(y)) {
                        let z = finite(z).max(0.0);
                        *out = h.amount(view.distance(x as f32, y as f32, z)) as u16;
                    }
                }
            }
        };
        let threads = std::thread::available_parallelism()
            .map_or(1, |t| t.get())
            .min(n.div_ceil(MIN_ROWS_PER_THREAD))
            .max(1);
        let rows = n.div_ceil(threads);
        let (mut sky_rest, mut mist_rest) = (&mut sky[..], &mut mist[..]);
        std::thread::scope(|s| {
            for t in 0..threads {
                let sky_part = take_front(&mut sky_rest, rows * n);
                let mist_part = take_front(&mut mist_rest, rows * n);
                let fill_rows = &fill_rows;
                s.spawn(move || fill_rows(t * rows, sky_part, mist_part));
            }
        });
        Tones { sky, haze: mist }
    }

    /// Share of the sky grid point `i` (row-major) sees; 1 without sky light.
    #[inline]
    pub(crate) fn sky(&self, i: usize) -> f32 {
        self.sky.get(i).copied().unwrap_or(1.0)
    }

    /// Haze of grid point `i` (row-major) in 1/256ths; 0 without haze.
    #[inline]
    pub(crate) fn haze(&self, i: usize) -> u32 {
        self.haze.get(i).map_or(0, |&h| u32::from(h))
    }
}

/// Cuts the first `len` items (or all that are left) off `rest`.
fn take_front<'a, T>(rest: &mut &'a mut [T], len: usize) -> &'a mut [T] {
    let all = std::mem::take(rest);
    let (front, back) = all.split_at_mut(len.min(all.len()));
    *rest = back;
    front
}
