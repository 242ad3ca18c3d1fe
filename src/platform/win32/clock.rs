//! The local offset from UTC, from Windows' time zone settings.

/// The local offset from UTC now, in seconds (summer time included).
pub fn utc_offset(_secs: u64) -> i64 {
    use windows_sys::Win32::System::Time::{GetTimeZoneInformation, TIME_ZONE_INFORMATION};
    // SAFETY: the call fills the structure we own and nothing else.
    let (state, tz) = unsafe {
        let mut tz: TIME_ZONE_INFORMATION = std::mem::zeroed();
        (GetTimeZoneInformation(&mut tz), tz)
    };
    // 1: standard time, 2: summer time; the bias is minutes *behind* UTC.
    let extra = match state {
        1 => tz.StandardBias,
        2 => tz.DaylightBias,
        _ => 0,
    };
    -i64::from(tz.Bias + extra) * 60
}
