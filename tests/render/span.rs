//! `monitors = "span"` headless: one picture the size of the monitors'
//! bounding rectangle, cut into each monitor's part, on layouts of two and
//! three monitors (a portrait one, different sizes and heights, a gap).
//! Where two monitors touch, the skyline goes on across the seam.

use mountains::render::Size;
use mountains::render::detail::for_frame;
use mountains::render::facts::SceneFacts;
use mountains::render::view::View;
use mountains::render::{Frame, render_full};
use mountains::saver::heads::Head;
use mountains::saver::span;
use mountains::settings::{Settings, ViewKind};
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
/// `at` on the desktop) shows the skyline, searched in desktop rows
/// `from..to`: the first land pixel with land under it (a lone star is
/// one pixel) and sky over it. `None` when the column shows no skyline
/// there (sky all the way, or land from the first row: the skyline lies
/// above the monitor).
fn skyline(
    part: &Frame,
    at: &Head,
    x: u32,
    (from, to): (i32, i32),
    sky: impl Fn(i32, i32) -> u32,
) -> Option<i32> {
    let dx = at.x + x as i32;
    let land = |dy: i32| not_sky(part.get(x, (dy - at.y) as u32), sky(dx, dy));
    let first = (from..to - 1).find(|&dy| land(dy) && land(dy + 1))?;
    (first > from).then_some(first)
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

/// The seed the seams are looked at in: its skyline crosses every seam of
/// [`layouts`] below the top of both monitors. The cut adds nothing to a
/// seam ([`seam_jumps`] checks it), so a skyline steeper than a pixel a
/// column steps as far across a seam as between any two columns: in 24
/// seeds, 96 of 104 seams that showed the skyline stepped at most 1 px,
/// and the rest were the land's own slopes (among them the crease
/// midpoint displacement leaves along the grid's middle line, where two
/// monitors side by side meet).
const SEAM_SEED: u64 = 9;

#[test]
fn span_skyline_goes_on_across_every_seam() {
    for (name, heads) in layouts() {
        let jumps = seam_jumps(&heads, SEAM_SEED, name);
        let expected = heads
            .iter()
            .filter(|a| heads.iter().any(|b| a.x + a.width as i32 == b.x))
            .count();
        assert_eq!(jumps.len(), expected, "{name}: seams counted");
        for (x, left, right) in jumps {
            let (left, right) = (
                left.unwrap_or_else(|| panic!("{name}: no skyline left of the seam at x = {x}")),
                right.unwrap_or_else(|| panic!("{name}: no skyline right of the seam at x = {x}")),
            );
            assert!(
                (left - right).abs() <= 1,
                "{name}: the skyline jumps from row {left} to {right} at x = {x}"
            );
        }
    }
}

/// Where the monitors of `heads` touch side by side, the seam's desktop x
/// and the skyline in the left monitor's last column and the right one's
/// first (over the rows both have), in seed `seed`'s span picture. Each
/// is checked against the uncut picture's skyline in the same column: the
/// cut adds nothing.
fn seam_jumps(heads: &[Head], seed: u64, name: &str) -> Vec<(i32, Option<i32>, Option<i32>)> {
    let (frame, facts) = span_picture(heads, seed);
    let whole = span::bounds(heads).unwrap();
    let parts = span::cut(&frame, &span::crops(heads));
    assert_eq!(parts.len(), heads.len(), "{name}");
    let (w, h) = (whole.width as f32, whole.height as f32);
    let sky = |dx: i32, dy: i32| {
        let fx = ((dx - whole.x) as f32 + 0.5) / w;
        facts.sky_at(fx, ((dy - whole.y) as f32 + 0.5) / h)
    };
    let mut jumps = Vec::new();
    for (a, pa) in heads.iter().zip(&parts) {
        for (b, pb) in heads.iter().zip(&parts) {
            let rows = (
                a.y.max(b.y),
                (a.y + a.height as i32).min(b.y + b.height as i32),
            );
            if a.x + a.width as i32 != b.x || rows.0 >= rows.1 {
                continue;
            }
            let left = skyline(pa, a, a.width - 1, rows, sky);
            let right = skyline(pb, b, 0, rows, sky);
            for (x, seen) in [(b.x - 1, left), (b.x, right)] {
                let column = (x - whole.x) as u32;
                let uncut = skyline(&frame, &whole, column, rows, sky);
                assert_eq!(seen, uncut, "{name}: the skyline moved at x = {x}");
            }
            eprintln!("{name}: seam at x={}: skyline {left:?} | {right:?}", b.x);
            jumps.push((b.x, left, right));
        }
    }
    jumps
}

/// Three and four 16:9 monitors side by side (48:9 and 64:9), at a
/// quarter of their sizes.
fn wide_spans() -> [Vec<Head>; 2] {
    let row = |n: i32| (0..n).map(|i| head(480 * i, 0, 480, 270)).collect();
    [row(3), row(4)]
}

#[test]
fn span_of_three_or_four_monitors_keeps_the_peaks_under_the_top() {
    // The land's height on screen grows with the width the back edge
    // spans: three monitors used to see it three times as tall as one,
    // rising out of the top of seed 7's picture. A column counts as land
    // on top where its two top rows are both far from the sky (a lone
    // star is one pixel).
    for heads in wide_spans() {
        for seed in [7, 5] {
            let (frame, facts) = span_picture(&heads, seed);
            let (w, h) = (frame.width() as f32, frame.height() as f32);
            let land = |x: u32, y: u32| {
                let sky = facts.sky_at((x as f32 + 0.5) / w, (y as f32 + 0.5) / h);
                not_sky(frame.get(x, y), sky)
            };
            let land_on_top = (0..frame.width())
                .filter(|&x| land(x, 0) && land(x, 1))
                .count();
            assert_eq!(
                land_on_top, 0,
                "{w}x{h}, seed {seed}: land in {land_on_top} columns of the top rows"
            );
        }
    }
}

#[test]
fn a_wide_vista_keeps_sky_over_tall_land_and_spans_the_width() {
    // A 1025 grid 250 wide whose every row rises 0.12, 0.2 and 0.32 of its
    // width (real land is lower at the front), in 48:9 and 64:9 frames:
    // a strip of sky over it, or, land too tall for even a 16:9 frame,
    // the 16:9 frame's land stretched sideways.
    for (w, h) in [(5760u32, 1080u32), (7680, 1080)] {
        for zmax in [30.0, 50.0, 80.0] {
            let v = View::new(ViewKind::Vista, 1025, 250.0, zmax, Size::new(w, h));
            let one = View::new(ViewKind::Vista, 1025, 250.0, zmax, Size::new(h * 16 / 9, h));
            let (wf, hf) = (w as f32, h as f32);
            let top = (0..=1024)
                .step_by(16)
                .map(|gy| v.project(512.0, gy as f32, zmax).y)
                .fold(f32::INFINITY, f32::min);
            let as_one = [(0.0, 0.0, 0.0), (300.0, 500.0, zmax), (1024.0, 1024.0, 9.0)]
                .into_iter()
                .all(|(gx, gy, z)| {
                    let (a, b) = (v.project(gx, gy, z), one.project(gx, gy, z));
                    let stretch = wf / (16.0 / 9.0 * hf);
                    let across = (a.x - wf / 2.0) - stretch * (b.x - 8.0 / 9.0 * hf);
                    (a.y - b.y).abs() < 0.01 && across.abs() < 0.01
                });
            assert!(
                top >= 0.11 * hf || (zmax > 30.0 && as_one),
                "{w}x{h}, land {zmax} high: it reaches row {top} of {hf}"
            );
            let (left, right) = (v.project(0.0, 0.0, 0.0), v.project(1024.0, 0.0, 0.0));
            assert!(
                left.x.abs() < 0.5 && (right.x - wf).abs() < 0.5,
                "{w}x{h}: the back edge runs from {} to {}",
                left.x,
                right.x
            );
            for gy in (0..=1024).step_by(64) {
                let (a, b) = (
                    v.project(0.0, gy as f32, 0.0),
                    v.project(1024.0, gy as f32, 0.0),
                );
                assert!(
                    a.x <= 0.5 && b.x >= wf - 0.5,
                    "{w}x{h}: row {gy}'s ends show"
                );
            }
            let near = v.project(512.0, 1024.0, 0.0).y;
            assert!(
                (hf..hf + 0.02 * hf + 3.0).contains(&near),
                "{w}x{h}: the near edge at row {near}"
            );
            eprintln!("{w}x{h} land {zmax}: top {top:.1}, as 16:9 {as_one}");
        }
    }
}
