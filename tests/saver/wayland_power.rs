//! Display-off and idle on a headless sway: an output powered off stops
//! all work, told by wlr-output-power-management; and the saver never
//! keeps the session awake (swayidle still times out while it runs).
//!
//! sway 1.7's headless outputs fail to commit `swaymsg output NAME dpms
//! off` ("Failed to commit output", no mode event): the proxy of
//! common/wl_proxy.rs plays the compositor's `zwlr_output_power_v1.mode`
//! events instead, as sway sends them for a real output.
#![cfg(target_os = "linux")]

use std::time::Duration;

use crate::common::power::cpu_ticks;
use crate::common::sway::Sway;
use crate::common::wl_proxy::{Edit, WlProxy};

/// CPU ticks (1/100 s) a saver with its display off may use while watched.
const OFF_TICKS: u64 = 1;

/// How long the saver is watched with its display off.
const OFF_FOR: Duration = Duration::from_secs(20);

/// The saver's last word of its display in its log: `on` or `off`.
fn display_said_last(sway: &Sway) -> Option<&'static str> {
    let log = sway.runtime_path("home/data/mountains/mountains.log");
    let text = std::fs::read_to_string(log).ok()?;
    let said = |l: &str, word: &str| l.trim_end().ends_with(&format!("display: {word}"));
    let last = text
        .lines()
        .rev()
        .find(|l| said(l, "on") || said(l, "off"))?;
    Some(if said(last, "off") { "off" } else { "on" })
}

/// True when more than a tenth of the output differs from black.
fn something_shown(sway: &Sway) -> bool {
    let (_, _, pixels) = sway.screenshot();
    pixels.iter().filter(|&&p| p & 0xff_ffff != 0).count() * 10 > pixels.len()
}

/// `mountains ARGS` (slides every 1.5 s) through the proxy: with the
/// output powered off it does nothing at all; powered on again, it draws
/// a fresh slide at once.
fn output_off_stops_all_work(name: &str, args: &[&str]) {
    let Some(sway) = Sway::start(name, 640, 480, 1, false) else {
        return;
    };
    let proxy = WlProxy::start(
        &sway.runtime_path("wayland-proxy"),
        &sway.socket_path(),
        Edit::Nothing,
    );
    let mut saver = sway.mountains_via("wayland-proxy", args);
    saver.poll("a mountain on the output", || something_shown(&sway));
    // The proxy tells only the power objects the compositor has answered:
    // its first word ("on") came after ours once, on a loaded machine,
    // and the saver drew on (159 ticks in 20 s).
    saver.poll("the output's power off, as the log says last", || {
        proxy.set_output_power(false) > 0 && display_said_last(&sway) == Some("off")
    });
    // Within 2 s of the switch: a strip or a slide under way ends.
    std::thread::sleep(Duration::from_secs(2));
    let pid = saver.pid();
    let before = cpu_ticks(pid);
    std::thread::sleep(OFF_FOR);
    let used = cpu_ticks(pid) - before;
    eprintln!("{name}: output off, {used} CPU ticks in {OFF_FOR:?}");
    saver.assert_running();
    let last = display_said_last(&sway);
    assert!(
        used <= OFF_TICKS,
        "{used} CPU ticks in {OFF_FOR:?} with the output off (at most {OFF_TICKS}; \
         the log's last word of the display: {last:?})"
    );
    proxy.set_output_power(true);
    saver.poll("'display: on' last in mountains.log", || {
        display_said_last(&sway) == Some("on")
    });
    let back = cpu_ticks(pid);
    let took = saver.poll("drawing again with the output on", || cpu_ticks(pid) > back);
    eprintln!("{name}: output on, drawing after {took:?}");
    saver.poll("a mountain on the output again", || something_shown(&sway));
}

#[test]
fn wayland_fullscreen_does_no_work_while_the_output_is_off() {
    output_off_stops_all_work("power-fs", &["/s"]);
}

#[test]
fn wayland_layer_does_no_work_while_the_output_is_off() {
    output_off_stops_all_work("power-layer", &["--layer", "background"]);
}

/// swayidle's view: the session still goes idle while `/s` runs (no idle
/// inhibitor, no fake input).
#[test]
fn wayland_fullscreen_lets_the_session_go_idle() {
    let Some(sway) = Sway::start("power-idle", 640, 480, 1, false) else {
        return;
    };
    let mut saver = sway.mountains(&["/s"]);
    saver.poll("a mountain on the output", || something_shown(&sway));
    let idle = sway.runtime_path("idle");
    let touch = format!("touch {}", idle.display());
    let mut swayidle = sway
        .command("swayidle")
        .args(["-w", "timeout", "2", &touch])
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .spawn()
        .expect("start swayidle (apt-get install swayidle)");
    let took = saver.poll("swayidle's timeout with the saver running", || {
        idle.exists()
    });
    let _ = swayidle.kill();
    let _ = swayidle.wait();
    eprintln!("idle after {took:?} (timeout 2 s)");
    saver.assert_running();
}
