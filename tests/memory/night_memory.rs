//! A night at 4K needs no more memory than a day: the stars are worked
//! out where they are drawn, the moon is the sun's light in other
//! colours, and the night's land and water tables replace the day's.

use mountains::render::Size;
use mountains::render::{Frame, detail, render_full};
use mountains::settings::{Settings, Sun};
use mountains::terrain;

use crate::common::counting;

/// The peak heap of drawing seed 42 at 4K under `sun`, beyond the field
/// and the frame.
fn peak_of_drawing(sun: Sun) -> usize {
    let s = Settings {
        sun,
        ..Settings::default()
    };
    let s = detail::for_frame(&s, Size::new(3840, 2160));
    let field = terrain::generate(&s, 42);
    let mut frame = Frame::new(3840, 2160).unwrap();
    counting::peak_of(|| render_full(&field, &s, &mut frame)).1
}

#[test]
fn a_4k_night_needs_no_more_memory_than_a_day() {
    let _alone = counting::alone();
    let day = peak_of_drawing(Sun::Midday);
    let night = peak_of_drawing(Sun::Night);
    assert!(day > 1 << 20, "the count missed the scene: {day} bytes");
    // Threads allocate in their own order: a little room either way.
    assert!(
        night <= day + (256 << 10),
        "a 4K night takes {:.2} MB to draw, a day {:.2} MB",
        night as f64 / 1e6,
        day as f64 / 1e6
    );
}
