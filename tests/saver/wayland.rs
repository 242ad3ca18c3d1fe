//! The window modes on a real Wayland compositor: a private headless sway
//! (sway, grim, wtype; Xwayland for the X11 path). Each test starts its
//! own compositor; common/wl_proxy.rs plays what sway 1.7 cannot (no
//! layer shell, an output unplugged, surfaces closed). Without the tools the tests fail, or skip with
//! MOUNTAINS_SKIP_MISSING=1; CI sets MOUNTAINS_REQUIRE_WAYLAND=1.
#![cfg(target_os = "linux")]

use crate::common::headless;
use crate::common::sway;
use crate::common::wl_pointer;
use crate::common::wl_proxy;

use headless::headless_render;
use sway::{Client, Sway};
use wl_pointer::VirtualPointer;
use wl_proxy::{Edit, WlProxy};

const W: u32 = 640;
const H: u32 = 480;

/// Share of pixels that differ from `before` (a screenshot of the empty output).
fn changed(before: &[u32], after: &[u32]) -> f64 {
    let n = before.iter().zip(after).filter(|(a, b)| a != b).count();
    n as f64 / before.len().max(1) as f64
}

/// `/s` with seed 5 held for a long time, once the finished mountain is
/// on the output exactly as `mountains render` makes it.
fn finished_fullscreen(sway: &Sway, what: &str) -> Client {
    let expected = headless_render(W as u16, H as u16);
    let args = ["/s", "--set", "seed=5", "--set", "pause_seconds=30"];
    let mut saver = sway.mountains(&args);
    let took = saver.poll(what, || sway.screenshot() == (W, H, expected.clone()));
    eprintln!("{what}: on the output after {took:?}");
    saver
}

#[test]
fn wayland_fullscreen_covers_the_output_with_every_strip_and_ends_on_a_key() {
    let Some(sway) = Sway::start("fs", W, H, 1, false) else {
        return;
    };
    // Exactly the headless render: every strip drawn, though the
    // compositor's buffers take turns (softbuffer's age 2).
    let mut saver = finished_fullscreen(&sway, "the finished mountain over the whole output");
    let tree = sway.tree();
    assert!(tree.contains("\"app_id\": \"mountains\""), "{tree}");
    assert!(tree.contains("\"fullscreen_mode\": 1"), "{tree}");
    sway.key("Escape");
    saver.expect_exit("Escape");
}

#[test]
fn wayland_fullscreen_draws_a_scaled_output_at_its_real_pixels() {
    // 640x480 pixels at scale 2: 320x240 in the compositor's units.
    let Some(sway) = Sway::start("scaled", W, H, 2, false) else {
        return;
    };
    let mut saver = finished_fullscreen(&sway, "the 640x480 mountain on the scale-2 output");
    saver.assert_running();
}

#[test]
fn wayland_fullscreen_ends_on_a_click_and_on_a_move_not_on_a_nudge() {
    let Some(sway) = Sway::start("pointer", W, H, 1, false) else {
        return;
    };
    let mut pointer = VirtualPointer::connect(&sway.socket_path()).expect("a virtual pointer");
    pointer.move_by(100.0, 100.0);
    let before = sway.screenshot().2;

    let mut saver = sway.mountains(&["/s"]);
    saver.poll("a mountain over the output", || {
        changed(&before, &sway.screenshot().2) > 0.9
    });
    pointer.move_by(3.0, 0.0);
    pointer.move_by(-3.0, 0.0);
    std::thread::sleep(std::time::Duration::from_millis(300));
    saver.assert_running();
    pointer.click();
    saver.expect_exit("a click");
    let said = saver.stderr();
    assert!(said.contains("ended by MouseInput"), "{said}");

    let mut saver = sway.mountains(&["/s"]);
    saver.poll("a mountain over the output", || {
        changed(&before, &sway.screenshot().2) > 0.9
    });
    pointer.move_by(20.0, 0.0);
    saver.expect_exit("a 20 px move");
    let said = saver.stderr();
    assert!(
        said.contains("ended by MouseMotion") || said.contains("ended by CursorMoved"),
        "{said}"
    );
}

#[test]
fn wayland_window_mode_draws_and_q_quits() {
    let Some(sway) = Sway::start("window", W, H, 1, false) else {
        return;
    };
    let before = sway.screenshot().2;
    let mut saver = sway.mountains(&["--window"]);
    // sway tiles the window over the whole output (no borders in the config).
    saver.poll("a mountain in the window", || {
        changed(&before, &sway.screenshot().2) > 0.9
    });
    let tree = sway.tree();
    assert!(tree.contains("\"app_id\": \"mountains\""), "{tree}");
    sway.key("q");
    saver.expect_exit("q");
}

/// Paused partway through drawing, the window shows exactly the frame
/// drawn so far (which P saves): no strip is missing from the buffer on
/// screen, whichever of softbuffer's two buffers it is. (A finished
/// mountain cannot show this: its last step repaints the whole frame.)
#[test]
fn wayland_window_paused_mid_drawing_shows_exactly_its_frame() {
    let Some(sway) = Sway::start("paused", W, H, 1, false) else {
        return;
    };
    // The first mountain is drawn at once when sway sizes the window; the
    // second, after a 1 s hold, strip by strip over 20 s.
    let finished = headless_render(W as u16, H as u16);
    let args = ["--window", "--set", "seed=5", "--set", "draw_seconds=20"];
    let mut saver = sway.mountains(&args);
    saver.poll("the first mountain", || {
        sway.screenshot() == (W, H, finished.clone())
    });
    saver.poll("the second mountain under way", || {
        sway.screenshot().2 != finished
    });
    std::thread::sleep(std::time::Duration::from_millis(700));
    sway.key("space");
    sway.key("p");
    let mut saved = None;
    saver.poll("a screenshot saved by P", || {
        saved = std::fs::read_dir(sway.screenshots_dir())
            .ok()
            .and_then(|d| {
                d.filter_map(|e| e.ok())
                    .map(|e| e.path())
                    .find(|p| p.extension().is_some_and(|x| x == "png"))
            });
        saved.is_some()
    });
    let (w, h, _, frame) = headless::read_png(&saved.unwrap());
    assert_eq!((w, h), (W, H), "the window covers the output");
    let shown = sway.screenshot().2;
    let differ = (0..frame.len()).filter(|&i| frame[i] != shown[i]);
    let rows: std::collections::BTreeSet<usize> = differ.map(|i| i / W as usize).collect();
    assert!(
        rows.is_empty(),
        "the window differs from its frame in rows {rows:?}"
    );
}

#[test]
fn wayland_a_second_fullscreen_saver_ends_at_once_and_a_crash_leaves_no_lock() {
    let Some(sway) = Sway::start("single", W, H, 1, false) else {
        return;
    };
    let before = sway.screenshot().2;
    let mut first = sway.mountains(&["/s"]);
    first.poll("the first saver's mountain", || {
        changed(&before, &sway.screenshot().2) > 0.9
    });
    let mut second = sway.mountains(&["/s"]);
    second.expect_exit("a saver already running");
    assert!(
        second.stderr().contains("already runs"),
        "{}",
        second.stderr()
    );
    first.assert_running();
    // A window mode is not a screensaver: it may run beside it.
    let mut window = sway.mountains(&["--window"]);
    std::thread::sleep(std::time::Duration::from_millis(500));
    window.assert_running();
    drop(window);

    first.kill();
    let mut third = sway.mountains(&["/s"]);
    third.poll("the next saver's mountain after a crash", || {
        changed(&before, &sway.screenshot().2) > 0.9
    });
    third.assert_running();
}

#[test]
fn xwayland_fullscreen_draws_and_ends_on_a_key_and_on_the_first_click() {
    let Some(sway) = Sway::start("xwayland", W, H, 1, true) else {
        return;
    };
    let before = sway.screenshot().2;
    let expected = headless_render(W as u16, H as u16);
    let args = ["/s", "--set", "seed=5", "--set", "pause_seconds=30"];
    let mut saver = sway.mountains_on_xwayland(&args);
    saver.poll("the finished mountain through Xwayland", || {
        sway.screenshot() == (W, H, expected.clone())
    });
    sway.key("Escape");
    saver.expect_exit("Escape through Xwayland");

    // The pointer rests where the saver's window will appear (sway then
    // draws its own arrow over the picture: the comparison is looser).
    let mut pointer = VirtualPointer::connect(&sway.socket_path()).expect("a virtual pointer");
    pointer.move_by(100.0, 100.0);
    let mut saver = sway.mountains_on_xwayland(&args);
    saver.poll("a mountain through Xwayland", || {
        changed(&before, &sway.screenshot().2) > 0.9
    });
    pointer.click();
    saver.expect_exit("the first click through Xwayland");
    // The click, not the pointer's arrival, ended it (MOUNTAINS_TRACE=1).
    let said = saver.stderr();
    assert!(said.contains("ended by Button"), "{said}");
}

/// `--layer background` with seed 5 held for a long time, once the finished
/// mountain is on the first output exactly as `mountains render` makes it.
fn finished_layer(sway: &Sway, what: &str) -> Client {
    finished_layer_via(sway, None, what)
}

/// The layer mode's arguments for seed 5, held for a long time.
const LAYER_ARGS: [&str; 6] = [
    "--layer",
    "background",
    "--set",
    "seed=5",
    "--set",
    "pause_seconds=30",
];

/// [`finished_layer`] on a proxy's socket (`via`) or on sway's own.
fn finished_layer_via(sway: &Sway, via: Option<&str>, what: &str) -> Client {
    let expected = headless_render(W as u16, H as u16);
    let mut saver = match via {
        Some(socket) => sway.mountains_via(socket, &LAYER_ARGS),
        None => sway.mountains(&LAYER_ARGS),
    };
    let took = saver.poll(what, || {
        sway.screenshot_output("HEADLESS-1") == (W, H, expected.clone())
    });
    eprintln!("{what}: on the output after {took:?}");
    saver
}

#[test]
fn wayland_layer_covers_the_output_with_the_rendered_mountain_and_ends_on_sigterm() {
    let Some(sway) = Sway::start("layer", W, H, 1, false) else {
        return;
    };
    let mut saver = finished_layer(&sway, "the finished mountain on the background layer");
    // A layer surface, not a window: sway's tree has no window of it.
    let tree = sway.tree();
    assert!(!tree.contains("\"app_id\": \"mountains\""), "{tree}");
    let asked = std::time::Instant::now();
    saver.terminate();
    saver.expect_exit("SIGTERM");
    eprintln!("SIGTERM: ended after {:?}", asked.elapsed());
    // Its own loop ended it, not the watcher's last resort (src/platform/signals.rs).
    let said = saver.stderr();
    assert!(said.contains("ended by \"SIGTERM or SIGINT\""), "{said}");
}

#[test]
fn wayland_layer_draws_a_scaled_output_at_its_real_pixels() {
    // 640x480 pixels at scale 2: the surface is 320x240 in sway's units.
    let Some(sway) = Sway::start("layer-scaled", W, H, 2, false) else {
        return;
    };
    let mut saver = finished_layer(&sway, "the 640x480 mountain on the scale-2 output");
    saver.assert_running();
}

#[test]
fn wayland_layer_follows_a_scale_changed_while_it_runs() {
    // The same 640x480 pixels at scale 2: the frame stays, the compositor
    // must be told the new buffer scale with it.
    let Some(sway) = Sway::start("layer-rescaled", W, H, 1, false) else {
        return;
    };
    let expected = headless_render(W as u16, H as u16);
    let mut saver = finished_layer(&sway, "the mountain at scale 1");
    sway.run("swaymsg", &["output", "HEADLESS-1", "scale", "2"]);
    saver.poll("the same mountain at scale 2", || {
        sway.screenshot_output("HEADLESS-1") == (W, H, expected.clone())
    });
    // Not only the old picture before the change arrived: still so later.
    std::thread::sleep(std::time::Duration::from_millis(500));
    assert_eq!(sway.screenshot_output("HEADLESS-1"), (W, H, expected));
    saver.assert_running();
}

#[test]
fn wayland_layer_draws_an_output_added_while_it_runs() {
    let Some(sway) = Sway::start("layer-outputs", W, H, 1, false) else {
        return;
    };
    let expected = headless_render(W as u16, H as u16);
    let mut saver = finished_layer(&sway, "the mountain on the first output");
    // Its size is set before it appears: a surface resized later keeps its
    // mountain, made for the first size (detail = "auto").
    let added = "HEADLESS-2";
    sway.run(
        "swaymsg",
        &[
            "output",
            added,
            "resolution",
            "640x480",
            "position",
            "640",
            "0",
        ],
    );
    sway.run("swaymsg", &["create_output"]);
    let outputs = sway.outputs();
    assert!(outputs.iter().any(|o| o == added), "{outputs:?}");
    let took = saver.poll("the mountain on the added output", || {
        sway.screenshot_output(added) == (W, H, expected.clone())
    });
    eprintln!("the added output drawn after {took:?}");
    // sway 1.7 cannot take a headless output away (no `output unplug`;
    // `output HEADLESS-2 disable` fails to commit): see
    // wayland_layer_drops_the_surface_of_an_output_taken_away.
    saver.assert_running();
    assert_eq!(sway.screenshot_output("HEADLESS-1"), (W, H, expected));
}

/// A proxy in front of `sway` on the socket `wayland-proxy`.
fn proxy(sway: &Sway, edit: Edit) -> WlProxy {
    WlProxy::start(
        &sway.runtime_path("wayland-proxy"),
        &sway.socket_path(),
        edit,
    )
}

#[test]
fn wayland_layer_drops_the_surface_of_an_output_taken_away() {
    let Some(sway) = Sway::start("layer-unplug", W, H, 1, false) else {
        return;
    };
    let expected = headless_render(W as u16, H as u16);
    let added = "HEADLESS-2";
    sway.run(
        "swaymsg",
        &[
            "output",
            added,
            "resolution",
            "640x480",
            "position",
            "640",
            "0",
        ],
    );
    sway.run("swaymsg", &["create_output"]);
    let proxy = proxy(&sway, Edit::Nothing);
    let mut saver = finished_layer_via(&sway, Some("wayland-proxy"), "the first output drawn");
    saver.poll("the second output drawn", || {
        sway.screenshot_output(added) == (W, H, expected.clone())
    });
    // sway 1.7 cannot unplug a headless output: the proxy says it is gone.
    assert!(proxy.remove_last_output() > 0, "no client knew an output");
    saver.poll_said("output HEADLESS-2 is gone");
    saver.poll("the removed output's surface gone", || {
        sway.screenshot_output(added).2 != expected
    });
    saver.assert_running();
    assert_eq!(sway.screenshot_output("HEADLESS-1"), (W, H, expected));
}

#[test]
fn wayland_layer_ends_with_status_0_when_the_compositor_closes_its_last_surface() {
    let Some(sway) = Sway::start("layer-closed", W, H, 1, false) else {
        return;
    };
    let expected = headless_render(W as u16, H as u16);
    sway.run(
        "swaymsg",
        &[
            "output",
            "HEADLESS-2",
            "resolution",
            "640x480",
            "position",
            "640",
            "0",
        ],
    );
    sway.run("swaymsg", &["create_output"]);
    let proxy = proxy(&sway, Edit::Nothing);
    let mut saver = finished_layer_via(&sway, Some("wayland-proxy"), "the mountain via the proxy");
    saver.poll("the second output drawn", || {
        sway.screenshot_output("HEADLESS-2") == (W, H, expected.clone())
    });
    // One surface closed: the other output's show goes on.
    assert_eq!(proxy.close_layer_surfaces(1), 1);
    saver.poll_said("the compositor closed the surface on HEADLESS-1");
    std::thread::sleep(std::time::Duration::from_millis(300));
    saver.assert_running();
    assert_eq!(sway.screenshot_output("HEADLESS-2"), (W, H, expected));
    // The last one closed: the show is no longer wanted.
    assert_eq!(proxy.close_layer_surfaces(1), 1);
    saver.expect_exit("the compositor closing the last surface");
    let said = saver.stderr();
    assert!(
        said.contains("ended by \"the compositor closed the layer surface\""),
        "{said}"
    );
}

#[test]
fn wayland_layer_refuses_a_compositor_without_layer_shell_naming_it() {
    let Some(sway) = Sway::start("layer-none", W, H, 1, false) else {
        return;
    };
    let _proxy = proxy(&sway, Edit::HideLayerShell);
    let mut saver = sway.mountains_via("wayland-proxy", &LAYER_ARGS);
    let status = saver.wait(sway::PATIENCE);
    let said = saver.stderr();
    assert_eq!(status.and_then(|s| s.code()), Some(1), "{said}");
    assert!(said.contains("has no zwlr_layer_shell_v1"), "{said}");
    // The other modes need no layer shell: the same proxy passes a window.
    let before = sway.screenshot().2;
    let mut window = sway.mountains_via("wayland-proxy", &["--window"]);
    window.poll("a window through the proxy", || {
        changed(&before, &sway.screenshot().2) > 0.9
    });
}

#[test]
fn wayland_layer_draws_a_fractionally_scaled_output_at_its_real_pixels() {
    // 960x480 pixels at scale 1.5: 640x320 in sway's units, which sway 1.7
    // tells as scale 2 (1280x640 pixels, shrunk: a quarter of the pixels
    // right); through a viewport, the output's own 960x480.
    let Some(sway) = Sway::start("layer-fractional", 960, H, 1, false) else {
        return;
    };
    sway.run("swaymsg", &["output", "HEADLESS-1", "scale", "1.5"]);
    let expected = headless_render(960, H as u16);
    let mut saver = sway.mountains(&LAYER_ARGS);
    let took = saver.poll("the 960x480 mountain on the scale-1.5 output", || {
        sway.screenshot_output("HEADLESS-1") == (960, H, expected.clone())
    });
    eprintln!("scale 1.5: on the output after {took:?}");
}
