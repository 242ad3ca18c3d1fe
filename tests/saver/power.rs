//! Power and display-off under Xvfb: the power state read from a fake
//! sysfs tree, acted on by the `on_battery` key and written to the log;
//! no work at all while held (CPU ticks from /proc, not wall-clock limits).
#![cfg(target_os = "linux")]

use std::time::Duration;

use crate::common::power::{FakeSysfs, cpu_ticks, log_text};
use crate::common::x_dpms::XDpms;
use crate::common::xvfb::{Saver, Xvfb, looks_drawn, poll};

/// CPU ticks (1/100 s) a saver holding a slide may use in a minute: the
/// watcher's look at the power every three seconds, a few file reads each.
const IDLE_TICKS_PER_MINUTE: u64 = 2;

/// How long the held saver is watched doing nothing.
const HELD_FOR: Duration = Duration::from_secs(60);

fn start(x: &Xvfb, name: &str, sys: &FakeSysfs, args: &[&str]) -> Saver {
    let env = sys.env();
    let env: Vec<(&str, &str)> = env.iter().map(|(k, v)| (*k, v.as_str())).collect();
    Saver::start(x, name, args, &env)
}

/// Waits until the log says `words`.
fn wait_for_log(saver: &mut Saver, words: &str) {
    let data = saver.data_dir();
    poll(saver, &format!("'{words}' in mountains.log"), || {
        log_text(&data).contains(words)
    });
}

/// The screen once the slide in progress is finished: the same for a
/// second (0.5 s of drawing; a loaded machine may take longer).
fn held_slide(saver: &mut Saver, x: &Xvfb) -> Vec<u32> {
    let mut last = x.grab_screen();
    poll(saver, "the slide finished and held", || {
        std::thread::sleep(Duration::from_secs(1));
        let now = x.grab_screen();
        let same = now == last;
        last = now;
        same
    });
    last
}

/// On battery with the default `on_battery = "hold"`: the first slide is
/// drawn whole, then held with no work for a minute (with a 1 s pause, 40
/// slides would have come); back on mains the slide show goes on.
#[test]
fn display_on_battery_the_slide_is_finished_then_held_with_no_work() {
    let Some(x) = Xvfb::start(640, 480, &[]) else {
        return;
    };
    let sys = FakeSysfs::new("hold");
    sys.on_battery(true);
    let mut saver = start(&x, "battery-hold", &sys, &["/s"]);
    wait_for_log(&mut saver, "power: on battery");
    poll(&mut saver, "a mountain on the screen", || {
        looks_drawn(&x.grab_screen())
    });
    let held = held_slide(&mut saver, &x);
    let before = cpu_ticks(saver.pid());
    std::thread::sleep(HELD_FOR);
    let used = cpu_ticks(saver.pid()) - before;
    eprintln!("on battery, held: {used} CPU ticks in {HELD_FOR:?}");
    saver.assert_running();
    assert!(x.grab_screen() == held, "the slide changed on battery");
    assert!(
        used <= IDLE_TICKS_PER_MINUTE,
        "{used} CPU ticks in {HELD_FOR:?} while held on battery (at most {IDLE_TICKS_PER_MINUTE})"
    );
    sys.on_battery(false);
    wait_for_log(&mut saver, "power: on mains power");
    poll(&mut saver, "a new slide once the power is back", || {
        x.grab_screen() != held
    });
}

/// `on_battery = "same"`: the slide show goes on as on mains.
#[test]
fn display_on_battery_same_goes_on() {
    let Some(x) = Xvfb::start(320, 240, &[]) else {
        return;
    };
    let sys = FakeSysfs::new("same");
    sys.on_battery(true);
    let args = ["/s", "--set", "on_battery=same"];
    let mut saver = start(&x, "battery-same", &sys, &args);
    wait_for_log(&mut saver, "power: on battery");
    poll(&mut saver, "a mountain on the screen", || {
        looks_drawn(&x.grab_screen())
    });
    std::thread::sleep(Duration::from_secs(1));
    let first = x.grab_screen();
    poll(&mut saver, "the next slide on battery", || {
        x.grab_screen() != first
    });
}

/// Power-saver mode counts as on battery, from the firmware's platform
/// profile or from power-profiles-daemon's state, and the log says so.
#[test]
fn display_power_saver_mode_holds_like_a_battery() {
    let Some(x) = Xvfb::start(320, 240, &[]) else {
        return;
    };
    let sys = FakeSysfs::new("saver");
    sys.ppd_profile("power-saver");
    let mut saver = start(&x, "power-saver", &sys, &["--root"]);
    wait_for_log(&mut saver, "power: on mains power, in power-saver mode");
    poll(&mut saver, "a mountain on the screen", || {
        looks_drawn(&x.grab_screen())
    });
    let held = held_slide(&mut saver, &x);
    // With a 1 s pause four slides would come.
    std::thread::sleep(Duration::from_secs(6));
    assert!(
        x.grab_screen() == held,
        "the slide changed in power-saver mode"
    );
    sys.ppd_profile("balanced");
    sys.platform_profile("low-power");
    std::thread::sleep(Duration::from_secs(3));
    assert!(
        x.grab_screen() == held,
        "the slide changed with the platform profile at low-power"
    );
    sys.platform_profile("balanced");
    wait_for_log(&mut saver, "power: on mains power\n");
    poll(&mut saver, "a new slide out of power-saver mode", || {
        x.grab_screen() != held
    });
}

/// The X server's idle time (MIT-SCREEN-SAVER, as idle daemons and
/// xscreensaver's idle timer see it) grows while `/s` runs: no fake
/// input, no screen-saver reset keeps the display awake.
#[test]
fn display_fullscreen_lets_the_x_server_count_idle_time() {
    use x11rb::connection::RequestConnection;
    use x11rb::protocol::screensaver::{self, ConnectionExt as _};
    let Some(x) = Xvfb::start(320, 240, &[]) else {
        return;
    };
    let has = x
        .conn
        .extension_information(screensaver::X11_EXTENSION_NAME);
    assert!(has.ok().flatten().is_some(), "Xvfb has no MIT-SCREEN-SAVER");
    let idle = || {
        let info = x
            .conn
            .screensaver_query_info(x.root)
            .unwrap()
            .reply()
            .unwrap();
        info.ms_since_user_input
    };
    let sys = FakeSysfs::new("idle");
    let mut saver = start(&x, "idle", &sys, &["/s"]);
    poll(&mut saver, "a mountain on the screen", || {
        looks_drawn(&x.grab_screen())
    });
    let first = idle();
    // Slides come and go meanwhile (a 1 s pause).
    std::thread::sleep(Duration::from_secs(4));
    let then = idle();
    eprintln!("X server idle: {first} ms, then {then} ms");
    saver.assert_running();
    assert!(
        then >= first + 3000,
        "the idle time was reset while the saver ran: {first} ms, then {then} ms"
    );
}

/// DPMS off (an X server with DPMS: common/x_dpms.rs in front of Xvfb):
/// no work at all while the monitor is off; when it is on again a fresh
/// slide is drawn. Full screen, a slide every 1.5 s.
#[test]
fn display_dpms_off_stops_all_work_and_a_fresh_slide_follows() {
    let Some(x) = Xvfb::start(640, 480, &[]) else {
        return;
    };
    let dpms = XDpms::start(x.display());
    let sys = FakeSysfs::new("dpms");
    let mut env = sys.env();
    env.push(("DISPLAY", dpms.display().to_string()));
    let env: Vec<(&str, &str)> = env.iter().map(|(k, v)| (*k, v.as_str())).collect();
    let mut saver = Saver::start(&x, "dpms", &["/s"], &env);
    poll(&mut saver, "a mountain on the screen", || {
        looks_drawn(&x.grab_screen())
    });
    dpms.set_power(false);
    wait_for_log(&mut saver, "display: off");
    // Within 2 s of the switch: a strip or a slide under way ends.
    std::thread::sleep(Duration::from_secs(2));
    let shown = x.grab_screen();
    let before = cpu_ticks(saver.pid());
    std::thread::sleep(OFF_FOR);
    let used = cpu_ticks(saver.pid()) - before;
    eprintln!("DPMS off: {used} CPU ticks in {OFF_FOR:?}");
    saver.assert_running();
    assert!(x.grab_screen() == shown, "drew with the monitor off");
    assert!(
        used <= OFF_TICKS,
        "{used} CPU ticks in {OFF_FOR:?} with the monitor off (at most {OFF_TICKS})"
    );
    dpms.set_power(true);
    wait_for_log(&mut saver, "display: on");
    let took = poll(&mut saver, "a fresh slide with the monitor on", || {
        x.grab_screen() != shown
    });
    eprintln!("DPMS on: a new picture after {took:?}");
}

/// CPU ticks (1/100 s) a saver with the monitor off may use while watched:
/// a DPMS request a second and the power every three (0 or 1 were seen).
const OFF_TICKS: u64 = 2;

/// How long the saver is watched with the monitor off.
const OFF_FOR: Duration = Duration::from_secs(20);
