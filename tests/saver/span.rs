//! `monitors = "span"` under Xvfb with RandR monitors: one landscape
//! across every monitor, each showing its part of the one picture (so the
//! skyline goes on across every seam), and a monitor that goes while it
//! runs.
#![cfg(unix)]

use crate::common::headless::headless_render;
use crate::common::randr;
use crate::common::xvfb::{self, Geometry, Saver, Xvfb, poll};

const LEFT: Geometry = (0, 0, 640, 480);
const RIGHT: Geometry = (640, 0, 640, 480);

/// The part `rect` of a `width` pixels wide picture.
fn part(picture: &[u32], width: u16, (x, y, w, h): Geometry) -> Vec<u32> {
    let (x, y, w, h) = (x as usize, y as usize, w as usize, h as usize);
    (y..y + h)
        .flat_map(|row| &picture[row * width as usize + x..][..w])
        .copied()
        .collect()
}

/// The saver's arguments in `mode` (`/s`, or `--layer background`), spanning the
/// monitors and drawing seed 5 (as `headless_render`), then `then`.
fn span_args<'a>(mode: &[&'a str], then: &[&'a str]) -> Vec<&'a str> {
    let mut args = mode.to_vec();
    args.extend(["--set", "monitors=span", "--set", "seed=5"]);
    args.extend_from_slice(then);
    args
}

/// Drawn at once and held 8 s: the next slide comes within the patience.
const NEXT_SLIDE_SOON: [&str; 4] = ["--set", "draw_seconds=0", "--set", "pause_seconds=8"];

/// `/s` spanning the monitors of `x`, drawing seed 5 (as `headless_render`).
fn spanning(x: &Xvfb, name: &str) -> Saver {
    let args = span_args(&["/s"], &["--set", "pause_seconds=60"]);
    Saver::start(x, name, &args, &[])
}

/// Waits until every monitor of `heads` shows its part of `picture`
/// (`width` wide, as the desktop's bounding rectangle).
fn expect_parts(x: &Xvfb, saver: &mut Saver, heads: &[Geometry], picture: &[u32], width: u16) {
    let took = poll(
        saver,
        "each monitor showing its part of one picture",
        || {
            heads
                .iter()
                .all(|&h| x.grab_rect(h) == part(picture, width, h))
        },
    );
    eprintln!("span on {} monitors after {took:?}", heads.len());
    assert_eq!(x.mapped_places(), heads, "one window per monitor");
}

#[test]
fn display_span_two_monitors_show_one_picture() {
    let Some(x) = Xvfb::start(1280, 480, &[]) else {
        return;
    };
    randr::set_monitors(&x.conn, x.root, &[LEFT, RIGHT], None);
    let picture = headless_render(1280, 480);
    let mut saver = spanning(&x, "span-two");
    expect_parts(&x, &mut saver, &[LEFT, RIGHT], &picture, 1280);
    saver.assert_running();
}

#[test]
fn display_span_portrait_and_monitors_of_other_sizes_show_one_picture() {
    let Some(x) = Xvfb::start(1070, 480, &[]) else {
        return;
    };
    // A portrait monitor, a landscape one lower down, a smaller one
    // higher up: one bounding rectangle, 1070x480, the desktop's own.
    let heads = [(0, 0, 270, 480), (270, 100, 480, 270), (750, 60, 320, 360)];
    randr::set_monitors(&x.conn, x.root, &heads, Some(0));
    let picture = headless_render(1070, 480);
    let mut saver = spanning(&x, "span-three");
    expect_parts(&x, &mut saver, &heads, &picture, 1070);
    saver.assert_running();
}

#[test]
fn display_span_a_monitor_removed_re_lays_the_span() {
    let Some(x) = Xvfb::start(1280, 480, &[]) else {
        return;
    };
    randr::set_monitors(&x.conn, x.root, &[LEFT, RIGHT], None);
    let (both, one) = (headless_render(1280, 480), headless_render(640, 480));
    let args = span_args(&["/s"], &NEXT_SLIDE_SOON);
    let mut saver = Saver::start(&x, "span-unplug", &args, &[]);
    expect_parts(&x, &mut saver, &[LEFT, RIGHT], &both, 1280);
    randr::delete_monitors(&x.conn, x.root, 1, 1);
    randr::announce_change(&x.conn, x.root);
    // The slide on screen is not cut short: the monitor left keeps its half
    // of the wide picture while the slide is held...
    std::thread::sleep(std::time::Duration::from_millis(1500));
    assert!(
        x.grab_rect(LEFT) == part(&both, 1280, LEFT),
        "the span was laid again in the middle of a slide"
    );
    // ...and the next slide is laid over the one monitor left: the whole
    // picture of seed 5 at its size, not the left half of the wide one.
    expect_parts(&x, &mut saver, &[LEFT], &one, 640);
    x.key(38);
    xvfb::expect_exit(&mut saver, "a key after the span was laid again");
}

/// The left (`from` 0) or right (`from` 640) half of a 1280x480 picture.
#[cfg(target_os = "linux")]
fn half(picture: &[u32], from: i16) -> (u32, u32, Vec<u32>) {
    (640, 480, part(picture, 1280, (from, 0, 640, 480)))
}

#[cfg(target_os = "linux")]
#[test]
fn wayland_span_two_outputs_show_one_picture() {
    let Some((sway, added)) = sway_two_outputs("span") else {
        return;
    };
    let picture = headless_render(1280, 480);
    let args = span_args(&["/s"], &["--set", "pause_seconds=30"]);
    let mut saver = sway.mountains(&args);
    let took = saver.poll("each output showing its half of one picture", || {
        sway.screenshot_output("HEADLESS-1") == half(&picture, 0)
            && sway.screenshot_output(added) == half(&picture, 640)
    });
    eprintln!("span on two outputs after {took:?}");
    saver.assert_running();
}

/// Two 640x480 sway outputs side by side (`HEADLESS-1` at 0,0 and the one
/// it returns at 640,0).
#[cfg(target_os = "linux")]
fn sway_two_outputs(name: &str) -> Option<(crate::common::sway::Sway, &'static str)> {
    let sway = crate::common::sway::Sway::start(name, 640, 480, 1, false)?;
    let added = "HEADLESS-2";
    let place = [
        "output",
        added,
        "resolution",
        "640x480",
        "position",
        "640",
        "0",
    ];
    sway.run("swaymsg", &place);
    sway.run("swaymsg", &["create_output"]);
    // sway lays a new output out again: the first one goes back to 0,0.
    sway.run("swaymsg", &["output", "HEADLESS-1", "position", "0", "0"]);
    Some((sway, added))
}

#[cfg(target_os = "linux")]
#[test]
fn wayland_layer_span_two_outputs_show_one_picture() {
    let Some((sway, added)) = sway_two_outputs("layer-span") else {
        return;
    };
    let picture = headless_render(1280, 480);
    let args = span_args(&["--layer", "background"], &["--set", "pause_seconds=30"]);
    let mut saver = sway.mountains(&args);
    let took = saver.poll(
        "each output's layer surface showing its half of one picture",
        || {
            sway.screenshot_output("HEADLESS-1") == half(&picture, 0)
                && sway.screenshot_output(added) == half(&picture, 640)
        },
    );
    eprintln!("layer span on two outputs after {took:?}");
    saver.assert_running();
    saver.terminate();
    saver.expect_exit("SIGTERM");
}

#[cfg(target_os = "linux")]
#[test]
fn wayland_layer_span_takes_in_an_output_added_at_the_next_slide() {
    let Some(sway) = crate::common::sway::Sway::start("layer-span-added", 640, 480, 1, false)
    else {
        return;
    };
    let (one, both) = (headless_render(640, 480), headless_render(1280, 480));
    let args = span_args(&["--layer", "background"], &NEXT_SLIDE_SOON);
    let mut saver = sway.mountains(&args);
    saver.poll("the span over the one output", || {
        sway.screenshot_output("HEADLESS-1") == (640, 480, one.clone())
    });
    let added = "HEADLESS-2";
    let place = [
        "output",
        added,
        "resolution",
        "640x480",
        "position",
        "640",
        "0",
    ];
    sway.run("swaymsg", &place);
    sway.run("swaymsg", &["create_output"]);
    sway.run("swaymsg", &["output", "HEADLESS-1", "position", "0", "0"]);
    // The slide on screen is not cut short: the first output keeps it...
    std::thread::sleep(std::time::Duration::from_millis(1500));
    assert!(
        sway.screenshot_output("HEADLESS-1") == (640, 480, one.clone()),
        "the span was laid again in the middle of a slide"
    );
    // ...and the next slide is laid over both outputs.
    let took = saver.poll("each output showing its half of the next slide", || {
        sway.screenshot_output("HEADLESS-1") == half(&both, 0)
            && sway.screenshot_output(added) == half(&both, 640)
    });
    eprintln!("the span over two outputs after {took:?}");
    saver.assert_running();
}
