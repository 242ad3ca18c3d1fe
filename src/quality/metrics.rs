//! Error between a picture and its reference: PSNR and SSIM.

use super::image::Image;

/// Peak value of a channel.
const PEAK: f64 = 255.0;
/// SSIM's Gaussian window: 11 x 11, sigma 1.5 (Wang, Bovik, Sheikh and
/// Simoncelli, 2004), and its stabilising constants for 8-bit values.
const SSIM_RADIUS: usize = 5;
const SSIM_SIGMA: f64 = 1.5;
const C1: f64 = (0.01 * PEAK) * (0.01 * PEAK);
const C2: f64 = (0.03 * PEAK) * (0.03 * PEAK);

/// Summed squared error over the three channels and the number of channel
/// values it covers, over the pixels `keep` accepts (by index).
pub fn squared_error(a: &Image, b: &Image, keep: impl Fn(usize) -> bool) -> (f64, u64) {
    assert_eq!(
        (a.width, a.height),
        (b.width, b.height),
        "pictures differ in size"
    );
    let mut sum = 0.0f64;
    let mut n = 0u64;
    for (i, (p, q)) in a.rgb.iter().zip(&b.rgb).enumerate() {
        if keep(i) {
            sum += (0..3).map(|c| f64::from(p[c] - q[c]).powi(2)).sum::<f64>();
            n += 3;
        }
    }
    (sum, n)
}

/// PSNR in dB for a mean squared error (infinite for none, NaN for no values).
pub fn psnr_of_mse(mse: f64) -> f64 {
    10.0 * (PEAK * PEAK / mse).log10()
}

/// PSNR in dB of `a` against `b` over all three channels of every pixel.
pub fn psnr(a: &Image, b: &Image) -> f64 {
    let (sum, n) = squared_error(a, b, |_| true);
    psnr_of_mse(sum / n as f64)
}

/// Share of pixels with some channel more than `levels` away from the reference.
pub fn share_off_by(a: &Image, b: &Image, levels: f32) -> f64 {
    let off = (a.rgb.iter().zip(&b.rgb))
        .filter(|(p, q)| (0..3).any(|c| (p[c] - q[c]).abs() > levels))
        .count();
    off as f64 / a.rgb.len().max(1) as f64
}

/// Mean SSIM of luma pictures `a` and `b` (`width` wide, 0..=255), with an
/// 11 x 11 Gaussian window (sigma 1.5), K1 = 0.01, K2 = 0.03, at full
/// resolution, over the pixels whose whole window lies in the picture.
pub fn ssim(a: &[f32], b: &[f32], width: usize) -> f64 {
    assert_eq!(a.len(), b.len(), "pictures differ in size");
    let height = a.len() / width.max(1);
    let weights = gaussian();
    let blur = |f: &dyn Fn(usize) -> f64| filtered(f, width, height, &weights);
    let (a64, b64) = (|i: usize| f64::from(a[i]), |i: usize| f64::from(b[i]));
    let mu_a = blur(&a64);
    let mu_b = blur(&b64);
    let aa = blur(&|i| a64(i) * a64(i));
    let bb = blur(&|i| b64(i) * b64(i));
    let ab = blur(&|i| a64(i) * b64(i));
    let mut sum = 0.0;
    for i in 0..mu_a.len() {
        let (ma, mb) = (mu_a[i], mu_b[i]);
        let (va, vb, cov) = (aa[i] - ma * ma, bb[i] - mb * mb, ab[i] - ma * mb);
        sum +=
            ((2.0 * ma * mb + C1) * (2.0 * cov + C2)) / ((ma * ma + mb * mb + C1) * (va + vb + C2));
    }
    sum / mu_a.len().max(1) as f64
}

/// The normalised 1-D Gaussian of SSIM's window.
fn gaussian() -> Vec<f64> {
    let r = SSIM_RADIUS as f64;
    let w: Vec<f64> = (0..=2 * SSIM_RADIUS)
        .map(|i| (-(i as f64 - r).powi(2) / (2.0 * SSIM_SIGMA * SSIM_SIGMA)).exp())
        .collect();
    let total: f64 = w.iter().sum();
    w.into_iter().map(|v| v / total).collect()
}

/// `f` (by pixel index) filtered with the separable window `w`, at each
/// pixel whose whole window lies inside: (width - 10) x (height - 10) values.
fn filtered(f: &dyn Fn(usize) -> f64, width: usize, height: usize, w: &[f64]) -> Vec<f64> {
    let n = w.len();
    if width < n || height < n {
        return Vec::new();
    }
    let ow = width - n + 1;
    let mut across = vec![0.0; ow * height];
    for y in 0..height {
        for x in 0..ow {
            across[y * ow + x] = (0..n).map(|k| w[k] * f(y * width + x + k)).sum();
        }
    }
    let oh = height - n + 1;
    let mut out = vec![0.0; ow * oh];
    for y in 0..oh {
        for x in 0..ow {
            out[y * ow + x] = (0..n).map(|k| w[k] * across[(y + k) * ow + x]).sum();
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A picture with some structure: a gradient and stripes.
    fn scene(width: usize, height: usize) -> Image {
        let rgb = (0..width * height)
            .map(|i| {
                let (x, y) = ((i % width) as f32, (i / width) as f32);
                [
                    x * 2.0,
                    100.0 + 50.0 * (y * 0.3).sin(),
                    ((x + y) % 7.0) * 30.0,
                ]
            })
            .collect();
        Image { width, height, rgb }
    }

    #[test]
    fn identical_pictures_score_infinity_and_one() {
        let a = scene(64, 48);
        assert_eq!(psnr(&a, &a), f64::INFINITY);
        let l = a.luma();
        assert!((ssim(&l, &l, 64) - 1.0).abs() < 1e-12);
        assert_eq!(share_off_by(&a, &a, 0.0), 0.0);
    }

    #[test]
    fn a_known_error_gives_its_psnr() {
        let a = scene(64, 48);
        // +-4 on every channel, alternating: MSE 16, PSNR 10 log10(255^2 / 16).
        let mut b = a.clone();
        for (i, p) in b.rgb.iter_mut().enumerate() {
            let d = if i % 2 == 0 { 4.0 } else { -4.0 };
            *p = p.map(|v| v + d);
        }
        let expected = 10.0 * (255.0f64 * 255.0 / 16.0).log10();
        assert!((psnr(&a, &b) - expected).abs() < 1e-4, "{}", psnr(&a, &b));
        assert_eq!(share_off_by(&a, &b, 3.5), 1.0);
        assert_eq!(share_off_by(&a, &b, 4.01), 0.0);
    }

    #[test]
    fn ssim_falls_with_noise_and_sees_structure_not_brightness_alone() {
        let a = scene(64, 48).luma();
        // Pseudo-random noise of +-20.
        let noisy: Vec<f32> = (a.iter().enumerate())
            .map(|(i, &v)| {
                v + ((i as u32).wrapping_mul(2_654_435_761) >> 27) as f32 * 40.0 / 31.0 - 20.0
            })
            .collect();
        let shifted: Vec<f32> = a.iter().map(|&v| v + 5.0).collect();
        let (s_noise, s_shift) = (ssim(&a, &noisy, 64), ssim(&a, &shifted, 64));
        assert!(s_noise < 0.9, "{s_noise}");
        assert!(s_shift > 0.99 && s_shift < 1.0, "{s_shift}");
        // A flat picture against itself plus a constant: only the means differ.
        let flat = vec![100.0f32; 30 * 30];
        let brighter = vec![110.0f32; 30 * 30];
        let expected = (2.0 * 100.0 * 110.0 + C1) / (100.0f64.powi(2) + 110.0f64.powi(2) + C1);
        assert!((ssim(&flat, &brighter, 30) - expected).abs() < 1e-9);
    }
}
