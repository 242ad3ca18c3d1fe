//! The reference pictures' own painter: a frame of 0x00RRGGBB pixels,
//! triangles filled at pixel centres (the corners as each program hands
//! them over), one-pixel lines, and a PNG writer. Nothing of the
//! project's renderer.

use std::io::BufWriter;
use std::path::Path;

/// A frame of packed 0x00RRGGBB pixels.
pub struct Canvas {
    /// Width in pixels.
    pub width: usize,
    /// Height in pixels.
    pub height: usize,
    pixels: Vec<u32>,
}

impl Canvas {
    /// A frame of `width` x `height` pixels, all `background`.
    pub fn new(width: usize, height: usize, background: u32) -> Self {
        Canvas {
            width,
            height,
            pixels: vec![background; width * height],
        }
    }

    /// Sets one pixel, if it is in the frame.
    pub fn put(&mut self, x: i64, y: i64, colour: u32) {
        if x >= 0 && y >= 0 && (x as usize) < self.width && (y as usize) < self.height {
            self.pixels[y as usize * self.width + x as usize] = colour;
        }
    }

    /// Fills the triangle `p` (either winding): every pixel whose centre is
    /// inside or on an edge.
    pub fn triangle(&mut self, p: [[f64; 2]; 3], colour: u32) {
        let edge = |a: [f64; 2], b: [f64; 2], x: f64, y: f64| {
            (b[0] - a[0]) * (y - a[1]) - (b[1] - a[1]) * (x - a[0])
        };
        let area = edge(p[0], p[1], p[2][0], p[2][1]);
        if area == 0.0 || !area.is_finite() {
            return;
        }
        let lo = |k: usize| p.iter().map(|q| q[k]).fold(f64::INFINITY, f64::min);
        let hi = |k: usize| p.iter().map(|q| q[k]).fold(f64::NEG_INFINITY, f64::max);
        let (x0, x1) = (lo(0).floor().max(0.0), hi(0).ceil().min(self.width as f64));
        let (y0, y1) = (lo(1).floor().max(0.0), hi(1).ceil().min(self.height as f64));
        for y in y0 as i64..y1 as i64 {
            for x in x0 as i64..x1 as i64 {
                let (cx, cy) = (x as f64 + 0.5, y as f64 + 0.5);
                let w = [
                    edge(p[1], p[2], cx, cy),
                    edge(p[2], p[0], cx, cy),
                    edge(p[0], p[1], cx, cy),
                ];
                if w.iter().all(|&w| w * area >= 0.0) {
                    self.put(x, y, colour);
                }
            }
        }
    }

    /// A one-pixel line from `a` to `b` (both ends drawn).
    pub fn line(&mut self, a: [f64; 2], b: [f64; 2], colour: u32) {
        let steps = (b[0] - a[0]).abs().max((b[1] - a[1]).abs()).ceil().max(1.0);
        if !steps.is_finite() {
            return;
        }
        for k in 0..=steps as i64 {
            let t = k as f64 / steps;
            let x = a[0] + (b[0] - a[0]) * t;
            let y = a[1] + (b[1] - a[1]) * t;
            self.put(x.floor() as i64, y.floor() as i64, colour);
        }
    }

    /// Writes the frame as an 8-bit RGB PNG.
    pub fn save(&self, path: &Path) -> std::io::Result<()> {
        let file = std::fs::File::create(path)?;
        let mut encoder =
            png::Encoder::new(BufWriter::new(file), self.width as u32, self.height as u32);
        encoder.set_color(png::ColorType::Rgb);
        encoder.set_depth(png::BitDepth::Eight);
        let bytes: Vec<u8> = self
            .pixels
            .iter()
            .flat_map(|&c| [(c >> 16) as u8, (c >> 8) as u8, c as u8])
            .collect();
        encoder
            .write_header()
            .and_then(|mut w| w.write_image_data(&bytes))
            .map_err(std::io::Error::other)
    }
}
