//! Opening heightmaps from other tools: fitting to 2^n+1 and sensible defaults.

use crate::common::heightmaps;

use std::path::Path;

use heightmaps::{gray_png, interlaced_gray8};
use mountains::settings::Settings;
use mountains::terrain::heightmap::{
    DEFAULT_EXTENT, DEFAULT_RELIEF, DataSet, FitMethod, decode, encode, meta,
};

const P: &str = "foreign.png";

/// Our vertical keys pinned to identity, so heights equal the filtered samples.
const IDENTITY: [(&str, &str); 4] = [
    (meta::KEY_SCALE, "1"),
    (meta::KEY_OFFSET, "0"),
    (meta::KEY_SEA_LEVEL, "0"),
    (meta::KEY_EXTENT, "400"),
];

fn load(bytes: &[u8]) -> DataSet {
    decode(bytes, Path::new(P)).unwrap()
}

/// Loaded heights sit on the 16-bit grid a save would use: within half a
/// step of the filtered samples.
fn near(got: f32, want: f32, d: &DataSet) -> bool {
    (got - want).abs() <= relief(d) / 65535.0 * 0.5 + 1e-3
}

fn relief(d: &DataSet) -> f32 {
    d.field.max() - d.field.min()
}

fn below_sea(d: &DataSet) -> f64 {
    let wet = d.field.heights().iter().filter(|&&h| h < 0.0).count();
    wet as f64 / d.field.heights().len() as f64
}

#[test]
fn eight_bit_300x200_is_cropped_centrally_and_resampled() {
    // Margins of 255 left and right of a central 200x200 ramp: if the crop
    // were not central, 255 would show up in the heights.
    let (w, h) = (300u32, 200u32);
    let samples: Vec<u16> = (0..w * h)
        .map(|i| {
            let (x, y) = (i % w, i / w);
            if (50..250).contains(&x) {
                ((x - 50 + y) / 2) as u16
            } else {
                255
            }
        })
        .collect();
    let d = load(&gray_png(w, h, 8, &samples, &[]));
    assert_eq!(d.field.size(), 257);
    assert_eq!(d.bit_depth, 8);
    assert_eq!(d.fit.method, FitMethod::Resampled);
    assert_eq!((d.fit.crop_x, d.fit.crop_y, d.fit.crop_side), (50, 0, 200));
    assert_eq!(d.field.extent(), DEFAULT_EXTENT);
    // Relief is the default fraction of the width, from the ramp's 0..=199 only.
    let want = DEFAULT_RELIEF * DEFAULT_EXTENT;
    assert!(
        (relief(&d) - want).abs() < 0.01 * want,
        "relief {}",
        relief(&d)
    );
    // The ramp rises to the front right: the back-left corner is lowest.
    assert_eq!(d.field.get(0, 0), d.field.min());
    assert_eq!(d.field.get(256, 256), d.field.max());
    let wet = below_sea(&d);
    assert!(wet > 0.02 && wet <= 0.10, "water covers {wet}");
    for what in [
        "mountains:scale",
        "mountains:sea_level",
        "mountains:extent",
        "fitted",
    ] {
        assert!(
            d.notes.iter().any(|n| n.contains(what)),
            "no note on {what}: {:?}",
            d.notes
        );
    }
}

#[test]
fn sixteen_bit_512_square_repeats_its_last_row_and_column() {
    let n = 512u32;
    let samples: Vec<u16> = (0..n * n)
        .map(|i| ((i % n) * 97 + (i / n) * 31) as u16)
        .collect();
    let d = load(&gray_png(n, n, 16, &samples, &IDENTITY));
    assert_eq!(d.field.size(), 513);
    assert_eq!(d.fit.method, FitMethod::RepeatEdge);
    for y in [0, 17, 511] {
        for x in [0, 200, 511] {
            let want = samples[y * 512 + x] as f32;
            assert!(
                near(d.field.get(x, y), want, &d),
                "({x},{y}): {} vs {want}",
                d.field.get(x, y)
            );
        }
        assert_eq!(d.field.get(512, y), d.field.get(511, y));
    }
    assert_eq!(d.field.row(512), d.field.row(511));
}

#[test]
fn tiny_image_is_enlarged_bilinearly() {
    let samples = [0u16, 1600, 3200, 6400];
    let d = load(&gray_png(2, 2, 16, &samples, &IDENTITY));
    assert_eq!(d.field.size(), 17);
    let f = &d.field;
    // Bilinear: at (u, v) the corners weigh (1-u)(1-v), u(1-v), (1-u)v, uv.
    let bilinear = |u: f32, v: f32| {
        (1.0 - u) * (1.0 - v) * 0.0
            + u * (1.0 - v) * 1600.0
            + (1.0 - u) * v * 3200.0
            + u * v * 6400.0
    };
    for (x, y) in [
        (0, 0),
        (16, 0),
        (0, 16),
        (16, 16),
        (8, 0),
        (8, 8),
        (4, 12),
        (13, 3),
    ] {
        let want = bilinear(x as f32 / 16.0, y as f32 / 16.0);
        assert!(
            near(f.get(x, y), want, &d),
            "({x},{y}): {} vs {want}",
            f.get(x, y)
        );
    }
}

#[test]
fn large_ramp_is_reduced_without_bending() {
    let n = 1300u32;
    let samples: Vec<u16> = (0..n * n).map(|i| ((i % n) * 40) as u16).collect();
    let d = load(&gray_png(n, n, 16, &samples, &IDENTITY));
    assert_eq!(d.field.size(), 1025);
    let step = 1299.0 * 40.0 / 1024.0;
    for x in [3, 100, 512, 1000] {
        let want = x as f32 * step;
        // The discrete tent may shift a point by a few hundredths of a pixel.
        let tolerance = 0.1 * 40.0;
        let got = d.field.get(x, 77);
        assert!((got - want).abs() < tolerance, "x {x}: {got} vs {want}");
    }
}

#[test]
fn interlaced_image_reads_like_a_plain_one() {
    let (w, h) = (37u32, 21u32);
    let samples: Vec<u8> = (0..w * h).map(|i| ((i * 7919) % 251) as u8).collect();
    let wide: Vec<u16> = samples.iter().map(|&s| u16::from(s)).collect();
    let plain = load(&gray_png(w, h, 8, &wide, &[]));
    let interlaced = load(&interlaced_gray8(w, h, &samples));
    assert_eq!(plain.field, interlaced.field);
}

#[test]
fn ground_at_the_lowest_level_is_under_water() {
    // 40% of the image is a flat sea floor at 0: the percentile lands on it,
    // and the water line still goes above it.
    let n = 100u32;
    let samples: Vec<u16> = (0..n * n)
        .map(|i| if i % n < 40 { 0 } else { (i % n) as u16 })
        .collect();
    let d = load(&gray_png(n, n, 8, &samples, &[]));
    assert!(d.field.get(0, 50) < 0.0);
    assert!(d.field.get(60, 50) > 0.0);
}

#[test]
fn flat_image_loads_as_flat_water() {
    let d = load(&gray_png(40, 40, 16, &vec![1234; 1600], &[]));
    let h = d.field.get(0, 0);
    assert!(h <= 0.0);
    assert!(d.field.heights().iter().all(|&x| x == h));
}

#[test]
fn foreign_load_then_save_then_load_is_exact() {
    let (w, h) = (300u32, 200u32);
    let samples: Vec<u16> = (0..w * h)
        .map(|i| ((i % w) * (i / w) % 256) as u16)
        .collect();
    let first = load(&gray_png(w, h, 8, &samples, &[]));
    let bytes = encode(
        &first.field,
        None,
        &crate::common::terrain_setup::temperate(),
        Path::new(P),
    )
    .unwrap();
    let second = load(&bytes);
    assert_eq!(second.field, first.field);
    assert!(second.notes.is_empty(), "{:?}", second.notes);
    assert!(
        encode(
            &second.field,
            None,
            &crate::common::terrain_setup::temperate(),
            Path::new(P)
        )
        .unwrap()
            == bytes
    );
}

#[test]
fn our_keys_in_compressed_text_chunks_are_read() {
    let samples: Vec<u16> = (0..17 * 17).map(|i| i as u16 * 100).collect();
    let mut out = Vec::new();
    let mut enc = png::Encoder::new(&mut out, 17, 17);
    enc.set_color(png::ColorType::Grayscale);
    enc.set_depth(png::BitDepth::Sixteen);
    enc.add_ztxt_chunk(meta::KEY_SCALE.into(), "0.5".into())
        .unwrap();
    enc.add_itxt_chunk(meta::KEY_SEA_LEVEL.into(), "100".into())
        .unwrap();
    enc.add_ztxt_chunk(meta::KEY_SEED.into(), "77".into())
        .unwrap();
    let mut w = enc.write_header().unwrap();
    let data: Vec<u8> = samples.iter().flat_map(|s| s.to_be_bytes()).collect();
    w.write_image_data(&data).unwrap();
    w.finish().unwrap();
    let d = load(&out);
    assert_eq!(d.seed, Some(77));
    assert_eq!(d.scale, 0.5);
    assert_eq!(d.field.get(0, 0), -100.0);
    assert_eq!(d.field.get(16, 16), 288.0 * 100.0 * 0.5 - 100.0);
}

#[test]
fn unknown_keys_are_ignored_and_bad_origin_keys_only_noted() {
    let samples = vec![500u16; 17 * 17];
    let mut text = IDENTITY.to_vec();
    text.push(("mountains:future_key", "whatever"));
    text.push(("Comment", "from a terrain tool"));
    text.push((meta::KEY_SEED, "not-a-seed"));
    text.push((meta::KEY_GENERATOR, "ridged"));
    let d = load(&gray_png(17, 17, 16, &samples, &text));
    assert_eq!(d.seed, None);
    assert_eq!(d.params, None);
    assert!(
        d.notes.iter().any(|n| n.contains(meta::KEY_SEED)),
        "{:?}",
        d.notes
    );
    assert!(
        d.notes.iter().any(|n| n.contains(meta::KEY_GENERATOR)),
        "{:?}",
        d.notes
    );
    assert!(d.field.heights().iter().all(|&h| h == 500.0));
}

#[test]
fn largest_allowed_side_and_extreme_aspect_load() {
    for (w, h) in [(16384u32, 3u32), (3, 16384)] {
        let samples: Vec<u16> = (0..w * h).map(|i| (i % 5000) as u16).collect();
        let d = load(&gray_png(w, h, 16, &samples, &[]));
        assert_eq!(d.field.size(), 17, "{w}x{h}");
        assert_eq!(d.fit.crop_side, 3);
        assert!(d.fit.cropped());
    }
}

mod random_images {
    use super::*;
    use proptest::prelude::*;

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(60))]
        #[test]
        fn any_small_gray_image_fits_and_round_trips(
            w in 2u32..80,
            h in 2u32..80,
            sixteen in any::<bool>(),
            seed in any::<u64>(),
        ) {
            let bits = if sixteen { 16 } else { 8 };
            let mut state = seed | 1;
            let samples: Vec<u16> = (0..w * h)
                .map(|_| {
                    state ^= state << 13;
                    state ^= state >> 7;
                    state ^= state << 17;
                    if sixteen { (state >> 48) as u16 } else { (state >> 56) as u16 }
                })
                .collect();
            let d = load(&gray_png(w, h, bits, &samples, &[]));
            let n = d.field.size();
            prop_assert!(n >= 17 && (n - 1).is_power_of_two());
            prop_assert_eq!(d.fit.crop_side, w.min(h));
            prop_assert!(d.field.heights().iter().all(|h| h.is_finite()));
            let relief = d.field.max() - d.field.min();
            prop_assert!(relief <= DEFAULT_RELIEF * DEFAULT_EXTENT * 1.0001);
            let bytes = encode(&d.field, None, &crate::common::terrain_setup::temperate(), Path::new(P)).unwrap();
            prop_assert_eq!(load(&bytes).field, d.field);
        }
    }
}

/// How many colours a picture of `d` has in `view`, at 320x200.
fn colours_drawn(d: &DataSet, view: mountains::settings::ViewKind) -> usize {
    let settings = Settings {
        view,
        ..crate::common::terrain_setup::temperate()
    };
    let mut frame = mountains::render::Frame::new(320, 200).unwrap();
    mountains::render::render_full(&d.field, &settings, &mut frame);
    let mut seen = frame.pixels().to_vec();
    seen.sort_unstable();
    seen.dedup();
    seen.len()
}

/// A small map far taller than it is wide (`mountains:scale` 0.01 over 33
/// samples, no sea level: issue 22 found it drawn as one dark brown frame
/// in the vista, whose camera stood low inside the land) is drawn as land
/// and sky in every view, at every relief from gentle to needle-like.
#[test]
fn a_map_taller_than_wide_is_drawn_in_every_view() {
    use mountains::settings::ViewKind;
    let n = 33;
    let samples: Vec<u16> = (0..n * n)
        .map(|i| {
            let (u, v) = ((i % n) as f32 / n as f32, (i / n) as f32 / n as f32);
            let h = 40.0 * (u * 7.3).sin() * (v * 5.1).cos() + 25.0 * u - 12.5;
            ((h + 70.0) / 140.0 * 65535.0) as u16
        })
        .collect();
    for scale in ["0.0000001", "0.001", "0.005", "0.01", "0.1", "1"] {
        let png = gray_png(
            n as u32,
            n as u32,
            16,
            &samples,
            &[(meta::KEY_SCALE, scale), ("mountains:sea_levle", "3")],
        );
        let d = load(&png);
        for view in [ViewKind::Vista, ViewKind::Perspective, ViewKind::Oblique] {
            let colours = colours_drawn(&d, view);
            assert!(colours >= 64, "scale {scale}, {view:?}: {colours} colours");
        }
    }
}
