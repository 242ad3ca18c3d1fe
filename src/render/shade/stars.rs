//! Stars in a clear night sky: a fixed field of points, each as bright as
//! its magnitude says, thinning out towards the horizon.
//!
//! The sky is cut into cells of [`CELL`] star pixels (a star pixel is one
//! pixel up to 1080 lines, a 2x2 block at 4K: a star is a point at every
//! size), and a few cells in a hundred hold a star at a place drawn from the
//! cell. Magnitudes follow the sky's own count: each magnitude brighter is
//! about three times rarer, down to the naked eye's sixth; a star's
//! brightness on the screen falls by 2.5 for each two magnitudes (the
//! screen's tone curve compresses starlight's range of 2.5 a magnitude).
//! Near the horizon the air dims and hides them (extinction).

use crate::render::base::colour::{Rgb, mix, smoothstep};
use crate::terrain::splitmix;

/// Star pixels a cell's side.
const CELL: u32 = 9;
/// How many cells in 256 hold a star.
const FILLED: u64 = 22;
/// The faintest magnitude drawn (the naked eye's limit).
const FAINTEST: f32 = 6.0;
/// The brightest star's brightness on the screen (0..=1, added to the sky)
/// and its magnitude.
const BRIGHTEST: f32 = 0.95;
const BRIGHTEST_MAG: f32 = 0.5;
/// Frame heights above the horizon line over which the stars come out.
const EXTINCTION: f32 = 0.22;
/// Blue-white and warm stars.
const BLUE: Rgb = [0.80, 0.88, 1.00];
const WARM: Rgb = [1.00, 0.88, 0.74];

/// The star field of one frame.
#[derive(Debug, Clone)]
pub(crate) struct Stars {
    /// Pixels a star pixel's side.
    scale: u32,
    /// The frame row of the horizon line and the frame's height.
    horizon_row: f32,
    height: f32,
    /// How much of the night's look (0..=1): stars fade in at dusk.
    night: f32,
    draw: u64,
}

impl Stars {
    /// The stars of a frame `height` lines high whose horizon line is row
    /// `horizon_row`, `night` (0..=1) into the night, drawn from `draw`;
    /// `None` by day.
    pub(crate) fn new(height: u32, horizon_row: f32, night: f32, draw: u64) -> Option<Self> {
        (night > 0.0).then(|| Stars {
            scale: (height as f32 / 1080.0).round().max(1.0) as u32,
            horizon_row,
            height: height.max(1) as f32,
            night,
            draw: splitmix::mix(draw ^ 0x5157_a125),
        })
    }

    /// The star on pixel (`x`, `y`), if one is: its colour times its
    /// brightness, to add to the sky.
    #[inline]
    pub(crate) fn at(&self, x: u32, y: u32) -> Option<Rgb> {
        let (sx, sy) = (x / self.scale, y / self.scale);
        let h = self.cell(sx / CELL, sy / CELL)?;
        let (ox, oy) = ((h >> 8) as u32 % CELL, (h >> 16) as u32 % CELL);
        if (sx % CELL, sy % CELL) != (ox, oy) {
            return None;
        }
        let up = (self.horizon_row - y as f32) / self.height;
        let air = smoothstep(0.0, EXTINCTION, up);
        if air <= 0.0 {
            return None;
        }
        // u in (0, 1]: each magnitude brighter a third as many stars.
        let u = (((h >> 24) & 0xffff) as f32 + 1.0) / 65536.0;
        let magnitude = (FAINTEST + u.ln() / 3f32.ln()).max(BRIGHTEST_MAG);
        let b = BRIGHTEST * 2.512f32.powf(-(magnitude - BRIGHTEST_MAG) / 2.0);
        let tint = ((h >> 40) & 0xff) as f32 / 255.0;
        let c = mix(BLUE, WARM, tint);
        Some(c.map(|v| v * b * air * self.night))
    }

    /// The draw of cell (`cx`, `cy`) if it holds a star.
    #[inline]
    fn cell(&self, cx: u32, cy: u32) -> Option<u64> {
        let h = splitmix::mix(self.draw ^ (u64::from(cx) << 32 | u64::from(cy)));
        (h & 0xff < FILLED).then_some(h)
    }

    /// The columns of row `y` in `x0..x1` that hold a star.
    pub(crate) fn in_row(&self, y: u32, x0: u32, x1: u32) -> impl Iterator<Item = u32> + '_ {
        let (sy, span) = (y / self.scale, CELL * self.scale);
        let cells = x0 / span..x1.div_ceil(span);
        let lies = (self.horizon_row - y as f32) > 0.0;
        cells
            .filter(move |_| lies)
            .filter_map(move |cx| {
                let h = self.cell(cx, sy / CELL)?;
                let (ox, oy) = ((h >> 8) as u32 % CELL, (h >> 16) as u32 % CELL);
                (sy % CELL == oy).then_some((cx * CELL + ox) * self.scale)
            })
            .flat_map(move |x| x..x + self.scale)
            .filter(move |&x| x >= x0 && x < x1)
    }
}
