//! Mono's 17 ordered-dither levels.

use mountains::render::dither::{LEVELS, is_on, level};

fn grey(v: u32) -> u32 {
    v << 16 | v << 8 | v
}

/// Pixels on in the 4x4 tile at tile position (`tx`, `ty`).
fn on_in_tile(k: u8, tx: u32, ty: u32) -> usize {
    (0..16)
        .filter(|i| is_on(k, tx * 4 + i % 4, ty * 4 + i / 4))
        .count()
}

#[test]
fn black_and_white_ends() {
    assert_eq!(LEVELS, 16);
    assert_eq!(level(0), 0);
    assert_eq!(level(0x00ff_ffff), 16);
    for y in 0..8 {
        for x in 0..8 {
            assert!(!is_on(0, x, y));
            assert!(is_on(16, x, y));
            assert!(is_on(200, x, y), "levels past 16 are white");
        }
    }
}

#[test]
fn level_k_lights_k_pixels_per_tile() {
    for k in 0..=16u8 {
        for (tx, ty) in [(0, 0), (1, 0), (3, 7), (1000, 20)] {
            assert_eq!(
                on_in_tile(k, tx, ty),
                k as usize,
                "level {k} tile {tx},{ty}"
            );
        }
    }
}

#[test]
fn levels_nest() {
    for k in 0..16u8 {
        for y in 0..4 {
            for x in 0..4 {
                assert!(
                    !is_on(k, x, y) || is_on(k + 1, x, y),
                    "level {k} at {x},{y}"
                );
            }
        }
    }
}

#[test]
fn half_grey_is_a_checkerboard() {
    for y in 0..8 {
        for x in 0..8 {
            assert_eq!(is_on(8, x, y), (x + y) % 2 == 0, "{x},{y}");
        }
    }
}

#[test]
fn greys_map_evenly_onto_levels() {
    for k in 0..=16u32 {
        assert_eq!(level(grey(k * 255 / 16)), k as u8, "grey {}", k * 255 / 16);
    }
    let mut last = 0;
    for v in 0..=255 {
        let l = level(grey(v));
        assert!(l >= last && l <= 16);
        last = l;
    }
}

#[test]
fn one_byte_greys_read_like_full_greys() {
    for v in 0..=255 {
        assert_eq!(level(v), level(grey(v)), "grey {v}");
    }
}

#[test]
fn colours_count_by_luminance() {
    assert!(level(0x0000_ff00) > level(0x00ff_0000));
    assert!(level(0x00ff_0000) > level(0x0001_00ff));
    assert_eq!(level(0xff00_0000), 0, "the unused top byte is ignored");
}
