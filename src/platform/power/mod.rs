//! Where the power comes from: mains or battery, and whether the system
//! asks for economy (a power-saver profile, Windows' battery saver). The
//! saver reads it every few seconds (`saver::watch`) and, by the
//! `on_battery` key, holds or slows its slide show.
//!
//! Linux reads sysfs and power-profiles-daemon's state file (`sysfs.rs`);
//! Windows asks `GetSystemPowerStatus` (`windows.rs`). Elsewhere the power
//! is taken to be mains.

#[cfg(target_os = "linux")]
pub mod sysfs;
pub mod windows;

/// What the system says about its power at one moment.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Power {
    /// Running on a battery: no mains supply is online.
    pub on_battery: bool,
    /// The system asks programs to save energy (power-saver profile,
    /// battery saver), whatever the supply.
    pub saver: bool,
}

impl Power {
    /// True when the `on_battery` key applies: on battery, or in power-saver mode.
    pub fn economy(self) -> bool {
        self.on_battery || self.saver
    }

    /// The state in words, as the log file records it.
    pub fn describe(self) -> &'static str {
        match (self.on_battery, self.saver) {
            (false, false) => "on mains power",
            (false, true) => "on mains power, in power-saver mode",
            (true, false) => "on battery",
            (true, true) => "on battery, in power-saver mode",
        }
    }
}

/// The power as the system reports it now; mains where it cannot tell.
pub fn read() -> Power {
    #[cfg(target_os = "linux")]
    return sysfs::read();
    #[cfg(windows)]
    return windows::read();
    #[cfg(not(any(target_os = "linux", windows)))]
    Power::default()
}
