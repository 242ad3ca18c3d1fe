//! Whether a picture and its reference line up: the shift of the reference
//! that best matches the picture, found by brute force.
//!
//! The reference is `k` times larger, so shifting where its boxes start by
//! one of its pixels moves the averaged picture by exactly 1/k of a pixel:
//! no interpolation. Both are compared as luma averaged down once more in
//! 2 x 2 boxes, which weakens the aliasing the picture itself carries; a
//! parabola through the best shift and its neighbours refines it.

use super::image::{Image, channels, luma};
use crate::render::Frame;

/// The best match found.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Shift {
    /// How far right the reference matches best, in the picture's pixels.
    pub dx: f64,
    /// How far down the reference matches best, in the picture's pixels.
    pub dy: f64,
    /// Mean squared luma error at no shift.
    pub mse_at_zero: f64,
    /// Mean squared luma error at the best whole shift (in reference pixels).
    pub mse_best: f64,
}

/// The shift, within `reach` reference pixels each way, of the boxes of
/// `reference` (the picture's pixel (x, y) averages its `k` x `k` box from
/// `origin + k (x, y)`) that best matches `picture`.
pub fn best_shift(
    picture: &Image,
    reference: &Frame,
    k: usize,
    origin: (i64, i64),
    reach: i64,
) -> Shift {
    let (w, h) = (picture.width, picture.height);
    let target = halved(&picture.luma(), w, h);
    let side = (2 * reach + 1) as usize;
    let mut mse = vec![f64::INFINITY; side * side];
    let (fw, fh) = (reference.width() as i64, reference.height() as i64);
    let lumas: Vec<f32> = reference
        .pixels()
        .iter()
        .map(|&p| luma(channels(p)))
        .collect();
    for (a, i) in (-reach..=reach).enumerate() {
        // Each reference row summed across the boxes of this shift.
        let xs: Vec<usize> = (0..(w * k) as i64)
            .map(|t| (origin.0 + i + t).clamp(0, fw - 1) as usize)
            .collect();
        let across: Vec<f32> = (0..fh as usize)
            .flat_map(|r| {
                let row = &lumas[r * fw as usize..][..fw as usize];
                let xs = &xs;
                (0..w).map(move |x| xs[k * x..k * x + k].iter().map(|&c| row[c]).sum::<f32>())
            })
            .collect();
        for (b, j) in (-reach..=reach).enumerate() {
            let mut down = vec![0.0f32; w * h];
            for y in 0..h {
                for t in 0..k as i64 {
                    let r = (origin.1 + j + (k * y) as i64 + t).clamp(0, fh - 1) as usize;
                    let src = &across[r * w..][..w];
                    for (d, s) in down[y * w..][..w].iter_mut().zip(src) {
                        *d += s;
                    }
                }
            }
            let scale = 1.0 / (k * k) as f32;
            down.iter_mut().for_each(|v| *v *= scale);
            mse[b * side + a] = interior_mse(&halved(&down, w, h), &target, w / 2, h / 2);
        }
    }
    let best = (0..mse.len())
        .min_by(|&p, &q| mse[p].total_cmp(&mse[q]))
        .unwrap_or(0);
    let (a, b) = (best % side, best / side);
    let along = |at: &dyn Fn(usize) -> f64, n: usize| refine(at, n, side);
    let dx = along(&|t| mse[b * side + t], a);
    let dy = along(&|t| mse[t * side + a], b);
    Shift {
        dx: (dx - reach as f64) / k as f64,
        dy: (dy - reach as f64) / k as f64,
        mse_at_zero: mse[reach as usize * side + reach as usize],
        mse_best: mse[best],
    }
}

/// The minimum of a parabola through sample `n` and its neighbours (`n`
/// itself at the ends of the range).
fn refine(at: &dyn Fn(usize) -> f64, n: usize, side: usize) -> f64 {
    if n == 0 || n + 1 >= side {
        return n as f64;
    }
    let (l, c, r) = (at(n - 1), at(n), at(n + 1));
    let curve = l - 2.0 * c + r;
    if curve <= 0.0 {
        return n as f64;
    }
    n as f64 + 0.5 * (l - r) / curve
}

/// `v` (`w` x `h`) averaged in 2 x 2 boxes.
fn halved(v: &[f32], w: usize, h: usize) -> Vec<f32> {
    let (hw, hh) = (w / 2, h / 2);
    let mut out = Vec::with_capacity(hw * hh);
    for y in 0..hh {
        for x in 0..hw {
            let i = 2 * y * w + 2 * x;
            out.push(0.25 * (v[i] + v[i + 1] + v[i + w] + v[i + w + 1]));
        }
    }
    out
}

/// Mean squared difference away from a 2-pixel border.
fn interior_mse(a: &[f32], b: &[f32], w: usize, h: usize) -> f64 {
    let (mut sum, mut n) = (0.0f64, 0u64);
    for y in 2..h.saturating_sub(2) {
        for x in 2..w.saturating_sub(2) {
            let d = f64::from(a[y * w + x] - b[y * w + x]);
            sum += d * d;
            n += 1;
        }
    }
    sum / n.max(1) as f64
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::Size;

    /// A smooth, structured picture `w` x `h`, sampled at (x + ox, y + oy) / k.
    fn drawn(
        Size {
            width: w,
            height: h,
        }: Size,
        k: f32,
        (ox, oy): (f32, f32),
    ) -> Frame {
        let mut f = Frame::new(w, h).unwrap();
        for (i, p) in f.pixels_mut().iter_mut().enumerate() {
            let (x, y) = (
                ((i as u32 % w) as f32 + ox) / k,
                ((i as u32 / w) as f32 + oy) / k,
            );
            let v =
                128.0 + 60.0 * (x * 0.21).sin() * (y * 0.17).cos() + 40.0 * ((x + y) * 0.05).sin();
            let v = v.clamp(0.0, 255.0) as u32;
            *p = v << 16 | v << 8 | v;
        }
        f
    }

    #[test]
    fn a_reference_drawn_shifted_is_found_shifted() {
        let k = 4;
        let picture = Image::box_down(
            &drawn(Size::new(256, 192), 4.0, (0.0, 0.0)),
            k,
            (0, 0),
            64,
            48,
        );
        // The reference drawn half a picture pixel further right and a
        // quarter further down: its content matches from boxes 2 and 1
        // reference pixels back.
        let shifted = drawn(Size::new(256, 192), 4.0, (2.0, 1.0));
        let s = best_shift(&picture, &shifted, k, (0, 0), 4);
        assert!(
            (s.dx + 0.5).abs() < 0.06 && (s.dy + 0.25).abs() < 0.06,
            "{s:?}"
        );
        let same = best_shift(
            &picture,
            &drawn(Size::new(256, 192), 4.0, (0.0, 0.0)),
            k,
            (0, 0),
            4,
        );
        assert!(same.dx.abs() < 0.02 && same.dy.abs() < 0.02, "{same:?}");
        assert_eq!(same.mse_at_zero, same.mse_best);
        assert!(s.mse_at_zero > s.mse_best);
    }
}
