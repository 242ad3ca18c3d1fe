//! Pictures as floating-point RGB, and a frame averaged down to one.

use crate::render::Frame;

/// An RGB picture with channels in 0..=255, row-major.
#[derive(Debug, Clone, PartialEq)]
pub struct Image {
    /// Width in pixels.
    pub width: usize,
    /// Height in pixels.
    pub height: usize,
    /// The pixels, row by row.
    pub rgb: Vec<[f32; 3]>,
}

/// The channels of a packed `0x00RRGGBB` pixel, 0..=255.
#[inline]
pub fn channels(p: u32) -> [f32; 3] {
    [(p >> 16) & 0xff, (p >> 8) & 0xff, p & 0xff].map(|c| c as f32)
}

/// Luma of an RGB colour (ITU-R BT.601 weights, as MATLAB's `rgb2gray`).
#[inline]
pub fn luma(c: [f32; 3]) -> f32 {
    0.299 * c[0] + 0.587 * c[1] + 0.114 * c[2]
}

impl Image {
    /// A frame as it is.
    pub fn of(frame: &Frame) -> Image {
        Image {
            width: frame.width() as usize,
            height: frame.height() as usize,
            rgb: frame.pixels().iter().map(|&p| channels(p)).collect(),
        }
    }

    /// `frame` averaged down in `k` x `k` boxes to `width` x `height`: the
    /// box of pixel (x, y) starts at frame pixel (`x0 + k x`, `y0 + k y`).
    /// Boxes reaching past the frame repeat its edge pixels.
    pub fn box_down(
        frame: &Frame,
        k: usize,
        (x0, y0): (i64, i64),
        width: usize,
        height: usize,
    ) -> Image {
        let (fw, fh) = (frame.width() as i64, frame.height() as i64);
        let pixels = frame.pixels();
        let xs: Vec<usize> = (0..width * k)
            .map(|i| (x0 + i as i64).clamp(0, fw - 1) as usize)
            .collect();
        let mut rgb = vec![[0.0f32; 3]; width * height];
        let mut sums = vec![[0u32; 3]; width];
        let scale = 1.0 / (k * k) as f32;
        for (y, out) in rgb.chunks_exact_mut(width).enumerate() {
            sums.fill([0; 3]);
            for dy in 0..k {
                let row = (y0 + (k * y + dy) as i64).clamp(0, fh - 1) as usize;
                let row = &pixels[row * fw as usize..][..fw as usize];
                for (x, sum) in sums.iter_mut().enumerate() {
                    for &fx in &xs[k * x..k * x + k] {
                        let p = row[fx];
                        sum[0] += (p >> 16) & 0xff;
                        sum[1] += (p >> 8) & 0xff;
                        sum[2] += p & 0xff;
                    }
                }
            }
            for (o, s) in out.iter_mut().zip(&sums) {
                *o = s.map(|v| v as f32 * scale);
            }
        }
        Image { width, height, rgb }
    }

    /// The luma of every pixel.
    pub fn luma(&self) -> Vec<f32> {
        self.rgb.iter().map(|&c| luma(c)).collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn averaging_down_takes_the_mean_of_each_box_from_its_offset() {
        let mut f = Frame::new(4, 5).unwrap();
        for (i, p) in f.pixels_mut().iter_mut().enumerate() {
            *p = (i as u32) << 16 | 10;
        }
        // Rows 1-2 and 3-4 (offset 1), columns 0-1 and 2-3.
        let img = Image::box_down(&f, 2, (0, 1), 2, 2);
        assert_eq!(img.rgb[0], [(4 + 5 + 8 + 9) as f32 / 4.0, 0.0, 10.0]);
        assert_eq!(img.rgb[3], [(14 + 15 + 18 + 19) as f32 / 4.0, 0.0, 10.0]);
        // A box past the bottom repeats the last row.
        let past = Image::box_down(&f, 2, (0, 4), 1, 1);
        assert_eq!(past.rgb[0][0], (16 + 17 + 16 + 17) as f32 / 4.0);
        assert_eq!(Image::box_down(&f, 1, (0, 0), 4, 5), Image::of(&f));
    }
}
