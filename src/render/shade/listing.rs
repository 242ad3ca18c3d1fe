//! Seed 000's colours, as `_DrawTriangle` in its listing
//! (MountainsAlgorithm.c) works them out: `look =
//! "fractal-mountain-climbing"` in the natural colours.
//!
//! A land face's colour class is its mean height against the treeline
//! (`treeline = .4 * normalHeight + 10000`, the highest point at
//! `normalHeight = 10000 * height`): 0 (green) below it, 150 (grey) 9000
//! above it, `(az - treeline) / 60` between. The class blends an HSV colour
//! in 16-bit integers from hue 0x5555 (green), full saturation and value
//! 0xAAAA to hue 0x2000, no saturation and value 0xEFFF; the light scales
//! the value (`c.blue *= i`, truncated to 16 bits), and `HSV2RGB` makes it
//! RGB. Water is RGB (0x9FFF, 0x9FFF, 0xFFFF), unshaded.

/// The listing's water, `c.red = 0x9FFF; c.green = 0x9FFF; c.blue =
/// 0xFFFF`, in 8 bits a channel (the high byte).
pub const WATER: u32 = 0x009f_9fff;

/// The listing's black-and-white water: `PenPat(bwPat[8])`, half grey.
pub const WATER_PATTERN: u8 = 8;

/// The listing's colour classes: 0 green below the treeline, 150 grey.
const GREY_CLASS: i64 = 150;

/// Seed 000's land colours for one field.
#[derive(Debug, Clone, Copy)]
pub struct Ramp {
    /// Listing height units (`normalHeight` at the highest point) per
    /// height unit of the field.
    per_unit: f64,
    /// `.4 * normalHeight + 10000`, in listing units.
    treeline: f64,
}

impl Ramp {
    /// The ramp for `height` (the Height menu, 1-10) over a field whose
    /// highest point is `highest` (> 0): the listing normalises its highest
    /// point to `normalHeight = 10000 * height`.
    pub fn new(height: u32, highest: f32) -> Self {
        let normal_height = 10_000.0 * f64::from(height);
        let highest = if highest.is_finite() && highest > 0.0 {
            f64::from(highest)
        } else {
            1.0
        };
        Ramp {
            per_unit: normal_height / highest,
            treeline: 0.4 * normal_height + 10_000.0,
        }
    }

    /// The listing's colour class (0 green to 150 grey) of a face whose
    /// mean height is `mean` in the field's units.
    pub fn class(&self, mean: f32) -> i64 {
        let az = f64::from(mean) * self.per_unit;
        if az > self.treeline + 9000.0 {
            GREY_CLASS
        } else if az < self.treeline || az.is_nan() {
            0
        } else {
            // C's conversion of a positive double to long: truncation.
            ((az - self.treeline) / 60.0) as i64
        }
    }

    /// The colour of a land face of mean height `mean` at brightness `i`
    /// (`0.5 + 0.5 cos` of the listing's light), packed 0x00RRGGBB.
    pub fn colour(&self, mean: f32, i: f64) -> u32 {
        let [hue, saturation, value] = hsv(self.class(mean));
        // `c.blue *= i`: the product truncated back into 16 bits.
        let value = (f64::from(value) * i.clamp(0.0, 1.0)) as u16;
        hsv_to_rgb(hue, saturation, value)
    }
}

impl Ramp {
    /// The listing's black-and-white pattern (0 black ..= 16 white) for a
    /// land face of mean height `mean` at brightness `i`: `pat = c.blue *
    /// 36 / 0x10000 - 10` of the lit value, at least 0, at most 15 but in
    /// the grey class, which may reach 16.
    pub fn pattern(&self, mean: f32, i: f64) -> u8 {
        let class = self.class(mean);
        let [_, _, value] = hsv(class);
        let value = (f64::from(value) * i.clamp(0.0, 1.0)) as u16;
        let pat = i64::from(u32::from(value) * 36 / 0x1_0000) - 10;
        let most = if class == GREY_CLASS { 16 } else { 15 };
        pat.clamp(0, most) as u8
    }
}

/// `_DrawTriangle`'s HSV colour of class `color` (0..=150), in the
/// listing's unsigned 32-bit arithmetic: hue, saturation, value.
fn hsv(color: i64) -> [u16; 3] {
    let rest = (GREY_CLASS - color.clamp(0, GREY_CLASS)) as u32;
    let hue = rest * (0x5555 - 0x2000) / 150 + 0x2000;
    let saturation = 0xFFFF * rest / 150;
    let value = 0xEFFF - rest * (0xEFFF - 0xAAAA) / 150;
    [hue, saturation, value].map(|c| c as u16)
}

/// The Color Picker's `HSV2RGB` for 16-bit fractions (hue 0..65536 is one
/// turn; saturation and value 0xFFFF are 1), the six-sector formula, each
/// channel rounded to 16 bits and shown by its high byte, as `WATER` is.
fn hsv_to_rgb(hue: u16, saturation: u16, value: u16) -> u32 {
    let h = f64::from(hue) / 65_536.0 * 6.0;
    let (s, v) = (
        f64::from(saturation) / 65_535.0,
        f64::from(value) / 65_535.0,
    );
    let sector = h.floor();
    let f = h - sector;
    let (p, q, t) = (v * (1.0 - s), v * (1.0 - s * f), v * (1.0 - s * (1.0 - f)));
    let [r, g, b] = match sector as u32 {
        0 => [v, t, p],
        1 => [q, v, p],
        2 => [p, v, t],
        3 => [p, q, v],
        4 => [t, p, v],
        _ => [v, p, q],
    };
    let byte = |c: f64| ((c * 65_535.0 + 0.5).clamp(0.0, 65_535.0) as u32) >> 8;
    (byte(r) << 16) | (byte(g) << 8) | byte(b)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_ends_of_the_ramp_are_the_listings_green_and_grey() {
        assert_eq!(hsv(0), [0x5555, 0xFFFF, 0xAAAA]);
        assert_eq!(hsv(150), [0x2000, 0, 0xEFFF]);
        // Hue 0x5555 is a third of a turn: pure green at value 2/3.
        assert_eq!(hsv_to_rgb(0x5555, 0xFFFF, 0xAAAA), 0x0000_aa00);
        assert_eq!(hsv_to_rgb(0x2000, 0, 0xEFFF), 0x00ef_efef);
    }

    #[test]
    fn classes_follow_the_treeline() {
        // Height 5: normalHeight 50000, treeline 30000, grey from 39000.
        let ramp = Ramp::new(5, 100.0);
        assert_eq!(ramp.class(59.9), 0);
        assert_eq!(ramp.class(60.0 + 0.12 * 10.0), 10);
        assert_eq!(ramp.class(78.1), 150);
        assert_eq!(ramp.class(-5.0), 0);
    }
}
