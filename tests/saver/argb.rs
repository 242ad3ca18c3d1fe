//! The embedded modes on a 32-bit (ARGB) window, as compositing desktops and
//! some xscreensaver setups give: the top byte of each pixel is alpha, and
//! every pixel drawn must be opaque, or a compositor shows nothing.
#![cfg(unix)]

use crate::common::xvfb;

use xvfb::{Saver, Xvfb, looks_drawn, poll};

/// Runs `--window-id` on a fresh 320x200 ARGB window of a server started
/// with `extra`, waits for the mountain, and checks every pixel's alpha.
fn draws_opaque(name: &str, extra: &[&str]) {
    let Some(x) = Xvfb::start(640, 480, extra) else {
        return;
    };
    let window = x.create_argb_window(320, 200);
    assert_eq!(x.depth(window), 32);
    let id = format!("0x{window:x}");
    let mut saver = Saver::start(&x, name, &["--window-id", &id], &[]);
    let mut raw = Vec::new();
    let took = poll(&mut saver, "a mountain in the 32-bit window", || {
        raw = x.grab_raw(window, 320, 200);
        let rgb: Vec<u32> = raw.iter().map(|p| p & 0x00ff_ffff).collect();
        looks_drawn(&rgb)
    });
    eprintln!("{name}: drawn after {took:?}");
    let see_through = raw.iter().filter(|&&p| p >> 24 != 0xff).count();
    assert_eq!(
        see_through,
        0,
        "{see_through} of {} pixels are not opaque (first: {:#010x})",
        raw.len(),
        raw.iter().find(|&&p| p >> 24 != 0xff).unwrap_or(&0)
    );
    saver.assert_running();
}

#[test]
fn display_window_id_on_a_32bit_window_draws_opaque_pixels() {
    draws_opaque("argb", &[]);
}

#[test]
fn display_window_id_on_a_32bit_window_without_shm_draws_opaque_pixels() {
    // No MIT-SHM: the bands path (plain PutImage) draws instead of softbuffer.
    draws_opaque("argb-noshm", &["-extension", "MIT-SHM"]);
}

#[test]
fn display_fullscreen_windows_are_24_bit() {
    // We never ask winit for transparency, so it keeps the root's visual
    // and the full-screen window needs no alpha.
    let Some(x) = Xvfb::start(640, 480, &[]) else {
        return;
    };
    let mut saver = Saver::start(&x, "fs-depth", &["/s"], &[]);
    poll(&mut saver, "a mountain on the screen", || {
        looks_drawn(&x.grab_screen())
    });
    let windows = x.mapped_windows();
    assert!(!windows.is_empty());
    for (window, geometry) in windows {
        assert_eq!(x.depth(window), 24, "window {geometry:?}");
    }
}

/// On a 30-bit or a 16-bit screen, whose own visual softbuffer cannot take,
/// /s and --window draw through one of the screen's 24- or 32-bit true
/// colour visuals, opaque (both were refused); an 8-bit screen, which has
/// none, is refused in words.
#[test]
fn display_30_and_16_bit_screens_draw_through_a_true_colour_visual() {
    for depth in ["depth=30", "depth=16"] {
        for mode in ["/s", "--window"] {
            let Some(x) = Xvfb::start(320, 240, &[depth]) else {
                return;
            };
            let mut saver = Saver::start(&x, "deep-screen", &[mode], &[]);
            let mut drawn = None;
            poll(
                &mut saver,
                &format!("{mode} on {depth}: a mountain"),
                || {
                    drawn = x.mapped_windows().into_iter().find(|&(w, g)| {
                        matches!(x.depth(w), 24 | 32) && looks_drawn(&x.grab(w, g.2, g.3))
                    });
                    drawn.is_some()
                },
            );
            let (window, g) = drawn.expect("polled until drawn");
            if x.depth(window) == 32 {
                let raw = x.grab_raw(window, g.2, g.3);
                assert!(
                    raw.iter().all(|p| p >> 24 == 0xff),
                    "{mode} on {depth}: see-through"
                );
            }
        }
    }
    let Some(x) = Xvfb::start(320, 240, &["depth=8"]) else {
        return;
    };
    let mut saver = Saver::start(&x, "shallow-screen", &["--window"], &[]);
    xvfb::expect_refusal(
        &mut saver,
        "this X screen offers only 8-bit visuals (PseudoColor, ",
    );
}
