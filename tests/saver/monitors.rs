//! Full screen on several monitors, and monitors that change while the
//! saver runs, under a private Xvfb whose monitors the test sets with RandR.
#![cfg(unix)]

use crate::common::xvfb;

use crate::common::randr;

use x11rb::protocol::xproto::ConnectionExt as _;
use xvfb::{Geometry, Saver, Xvfb, expect_exit, looks_drawn, poll};

const LEFT: Geometry = (0, 0, 640, 480);
const RIGHT: Geometry = (640, 0, 640, 480);

/// A 1280x480 screen split into two 640x480 monitors side by side.
fn two_monitors() -> Option<Xvfb> {
    let x = Xvfb::start(1280, 480, &[])?;
    randr::set_monitors(&x.conn, x.root, &[LEFT, RIGHT], None);
    Some(x)
}

#[test]
fn display_fullscreen_covers_each_monitor_with_its_own_mountain() {
    let Some(x) = two_monitors() else {
        return;
    };
    let mut saver = Saver::start(&x, "mon-two", &["/s", "--set", "pause_seconds=60"], &[]);
    let took = poll(&mut saver, "a mountain on both monitors", || {
        looks_drawn(&x.grab_rect(LEFT)) && looks_drawn(&x.grab_rect(RIGHT))
    });
    eprintln!("two monitors drawn after {took:?}");
    assert_eq!(
        x.mapped_places(),
        vec![LEFT, RIGHT],
        "one window per monitor"
    );
    // Wait for the held pictures, then compare them: each monitor has its own seed.
    std::thread::sleep(std::time::Duration::from_millis(1500));
    assert_ne!(
        x.grab_rect(LEFT),
        x.grab_rect(RIGHT),
        "both monitors show the same mountain"
    );
    saver.assert_running();
}

#[test]
fn display_fullscreen_primary_only_leaves_the_other_monitor_black() {
    let Some(x) = two_monitors() else {
        return;
    };
    let args = ["/s", "--set", "monitors=primary"];
    let mut saver = Saver::start(&x, "mon-primary", &args, &[]);
    poll(&mut saver, "a mountain on the first monitor", || {
        looks_drawn(&x.grab_rect(LEFT))
    });
    assert_eq!(
        x.mapped_places(),
        vec![LEFT, RIGHT],
        "one window per monitor"
    );
    assert!(
        x.grab_rect(RIGHT).iter().all(|&p| p == 0),
        "the second monitor is not black"
    );
    saver.assert_running();
}

#[test]
fn display_fullscreen_primary_only_follows_the_primary_flag() {
    let Some(x) = Xvfb::start(1280, 480, &[]) else {
        return;
    };
    randr::set_monitors(&x.conn, x.root, &[LEFT, RIGHT], Some(1));
    let args = ["/s", "--set", "monitors=primary"];
    let mut saver = Saver::start(&x, "mon-primary-right", &args, &[]);
    poll(
        &mut saver,
        "a mountain on the primary (right) monitor",
        || looks_drawn(&x.grab_rect(RIGHT)),
    );
    assert_eq!(
        x.mapped_places(),
        vec![LEFT, RIGHT],
        "one window per monitor"
    );
    assert!(
        x.grab_rect(LEFT).iter().all(|&p| p == 0),
        "the monitor that is not primary is not black"
    );
    saver.assert_running();
}

#[test]
fn display_fullscreen_follows_a_resolution_change() {
    let Some(x) = Xvfb::start(1280, 480, &[]) else {
        return;
    };
    let mut saver = Saver::start(&x, "mon-mode", &["/s", "--set", "pause_seconds=60"], &[]);
    let wide = (0, 0, 1280, 480);
    poll(&mut saver, "a mountain on the screen", || {
        looks_drawn(&x.grab_rect(wide))
    });
    assert_eq!(x.mapped_places(), vec![wide]);

    randr::set_resolution(&x.conn, x.root, 640, 480);
    let took = poll(&mut saver, "the window to fit the 640x480 mode", || {
        x.mapped_places() == vec![LEFT]
    });
    eprintln!("window fitted 640x480 after {took:?}");
    poll(&mut saver, "a mountain fitted to 640x480", || {
        looks_drawn(&x.grab_rect(LEFT))
    });

    randr::set_resolution(&x.conn, x.root, 1280, 480);
    poll(&mut saver, "the window to fit 1280x480 again", || {
        x.mapped_places() == vec![wide]
    });
    poll(&mut saver, "a mountain across 1280x480 again", || {
        looks_drawn(&x.grab_rect(wide))
    });
    saver.assert_running();
}

#[test]
fn display_fullscreen_opens_and_closes_windows_as_monitors_come_and_go() {
    let Some(x) = Xvfb::start(1280, 480, &[]) else {
        return;
    };
    let mut saver = Saver::start(&x, "mon-plug", &["/s"], &[]);
    let wide = (0, 0, 1280, 480);
    poll(&mut saver, "one window", || x.mapped_places() == vec![wide]);
    randr::set_monitors(&x.conn, x.root, &[LEFT, RIGHT], None);
    randr::announce_change(&x.conn, x.root);
    poll(&mut saver, "a window per monitor", || {
        x.mapped_places() == vec![LEFT, RIGHT]
    });
    poll(&mut saver, "a mountain on both monitors", || {
        looks_drawn(&x.grab_rect(LEFT)) && looks_drawn(&x.grab_rect(RIGHT))
    });
    // The second monitor goes: its window closes, the first stays.
    randr::delete_monitors(&x.conn, x.root, 1, 1);
    randr::announce_change(&x.conn, x.root);
    poll(&mut saver, "the second window to close", || {
        x.mapped_places() == vec![LEFT]
    });
    // The input grab survived the windows coming and going: a key ends it.
    x.key(38);
    xvfb::expect_exit(&mut saver, "a key after the windows changed");
}

/// Where the pointer is on the screen.
fn pointer(x: &Xvfb) -> (i16, i16) {
    let reply = x.conn.query_pointer(x.root).unwrap().reply().unwrap();
    (reply.root_x, reply.root_y)
}

/// Starts `/s` on `x` and waits for its mountain on the whole screen and
/// for its input grab, whose connection tells the server's moves of the
/// pointer from a person's (before it holds, a window's pointer events
/// are the witness: see app.rs).
fn start_drawn(x: &Xvfb, name: &str) -> Saver {
    let trace = [("MOUNTAINS_TRACE", "1")];
    let mut saver = Saver::start(x, name, &["/s", "--set", "pause_seconds=60"], &trace);
    let screen = (0, 0, x.size.0, x.size.1);
    poll(&mut saver, "a mountain on the screen", || {
        looks_drawn(&x.grab_rect(screen))
    });
    poll(&mut saver, "the input grab", || {
        x.pointer_grabbed_elsewhere()
    });
    saver
}

/// Waits for the saver's window to fit the 640x480 screen the test made,
/// and for a mountain on it: the server's move of the pointer has long
/// reached the saver by then.
fn expect_fitted_to_640x480(x: &Xvfb, saver: &mut Saver) {
    poll(saver, "the window to fit the 640x480 mode", || {
        x.mapped_places() == vec![LEFT]
    });
    poll(saver, "a mountain fitted to 640x480", || {
        looks_drawn(&x.grab_rect(LEFT))
    });
    saver.assert_running();
}

/// An 800x600 screen with the pointer near its corner, outside the
/// 640x480 the tests shrink it to, and `/s` drawn on it.
fn cornered(name: &str) -> Option<(Xvfb, Saver)> {
    let x = Xvfb::start(800, 600, &[])?;
    x.warp_to(780, 580);
    assert_eq!(pointer(&x), (780, 580));
    let saver = start_drawn(&x, name);
    Some((x, saver))
}

/// A smaller mode puts the pointer back onto the screen: the server moved
/// it, not a person, and the saver runs on (issue 36: it ended at once,
/// "ended by PointerAt(639, 479)"). A move after the change still ends it.
#[test]
fn display_fullscreen_a_mode_change_that_moves_the_pointer_does_not_end_it() {
    let Some((x, mut saver)) = cornered("mon-clamp") else {
        return;
    };
    randr::set_resolution(&x.conn, x.root, 640, 480);
    assert_eq!(pointer(&x), (639, 479), "the server moved the pointer");
    expect_fitted_to_640x480(&x, &mut saver);
    x.warp_to(300, 300);
    expect_exit(&mut saver, "the pointer moved after the mode change");
}

/// Many mode changes in a row, each moving the pointer further in: none
/// is a person; a relative move afterwards is.
#[test]
fn display_fullscreen_a_storm_of_mode_changes_does_not_end_it() {
    let Some((x, mut saver)) = cornered("mon-storm") else {
        return;
    };
    for _ in 0..4 {
        for (w, h) in [(760, 560), (700, 520), (640, 480), (800, 600)] {
            randr::set_resolution(&x.conn, x.root, w, h);
        }
    }
    randr::set_resolution(&x.conn, x.root, 640, 480);
    assert_eq!(pointer(&x), (639, 479), "the server moved the pointer");
    expect_fitted_to_640x480(&x, &mut saver);
    x.move_by(-30, 0);
    expect_exit(&mut saver, "a 30 px move after the storm");
}

/// The output goes off and comes back with a smaller mode (a projector
/// unplugged and plugged again): the pointer the server moves is no person.
#[test]
fn display_fullscreen_an_output_that_goes_and_comes_back_smaller_does_not_end_it() {
    let Some((x, mut saver)) = cornered("mon-off") else {
        return;
    };
    randr::switch_off(&x.conn, x.root);
    randr::set_resolution(&x.conn, x.root, 640, 480);
    assert_eq!(pointer(&x), (639, 479), "the server moved the pointer");
    expect_fitted_to_640x480(&x, &mut saver);
    x.key(38);
    expect_exit(&mut saver, "a key after the output came back");
}
