//! The power as Windows reports it, under Wine: `/s` asks
//! GetSystemPowerStatus and registers for the console display state
//! (PowerSettingRegisterNotification, imported from powrprof.dll: the exe
//! must still load), and writes what it sees to mountains.log. Wine reads
//! this machine's power supplies; what a real battery and a screen turned
//! off do is on docs/windows-checklist.md.
#![cfg(unix)]

use std::path::{Path, PathBuf};

use crate::common::wine::Session;
use crate::common::xvfb::{Xvfb, looks_drawn, poll};

/// Every `mountains.log` under the Wine prefix's user folders.
fn logs(prefix: &Path) -> Vec<PathBuf> {
    let users = prefix.join("drive_c/users");
    let Ok(users) = std::fs::read_dir(users) else {
        return Vec::new();
    };
    users
        .flatten()
        .map(|u| {
            u.path()
                .join("AppData/Roaming/mountains/data/mountains.log")
        })
        .filter(|p| p.exists())
        .collect()
}

#[test]
#[ignore = "needs Wine, mingw and the cross-built exe: sh scripts/wine_test.sh"]
fn display_wine_fullscreen_logs_the_power_windows_reports() {
    let Some(session) = Session::begin() else {
        return;
    };
    let wine = session.wine;
    let env = wine.env();
    let prefix = PathBuf::from(&env.iter().find(|(k, _)| *k == "WINEPREFIX").unwrap().1);
    for log in logs(&prefix) {
        std::fs::remove_file(log).unwrap();
    }
    let Some(x) = Xvfb::start(320, 240, &[]) else {
        return;
    };
    let args = ["/s", "--set", "draw_seconds=0.5"];
    let mut saver = session.start(&x, "wine-power", "mountains.exe", &args);
    poll(&mut saver, "a mountain on the screen", || {
        looks_drawn(&x.grab_screen())
    });
    let text = || {
        logs(&prefix)
            .iter()
            .filter_map(|p| std::fs::read_to_string(p).ok())
            .collect::<String>()
    };
    poll(&mut saver, "the power in mountains.log", || {
        text().contains("power: on ")
    });
    let said = text();
    eprintln!("Wine's mountains.log:\n{said}");
    assert!(!said.contains("not followed"), "{said}");
    saver.assert_running();
}
