//! Bad files: each kind gives its own clear error naming the file; none panics.

use crate::common::heightmaps;

use std::path::Path;

use heightmaps::{encode, gray_png, hand_png, ihdr};
use mountains::terrain::heightmap::{ErrorKind, HeightmapError, decode, load, meta};
use proptest::prelude::*;

const P: &str = "bad/heights.png";

fn fails(bytes: &[u8]) -> HeightmapError {
    let e = decode(bytes, Path::new(P)).expect_err("a bad file loaded");
    assert!(
        e.to_string().starts_with("bad/heights.png: "),
        "no file name: {e}"
    );
    e
}

fn good_png() -> Vec<u8> {
    let samples: Vec<u16> = (0..40 * 30).map(|i| (i * 53 % 65536) as u16).collect();
    gray_png(40, 30, 16, &samples, &[(meta::KEY_SEED, "5")])
}

#[test]
fn not_a_png() {
    for bytes in [
        &b"hello, I am a text file"[..],
        b"",
        b"\xff\xd8\xff\xe0\x00\x10JFIF\x00",
        b"GIF89a",
    ] {
        let e = fails(bytes);
        assert_eq!(e.kind, ErrorKind::NotPng, "{e}");
        assert!(e.problem.contains("not a PNG"), "{e}");
    }
}

#[test]
fn truncated_at_several_points() {
    let png = good_png();
    let idat = png.windows(4).position(|w| w == b"IDAT").unwrap();
    let iend = png.windows(4).position(|w| w == b"IEND").unwrap();
    for cut in [
        4,
        8,
        12,
        20,
        33,
        idat,
        idat + 10,
        (idat + iend) / 2,
        iend - 8,
        iend,
    ] {
        let e = fails(&png[..cut]);
        assert_eq!(e.kind, ErrorKind::Truncated, "cut at {cut}: {e}");
        assert!(e.problem.contains("truncated"), "{e}");
    }
}

#[test]
fn every_prefix_fails_cleanly() {
    let png = good_png();
    for cut in 0..png.len() - 12 {
        let e = fails(&png[..cut]);
        assert!(
            matches!(
                e.kind,
                ErrorKind::Truncated | ErrorKind::NotPng | ErrorKind::Damaged
            ),
            "cut at {cut}: {e}"
        );
    }
}

#[test]
fn colour_and_palette_and_alpha_are_refused() {
    use png::{BitDepth::*, ColorType::*};
    let cases = [
        (Rgb, Eight, 3, "RGB"),
        (Rgb, Sixteen, 6, "RGB"),
        (Rgba, Eight, 4, "RGBA"),
        (Indexed, Eight, 1, "palette"),
        (GrayscaleAlpha, Eight, 2, "alpha"),
        (GrayscaleAlpha, Sixteen, 4, "alpha"),
    ];
    for (color, depth, bytes_per_pixel, word) in cases {
        let data = vec![7u8; 20 * 20 * bytes_per_pixel];
        let e = fails(&encode(20, 20, color, depth, &data, &[]));
        assert_eq!(e.kind, ErrorKind::NotGrayscale, "{color:?}");
        assert!(
            e.problem.contains(word) && e.problem.contains("grayscale"),
            "{e}"
        );
    }
}

#[test]
fn low_bit_depths_are_refused() {
    use png::BitDepth::*;
    for (depth, bits) in [(One, 1), (Two, 2), (Four, 4)] {
        let data = vec![0x5au8; 20 * (20 * bits as usize).div_ceil(8)];
        let e = fails(&encode(
            20,
            20,
            png::ColorType::Grayscale,
            depth,
            &data,
            &[],
        ));
        assert_eq!(e.kind, ErrorKind::BitDepth);
        assert!(e.problem.contains(&format!("{bits}-bit")), "{e}");
    }
}

#[test]
fn absurd_dimensions_are_refused_before_decoding() {
    for (w, h) in [
        (1_000_000, 1_000_000),
        (16385, 2),
        (2, 16385),
        (u32::MAX >> 1, u32::MAX >> 1),
    ] {
        let e = fails(&hand_png(ihdr(w, h, 16, 0, 0), &[0, 0, 0], &[]));
        assert_eq!(e.kind, ErrorKind::TooLarge, "{w}x{h}: {e}");
        assert!(e.problem.contains(&format!("{w}x{h}")), "{e}");
    }
}

#[test]
fn a_header_the_data_cannot_fill_is_truncated() {
    let e = fails(&hand_png(ihdr(16384, 16384, 16, 0, 0), &[0, 0, 0], &[]));
    assert_eq!(e.kind, ErrorKind::Truncated, "{e}");
}

#[test]
fn too_small_and_zero_sizes_are_refused() {
    let e = fails(&hand_png(ihdr(1, 1, 8, 0, 0), &[0, 9], &[]));
    assert_eq!(e.kind, ErrorKind::TooSmall, "{e}");
    for (w, h) in [(0, 5), (5, 0), (0, 0)] {
        let e = fails(&hand_png(ihdr(w, h, 8, 0, 0), &[0], &[]));
        assert_eq!(e.kind, ErrorKind::Damaged, "{e}");
        // Said in a person's words, not the png crate's "Invalid image
        // dimensions".
        assert!(
            e.problem
                .contains("its header says the image is 0 pixels wide or 0 tall"),
            "{w}x{h}: {e}"
        );
    }
}

#[test]
fn corrupt_checksum_or_data_is_damaged() {
    let mut png = good_png();
    png[29] ^= 0xff; // IHDR CRC
    assert_eq!(fails(&png).kind, ErrorKind::Damaged);
    // Rows that are not valid zlib data.
    let mut raw = vec![0u8; 17 * 35];
    raw[0] = 9; // no such filter type
    let e = fails(&hand_png(ihdr(17, 17, 16, 0, 0), &raw, &[]));
    assert_eq!(e.kind, ErrorKind::Damaged, "{e}");
    assert!(
        e.problem.contains("filter type 9, which PNG does not have"),
        "{e}"
    );
    assert!(!e.problem.contains("ChunkType {"), "{e}");
}

#[test]
fn bad_metadata_values_name_the_key() {
    let samples = vec![100u16; 17 * 17];
    let cases = [
        (meta::KEY_SCALE, "abc"),
        (meta::KEY_SCALE, "NaN"),
        (meta::KEY_SCALE, "-1"),
        (meta::KEY_OFFSET, "inf"),
        (meta::KEY_OFFSET, "12 metres"),
        (meta::KEY_SEA_LEVEL, "NaN"),
        (meta::KEY_EXTENT, "0"),
        (meta::KEY_FORMAT, "99"),
    ];
    for (key, value) in cases {
        let e = fails(&gray_png(17, 17, 16, &samples, &[(key, value)]));
        assert_eq!(
            e.kind,
            ErrorKind::Metadata(key.to_string()),
            "{key}={value}: {e}"
        );
        assert!(e.problem.starts_with(key), "{e}");
    }
}

#[test]
fn a_scale_that_overflows_heights_is_refused() {
    let samples = vec![65535u16; 17 * 17];
    let e = fails(&gray_png(
        17,
        17,
        16,
        &samples,
        &[(meta::KEY_SCALE, "1e300")],
    ));
    assert_eq!(e.kind, ErrorKind::Metadata(meta::KEY_SCALE.into()), "{e}");
    // Said as it was written, not as its 301 digits.
    assert!(e.problem.contains("1e300 is out of range"), "{e}");
    assert!(e.to_string().len() < 200, "{e}");
}

/// Accepted-looking but extreme metadata drew a one-colour frame with exit
/// 0; each value now has a range, and the relief one against the width.
#[test]
fn extreme_metadata_is_refused_with_its_range() {
    let samples: Vec<u16> = (0..17 * 17).map(|i| (i * 97 % 65536) as u16).collect();
    let cases = [
        (
            &[(meta::KEY_SCALE, "13")][..],
            meta::KEY_SCALE,
            "13 is out of range (allowed: above 0 to 1)",
        ),
        (
            &[(meta::KEY_OFFSET, "1e30")],
            meta::KEY_OFFSET,
            "1e30 is out of range (allowed: -100000 to 100000)",
        ),
        (
            &[(meta::KEY_SEA_LEVEL, "-1e9")],
            meta::KEY_SEA_LEVEL,
            "out of range",
        ),
        (
            &[(meta::KEY_EXTENT, "1e-30")],
            meta::KEY_EXTENT,
            "out of range (allowed: 1 to 100000)",
        ),
        (
            &[(meta::KEY_SCALE, "1"), (meta::KEY_EXTENT, "10")],
            meta::KEY_SCALE,
            "makes a relief of 65535 over a width of 10: more than 256 times the width",
        ),
    ];
    for (text, key, message) in cases {
        let e = fails(&gray_png(17, 17, 16, &samples, text));
        assert_eq!(
            e.kind,
            ErrorKind::Metadata(key.to_string()),
            "{text:?}: {e}"
        );
        assert!(e.problem.contains(message), "{text:?}: {e}");
    }
    // Our own values are well inside.
    let ours = [
        (meta::KEY_SCALE, "0.004"),
        (meta::KEY_OFFSET, "-40"),
        (meta::KEY_EXTENT, "250"),
    ];
    assert!(
        decode(
            &gray_png(17, 17, 16, &samples, &ours),
            std::path::Path::new("ok.png")
        )
        .is_ok()
    );
}

#[test]
fn huge_text_chunk_is_refused_not_buffered() {
    let big = vec![b'x'; 40 << 20];
    let mut text = b"Comment\0".to_vec();
    text.extend_from_slice(&big);
    // The decoder must give up while buffering, before it could check the
    // CRC, so a zero CRC saves computing one over 40 MiB.
    let mut huge = (text.len() as u32).to_be_bytes().to_vec();
    huge.extend_from_slice(b"tEXt");
    huge.extend_from_slice(&text);
    huge.extend_from_slice(&[0; 4]);
    let e = fails(&hand_png(
        ihdr(17, 17, 8, 0, 0),
        &vec![0u8; 17 * 18],
        &[huge],
    ));
    assert_eq!(e.kind, ErrorKind::TooLarge, "{e}");
    assert!(
        e.problem
            .contains("needs more than the 32 MiB of memory a heightmap may use for its chunks"),
        "{e}"
    );
}

#[test]
fn compressed_text_bomb_of_ours_is_refused() {
    let samples = vec![100u16; 17 * 17];
    let mut out = Vec::new();
    let mut enc = png::Encoder::new(&mut out, 17, 17);
    enc.set_color(png::ColorType::Grayscale);
    enc.set_depth(png::BitDepth::Sixteen);
    enc.add_ztxt_chunk(meta::KEY_SCALE.into(), "1".repeat(1 << 20))
        .unwrap();
    let mut w = enc.write_header().unwrap();
    w.write_image_data(
        &samples
            .iter()
            .flat_map(|s| s.to_be_bytes())
            .collect::<Vec<u8>>(),
    )
    .unwrap();
    w.finish().unwrap();
    let e = fails(&out);
    assert_eq!(e.kind, ErrorKind::Metadata(meta::KEY_SCALE.into()), "{e}");
    // The cause is our cap, not damage: the message says which.
    assert!(
        e.problem.contains("longer than the 4 KiB a value may have"),
        "{e}"
    );
}

#[test]
fn missing_file_is_an_io_error_naming_it() {
    let e = load(Path::new("/nonexistent/dir/none.png")).unwrap_err();
    assert_eq!(e.kind, ErrorKind::Io);
    assert!(
        e.to_string().starts_with("/nonexistent/dir/none.png: "),
        "{e}"
    );
}

#[test]
fn a_directory_is_an_io_error() {
    let dir = heightmaps::temp_dir("load-dir");
    let e = load(&dir).unwrap_err();
    assert_eq!(e.kind, ErrorKind::Io, "{e}");
}

#[test]
fn our_own_file_passes_these_checks() {
    let f = heightmaps::field(5, 400.0);
    let bytes = mountains::terrain::heightmap::encode(
        &f,
        Some(1),
        &crate::common::terrain_setup::temperate(),
        Path::new(P),
    )
    .unwrap();
    decode(&bytes, Path::new(P)).unwrap();
    decode(&good_png(), Path::new(P)).unwrap();
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]
    #[test]
    fn damaged_bytes_never_panic(flips in proptest::collection::vec((any::<prop::sample::Index>(), any::<u8>()), 1..8)) {
        let mut png = good_png();
        for (at, byte) in flips {
            let i = at.index(png.len());
            png[i] = byte;
        }
        let _ = decode(&png, Path::new(P));
    }
}
