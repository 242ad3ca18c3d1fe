//! Memory of the full-screen saver while its monitors change again and
//! again (issue 22 item 5), under a private Xvfb whose monitors the test
//! sets with RandR.
#![cfg(unix)]

use crate::common::xvfb;

use crate::common::randr;

use std::time::{Duration, Instant};

use xvfb::{Geometry, PATIENCE, Saver, Xvfb, looks_drawn, poll};

/// The screen the storms play on.
const SCREEN: (u16, u16) = (3840, 1080);

/// 31 layouts of the screen: one to four monitors side by side, of
/// changing widths (given in 3-pixel units), so that windows open, close,
/// move and resize. The last covers the whole screen, as at the start.
fn layouts() -> Vec<Vec<Geometry>> {
    let splits: [&[u16]; 31] = [
        &[1280],
        &[640, 640],
        &[320, 960],
        &[960, 320],
        &[400, 400, 480],
        &[1280],
        &[320, 320, 320, 320],
        &[800, 480],
        &[200, 1080],
        &[640, 320, 320],
        &[1000, 280],
        &[1280],
        &[512, 256, 512],
        &[300, 300, 680],
        &[700, 580],
        &[240, 240, 400, 400],
        &[1280],
        &[880, 400],
        &[160, 1120],
        &[640, 640],
        &[360, 560, 360],
        &[1100, 180],
        &[420, 860],
        &[1280],
        &[256, 256, 256, 512],
        &[600, 680],
        &[480, 800],
        &[960, 160, 160],
        &[340, 940],
        &[720, 560],
        &[1280],
    ];
    splits
        .iter()
        .map(|widths| {
            let mut left = 0i16;
            widths
                .iter()
                .map(|&w| {
                    let g = (left, 0, w * 3, SCREEN.1);
                    left += 3 * w as i16;
                    g
                })
                .collect()
        })
        .collect()
}

/// A number of the saver's /proc/PID/status (`VmRSS:` in KiB, `Threads:`).
fn status_number(saver: &Saver, field: &str) -> u64 {
    let status = std::fs::read_to_string(format!("/proc/{}/status", saver.pid())).unwrap();
    status
        .lines()
        .find_map(|l| l.strip_prefix(field))
        .and_then(|v| v.trim().trim_end_matches("kB").trim().parse().ok())
        .unwrap_or_else(|| panic!("no {field} in /proc/PID/status"))
}

/// Sets each layout in turn, waiting until the saver's windows cover it.
/// `defined`: how many monitors the last layout defined.
fn storm(x: &Xvfb, saver: &mut Saver, defined: &mut usize) {
    for layout in layouts() {
        randr::delete_monitors(&x.conn, x.root, 0, *defined);
        randr::set_monitors(&x.conn, x.root, &layout, None);
        *defined = layout.len();
        randr::announce_change(&x.conn, x.root);
        let what = format!("the windows to follow {layout:?}");
        poll(saver, &what, || x.mapped_places() == layout);
    }
}

/// CPU time the saver has used so far, in clock ticks.
fn cpu_ticks(pid: u32) -> u64 {
    let stat = std::fs::read_to_string(format!("/proc/{pid}/stat")).unwrap();
    // utime and stime: fields 14 and 15, the 12th and 13th after the name.
    let after_name = &stat[stat.rfind(')').expect("a stat line") + 1..];
    let fields: Vec<&str> = after_name.split_whitespace().collect();
    fields[11].parse::<u64>().unwrap() + fields[12].parse::<u64>().unwrap()
}

/// Whether any of the saver's threads is running or waiting for a core
/// (state `R`): a saver starved of CPU by other tests uses no time, yet is
/// not at rest.
fn any_thread_runnable(pid: u32) -> bool {
    let Ok(tasks) = std::fs::read_dir(format!("/proc/{pid}/task")) else {
        return false;
    };
    tasks.flatten().any(|task| {
        let stat = std::fs::read_to_string(task.path().join("stat")).unwrap_or_default();
        let state = stat.rfind(')').map(|i| stat[i + 1..].trim_start());
        state.is_some_and(|s| s.starts_with('R'))
    })
}

/// Waits until the whole screen shows a mountain and the saver has been at
/// rest (no CPU time used, no thread runnable) for a quarter of a second: the hold, with no
/// work left over from windows and sizes that are gone. Fails, telling the
/// threads and memory of the moment, when that takes longer than `PATIENCE`.
fn at_rest(x: &Xvfb, saver: &mut Saver) {
    let whole = (0, 0, SCREEN.0, SCREEN.1);
    let pid = saver.pid();
    let start = Instant::now();
    let mut quiet_since = (Instant::now(), cpu_ticks(pid));
    while start.elapsed() < PATIENCE {
        saver.assert_running();
        std::thread::sleep(Duration::from_millis(20));
        let ticks = cpu_ticks(pid);
        if ticks > quiet_since.1 + 1 || any_thread_runnable(pid) {
            quiet_since = (Instant::now(), ticks);
        } else if quiet_since.0.elapsed() >= QUIET && looks_drawn(&x.grab_rect(whole)) {
            return;
        }
    }
    panic!(
        "the saver is still at work {PATIENCE:?} after the storm, with {} threads and {} KiB resident",
        status_number(saver, "Threads:"),
        status_number(saver, "VmRSS:")
    );
}

/// How long the saver must use no CPU to count as at rest.
const QUIET: Duration = Duration::from_millis(250);

/// Six storms of 31 layouts each: once the saver is at rest again after
/// each storm, its resident memory comes back to where it came back to
/// after the second and third (the first may still settle allocator
/// pools). Before the fix, every resize
/// started a redraw on a thread of its own and a closed window's redraw ran
/// on: 3840x1080 storms left the saver busy for a minute with up to 390 MB
/// of frames and scenes nobody would see.
#[test]
fn display_fullscreen_memory_stays_flat_through_monitor_storms() {
    let Some(x) = Xvfb::start(SCREEN.0, SCREEN.1, &[]) else {
        return;
    };
    let args = ["/s", "--set", "pause_seconds=60"];
    let mut saver = Saver::start(&x, "churn", &args, &[]);
    at_rest(&x, &mut saver);
    eprintln!(
        "before the storms: VmRSS {} KiB",
        status_number(&saver, "VmRSS:")
    );
    let mut defined = 0;
    let mut after = Vec::new();
    for n in 1..=6 {
        storm(&x, &mut saver, &mut defined);
        at_rest(&x, &mut saver);
        let rss = status_number(&saver, "VmRSS:");
        eprintln!("after storm {n}: VmRSS {rss} KiB");
        after.push(rss);
    }
    // A leak raises the floor the resident memory comes back to, storm
    // after storm; the allocator's pools move the level between storms by
    // up to 6 MiB either way (one run: 61.9, 67.7, 61.0, 66.1, 61.7, 61.5
    // MiB), so each end is the lesser of two storms'. The bound is the one
    // before, a MiB a storm: three storms apart, 3 MiB.
    let floor = |a: usize, b: usize| after[a].min(after[b]);
    let growth = floor(4, 5).saturating_sub(floor(1, 2));
    assert!(
        growth <= 3 * 1024,
        "resident memory's floor grew by {growth} KiB from storms 2-3 to storms 5-6: {after:?} KiB"
    );
    saver.assert_running();
}
