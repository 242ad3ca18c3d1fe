//! The sun's place for `sun = "clock"` (src/solar.rs) against published
//! reference values, within the 1 degree.

use mountains::solar::{position, seen};

/// 1970-01-01 to the given UTC date and time, in seconds.
fn utc(y: i64, m: i64, d: i64, h: i64, min: i64, s: i64) -> f64 {
    // Days from civil (Howard Hinnant's algorithm), as src/clock.rs inverts it.
    let y = if m <= 2 { y - 1 } else { y };
    let era = y.div_euclid(400);
    let yoe = y - era * 400;
    let mp = (m + 9) % 12;
    let doy = (153 * mp + 2) / 5 + d - 1;
    let doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
    let days = era * 146_097 + doe - 719_468;
    (days * 86_400 + h * 3600 + min * 60 + s) as f64
}

/// Degrees between two compass bearings.
fn bearing_gap(a: f64, b: f64) -> f64 {
    let d = (a - b).rem_euclid(360.0);
    d.min(360.0 - d)
}

fn check(what: &str, unix: f64, (lat, lon): (f64, f64), elevation: f64, azimuth: f64) {
    let p = position(unix, lat, lon);
    assert!(
        (p.elevation - elevation).abs() < 1.0,
        "{what}: elevation {:.3}, the reference {elevation}",
        p.elevation
    );
    assert!(
        bearing_gap(p.azimuth, azimuth) < 1.0,
        "{what}: azimuth {:.3}, the reference {azimuth}",
        p.azimuth
    );
}

/// NOAA's own spreadsheet, NOAA_Solar_Calculations_day.xls
/// (gml.noaa.gov/grad/solcalc/calcdetails.html), as published with its
/// example inputs: latitude 40 N, longitude 105 W, time zone -7,
/// 2010-06-21; its "Solar Elevation corrected for atm refraction" and
/// "Solar Azimuth Angle" columns at these local times (UTC = local + 7 h),
/// night, dawn, morning, noon, afternoon, dusk.
#[test]
fn the_sun_stands_where_noaas_spreadsheet_puts_it() {
    let rows = [
        ((3, 0), -14.1628424848915, 41.6104386951082),
        ((4, 30), -0.729664707309071, 57.6799724300864),
        ((6, 0), 14.5538438427532, 71.3721272242721),
        ((9, 0), 48.4962923894066, 99.4675295274194),
        ((12, 0), 73.4384793439627, 178.533230037881),
        ((15, 0), 49.1836829941271, 259.809563932718),
        ((19, 30), 0.0989819972923182, 301.72829080667),
        ((22, 30), -23.0289418687351, 337.092115850051),
    ];
    for ((h, m), elevation, azimuth) in rows {
        let unix = utc(2010, 6, 21, h + 7, m, 0);
        let what = format!("Boulder 2010-06-21 {h:02}:{m:02} local");
        check(&what, unix, (40.0, -105.0), elevation, azimuth);
    }
}

/// NREL's Solar Position Algorithm report (Reda and Andreas,
/// NREL/TP-560-34302, rev. 2008), its worked example: Golden, Colorado,
/// 39.742476 N 105.1786 W, 2003-10-17 12:30:30 local (UTC-7): topocentric
/// zenith 50.11162 degrees (elevation 39.88838), azimuth 194.34024.
#[test]
fn the_sun_stands_where_nrels_spa_example_puts_it() {
    let unix = utc(2003, 10, 17, 19, 30, 30);
    check(
        "Golden 2003-10-17",
        unix,
        (39.742476, -105.1786),
        39.88838,
        194.34024,
    );
}

/// Meeus, *Astronomical Algorithms* (2nd ed.), the algorithm NOAA's
/// calculator follows: example 25.a gives the sun's declination on
/// 1992-10-13 at 0 h as -7.78507 degrees, example 28.b the equation of
/// time then as +13 min 42.6 s (3.4275 degrees). So at 0 h UTC it is
/// solar noon at 176.5725 E, where the sun stands due south (north where
/// the latitude is south of the declination) at 90 - |latitude -
/// declination| degrees before refraction (which adds 0.04 degrees at 22
/// degrees up, less higher): far north, the tropics and the south.
#[test]
fn at_solar_noon_the_sun_stands_as_meeus_declination_says() {
    let unix = utc(1992, 10, 13, 0, 0, 0);
    let declination = -7.78507;
    for latitude in [60.0, 30.0, 0.0, -35.0, -60.0] {
        let elevation = 90.0 - f64::abs(latitude - declination);
        let azimuth = if latitude > declination { 180.0 } else { 0.0 };
        let what = format!("solar noon 1992-10-13 at latitude {latitude}");
        check(&what, unix, (latitude, 176.5725), elevation, azimuth);
    }
}

/// The view faces the equator: in the north the morning sun stands on
/// the viewer's left and the evening sun on the right, the noon sun
/// behind the range; in the south the other way round.
#[test]
fn the_clock_sun_crosses_the_view_from_the_side_it_rises_on() {
    let day = |h| utc(2010, 6, 21, h, 0, 0);
    // Boulder (UTC-7): 08:00, noon and 17:00 local.
    let (am, noon, pm) = (
        seen(day(15), 40.0, -105.0),
        seen(day(19), 40.0, -105.0),
        seen(day(24), 40.0, -105.0),
    );
    assert!(am.azimuth < 30.0 || am.azimuth > 330.0, "{am:?}");
    assert!((noon.azimuth - 90.0).abs() < 10.0, "{noon:?}");
    assert!((pm.azimuth - 180.0).abs() < 30.0, "{pm:?}");
    assert!(!am.afternoon && pm.afternoon);
    // Sydney (UTC+10) on the same day: its 09:00 sun on the right of a
    // view to the north, behind the range.
    let south = seen(utc(2010, 6, 20, 23, 0, 0), -33.87, 151.21);
    assert!(south.azimuth > 90.0 && south.azimuth < 180.0, "{south:?}");
    assert!(south.elevation > 0.0 && !south.afternoon, "{south:?}");
}
