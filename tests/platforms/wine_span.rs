//! `monitors = "span"` in the Windows build under Wine: `/s` lays one
//! picture over the virtual screen of two monitors, each showing its part.
//! Wine's monitors here are Xinerama heads side by side (see
//! `Xvfb::start_xinerama`), as Windows' are the virtual screen's.
#![cfg(unix)]

use crate::common::headless::headless_render;
use crate::common::wine::Session;
use crate::common::xvfb::{Xvfb, poll};

#[test]
#[ignore = "needs Wine, mingw, Xephyr and the cross-built exe: sh scripts/wine_test.sh"]
fn display_wine_span_two_monitors_show_one_picture() {
    let Some(session) = Session::begin() else {
        return;
    };
    let Some(x) = Xvfb::start_xinerama(&[(640, 480), (640, 480)]) else {
        return;
    };
    let _xinerama = session.monitors_from_xinerama();
    // The Linux build's picture of the whole 1280x480 desktop: the seed
    // makes the same mountain on every platform.
    let picture = headless_render(1280, 480);
    let args = [
        "/s",
        "--set",
        "monitors=span",
        "--set",
        "seed=5",
        "--set",
        "draw_seconds=0.5",
        "--set",
        "draw_seconds=0.5",
        "--set",
        "pause_seconds=60",
    ];
    let mut saver = session.start(&x, "wine-span", "mountains.exe", &args);
    let took = poll(&mut saver, "one picture across both monitors", || {
        x.grab_screen() == picture
    });
    eprintln!("wine span: one picture after {took:?}");
    saver.assert_running();
}
