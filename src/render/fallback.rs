//! Stand-ins for `render::dither` and `render::ridges`, which the colour work
//! is writing now. Same signatures; once those land, the lead deletes this
//! file and points the two `use super::fallback::...` lines at the real ones.

/// 17-level ordered dither (stand-in for `render::dither`).
pub(crate) mod dither {
    /// 4x4 Bayer matrix: the order in which a cell's pixels turn on.
    const BAYER: [[u8; 4]; 4] = [[0, 8, 2, 10], [12, 4, 14, 6], [3, 11, 1, 9], [15, 7, 13, 5]];

    /// Pattern level 0 (black) to 16 (white) for a grey of 0-255.
    pub(crate) fn level(gray: u32) -> u8 {
        ((gray.min(255) * 17) / 256) as u8
    }

    /// Whether pixel (`x`, `y`) is white in pattern `level`.
    pub(crate) fn is_on(level: u8, x: u32, y: u32) -> bool {
        BAYER[(y & 3) as usize][(x & 3) as usize] < level
    }
}

/// Layered ridge silhouettes (stand-in for `render::ridges`).
pub(crate) mod ridges {
    use crate::render::frame::{Frame, Rect};
    use crate::settings::Settings;
    use crate::terrain::Heightfield;

    /// One silhouette per grid row, back to front, lighter in the distance.
    pub(crate) struct Ridges {
        rows: Vec<Vec<f32>>,
        width: u32,
        height: u32,
        top: f32,
    }

    /// Rows drawn, at most: a silhouette per pixel row is plenty.
    const MAX_ROWS: usize = 64;

    impl Ridges {
        /// Samples the field's rows for a `width` x `height` frame.
        pub(crate) fn new(
            field: &Heightfield,
            _settings: &Settings,
            width: u32,
            height: u32,
        ) -> Self {
            let n = field.size();
            let step = n.div_ceil(MAX_ROWS).max(1);
            let rows = (0..n)
                .step_by(step)
                .map(|y| field.row(y).to_vec())
                .collect();
            Ridges {
                rows,
                width,
                height,
                top: field.max().max(1e-3),
            }
        }

        /// How many strips (silhouettes) there are.
        pub(crate) fn strips_total(&self) -> usize {
            self.rows.len()
        }

        /// Draws silhouette `i` and returns the rectangle it changed.
        pub(crate) fn draw_strip(&self, frame: &mut Frame, i: usize) -> Rect {
            let (Some(row), true) = (self.rows.get(i), frame.width() == self.width) else {
                return Rect::default();
            };
            let (w, h) = (self.width, self.height);
            let t = (i + 1) as f32 / self.rows.len() as f32;
            let shade = (200.0 - 170.0 * t) as u32;
            let colour = shade << 16 | shade << 8 | (shade + 30).min(255);
            let base = h as f32 * (0.45 + 0.5 * t);
            let n = row.len() - 1;
            for x in 0..w {
                let hgt = row[(x as usize * n) / w.max(1) as usize].max(0.0);
                let y0 = (base - hgt / self.top * h as f32 * 0.4).clamp(0.0, h as f32) as u32;
                for y in y0..h {
                    frame.pixels_mut()[(y * w + x) as usize] = colour;
                }
            }
            frame.bounds()
        }
    }
}
