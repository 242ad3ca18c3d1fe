//! `monitors = "span"` headless: one picture the size of the monitors'
//! bounding rectangle, cut into each monitor's part, on layouts of two and
//! three monitors (a portrait one, different sizes and heights, a gap).
//! Where two monitors touch, the skyline goes on across the seam.

use mountains::render::Size;
use mountains::render::detail::for_frame;
use mountains::render::facts::SceneFacts;
use mountains::render::{Frame, render_full};
use mountains::saver::heads::Head;
use mountains::saver::span;
use mountains::settings::Settings;
use mountains::terrain;

fn head(x: i32, y: i32, width: u32, height: u32) -> Head {
    Head {
        x,
        y,
        width,
        height,
        primary: false,
    }
}

/// The layouts, at a quarter of real monitors' sizes (a 1920x1080
/// monitor is 480x270 here).
fn layouts() -> Vec<(&'static str, Vec<Head>)> {
    vec![
        (
            "two side by side",
            vec![head(0, 0, 480, 270), head(480, 0, 480, 270)],
        ),
        (
            "portrait, landscape, smaller; different heights",
            vec![
                head(0, 0, 270, 480),
                head(270, 120, 480, 270),
                head(750, 150, 320, 200),
            ],
        ),
        (
            "three, the left above the desktop's origin",
            vec![
                head(-480, -40, 480, 270),
                head(0, 0, 480, 270),
                head(480, 0, 360, 270),
            ],
        ),
        (
            "a gap between two",
            vec![head(0, 0, 480, 270), head(520, 30, 480, 270)],
        ),
    ]
}

/// The span's picture of seed `seed` over `heads`, and its facts.
fn span_picture(heads: &[Head], seed: u64) -> (Frame, SceneFacts) {
    let whole = span::bounds(heads).unwrap();
    let (w, h) = (whole.width, whole.height);
    let settings = for_frame(&Settings::default(), Size::new(w, h));
    let field = terrain::generate(&settings, seed);
    let mut frame = Frame::new(w, h).unwrap();
    render_full(&field, &settings, &mut frame);
    (frame, SceneFacts::of(&field, &settings, Size::new(w, h)))
}

/// True when `pixel` is far from the sky's own colour: land (or sea).
fn not_sky(pixel: u32, sky: u32) -> bool {
    let channel = |c: u32, s: u32| (c as i32 - s as i32).abs();
    let far = (0..3).map(|i| channel((pixel >> (8 * i)) & 0xff, (sky >> (8 * i)) & 0xff));
    far.sum::<i32>() > 48
}

/// The desktop row where column `x` of `part` (a monitor's picture, at
/// `at` on the desktop) stops being sky, searched from desktop row `from`
/// down to `to`; `to` when it is sky all the way.
fn skyline(
    part: &Frame,
    at: &Head,
    x: u32,
    (from, to): (i32, i32),
    sky: impl Fn(i32, i32) -> u32,
) -> i32 {
    let dx = at.x + x as i32;
    (from..to)
        .find(|&dy| not_sky(part.get(x, (dy - at.y) as u32), sky(dx, dy)))
        .unwrap_or(to)
}

#[test]
fn span_crops_lie_where_the_desktop_puts_each_monitor() {
    for (name, heads) in layouts() {
        let whole = span::bounds(&heads).unwrap();
        let crops = span::crops(&heads);
        for (h, c) in heads.iter().zip(&crops) {
            assert_eq!((c.x1 - c.x0, c.y1 - c.y0), (h.width, h.height), "{name}");
            assert_eq!(
                (whole.x + c.x0 as i32, whole.y + c.y0 as i32),
                (h.x, h.y),
                "{name}: a crop is not at its monitor's place"
            );
        }
    }
}

#[test]
fn span_skyline_goes_on_across_every_seam() {
    for (name, heads) in layouts() {
        let (frame, facts) = span_picture(&heads, 7);
        let whole = span::bounds(&heads).unwrap();
        let parts = span::cut(&frame, &span::crops(&heads));
        assert_eq!(parts.len(), heads.len(), "{name}");
        let (w, h) = (whole.width as f32, whole.height as f32);
        let sky = |dx: i32, dy: i32| {
            let fx = ((dx - whole.x) as f32 + 0.5) / w;
            facts.sky_at(fx, ((dy - whole.y) as f32 + 0.5) / h)
        };
        let mut seams = 0;
        for (a, pa) in heads.iter().zip(&parts) {
            for (b, pb) in heads.iter().zip(&parts) {
                let touch = a.x + a.width as i32 == b.x;
                let rows = (
                    a.y.max(b.y),
                    (a.y + a.height as i32).min(b.y + b.height as i32),
                );
                if !touch || rows.0 >= rows.1 {
                    continue;
                }
                seams += 1;
                let left = skyline(pa, a, a.width - 1, rows, sky);
                let right = skyline(pb, b, 0, rows, sky);
                // The picture's own steepness just inside each monitor: a
                // seam may jump as far as the skyline does there.
                let inside_a = (left - skyline(pa, a, a.width - 2, rows, sky)).abs();
                let inside_b = (right - skyline(pb, b, 1, rows, sky)).abs();
                let allowed = 1.max(inside_a).max(inside_b);
                eprintln!(
                    "{name}: seam at x={}: skyline {left} | {right} (inside {inside_a}, {inside_b})",
                    b.x
                );
                assert!(
                    (left - right).abs() <= allowed,
                    "{name}: the skyline jumps from row {left} to {right} at x = {}",
                    b.x
                );
            }
        }
        let expected = heads
            .iter()
            .filter(|a| heads.iter().any(|b| a.x + a.width as i32 == b.x))
            .count();
        assert_eq!(seams, expected, "{name}: seams counted");
    }
}

#[test]
#[ignore = "open: the vista cuts the peaks of frames wider than about 32:9 (the land grows with the width); lowering the back edge alone does not keep them"]
fn span_of_three_monitors_keeps_the_peaks_under_the_top() {
    // Three 16:9 monitors side by side (48:9): the land grows three times
    // as tall in heights of the frame as on one; it used to rise out of
    // the top of seed 7's picture.
    let heads = [
        head(0, 0, 480, 270),
        head(480, 0, 480, 270),
        head(960, 0, 480, 270),
    ];
    for seed in [7, 5] {
        let (frame, facts) = span_picture(&heads, seed);
        let w = frame.width() as f32;
        let land_on_top = (0..frame.width())
            .filter(|&x| {
                not_sky(
                    frame.get(x, 0),
                    facts.sky_at((x as f32 + 0.5) / w, 0.5 / 270.0),
                )
            })
            .count();
        assert_eq!(
            land_on_top, 0,
            "seed {seed}: land in {land_on_top} columns of the top row"
        );
    }
}
