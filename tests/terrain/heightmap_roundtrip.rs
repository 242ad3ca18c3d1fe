//! Saving and loading our own data sets: exact after the first quantisation.

use crate::common::heightmaps;

use std::path::Path;

use heightmaps::field;
use mountains::settings::Detail;
use mountains::settings::{Generator, Profile, Settings};
use mountains::terrain::Heightfield;
use mountains::terrain::heightmap::{
    self, ErrorKind, FitMethod, GeneratorParams, decode, encode, meta,
};
use proptest::prelude::*;

const P: &str = "mem.png";

fn odd_settings() -> Settings {
    Settings {
        generator: Generator::Triangle,
        cragginess: 17,
        elevation: 123.5,
        roughness: 3.25,
        contour: 0.5,
        profile: Profile::Bay,
        height: 9,
        detail: Detail::Level(6),
        low_detail: true,
        sea_level: -0.125,
        ..crate::common::terrain_setup::temperate()
    }
}

fn roundtrip_is_exact(f: &Heightfield, seed: Option<u64>, s: &Settings) {
    let first = encode(f, seed, s, Path::new(P)).unwrap();
    let loaded = decode(&first, Path::new(P)).unwrap();
    let second = encode(&loaded.field, seed, s, Path::new(P)).unwrap();
    assert!(first == second, "save -> load -> save changed the bytes");
    let again = decode(&second, Path::new(P)).unwrap();
    assert_eq!(
        again.field, loaded.field,
        "load -> save -> load changed the heights"
    );
}

#[test]
fn save_load_save_is_byte_identical() {
    roundtrip_is_exact(&field(6, 400.0), Some(12345), &odd_settings());
    roundtrip_is_exact(
        &field(4, 1.5),
        None,
        &crate::common::terrain_setup::temperate(),
    );
}

#[test]
fn first_quantisation_is_within_half_a_step() {
    let f = field(7, 400.0);
    let bytes = encode(
        &f,
        Some(1),
        &crate::common::terrain_setup::temperate(),
        Path::new(P),
    )
    .unwrap();
    let d = decode(&bytes, Path::new(P)).unwrap();
    let step = (f.max() - f.min()) / 65535.0;
    for (a, b) in f.heights().iter().zip(d.field.heights()) {
        assert!((a - b).abs() <= step * 0.5 + 1e-6, "{a} -> {b}");
    }
    assert_eq!(d.field.min(), f.min());
    assert_eq!(d.field.max(), f.max());
    assert_eq!(d.field.extent(), 400.0);
    assert_eq!(d.field.size(), f.size());
    assert_eq!(d.fit.method, FitMethod::Exact);
    assert!(
        d.notes.is_empty(),
        "our own file needs no guesses: {:?}",
        d.notes
    );
}

#[test]
fn seed_and_parameters_come_back() {
    let s = odd_settings();
    let bytes = encode(&field(5, 333.25), Some(u64::MAX), &s, Path::new(P)).unwrap();
    let d = decode(&bytes, Path::new(P)).unwrap();
    assert_eq!(d.seed, Some(u64::MAX));
    assert_eq!(d.params, Some(GeneratorParams::from_settings(&s)));
    assert_eq!(d.field.extent(), 333.25);
    let mut back = crate::common::terrain_setup::temperate();
    d.params.unwrap().apply_to(&mut back);
    assert_eq!(
        GeneratorParams::from_settings(&back),
        GeneratorParams::from_settings(&s)
    );
}

#[test]
fn no_seed_means_no_parameters() {
    let bytes = encode(&field(4, 400.0), None, &odd_settings(), Path::new(P)).unwrap();
    let d = decode(&bytes, Path::new(P)).unwrap();
    assert_eq!(d.seed, None);
    assert_eq!(d.params, None);
}

#[test]
fn flat_field_round_trips() {
    let mut f = Heightfield::flat(4, 400.0);
    f.heights_mut().iter_mut().for_each(|h| *h = -3.5);
    roundtrip_is_exact(&f, Some(3), &crate::common::terrain_setup::temperate());
    let d = decode(
        &encode(
            &f,
            Some(3),
            &crate::common::terrain_setup::temperate(),
            Path::new(P),
        )
        .unwrap(),
        Path::new(P),
    )
    .unwrap();
    assert!(d.field.heights().iter().all(|&h| h == -3.5));
}

#[test]
fn file_is_a_plain_16_bit_heightmap_for_other_tools() {
    let f = field(5, 400.0);
    let bytes = encode(
        &f,
        Some(9),
        &crate::common::terrain_setup::temperate(),
        Path::new(P),
    )
    .unwrap();
    let mut reader = png::Decoder::new(std::io::Cursor::new(&bytes))
        .read_info()
        .unwrap();
    let info = reader.info();
    assert_eq!((info.width, info.height), (33, 33));
    assert_eq!(info.color_type, png::ColorType::Grayscale);
    assert_eq!(info.bit_depth, png::BitDepth::Sixteen);
    let keys: Vec<&str> = info
        .uncompressed_latin1_text
        .iter()
        .map(|c| c.keyword.as_str())
        .collect();
    for key in [
        meta::KEY_SCALE,
        meta::KEY_OFFSET,
        meta::KEY_SEA_LEVEL,
        meta::KEY_EXTENT,
        meta::KEY_SEED,
        meta::KEY_GENERATOR,
    ] {
        assert!(keys.contains(&key), "{key} missing from {keys:?}");
    }
    let mut buf = vec![0; reader.output_buffer_size().unwrap()];
    reader.next_frame(&mut buf).unwrap();
    let samples: Vec<u16> = buf
        .chunks(2)
        .map(|b| u16::from_be_bytes([b[0], b[1]]))
        .collect();
    // The whole 16-bit range is used, lowest height black, highest white.
    assert_eq!(samples.iter().min(), Some(&0));
    assert_eq!(samples.iter().max(), Some(&65535));
    let lowest = f.heights().iter().position(|&h| h == f.min()).unwrap();
    assert_eq!(samples[lowest], 0);
}

#[test]
fn save_and_load_through_files() {
    let dir = heightmaps::temp_dir("roundtrip-files");
    let path = dir.join("mountain 42.png");
    let f = field(6, 400.0);
    heightmap::save(
        &path,
        &f,
        Some(42),
        &crate::common::terrain_setup::temperate(),
    )
    .unwrap();
    let d = heightmap::load(&path).unwrap();
    assert_eq!(d.seed, Some(42));
    let bytes = std::fs::read(&path).unwrap();
    assert_eq!(d.field, decode(&bytes, &path).unwrap().field);
    heightmap::save(
        &path,
        &d.field,
        d.seed,
        &crate::common::terrain_setup::temperate(),
    )
    .unwrap();
    assert!(
        std::fs::read(&path).unwrap() == bytes,
        "re-save changed the file"
    );
}

#[test]
fn unstorable_fields_are_refused() {
    let mut f = field(4, 400.0);
    f.set(3, 4, f32::NAN);
    let e = encode(
        &f,
        None,
        &crate::common::terrain_setup::temperate(),
        Path::new("nan.png"),
    )
    .unwrap_err();
    assert_eq!(e.kind, ErrorKind::BadField);
    assert!(e.to_string().starts_with("nan.png: "), "{e}");
    for extent in [0.0, -1.0, f32::INFINITY] {
        let f = field(4, extent);
        let e = encode(
            &f,
            None,
            &crate::common::terrain_setup::temperate(),
            Path::new("x.png"),
        )
        .unwrap_err();
        assert_eq!(e.kind, ErrorKind::BadField, "extent {extent}");
    }
}

/// A field the reader would refuse is refused by the writer, naming the key:
/// a file of ours must always load again.
#[test]
fn fields_outside_the_files_ranges_are_refused_on_saving() {
    let cases: [(f32, f32, &str); 4] = [
        (100_037.46, 0.0, "mountains:offset"),
        (-100_001.0, 10.0, "mountains:offset"),
        (0.0, 70_000.0, "mountains:scale"),
        (0.0, 1.0, "mountains:extent"),
    ];
    for (i, (base, relief, key)) in cases.into_iter().enumerate() {
        let extent = if key == "mountains:extent" {
            2e5
        } else {
            400.0
        };
        let mut f = Heightfield::flat(4, extent);
        for (j, h) in f.heights_mut().iter_mut().enumerate() {
            *h = base + relief * (j % 7) as f32 / 6.0;
        }
        let e = encode(
            &f,
            Some(1),
            &crate::common::terrain_setup::temperate(),
            Path::new(P),
        )
        .unwrap_err();
        assert_eq!(e.kind, ErrorKind::BadField, "case {i}: {e}");
        assert!(e.problem.contains(key), "case {i}: {e}");
        assert!(e.problem.contains("loads again"), "case {i}: {e}");
    }
}

/// Whether `f` lies outside what a data set file can hold (see meta.rs).
fn outside_the_file_format(f: &Heightfield) -> bool {
    let (lo, hi) = f
        .heights()
        .iter()
        .fold((f32::INFINITY, f32::NEG_INFINITY), |(lo, hi), &h| {
            (lo.min(h), hi.max(h))
        });
    !(-1e5..=1e5).contains(&lo) || f64::from(hi) - f64::from(lo) > 65535.0
}

#[test]
fn refit_keeps_corners_and_relief() {
    let f = field(7, 400.0);
    let small = heightmap::refit(&f, 5);
    assert_eq!(small.size(), 33);
    assert_eq!(small.extent(), 400.0);
    let big = heightmap::refit(&f, 8);
    assert_eq!(big.size(), 257);
    assert_eq!(big.get(0, 0), f.get(0, 0));
    assert!((big.get(256, 256) - f.get(128, 128)).abs() < 1e-4);
    assert!(small.max() <= f.max() && small.min() >= f.min());
}

fn arb_field() -> impl Strategy<Value = Heightfield> {
    (
        prop_oneof![Just(4u32), Just(5u32)],
        -1e5f32..1e5f32,
        prop_oneof![Just(1e-3f32), Just(1.0f32), Just(100.0f32), Just(1e4f32)],
        any::<u64>(),
    )
        .prop_map(|(n, base, range, salt)| {
            let mut f = Heightfield::flat(n, 400.0);
            let mut state = salt | 1;
            for h in f.heights_mut() {
                state ^= state << 13;
                state ^= state >> 7;
                state ^= state << 17;
                *h = base + range * (state >> 40) as f32 / (1u64 << 24) as f32;
            }
            f
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]
    #[test]
    fn roundtrip_exact_for_random_fields(f in arb_field(), seed in proptest::option::of(any::<u64>())) {
        let s = crate::common::terrain_setup::temperate();
        let first = match encode(&f, seed, &s, Path::new(P)) {
            Ok(bytes) => bytes,
            Err(e) => {
                prop_assert_eq!(&e.kind, &ErrorKind::BadField);
                prop_assert!(outside_the_file_format(&f), "refused a storable field: {}", e);
                return Ok(());
            }
        };
        let loaded = decode(&first, Path::new(P)).unwrap();
        let second = encode(&loaded.field, seed, &s, Path::new(P)).unwrap();
        prop_assert!(first == second);
        let again = decode(&second, Path::new(P)).unwrap();
        prop_assert_eq!(again.field, loaded.field);
        prop_assert_eq!(loaded.seed, seed);
    }
}
