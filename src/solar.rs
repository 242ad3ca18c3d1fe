//! Where the sun stands for a place and a time: NOAA's solar calculator
//! (its spreadsheet `NOAA_Solar_Calculations_day.xls`, after Meeus's
//! *Astronomical Algorithms*), good to a small fraction of a degree for
//! these centuries; and the sun of `sun = "clock"` as the view sees it.
//!
//! No crate: the `spa` crate wants `chrono` for its times, and NOAA's
//! algorithm is these few lines; tests/render/solar.rs checks them against
//! NOAA's and NREL's published values.

use crate::render::hour::SunAt;
use crate::settings::{Settings, Sun};

/// The sun seen from a place on the ground.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Position {
    /// Degrees above the horizon, with the atmosphere's refraction
    /// (negative below it).
    pub elevation: f64,
    /// Degrees clockwise from north.
    pub azimuth: f64,
    /// Degrees of hour angle: negative before solar noon, positive after.
    pub hour_angle: f64,
}

/// The sun at `unix` seconds (UTC) seen from `latitude` degrees north and
/// `longitude` degrees east, as NOAA's spreadsheet works it out (its
/// columns in order).
pub fn position(unix: f64, latitude: f64, longitude: f64) -> Position {
    let (sin, cos) = (|d: f64| d.to_radians().sin(), |d: f64| d.to_radians().cos());
    let julian_day = unix / 86_400.0 + 2_440_587.5;
    let t = (julian_day - 2_451_545.0) / 36_525.0;
    let mean_long = (280.46646 + t * (36000.76983 + t * 0.0003032)).rem_euclid(360.0);
    let mean_anom = 357.52911 + t * (35999.05029 - 0.0001537 * t);
    let ecc = 0.016708634 - t * (0.000042037 + 0.0000001267 * t);
    let centre = sin(mean_anom) * (1.914602 - t * (0.004817 + 0.000014 * t))
        + sin(2.0 * mean_anom) * (0.019993 - 0.000101 * t)
        + sin(3.0 * mean_anom) * 0.000289;
    let omega = 125.04 - 1934.136 * t;
    let app_long = mean_long + centre - 0.00569 - 0.00478 * sin(omega);
    let mean_obliq =
        23.0 + (26.0 + (21.448 - t * (46.815 + t * (0.00059 - t * 0.001813))) / 60.0) / 60.0;
    let obliq = mean_obliq + 0.00256 * cos(omega);
    let declination = (sin(obliq) * sin(app_long)).asin().to_degrees();
    let y = (obliq / 2.0).to_radians().tan().powi(2);
    let l2 = 2.0 * mean_long.to_radians();
    let m = mean_anom.to_radians();
    let eq_of_time = 4.0
        * (y * l2.sin() - 2.0 * ecc * m.sin() + 4.0 * ecc * y * m.sin() * l2.cos()
            - 0.5 * y * y * (2.0 * l2).sin()
            - 1.25 * ecc * ecc * (2.0 * m).sin())
        .to_degrees();
    let minutes = unix.rem_euclid(86_400.0) / 60.0;
    let true_solar = (minutes + eq_of_time + 4.0 * longitude).rem_euclid(1440.0);
    let hour_angle = true_solar / 4.0 - 180.0;
    let cos_zenith =
        sin(latitude) * sin(declination) + cos(latitude) * cos(declination) * cos(hour_angle);
    let zenith = cos_zenith.clamp(-1.0, 1.0).acos().to_degrees();
    let elevation = 90.0 - zenith;
    let across = cos(latitude) * sin(zenith);
    let turn = if across.abs() < 1e-12 {
        0.0
    } else {
        ((sin(latitude) * cos(zenith) - sin(declination)) / across)
            .clamp(-1.0, 1.0)
            .acos()
            .to_degrees()
    };
    let azimuth = if hour_angle > 0.0 {
        (turn + 180.0).rem_euclid(360.0)
    } else {
        (540.0 - turn).rem_euclid(360.0)
    };
    Position {
        elevation: elevation + refraction(elevation),
        azimuth,
        hour_angle,
    }
}

/// NOAA's approximate atmospheric refraction at `elevation` degrees, in degrees.
fn refraction(elevation: f64) -> f64 {
    let tan = elevation.to_radians().tan();
    let arcsec = if elevation > 85.0 {
        0.0
    } else if elevation > 5.0 {
        58.1 / tan - 0.07 / tan.powi(3) + 0.000086 / tan.powi(5)
    } else if elevation > -0.575 {
        1735.0
            + elevation * (-518.2 + elevation * (103.4 + elevation * (-12.79 + elevation * 0.711)))
    } else {
        -20.772 / tan
    };
    arcsec / 3600.0
}

/// The sun of `sun = "clock"` at `unix` seconds for `latitude` and
/// `longitude`, as the view sees it. The view looks towards the equator
/// (south in the north, north in the south), where the sun stands at noon,
/// so the day's sun crosses behind the range from one side to the other:
/// in the north it rises on the viewer's left and sets on the right, as
/// the named times put morning and evening; in the south the other way.
pub fn seen(unix: f64, latitude: f64, longitude: f64) -> SunAt {
    let p = position(unix, latitude, longitude);
    // Compass degrees to degrees round from the viewer's left: facing
    // south, east is on the left; facing north, west is.
    let azimuth = if latitude >= 0.0 {
        p.azimuth - 90.0
    } else {
        p.azimuth + 90.0
    };
    SunAt {
        elevation: p.elevation as f32,
        azimuth: azimuth.rem_euclid(360.0) as f32,
        afternoon: p.hour_angle > 0.0,
    }
}

/// The sun `settings` ask to be drawn under now: where it stands for
/// `sun = "clock"` (the saver's side: render reads no clock), else none.
pub fn now_for(settings: &Settings) -> Option<SunAt> {
    (settings.sun == Sun::Clock).then(|| {
        let now = crate::clock::now() as f64;
        seen(now, settings.latitude.into(), settings.longitude.into())
    })
}
