//! Every data set that loads draws a picture in every view (issue 22 item
//! 8): flat, near-flat, tiny and huge scales, all sea, all land, a single
//! spike, 2x2 and odd sizes, 16-bit extremes. Before, 57 of 2857 such maps
//! loaded and then drew a frame of one colour, with exit 0 and no word: the
//! vista's camera stood below land raised over its sea and saw only the
//! near edge's face (here 74 of the 3822 frames; a wider sweep of 43953
//! frames found 153, every one in the vista).

use crate::common::heightmaps;

use std::path::Path;

use heightmaps::gray_png;
use mountains::render::{Frame, render_full};
use mountains::settings::{ColorMode, Settings, ViewKind};
use mountains::terrain::heightfield::MAX_DRAWN_RELIEF;
use mountains::terrain::heightmap::{DataSet, decode, meta};

/// The frame each map is drawn into: small, the framing is in fractions.
const FRAME: (u32, u32) = (64, 48);
/// The smallest frame the program draws a mountain in (the Windows
/// screensaver preview), where wire meshes are thinned to stay legible.
const PREVIEW: (u32, u32) = (152, 112);
/// Every view.
const VIEWS: [ViewKind; 3] = [ViewKind::Vista, ViewKind::Perspective, ViewKind::Oblique];

/// The sides of the maps: the smallest, odd and uneven ones, 2^n and 2^n + 1.
const SIDES: [(u32, u32); 7] = [
    (2, 2),
    (3, 3),
    (5, 4),
    (17, 17),
    (33, 33),
    (33, 20),
    (64, 64),
];

/// A small hash of a point, for noise that is the same on every run.
fn hash(x: u32, y: u32) -> u16 {
    let mut h = x.wrapping_mul(0x9e37_79b9) ^ y.wrapping_mul(0x85eb_ca6b);
    h ^= h >> 15;
    h = h.wrapping_mul(0x2c1b_3c6d);
    (h >> 16) as u16
}

/// The shapes of the maps: name and the sample at (x, y) of a w x h map.
type Shape = (&'static str, fn(u32, u32, u32, u32) -> u16);

const SHAPES: [Shape; 13] = [
    ("zero", |_, _, _, _| 0),
    ("middle", |_, _, _, _| 32768),
    ("top", |_, _, _, _| 65535),
    ("near-flat", |x, y, _, _| 30000 + ((x + y) % 2) as u16),
    (
        "spike",
        |x, y, w, h| {
            if (x, y) == (w / 2, h / 2) { 65535 } else { 0 }
        },
    ),
    (
        "pit",
        |x, y, w, h| {
            if (x, y) == (w / 2, h / 2) { 0 } else { 65535 }
        },
    ),
    ("ramp", |x, _, w, _| {
        (u64::from(x) * 65535 / u64::from(w.max(2) - 1)) as u16
    }),
    (
        "front-wall",
        |_, y, _, h| if y + 1 == h { 65535 } else { 0 },
    ),
    ("back-wall", |_, y, _, _| if y == 0 { 65535 } else { 0 }),
    ("halves", |x, _, w, _| if x < w / 2 { 0 } else { 65535 }),
    (
        "checker",
        |x, y, _, _| if (x + y) % 2 == 0 { 0 } else { 65535 },
    ),
    ("noise", |x, y, _, _| hash(x, y)),
    ("bumps", |x, y, _, _| {
        let v = (x as f32 * 0.4).sin() * (y as f32 * 0.3).cos();
        (32768.0 + 20000.0 * v) as u16
    }),
];

/// The metadata the maps carry: none, a misspelt key, tiny and huge
/// scales, the sea above or below every sample, tiny and huge widths, and
/// land lifted far over its sea (which drew one colour in the vista).
const METADATA: [&[(&str, &str)]; 14] = [
    &[],
    &[(meta::KEY_SCALE, "0.01"), ("mountains:sea_levle", "0.5")],
    &[(meta::KEY_SCALE, "1e-9")],
    &[(meta::KEY_SCALE, "1e-4"), (meta::KEY_EXTENT, "100000")],
    &[(meta::KEY_SCALE, "1"), (meta::KEY_EXTENT, "100000")],
    &[(meta::KEY_SEA_LEVEL, "100000")],
    &[(meta::KEY_SEA_LEVEL, "-100000")],
    &[(meta::KEY_SCALE, "0.001"), (meta::KEY_EXTENT, "1")],
    &[(meta::KEY_OFFSET, "-100000"), (meta::KEY_SCALE, "1e-6")],
    &[(meta::KEY_SCALE, "1"), (meta::KEY_SEA_LEVEL, "32767.5")],
    &[(meta::KEY_SEA_LEVEL, "-5"), (meta::KEY_EXTENT, "20")],
    &[(meta::KEY_SEA_LEVEL, "0"), (meta::KEY_EXTENT, "100000")],
    &[
        (meta::KEY_SCALE, "1e-4"),
        (meta::KEY_SEA_LEVEL, "0"),
        (meta::KEY_EXTENT, "20"),
    ],
    &[
        (meta::KEY_SCALE, "1"),
        (meta::KEY_SEA_LEVEL, "-5"),
        (meta::KEY_EXTENT, "100000"),
    ],
];

/// How many colours a frame holds, up to 2.
fn colours(frame: &Frame) -> usize {
    let first = frame.pixels()[0];
    if frame.pixels().iter().all(|&p| p == first) {
        1
    } else {
        2
    }
}

/// Calls `draw` with every map of the corpus that loads, and its label;
/// returns how many loaded.
fn each_loaded_map(mut draw: impl FnMut(&DataSet, &str)) -> usize {
    let mut loaded = 0;
    for (w, h) in SIDES {
        for (shape, sample) in SHAPES {
            let samples: Vec<u16> = (0..h)
                .flat_map(|y| (0..w).map(move |x| sample(x, y, w, h)))
                .collect();
            for text in METADATA {
                let png = gray_png(w, h, 16, &samples, text);
                let Ok(data) = decode(&png, Path::new("map.png")) else {
                    continue;
                };
                loaded += 1;
                draw(&data, &format!("{w}x{h} {shape} {text:?}"));
            }
        }
    }
    assert!(
        loaded > 500,
        "only {loaded} maps loaded: the corpus tests little"
    );
    loaded
}

/// Draws every loaded map of the corpus in a `size` frame once with each
/// of `ways` (settings and their label) and asserts that no frame is of one
/// colour.
fn no_frame_is_one_colour(size: (u32, u32), ways: &[(Settings, String)]) {
    let mut drawn = 0;
    let mut blank = Vec::new();
    let loaded = each_loaded_map(|data, label| {
        for (settings, way) in ways {
            let mut frame = Frame::new(size.0, size.1).unwrap();
            render_full(&data.field, settings, &mut frame);
            drawn += 1;
            if colours(&frame) == 1 {
                blank.push(format!("{label} {way}"));
            }
        }
    });
    eprintln!("{loaded} maps loaded, {drawn} frames drawn");
    assert!(
        blank.is_empty(),
        "{} of {drawn} frames are one colour:\n{}",
        blank.len(),
        blank.join("\n")
    );
}

#[test]
fn every_loaded_data_set_draws_more_than_one_colour_in_every_view() {
    let ways: Vec<_> = VIEWS
        .iter()
        .map(|&view| {
            let settings = Settings {
                view,
                ..crate::common::terrain_setup::temperate()
            };
            (settings, format!("{view:?}"))
        })
        .collect();
    no_frame_is_one_colour(FRAME, &ways);
}

/// The sky of the natural colours is a gradient, so a frame showing no land
/// at all still has more than one colour; Mono and Filled draw on a black
/// window, so there one colour means the land is not seen. Before, in a
/// preview-sized frame, 634 of 7,644 such frames were black: land taller
/// than a pixel is wide (a spike on a tiny grid, land lifted far over its
/// sea) drawn as a needle thinner than a pixel or not at all, in every mode,
/// and, in Mono, land seen only from its dark side (solid black, like the
/// window).
#[test]
fn every_loaded_data_set_shows_land_on_a_black_window() {
    let ways: Vec<_> = VIEWS
        .iter()
        .flat_map(|&view| [(view, ColorMode::Mono), (view, ColorMode::Filled)])
        .map(|(view, color)| {
            let settings = Settings {
                view,
                color,
                ..crate::common::terrain_setup::temperate()
            };
            (settings, format!("{view:?} {color:?}"))
        })
        .collect();
    no_frame_is_one_colour(PREVIEW, &ways);
}

/// A data set far taller than wide keeps its heights (saving it again gives
/// the same file) and is drawn squashed, with a note saying so.
#[test]
fn a_needle_keeps_its_heights_and_is_drawn_squashed_with_a_note() {
    let (w, h) = (17, 17);
    let samples: Vec<u16> = (0..h)
        .flat_map(|y| (0..w).map(move |x| if (x, y) == (8, 8) { 65535 } else { 0 }))
        .collect();
    let text: &[(&str, &str)] = &[(meta::KEY_SCALE, "0.001"), (meta::KEY_EXTENT, "1")];
    let data = decode(&gray_png(w, h, 16, &samples, text), Path::new("map.png")).unwrap();
    let (lo, hi) = data.field.min_max();
    // 65.535 units of relief on a grid 1 unit wide.
    assert!(
        (hi - lo - 65.535).abs() < 1e-3,
        "heights changed: {lo}..{hi}"
    );
    let scale = data.field.drawn_scale();
    assert!(
        (scale * (hi.max(0.0) - lo.min(0.0)) - MAX_DRAWN_RELIEF).abs() < 1e-3,
        "drawn scale {scale}"
    );
    let drawn = data.field.drawn().expect("a needle is drawn squashed");
    assert_eq!(drawn.size(), data.field.size());
    assert!((drawn.max() - hi * scale).abs() < 1e-4);
    assert!(
        data.notes
            .iter()
            .any(|n| n.contains("drawn 2 times as tall")),
        "{:?}",
        data.notes
    );
    // An ordinary mountain is drawn as it is.
    let flat = decode(
        &gray_png(w, h, 16, &vec![1000; 17 * 17], &[]),
        Path::new("m.png"),
    )
    .unwrap();
    assert!(flat.field.drawn().is_none());
}
