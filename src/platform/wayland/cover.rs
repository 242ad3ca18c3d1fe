//! How a layer surface's buffer covers its output pixel for pixel: the
//! buffer's size, and what tells the compositor how to show it (an integer
//! buffer scale, or a viewport for fractional scales). Pure arithmetic on
//! what the compositor said of the surface and the output.

use crate::render::Size;

/// How a surface's buffer covers its output.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Cover {
    /// The surface's logical size times the output's integer scale, with
    /// that buffer scale.
    Scaled {
        /// The buffer's size in pixels.
        size: Size,
        /// The buffer scale (1 on an unscaled output).
        scale: i32,
    },
    /// The output's mode (its real pixels) shown at the surface's logical
    /// size through a viewport: a fractional scale (1.5), where the
    /// output's integer scale (2) would draw more pixels than it has and
    /// the compositor would shrink them.
    Viewport {
        /// The buffer's size in pixels: the output's mode.
        size: Size,
        /// The surface's size in the compositor's units.
        logical: Size,
    },
}

impl Cover {
    /// The buffer's size in pixels.
    pub fn size(&self) -> Size {
        match *self {
            Cover::Scaled { size, .. } | Cover::Viewport { size, .. } => size,
        }
    }
}

/// The cover of a surface of `logical` size on an output of integer
/// `scale` whose current mode, turned as the output is, is `mode`;
/// `viewporter`: whether the compositor offers viewports.
pub fn cover(logical: Size, scale: i32, mode: Option<Size>, viewporter: bool) -> Cover {
    let scale = scale.max(1);
    let size = scaled(logical, scale);
    let real = |m: Size| !m.is_empty() && !logical.is_empty();
    match mode {
        Some(mode) if viewporter && mode != size && real(mode) => Cover::Viewport {
            size: mode,
            logical,
        },
        _ => Cover::Scaled { size, scale },
    }
}

/// `logical` times an integer `scale` (at least 1).
fn scaled(logical: Size, scale: i32) -> Size {
    let scale = scale.max(1).unsigned_abs();
    Size::new(
        logical.width.saturating_mul(scale),
        logical.height.saturating_mul(scale),
    )
}

/// An output's mode (`width`, `height` in pixels) as it is shown: sides
/// swapped when the output is turned a quarter (`quarter_turned`).
pub fn turned(mode: (i32, i32), quarter_turned: bool) -> Size {
    let (w, h) = if quarter_turned {
        (mode.1, mode.0)
    } else {
        mode
    };
    Size::new(w.max(0) as u32, h.max(0) as u32)
}

/// The compositor's units an output of `pixels` (turned) spans at an
/// integer `scale`: for a configure that leaves the size to the client.
pub fn logical_of(pixels: Size, scale: i32) -> Size {
    let scale = scale.max(1).unsigned_abs();
    Size::new(pixels.width / scale, pixels.height / scale)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_integer_scale_multiplies_the_logical_size() {
        let c = cover(Size::new(320, 240), 2, Some(Size::new(640, 480)), true);
        assert_eq!(
            c,
            Cover::Scaled {
                size: Size::new(640, 480),
                scale: 2
            }
        );
        let c = cover(Size::new(640, 480), 1, Some(Size::new(640, 480)), true);
        assert_eq!(c.size(), Size::new(640, 480));
        assert_eq!(
            cover(Size::new(640, 480), 0, None, false).size(),
            Size::new(640, 480)
        );
    }

    #[test]
    fn a_fractional_scale_draws_the_modes_pixels_through_a_viewport() {
        // 640x480 at 1.5: sway says scale 2 and a 427x320 surface; 854x640
        // would be shrunk, the mode's 640x480 are the output's pixels.
        let c = cover(Size::new(427, 320), 2, Some(Size::new(640, 480)), true);
        assert_eq!(
            c,
            Cover::Viewport {
                size: Size::new(640, 480),
                logical: Size::new(427, 320)
            }
        );
        // Without viewports: the integer scale, shrunk by the compositor.
        let c = cover(Size::new(427, 320), 2, Some(Size::new(640, 480)), false);
        assert_eq!(c.size(), Size::new(854, 640));
        // No mode known: the same.
        assert_eq!(
            cover(Size::new(427, 320), 2, None, true).size(),
            Size::new(854, 640)
        );
    }

    #[test]
    fn a_turned_output_swaps_its_sides() {
        assert_eq!(turned((1920, 1080), false), Size::new(1920, 1080));
        assert_eq!(turned((1920, 1080), true), Size::new(1080, 1920));
        assert_eq!(logical_of(Size::new(1080, 1920), 2), Size::new(540, 960));
        assert_eq!(logical_of(Size::new(1920, 1080), 0), Size::new(1920, 1080));
    }
}
