//! The light of `sun = "clock"`: the sun where the saver says it stands
//! now, its colours by its height (dawn and dusk warm, the day white and
//! blue, twilight fading to the night's). Render reads no clock: the saver
//! works out the sun's place for the hour and hands it in ([`SunAt`]).
//!
//! Below the horizon the sun lights nothing: through civil and nautical
//! twilight (down to 12 degrees) the sky and the light fade to the
//! night's, and the moon takes over where `sun = "night"` puts it (no lunar
//! ephemeris: the land needs a light, and ahead of the viewer it glitters
//! on the water).

use super::light::{EVENING, Lighting, MIDDAY, MORNING, NIGHT, NIGHT_TURN, SUNSET, Time};
use crate::render::base::colour::{mix, smoothstep};

/// Degrees below the horizon where twilight ends and the night's look is whole.
const DARK: f32 = -12.0;

/// Where the sun stands, seen from the viewer.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SunAt {
    /// Degrees above the horizon (negative below it).
    pub elevation: f32,
    /// Degrees round from the viewer's left (0) through straight ahead (90)
    /// to the right (180), as the named times give theirs.
    pub azimuth: f32,
    /// Whether the sun is going down (evening colours rather than morning's).
    pub afternoon: bool,
}

impl Lighting {
    /// The light of the sun at `at`: its own place, colours by its height.
    pub fn at_hour(at: SunAt) -> Self {
        let low = if at.afternoon { &EVENING } else { &MORNING };
        let el = if at.elevation.is_finite() {
            at.elevation
        } else {
            0.0
        };
        let az = if at.azimuth.is_finite() {
            at.azimuth
        } else {
            90.0
        };
        if el >= low.elevation {
            let t = smoothstep(low.elevation, MIDDAY.elevation, el);
            return Self::at(&placed(blend(low, &MIDDAY, t), el, az), 0.0);
        }
        if el >= 0.0 {
            let t = smoothstep(0.0, low.elevation, el);
            return Self::at(&placed(blend(&SUNSET, low, t), el, az), 0.0);
        }
        let night = smoothstep(0.0, DARK, el);
        let mut time = blend(&SUNSET, &NIGHT, night);
        // The first half of twilight: the sun's last light, grazing and
        // fading; the second: the moon's, growing.
        let (fade, lamp) = if night < 0.5 {
            (1.0 - 2.0 * night, placed(time, 1.0, az))
        } else {
            (
                2.0 * night - 1.0,
                placed(time, NIGHT.elevation, NIGHT.azimuth + NIGHT_TURN),
            )
        };
        time = lamp;
        time.direct = time.direct.map(|c| c * fade);
        Self::at(&time, 0.0).under_moon(night)
    }
}

/// `time`'s colours with the sun at `elevation` and `azimuth`.
fn placed(time: Time, elevation: f32, azimuth: f32) -> Time {
    Time {
        elevation,
        azimuth,
        ..time
    }
}

/// The colours `t` (0..=1) of the way from `a`'s to `b`'s (`a`'s place).
fn blend(a: &Time, b: &Time, t: f32) -> Time {
    Time {
        direct: mix(a.direct, b.direct, t),
        ambient: mix(a.ambient, b.ambient, t),
        zenith: mix(a.zenith, b.zenith, t),
        horizon: mix(a.horizon, b.horizon, t),
        ..*a
    }
}
