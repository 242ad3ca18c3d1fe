//! Windows: `GetSystemPowerStatus`, the AC line and the battery-saver flag.
//! What its fields mean is plain data, built (and tested) everywhere.

#[cfg(windows)]
use windows_sys::Win32::System::Power::{GetSystemPowerStatus, SYSTEM_POWER_STATUS};

use super::Power;

/// `ACLineStatus`: offline, that is on battery.
const AC_OFFLINE: u8 = 0;
/// `SystemStatusFlag`: battery saver is on.
const SAVER_ON: u8 = 1;

/// The power as Windows reports it now; mains if it cannot say.
#[cfg(windows)]
pub fn read() -> Power {
    // SAFETY: plain data, filled in by the call.
    let mut status: SYSTEM_POWER_STATUS = unsafe { std::mem::zeroed() };
    // SAFETY: a pointer to a live struct of the right type.
    if unsafe { GetSystemPowerStatus(&mut status) } == 0 {
        return Power::default();
    }
    from_status(status.ACLineStatus, status.SystemStatusFlag)
}

/// The power for `GetSystemPowerStatus`'s AC line (0 off, 1 on, 255
/// unknown) and system status flag.
pub fn from_status(ac_line: u8, flag: u8) -> Power {
    Power {
        on_battery: ac_line == AC_OFFLINE,
        saver: flag == SAVER_ON,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_an_ac_line_offline_is_a_battery() {
        assert!(from_status(0, 0).on_battery);
        assert!(!from_status(1, 0).on_battery);
        assert!(!from_status(255, 0).on_battery, "unknown counts as mains");
        assert!(from_status(1, 1).saver);
        assert!(!from_status(0, 0).saver);
    }
}
