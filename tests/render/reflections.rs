//! Reflections (issue 19): the water mirrors the land and the sky in the
//! vista and the perspective view; `reflections = false` is the water as it
//! was; the slide show's strips give the full frame's pixels.

use std::sync::Arc;

use mountains::render::Size;
use mountains::render::classes::{Class, render_classes};
use mountains::render::view::{self, View};
use mountains::render::{Frame, Painter, render_full};
use mountains::settings::{Clouds, ColorMode, Settings, Sun, ViewKind};
use mountains::terrain::Heightfield;

use crate::common::golden;

/// A sea `depth` deep with one cone `height` tall standing in it, centred
/// at grid point (`cx`, `cy`) of a 129-point grid 400 units wide.
fn peak(cx: f32, cy: f32, height: f32) -> Heightfield {
    let mut f = Heightfield::flat(7, 400.0);
    let n = f.size();
    for y in 0..n {
        for x in 0..n {
            let d = ((x as f32 - cx).powi(2) + (y as f32 - cy).powi(2)).sqrt();
            f.set(x, y, (height * (1.0 - d / 14.0)).max(-6.0));
        }
    }
    f
}

fn vista(reflections: bool) -> Settings {
    Settings {
        view: ViewKind::Vista,
        color: ColorMode::Natural,
        reflections,
        shadows: false,
        ..Settings::default()
    }
}

fn full(field: &Heightfield, s: &Settings, w: u32, h: u32) -> Frame {
    let mut frame = Frame::new(w, h).unwrap();
    render_full(field, s, &mut frame);
    frame
}

fn rgb(c: u32) -> [i32; 3] {
    [
        (c >> 16) as i32 & 0xff,
        (c >> 8) as i32 & 0xff,
        c as i32 & 0xff,
    ]
}

fn distance(a: u32, b: u32) -> i32 {
    let (a, b) = (rgb(a), rgb(b));
    (0..3).map(|i| (a[i] - b[i]).abs()).sum()
}

/// Where the cone of height `height` shows in a `w` x `h` vista: the row
/// of its foot towards the viewer, the row where a mirror would show its
/// top (its top's image below the water), and the lowest row below the
/// foot down to which the water in the peak's column differs from the
/// water a quarter of the frame to the side by more than the streaks alone
/// make it ([`RUN`] rows running), with reflections on or off.
struct Seen {
    foot: f32,
    image: f32,
    mirrored_to: Option<u32>,
}

/// How much two colours may differ across a row of water from the streaks
/// alone (sums of channel differences): without reflections single rows
/// reach 53, but no four rows running exceed this.
const STREAKS: i32 = 40;
/// Rows running that must differ by more than [`STREAKS`].
const RUN: u32 = 4;

fn seen(height: f32, reflections: bool) -> Seen {
    let (w, h) = (480u32, 300u32);
    let (cx, cy) = (64.0, 40.0);
    let field = peak(cx, cy, height);
    // A clear sky: the peak's image, not the clouds', is measured.
    let s = Settings {
        clouds: Clouds::Amount(0.0),
        ..vista(reflections)
    };
    let frame = full(&field, &s, w, h);
    let view = vista_view(&field, Size::new(w, h));
    let top = view.project(cx, cy, height);
    // The foot on the near side, where the cone meets the water.
    let foot = view.project(cx, cy + 14.0, 0.0).y;
    let image = view.project(cx, cy, -height).y;
    let x = top.x.round() as u32;
    let side = x + w / 4;
    let px = |x: u32, y: u32| frame.pixels()[(y * w + x) as usize];
    let differs = |y: u32| distance(px(x, y), px(side, y)) > STREAKS;
    let mirrored_to = ((foot.ceil() as u32 + 2)..h)
        .filter(|&y| (y + 1 - RUN..=y).all(differs))
        .max();
    Seen {
        foot,
        image,
        mirrored_to,
    }
}

/// One peak by the water: its reflection lies below the shore, flipped
/// (reaching down to where a mirror shows its top), and a taller peak's
/// reaches lower. Without reflections the water below the peak is like
/// the water beside it.
#[test]
fn a_peak_by_the_water_is_mirrored_below_its_shore() {
    let mut reach = Vec::new();
    for height in [40.0, 80.0] {
        let on = seen(height, true);
        let below = on
            .mirrored_to
            .unwrap_or_else(|| panic!("no reflection of a {height} peak"));
        let (depth, want) = (below as f32 - on.foot, on.image - on.foot);
        assert!(
            (depth - want).abs() < 0.2 * want,
            "peak {height}: mirrored {depth} px below its foot, a mirror shows its top {want} px below"
        );
        reach.push(depth);
        let off = seen(height, false);
        assert_eq!(
            off.mirrored_to, None,
            "peak {height}: the plain water below it differs from the water beside it"
        );
    }
    assert!(
        reach[1] > reach[0] * 1.3,
        "a peak twice as tall is mirrored {} px down, the lower {} px",
        reach[1],
        reach[0]
    );
}

/// `reflections = false` with a clear sky is the water as it was before
/// issue 19: the water of the pinned pictures of the vista and the
/// perspective made before it, pixel for pixel.
#[test]
fn without_reflections_the_water_is_as_it_was() {
    let f = golden::rugged_field(5);
    let dir = golden::dir().join("plain-water");
    for (view, name) in [
        (ViewKind::Vista, "natural-vista"),
        (ViewKind::Perspective, "natural-perspective"),
    ] {
        let s = Settings {
            view,
            color: ColorMode::Natural,
            reflections: false,
            clouds: Clouds::Amount(0.0),
            // The land's finer light is not the water's; where near land
            // hides farther water, the cleaned crest mixes the land's
            // colour into the water pixel beside it.
            fine_relief: false,
            ..Settings::default()
        };
        let got = full(&f, &s, 96, 72);
        let want = golden::read_png(&dir.join(format!("{name}.png"))).expect("a pinned picture");
        // The water's pixels: the sky has the sun's glow now (issue 19
        // too), and the skyline mixes the sky into the pixels beside it.
        let mut classes = Frame::new(96, 72).unwrap();
        render_classes(&f, &s, &mut classes).expect("a class picture");
        let class = |x: i32, y: i32| {
            let (x, y) = (x.clamp(0, 95), y.clamp(0, 71));
            Class::of(classes.get(x as u32, y as u32))
        };
        let by_sky = |x: i32, y: i32| {
            (-1..=1).any(|dy| (-1..=1).any(|dx| class(x + dx, y + dy) == Class::Sky))
        };
        let water: Vec<usize> = (0..96 * 72)
            .filter(|&i| {
                let (x, y) = ((i % 96) as i32, (i / 96) as i32);
                class(x, y) == Class::Water && !by_sky(x, y)
            })
            .collect();
        assert!(
            water.len() > 96 * 72 / 20,
            "{name}: {} water pixels",
            water.len()
        );
        let changed = water
            .iter()
            .filter(|&&i| got.pixels()[i] != want.pixels()[i])
            .count();
        assert_eq!(changed, 0, "{name}: the plain water changed");
        let mirrored = full(
            &f,
            &Settings {
                reflections: true,
                ..s
            },
            96,
            72,
        );
        assert!(mirrored != want, "{name}: reflections change nothing");
    }
}

/// The slide show's strips give the full frame's pixels with reflections,
/// in the vista and the perspective view, turned every way.
#[test]
fn strips_give_the_full_frames_mirrored_water() {
    let f = peak(50.0, 30.0, 60.0);
    for view in [ViewKind::Vista, ViewKind::Perspective] {
        for rotation in [0, 90, 180, 270] {
            let s = Settings {
                view,
                rotation,
                ..vista(true)
            };
            let (w, h) = (320, 200);
            let all = full(&f, &s, w, h);
            for budget in [1, 5, usize::MAX] {
                let mut frame = Frame::new(w, h).unwrap();
                frame.clear(0x00ab_cdef);
                let mut p = Painter::new(Arc::new(f.clone()), &s, Size::new(w, h));
                while !p.is_done() {
                    p.step(&mut frame, budget);
                }
                assert!(frame == all, "{view:?} {rotation} budget {budget}");
            }
        }
    }
}

/// Pixels of the water (below the horizon, away from the land) brighter
/// than their row's median by far and warm: the sun's glitter.
fn glints(frame: &Frame, from_row: u32) -> usize {
    let (w, h) = (frame.width(), frame.height());
    let luma = |c: u32| {
        let [r, g, b] = rgb(c);
        (r * 77 + g * 150 + b * 29) >> 8
    };
    let mut count = 0;
    for y in from_row..h {
        let row = &frame.pixels()[(y * w) as usize..((y + 1) * w) as usize];
        let mut l: Vec<i32> = row.iter().map(|&c| luma(c)).collect();
        l.sort_unstable();
        let median = l[l.len() / 2];
        count += row
            .iter()
            .filter(|&&c| {
                let [r, _, b] = rgb(c);
                luma(c) > median + 30 && r > b
            })
            .count();
    }
    count
}

/// Looking into a low sun (`sun = "sunset"`), the open water below it
/// glitters: facets of the streaked water mirror the sun. With the sun to
/// the side (`"evening"`) none does, and without reflections none does.
#[test]
fn the_water_below_a_sunset_glitters() {
    let field = peak(20.0, 20.0, 3.0);
    let (w, h) = (480, 300);
    let with = |sun: Sun, reflections: bool| {
        let s = Settings {
            sun,
            clouds: Clouds::Amount(0.0),
            ..vista(reflections)
        };
        glints(&full(&field, &s, w, h), h / 2)
    };
    let sunset = with(Sun::Sunset, true);
    let evening = with(Sun::Evening, true);
    let plain = with(Sun::Sunset, false);
    eprintln!("glints: sunset {sunset}, evening {evening}, sunset without reflections {plain}");
    assert!(sunset >= 100, "only {sunset} glints under a sunset");
    assert_eq!(evening, 0, "glints with the sun to the side");
    assert_eq!(plain, 0, "glints without reflections");
}

/// The vista the scene fits to `field` in a frame of `frame`, each row's
/// highest point its top: where the tests find the pixels of a point.
pub(crate) fn vista_view(field: &Heightfield, frame: Size) -> View {
    let row_top: Vec<f32> = (0..field.size())
        .map(|y| field.row(y).iter().copied().fold(0.0, f32::max))
        .collect();
    View::fitted(
        ViewKind::Vista,
        field.size(),
        field.extent(),
        (&row_top, view::near_floor(field)),
        frame,
    )
}

/// How much of the streaks on the near water of slide `seed` (defaults,
/// a 1920x1080 frame) are thin lines across the frame rather than bands:
/// down the bottom fifth, the mean luminance of each row's water, its part
/// that changes within a few rows (the row less the mean of the 7 round it)
/// against its part that changes over tens of rows (that mean less the mean
/// of 31 of those), as root mean squares.
fn thin_lines_on_near_water(seed: u64) -> f64 {
    let size = Size::new(1920, 1080);
    let prefs = Settings {
        seed: Some(seed),
        ..Settings::default()
    };
    let s = mountains::render::detail::for_frame(&prefs, size);
    let field = mountains::terrain::generate(&s, seed);
    let (w, h) = (size.width, size.height);
    let frame = full(&field, &s, w, h);
    let mut classes = Frame::new(w, h).unwrap();
    render_classes(&field, &s, &mut classes).expect("a class picture");
    let luma = |c: u32| {
        let [r, g, b] = rgb(c);
        0.299 * r as f64 + 0.587 * g as f64 + 0.114 * b as f64
    };
    let rows: Vec<f64> = (h * 4 / 5..h - 2)
        .map(|y| {
            let water: Vec<f64> = (0..w)
                .map(|x| (y * w + x) as usize)
                .filter(|&i| Class::of(classes.pixels()[i]) == Class::Water)
                .map(|i| luma(frame.pixels()[i]))
                .collect();
            assert!(
                water.len() as u32 > w / 4,
                "seed {seed}: row {y} is not water"
            );
            water.iter().sum::<f64>() / water.len() as f64
        })
        .collect();
    let mean = |v: &[f64], k: usize| -> Vec<f64> {
        v.windows(k)
            .map(|w| w.iter().sum::<f64>() / k as f64)
            .collect()
    };
    let (near, far) = (mean(&rows, 7), mean(&mean(&rows, 7), 31));
    let rms = |d: Vec<f64>| (d.iter().map(|d| d * d).sum::<f64>() / d.len() as f64).sqrt();
    let thin = rms(far
        .iter()
        .enumerate()
        .map(|(i, _)| rows[i + 18] - near[i + 15])
        .collect());
    let broad = rms(far
        .iter()
        .enumerate()
        .map(|(i, f)| near[i + 15] - f)
        .collect());
    thin / broad
}

/// Slides whose near water mirrors the land across the frame: the wind's
/// streaks there are bands, not thin lines across the whole frame a few
/// pixels apart (the mirror's share fell with the ripple's size either
/// way, a line of whole mirror at each of its zero crossings, and the
/// streaks' finer layer, seen many pixels thick, drew its rows as lines).
#[test]
fn the_streaks_on_near_water_are_bands_not_thin_lines() {
    let ratios: Vec<f64> = [1006, 1010, 1018]
        .into_iter()
        .map(thin_lines_on_near_water)
        .collect();
    let mean = ratios.iter().sum::<f64>() / ratios.len() as f64;
    assert!(mean < 0.45, "thin lines against bands: {ratios:.2?}");
}
