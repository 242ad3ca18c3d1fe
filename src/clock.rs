//! Wall-clock times for people: the local date and time, with the offset
//! from UTC, for log lines and the names of saved files. No date crate:
//! the calendar is a few lines, and the offset comes from the system.

use std::time::{SystemTime, UNIX_EPOCH};

/// Seconds since 1970-01-01 UTC, now.
pub fn now() -> u64 {
    SystemTime::now()
        .duration_since(UNIX_EPOCH)
        .map_or(0, |d| d.as_secs())
}

/// `YYYY-MM-DD HH:MM:SS` of `secs` shifted by `offset` seconds.
pub fn format(secs: u64, offset: i64) -> String {
    let t = secs as i64 + offset;
    let (days, rem) = (t.div_euclid(86_400), t.rem_euclid(86_400));
    let (y, m, d) = civil_from_days(days);
    format!(
        "{y:04}-{m:02}-{d:02} {:02}:{:02}:{:02}",
        rem / 3600,
        rem % 3600 / 60,
        rem % 60
    )
}

/// `+01:00`-style text for an offset in seconds.
pub fn format_offset(offset: i64) -> String {
    let sign = if offset < 0 { '-' } else { '+' };
    let m = offset.abs() / 60;
    format!("{sign}{:02}:{:02}", m / 60, m % 60)
}

/// The local date and time of `secs` with its offset from UTC:
/// `2026-11-24 23:45:12 +01:00`.
pub fn local(secs: u64) -> String {
    let offset = utc_offset(secs);
    format!("{} {}", format(secs, offset), format_offset(offset))
}

/// The local date and time of `secs`, without the offset (file names).
pub fn local_plain(secs: u64) -> String {
    format(secs, utc_offset(secs))
}

/// Days since 1970-01-01 to a calendar date (Howard Hinnant's algorithm).
fn civil_from_days(z: i64) -> (i64, u32, u32) {
    let z = z + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z.rem_euclid(146_097);
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let d = (doy - (153 * mp + 2) / 5 + 1) as u32;
    let m = if mp < 10 { mp + 3 } else { mp - 9 } as u32;
    (yoe + era * 400 + i64::from(m <= 2), m, d)
}

/// The local offset from UTC at `secs`, in seconds (summer time
/// included; the system's, see `platform::os`).
pub use crate::platform::os::utc_offset;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dates_offsets_and_leap_days() {
        assert_eq!(format(0, 0), "1970-01-01 00:00:00");
        assert_eq!(format(1_795_314_912, 0), "2026-11-22 02:35:12");
        assert_eq!(format(1_795_314_912, 3600), "2026-11-22 03:35:12");
        assert_eq!(format(1_795_314_912, -3 * 3600), "2026-11-21 23:35:12");
        assert_eq!(format(951_782_400, 0), "2000-02-29 00:00:00");
        assert_eq!(format_offset(3600), "+01:00");
        assert_eq!(format_offset(-(5 * 3600 + 1800)), "-05:30");
        assert_eq!(format_offset(0), "+00:00");
    }

    #[test]
    fn local_time_is_utc_shifted_by_the_offset_it_names() {
        let t = 1_795_314_912;
        let text = local(t);
        let offset = utc_offset(t);
        assert_eq!(
            text,
            format!("{} {}", format(t, offset), format_offset(offset))
        );
        assert!(offset.abs() <= 14 * 3600, "{offset}");
    }
}
