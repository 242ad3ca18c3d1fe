//! Linux: the power supplies in sysfs (`/sys/class/power_supply/*`), the
//! firmware's platform profile (`/sys/firmware/acpi/platform_profile`) and
//! power-profiles-daemon's saved state. Plain files, read every few
//! seconds: no D-Bus connection (a D-Bus crate is heavy, and UPower itself
//! reads these same files).
//!
//! For tests only, `MOUNTAINS_SYSFS_ROOT` stands in for `/sys` and
//! `MOUNTAINS_PPD_STATE` for power-profiles-daemon's state file.

use std::path::{Path, PathBuf};

use super::Power;

/// Where power-profiles-daemon keeps the profile chosen (it writes the file
/// on every change; readable by all).
const PPD_STATE: &str = "/var/lib/power-profiles-daemon/state.ini";

/// The power as sysfs and power-profiles-daemon report it now.
pub fn read() -> Power {
    let sys = root();
    let ppd =
        std::env::var_os("MOUNTAINS_PPD_STATE").map_or_else(|| PPD_STATE.into(), PathBuf::from);
    read_from(&sys, &ppd)
}

/// The sysfs root: `/sys`, or `MOUNTAINS_SYSFS_ROOT` in tests.
fn root() -> PathBuf {
    std::env::var_os("MOUNTAINS_SYSFS_ROOT").map_or_else(|| "/sys".into(), PathBuf::from)
}

/// The power as the sysfs tree at `sys` and the state file `ppd` say.
pub fn read_from(sys: &Path, ppd: &Path) -> Power {
    let supplies = supplies(&sys.join("class/power_supply"));
    let profile = read_trimmed(&sys.join("firmware/acpi/platform_profile"));
    Power {
        on_battery: on_battery(&supplies),
        saver: profile.as_deref() == Some("low-power") || ppd_saver(ppd),
    }
}

/// One entry of `/sys/class/power_supply`.
#[derive(Debug, Default)]
struct Supply {
    kind: String,
    online: bool,
    status: String,
    /// `Device`: a mouse's or a headset's battery, not the system's.
    device_scope: bool,
}

impl Supply {
    fn is_battery(&self) -> bool {
        self.kind == "Battery"
    }
}

/// Every supply of the system (not of its devices), in no order.
fn supplies(dir: &Path) -> Vec<Supply> {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return Vec::new();
    };
    entries
        .flatten()
        .filter_map(|e| supply(&e.path()))
        .filter(|s| !s.device_scope)
        .collect()
}

/// The supply at `dir`, reading only the files its type needs (the saver
/// looks every few seconds for hours).
fn supply(dir: &Path) -> Option<Supply> {
    let kind = read_trimmed(&dir.join("type")).filter(|k| !k.is_empty())?;
    let mut supply = Supply {
        kind,
        ..Supply::default()
    };
    if supply.is_battery() {
        supply.device_scope = read_trimmed(&dir.join("scope")).as_deref() == Some("Device");
        supply.status = read_trimmed(&dir.join("status")).unwrap_or_default();
    } else {
        supply.online = read_trimmed(&dir.join("online")).as_deref() == Some("1");
    }
    Some(supply)
}

/// On battery: a system battery and no mains (or USB) supply online. A
/// machine whose supplies list no mains at all tells by the battery's own
/// status. A desktop without a battery is never on battery.
fn on_battery(supplies: &[Supply]) -> bool {
    let batteries: Vec<&Supply> = supplies.iter().filter(|s| s.is_battery()).collect();
    if batteries.is_empty() {
        return false;
    }
    let mains: Vec<&Supply> = supplies.iter().filter(|s| !s.is_battery()).collect();
    if mains.is_empty() {
        return batteries.iter().any(|b| b.status == "Discharging");
    }
    !mains.iter().any(|m| m.online)
}

/// power-profiles-daemon's saved profile is `power-saver`.
fn ppd_saver(path: &Path) -> bool {
    let Some(text) = std::fs::read_to_string(path).ok() else {
        return false;
    };
    let mut in_state = false;
    for line in text.lines().map(str::trim) {
        if line.starts_with('[') {
            in_state = line == "[State]";
        } else if in_state
            && let Some((key, value)) = line.split_once('=')
            && key.trim() == "Profile"
        {
            return value.trim() == "power-saver";
        }
    }
    false
}

fn read_trimmed(path: &Path) -> Option<String> {
    std::fs::read_to_string(path)
        .ok()
        .map(|s| s.trim().to_owned())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn supply(kind: &str, online: bool, status: &str) -> Supply {
        Supply {
            kind: kind.into(),
            online,
            status: status.into(),
            device_scope: false,
        }
    }

    #[test]
    fn mains_online_means_not_on_battery() {
        let s = [
            supply("Mains", true, ""),
            supply("Battery", false, "Discharging"),
        ];
        assert!(!on_battery(&s));
        let s = [
            supply("Mains", false, ""),
            supply("Battery", false, "Charging"),
        ];
        assert!(
            on_battery(&s),
            "no mains online: on battery whatever it says"
        );
        let s = [supply("Mains", false, ""), supply("USB", true, "")];
        assert!(!on_battery(&s), "no battery: never on battery");
    }

    #[test]
    fn without_a_mains_entry_the_battery_status_tells() {
        assert!(on_battery(&[supply("Battery", false, "Discharging")]));
        assert!(!on_battery(&[supply("Battery", false, "Full")]));
    }

    #[test]
    fn the_state_file_names_the_profile() {
        let dir = std::env::temp_dir().join(format!("mountains-ppd-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("state.ini");
        std::fs::write(&path, "[State]\nDriver=placeholder\nProfile=power-saver\n").unwrap();
        assert!(ppd_saver(&path));
        std::fs::write(&path, "[State]\nProfile=balanced\n").unwrap();
        assert!(!ppd_saver(&path));
        std::fs::write(&path, "[Other]\nProfile=power-saver\n").unwrap();
        assert!(!ppd_saver(&path));
        assert!(!ppd_saver(&dir.join("missing")));
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
