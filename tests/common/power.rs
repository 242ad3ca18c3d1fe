//! Test helpers for the power tests: a fake sysfs tree (power supplies and
//! the platform profile) and power-profiles-daemon state file that the
//! program reads instead of the real ones (`MOUNTAINS_SYSFS_ROOT`,
//! `MOUNTAINS_PPD_STATE`), and the CPU time a process has used.
#![allow(dead_code)]

use std::path::{Path, PathBuf};

/// A fake `/sys` with a mains supply `AC` and a battery `BAT0`; removed on drop.
pub struct FakeSysfs {
    root: PathBuf,
}

impl FakeSysfs {
    /// A tree on mains power, balanced profile.
    pub fn new(name: &str) -> FakeSysfs {
        let root =
            std::env::temp_dir().join(format!("mountains-sysfs-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&root);
        let fake = FakeSysfs { root };
        fake.write("class/power_supply/AC/type", "Mains");
        fake.write("class/power_supply/BAT0/type", "Battery");
        fake.write("class/power_supply/BAT0/scope", "System");
        // A wireless mouse's battery: never the system's.
        fake.write("class/power_supply/hidpp_battery_0/type", "Battery");
        fake.write("class/power_supply/hidpp_battery_0/scope", "Device");
        fake.write("class/power_supply/hidpp_battery_0/status", "Discharging");
        fake.write("firmware/acpi/platform_profile", "balanced");
        fake.write(
            "ppd/state.ini",
            "[State]\nDriver=platform_profile\nProfile=balanced\n",
        );
        fake.on_battery(false);
        fake
    }

    /// Unplugs (true) or plugs in (false) the mains supply.
    pub fn on_battery(&self, battery: bool) {
        self.write(
            "class/power_supply/AC/online",
            if battery { "0" } else { "1" },
        );
        let status = if battery { "Discharging" } else { "Charging" };
        self.write("class/power_supply/BAT0/status", status);
    }

    /// Sets the firmware's platform profile (`low-power`, `balanced`).
    pub fn platform_profile(&self, profile: &str) {
        self.write("firmware/acpi/platform_profile", profile);
    }

    /// Sets power-profiles-daemon's saved profile (`power-saver`, `balanced`).
    pub fn ppd_profile(&self, profile: &str) {
        self.write(
            "ppd/state.ini",
            &format!("[State]\nDriver=platform_profile\nProfile={profile}\n"),
        );
    }

    /// The variables that point the program at this tree.
    pub fn env(&self) -> Vec<(&'static str, String)> {
        vec![
            ("MOUNTAINS_SYSFS_ROOT", self.root.display().to_string()),
            (
                "MOUNTAINS_PPD_STATE",
                self.root.join("ppd/state.ini").display().to_string(),
            ),
        ]
    }

    /// Writes `text` to `path` under the root at once (a rename, as the
    /// kernel's files never show half a value).
    fn write(&self, path: &str, text: &str) {
        let path = self.root.join(path);
        std::fs::create_dir_all(path.parent().unwrap()).unwrap();
        let tmp = path.with_extension("tmp");
        std::fs::write(&tmp, format!("{text}\n")).unwrap();
        std::fs::rename(&tmp, &path).unwrap();
    }

    /// The root, for tests that read it themselves.
    pub fn root(&self) -> &Path {
        &self.root
    }
}

impl Drop for FakeSysfs {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.root);
    }
}

/// CPU time process `pid` has used so far, all its threads, in clock ticks
/// (user + system, from `/proc/PID/stat`).
pub fn cpu_ticks(pid: u32) -> u64 {
    let stat = std::fs::read_to_string(format!("/proc/{pid}/stat")).expect("/proc/PID/stat");
    // The command name may hold spaces and parentheses: fields start after the last ')'.
    let fields: Vec<&str> = stat[stat.rfind(')').unwrap() + 1..]
        .split_whitespace()
        .collect();
    // utime and stime are fields 14 and 15 of the line; here state (3) is first.
    let ticks = |i: usize| fields[i].parse::<u64>().expect("a tick count");
    ticks(11) + ticks(12)
}

/// The lines of the program's log file (`mountains.log` in `data_dir`).
pub fn log_text(data_dir: &Path) -> String {
    std::fs::read_to_string(data_dir.join("mountains.log")).unwrap_or_default()
}
