//! The smooth step every blend in the program eases along: one owner for
//! the terrain's coast and wetness and for the picture's colours, clouds,
//! ripples and ridges.

/// 3t^2 - 2t^3 for `t` in 0..=1: from 0 to 1 with a level start and end,
/// so a blend along it shows no edge where it begins or stops.
#[inline]
pub fn hermite(t: f32) -> f32 {
    t * t * (3.0 - 2.0 * t)
}

/// Hermite step from 0 at `e0` to 1 at `e1` (0 below, 1 above).
#[inline]
pub fn smoothstep(e0: f32, e1: f32, x: f32) -> f32 {
    hermite(((x - e0) / (e1 - e0)).clamp(0.0, 1.0))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_step_is_level_at_its_ends_and_half_way_at_its_middle() {
        assert_eq!((hermite(0.0), hermite(0.5), hermite(1.0)), (0.0, 0.5, 1.0));
        assert_eq!(
            (smoothstep(2.0, 4.0, 1.0), smoothstep(2.0, 4.0, 9.0)),
            (0.0, 1.0)
        );
        assert_eq!(smoothstep(2.0, 4.0, 3.0), 0.5);
        // Level at the ends: a small step there moves it far less than the step.
        let d = 1e-3;
        assert!(hermite(d) < d * d * 4.0 && 1.0 - hermite(1.0 - d) < d * d * 4.0);
        let rising = (0..=100)
            .map(|i| hermite(i as f32 / 100.0))
            .collect::<Vec<_>>();
        assert!(rising.windows(2).all(|w| w[1] > w[0]));
    }
}
