//! The painter: stepping, parallel full frames, fitting, odd frame sizes.

use std::sync::Arc;

use mountains::render::Size;
use mountains::render::{Frame, Painter, Rect, render_full};
use mountains::settings::{ColorMode, Settings, ViewKind};
use mountains::terrain::Heightfield;

use crate::common::golden;

use golden::rugged_field as field;

fn settings(color: ColorMode, view: ViewKind, rotation: u32) -> Settings {
    Settings {
        color,
        view,
        rotation,
        ..Settings::default()
    }
}

const MODES: [ColorMode; 6] = [
    ColorMode::Natural,
    ColorMode::Gray,
    ColorMode::Sonar,
    ColorMode::Outline,
    ColorMode::Mono,
    ColorMode::Ridges,
];

fn stepped(field: &Heightfield, s: &Settings, w: u32, h: u32, budget: usize) -> Frame {
    let mut frame = Frame::new(w, h).unwrap();
    // Start from garbage: the first step must paint every pixel itself.
    frame.clear(0x00ab_cdef);
    let mut p = Painter::new(Arc::new(field.clone()), s, Size::new(w, h));
    let mut steps = 0;
    while !p.is_done() {
        let before = p.strips_done();
        p.step(&mut frame, budget);
        assert!(p.strips_done() > before || p.is_done(), "no progress");
        steps += 1;
        assert!(steps <= p.strips_total() + 1, "more steps than strips");
    }
    frame
}

fn full(field: &Heightfield, s: &Settings, w: u32, h: u32) -> Frame {
    let mut frame = Frame::new(w, h).unwrap();
    frame.clear(0x0012_3456);
    render_full(field, s, &mut frame);
    frame
}

#[test]
fn stepping_equals_the_full_frame_in_every_mode() {
    let f = field(5);
    for color in MODES {
        for (view, rotation) in [
            (ViewKind::Oblique, 0),
            (ViewKind::Perspective, 90),
            (ViewKind::Oblique, 270),
            (ViewKind::Vista, 0),
            (ViewKind::Vista, 180),
        ] {
            let s = settings(color, view, rotation);
            let all = full(&f, &s, 160, 120);
            for budget in [1, 3, 7, usize::MAX] {
                let got = stepped(&f, &s, 160, 120, budget);
                assert!(
                    got == all,
                    "{color:?} {view:?} {rotation}: budget {budget} differs from render_full"
                );
            }
        }
    }
}

/// `finish` (what the saver's redraw runs) draws the same pixels whether the
/// painter is fresh (all cores) or part-way (the rest, strip by strip).
#[test]
fn finish_equals_the_full_frame_fresh_or_part_way() {
    let f = field(5);
    for color in [ColorMode::Natural, ColorMode::Sonar, ColorMode::Ridges] {
        let s = settings(color, ViewKind::Vista, 0);
        let all = full(&f, &s, 160, 120);
        for begun in [0, 5] {
            let mut frame = Frame::new(160, 120).unwrap();
            frame.clear(0x00ab_cdef);
            let mut p = Painter::new(Arc::new(f.clone()), &s, Size::new(160, 120));
            p.step(&mut frame, begun);
            let damage = p.finish(&mut frame);
            assert!(p.is_done(), "{color:?}: not done after finish");
            assert!(
                frame == all,
                "{color:?}: finish after {begun} strips differs"
            );
            assert!(!damage.is_empty(), "{color:?}: finish reported no damage");
        }
    }
}

/// A step's damage holds every pixel it changed; in the vista, where a
/// strip winds across the frame over its peaks, the damage follows the
/// strip instead of boxing it (what the saver copies and sends).
#[test]
fn damage_covers_every_changed_pixel() {
    let f = field(5);
    let cases = [
        (ColorMode::Natural, ViewKind::Oblique),
        (ColorMode::Sonar, ViewKind::Oblique),
        (ColorMode::Outline, ViewKind::Oblique),
        (ColorMode::Natural, ViewKind::Vista),
    ];
    for (color, view) in cases {
        let s = settings(color, view, 0);
        let (w, h) = (640u32, 240u32);
        let mut frame = Frame::new(w, h).unwrap();
        let mut p = Painter::new(Arc::new(f.clone()), &s, Size::new(w, h));
        let first = p.step(&mut frame, 1);
        assert_eq!(
            first.bounds(),
            frame.bounds(),
            "the first step paints the background"
        );
        let (mut kept, mut boxed) = (0u64, 0u64);
        while !p.is_done() {
            let before = frame.clone();
            let d = p.step(&mut frame, 2);
            for y in 0..h {
                for x in 0..w {
                    let i = (y * w + x) as usize;
                    assert!(
                        d.contains(x, y) || before.pixels()[i] == frame.pixels()[i],
                        "{color:?}: pixel ({x}, {y}) changed outside the damage {d:?}"
                    );
                }
            }
            let area = |r: Rect| u64::from(r.x1 - r.x0) * u64::from(r.y1 - r.y0);
            kept += d.rects().map(area).sum::<u64>();
            boxed += area(d.bounds());
        }
        if view == ViewKind::Vista {
            assert!(
                kept * 10 < boxed * 7,
                "the damage boxes the strips: {kept} of {boxed} pixels"
            );
        }
        assert!(
            p.step(&mut frame, 5).is_empty(),
            "a finished painter drew more"
        );
    }
}

#[test]
fn frames_of_any_shape_never_panic_and_show_the_mountain() {
    let f = field(4);
    for (w, h) in [(1, 1), (152, 112), (3, 500), (500, 3), (7680, 2160), (2, 2)] {
        for color in MODES {
            for view in [ViewKind::Oblique, ViewKind::Perspective] {
                let s = settings(color, view, 0);
                let frame = full(&f, &s, w, h);
                if w >= 100 && h >= 100 {
                    let sky = sky_only(&f, &s, w, h);
                    let drawn = (frame.pixels().iter().zip(sky.pixels()))
                        .filter(|(p, s)| p != s)
                        .count();
                    // Sonar and Outline draw only lines on black.
                    let lines = matches!(color, ColorMode::Sonar | ColorMode::Outline);
                    let part = if lines { 2000 } else { 50 };
                    assert!(
                        drawn * part > (w * h) as usize,
                        "{w}x{h} {color:?} {view:?}: almost nothing drawn"
                    );
                }
            }
        }
    }
}

/// The frame with only the sky painted (a painter's first step, no strips).
fn sky_only(field: &Heightfield, s: &Settings, w: u32, h: u32) -> Frame {
    let mut frame = Frame::new(w, h).unwrap();
    Painter::new(Arc::new(field.clone()), s, Size::new(w, h)).step(&mut frame, 0);
    frame
}

/// Bounding box of the pixels that differ from the sky alone.
fn drawn_box(frame: &Frame, sky: &Frame) -> (u32, u32, u32, u32) {
    let (w, h) = (frame.width(), frame.height());
    let (mut x0, mut y0, mut x1, mut y1) = (w, h, 0, 0);
    for y in 0..h {
        for x in 0..w {
            let i = (y * w + x) as usize;
            if frame.pixels()[i] != sky.pixels()[i] {
                (x0, y0, x1, y1) = (x0.min(x), y0.min(y), x1.max(x + 1), y1.max(y + 1));
            }
        }
    }
    (x0, y0, x1, y1)
}

#[test]
fn the_mountain_fills_frames_of_every_aspect() {
    let f = field(5);
    for (w, h) in [(152, 112), (1920, 1080), (3840, 600), (300, 900)] {
        for view in [ViewKind::Oblique, ViewKind::Perspective] {
            let s = settings(ColorMode::Natural, view, 0);
            let frame = full(&f, &s, w, h);
            let (x0, y0, x1, y1) = drawn_box(&frame, &sky_only(&f, &s, w, h));
            let what = format!("{w}x{h} {view:?}: drawn box {x0},{y0}-{x1},{y1}");
            assert!(
                x0 > 0 && y0 > 0 && x1 < w && y1 < h,
                "{what}: touches the border"
            );
            let wide = (x1 - x0) as f32 / w as f32;
            let tall = (y1 - y0) as f32 / h as f32;
            assert!(wide > 0.85 || tall > 0.6, "{what}: does not fill the frame");
            // The classic views are fitted with a margin of at most 2% a side.
            let slack = |px: u32| 3.0 / px as f32;
            assert!(
                wide >= 0.96 - slack(w) || tall >= 0.96 - slack(h),
                "{what}: a margin over 2% ({wide:.3} x {tall:.3})"
            );
            let centre = (x0 + x1) as f32 / 2.0 / w as f32;
            assert!((centre - 0.5).abs() < 0.05, "{what}: not centred");
        }
    }
}

#[test]
fn a_resized_painter_refuses_the_old_frame() {
    let f = Arc::new(field(4));
    let s = Settings::default();
    let mut p = Painter::new(f.clone(), &s, Size::new(200, 100));
    let mut small = Frame::new(100, 50).unwrap();
    assert!(
        p.step(&mut small, 10).is_empty(),
        "drew into a frame of another size"
    );
    assert!(
        small.pixels().iter().all(|&p| p == 0),
        "touched a frame of another size"
    );
    // A huge frame size plans without per-pixel allocation (the frame
    // itself is what `Frame::new` refuses).
    let huge = Painter::new(f, &s, Size::new(1 << 20, 1 << 20));
    assert!(huge.strips_total() > 0);
    assert!(Frame::new(1 << 20, 1 << 20).is_none());
}

/// A painter that has drawn every strip, stepped or finished whole, lets
/// go of its scene (the field, the shadow and sky-light maps): a held slide
/// keeps only its frame. Stepping it again draws nothing.
#[test]
fn a_done_painter_holds_no_field() {
    let f = Arc::new(field(5));
    for mode in MODES {
        let s = settings(mode, ViewKind::Vista, 0);
        let mut stepped = Painter::new(f.clone(), &s, Size::new(120, 80));
        let mut frame = Frame::new(120, 80).unwrap();
        while !stepped.is_done() {
            stepped.step(&mut frame, 7);
        }
        let mut finished = Painter::new(f.clone(), &s, Size::new(120, 80));
        finished.finish(&mut Frame::new(120, 80).unwrap());
        assert_eq!(
            Arc::strong_count(&f),
            1,
            "{mode:?}: a done painter still holds the field"
        );
        let before = frame.clone();
        assert!(stepped.step(&mut frame, 7).is_empty(), "{mode:?}");
        assert!(frame == before, "{mode:?}: drew again when done");
        assert_eq!(stepped.strips_total(), stepped.strips_done(), "{mode:?}");
    }
}

#[test]
fn the_same_field_gives_the_same_pixels_on_any_thread_count() {
    let f = field(6);
    for color in [ColorMode::Natural, ColorMode::Sonar, ColorMode::Mono] {
        let s = settings(color, ViewKind::Oblique, 0);
        let a = full(&f, &s, 640, 480);
        let b = stepped(&f, &s, 640, 480, usize::MAX);
        assert!(a == b, "{color:?}: banded full frame differs from one band");
    }
}

/// The full frame is drawn in bands of columns, each walking only the cells
/// that can reach it: on a fine grid in a wide frame, in every view and
/// turn, with faces, skirts and shores crossing the cuts, it still equals
/// one band stepping through every cell.
#[test]
fn bands_of_columns_equal_one_band_in_every_view() {
    let f = field(7);
    for color in [ColorMode::Natural, ColorMode::Mono] {
        for view in [ViewKind::Vista, ViewKind::Perspective, ViewKind::Oblique] {
            for rotation in [0, 90, 180, 270] {
                let s = settings(color, view, rotation);
                let a = full(&f, &s, 700, 300);
                let b = stepped(&f, &s, 700, 300, usize::MAX);
                assert!(
                    a == b,
                    "{color:?} {view:?} {rotation}: bands differ from one band"
                );
            }
        }
    }
}

/// The pinned look of each mode: 96x72 pictures of `field(5)` under
/// tests/golden/, one per mode and view, to be looked at (they were FNV
/// hashes, which nobody could see).
///
/// When the look changes on purpose (a new palette, a new fit), look at the
/// pictures the failing test writes to target/golden-actual/ beside the
/// pinned ones; if they are right, run the test again with
/// `MOUNTAINS_PIN_GOLDEN=1` to write them under tests/golden/, and commit
/// them. Sonar and Outline do not depend on the palette; the others do.
#[test]
fn golden_pictures_pin_each_mode() {
    let f = field(5);
    let cases = [
        (ColorMode::Natural, ViewKind::Vista, "natural-vista"),
        (ColorMode::Natural, ViewKind::Oblique, "natural-oblique"),
        (
            ColorMode::Natural,
            ViewKind::Perspective,
            "natural-perspective",
        ),
        (ColorMode::Sonar, ViewKind::Oblique, "sonar-oblique"),
        (
            ColorMode::Outline,
            ViewKind::Perspective,
            "outline-perspective",
        ),
        (ColorMode::Mono, ViewKind::Oblique, "mono-oblique"),
        (ColorMode::Gray, ViewKind::Oblique, "gray-oblique"),
    ];
    let pictures = cases.map(|(color, view, name)| {
        let got = full(&f, &settings(color, view, 0), 96, 72);
        (format!("{name}.png"), got)
    });
    let wrong = golden::compare(pictures);
    assert!(
        wrong.is_empty(),
        "the look changed: {wrong:?}; compare target/golden-actual/ with tests/golden/"
    );
}

#[test]
fn broken_heights_and_extents_never_panic() {
    let mut f = field(4);
    f.set(3, 3, f32::NAN);
    f.set(5, 9, f32::INFINITY);
    f.set(9, 5, f32::NEG_INFINITY);
    f.set(16, 16, 1e30);
    for extent in [400.0, 0.0, -5.0, f32::NAN, 1e-30, 1e30] {
        f.set_extent(extent);
        for color in MODES {
            for view in [ViewKind::Oblique, ViewKind::Perspective] {
                let s = settings(color, view, 90);
                let frame = full(&f, &s, 64, 48);
                let again = stepped(&f, &s, 64, 48, 5);
                assert!(
                    frame == again,
                    "extent {extent} {color:?} {view:?}: stepping differs"
                );
            }
        }
    }
}

/// Generated mountains (crags, folds, shores) in every view and turn at a
/// real detail: the full frame, drawn front to back keeping the first write
/// and skipping hidden cells, equals stepping back to front pixel for pixel.
#[test]
fn front_to_back_equals_back_to_front_on_generated_mountains() {
    use mountains::render::detail;
    use mountains::terrain::generate;
    let (w, h) = (480, 270);
    for (seed, view, rotation, color) in [
        (42, ViewKind::Vista, 0, ColorMode::Natural),
        (3, ViewKind::Vista, 90, ColorMode::Natural),
        (1997, ViewKind::Perspective, 180, ColorMode::Natural),
        (7, ViewKind::Oblique, 270, ColorMode::Mono),
        (108, ViewKind::Vista, 270, ColorMode::Gray),
    ] {
        let s = detail::for_frame(&settings(color, view, rotation), Size::new(w, h));
        let f = generate(&s, seed);
        let a = full(&f, &s, w, h);
        let b = stepped(&f, &s, w, h, usize::MAX);
        let differ = a
            .pixels()
            .iter()
            .zip(b.pixels())
            .filter(|(p, q)| p != q)
            .count();
        assert_eq!(differ, 0, "seed {seed} {view:?} {rotation}: pixels differ");
    }
}

/// A sea of one depth, a hill at the back: down a column of the near water
/// the vista's wind streaks make the brightness rise and fall (11 turns;
/// without them 2). The classic views keep their plain water: their golden
/// pictures above did not change.
#[test]
fn open_water_shows_wind_streaks_in_the_vista() {
    let mut f = Heightfield::flat(6, 400.0);
    let n = f.size();
    for y in 0..n {
        for x in 0..n {
            let d = ((x as f32 - 8.0).powi(2) + (y as f32 - 6.0).powi(2)).sqrt();
            f.set(x, y, (60.0 - 8.0 * d).max(-10.0));
        }
    }
    let turns = || {
        let (w, h) = (320, 180);
        let frame = full(&f, &settings(ColorMode::Natural, ViewKind::Vista, 0), w, h);
        let gray = |y: u32| {
            let c = frame.pixels()[(y * w + w * 3 / 4) as usize];
            (c >> 16 & 0xff) + (c >> 8 & 0xff) + (c & 0xff)
        };
        let column: Vec<i64> = (h * 3 / 4..h).map(|y| i64::from(gray(y))).collect();
        let steps: Vec<i64> = column.windows(2).map(|p| (p[1] - p[0]).signum()).collect();
        let steps: Vec<i64> = steps.into_iter().filter(|&s| s != 0).collect();
        steps.windows(2).filter(|s| s[0] != s[1]).count()
    };
    let vista = turns();
    assert!(vista >= 6, "the vista's near water turns {vista} times");
}
