//! Mono's 17 shades: seed 000's `bwPat` patterns.

use mountains::render::dither::{LEVELS, is_on, level};

fn grey(v: u32) -> u32 {
    v << 16 | v << 8 | v
}

/// Pixels on (white) in the 8x8 tile at tile position (`tx`, `ty`).
fn on_in_tile(k: u8, tx: u32, ty: u32) -> usize {
    (0..64)
        .filter(|i| is_on(k, tx * 8 + i % 8, ty * 8 + i / 8))
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

/// The listing's patterns light 0, 6, 8, 12, ... 60, 64 of every 8x8
/// tile's pixels: brighter at every level, the same in every tile.
#[test]
fn each_level_lights_the_listings_share_of_every_tile() {
    let white = [
        0, 6, 8, 12, 16, 20, 24, 28, 32, 36, 40, 44, 48, 52, 56, 60, 64,
    ];
    for k in 0..=16u8 {
        for (tx, ty) in [(0, 0), (1, 0), (3, 7), (1000, 20)] {
            assert_eq!(
                on_in_tile(k, tx, ty),
                white[k as usize],
                "level {k} tile {tx},{ty}"
            );
        }
    }
}

/// Rows as the listing writes them: level 1 is 0xFFBFBFBF (a white pixel
/// at the second column of rows 1-3 and 5-7), level 15 is 0x80000800
/// (black only at the top left and in row 2's fifth column).
#[test]
fn patterns_are_the_listings_rows() {
    for y in 0..8 {
        for x in 0..8 {
            let level1 = y % 4 != 0 && x == 1;
            assert_eq!(is_on(1, x, y), level1, "level 1 at {x},{y}");
            let level15_black = (x, y % 4) == (0, 0) || (x, y % 4) == (4, 2);
            assert_eq!(is_on(15, x, y), !level15_black, "level 15 at {x},{y}");
        }
    }
}

/// 0xAA55AA55: a checkerboard, white where x + y is odd.
#[test]
fn half_grey_is_a_checkerboard() {
    for y in 0..8 {
        for x in 0..8 {
            assert_eq!(is_on(8, x, y), (x + y) % 2 == 1, "{x},{y}");
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

/// Mono's faces are lifted above the window's black: levels spread over
/// `FACE_FLOOR..=16`, in order; with no floor (seed 000's own look) each
/// level is itself.
#[test]
fn lifted_levels_keep_their_order_above_the_floor() {
    use mountains::render::dither::{FACE_FLOOR, lifted};
    const { assert!(FACE_FLOOR >= 1, "a face may be as black as the window") };
    for k in 0..=16u8 {
        assert_eq!(lifted(k, 0), k);
    }
    assert_eq!(lifted(0, FACE_FLOOR), FACE_FLOOR);
    assert_eq!(lifted(16, FACE_FLOOR), 16);
    let lifted: Vec<u8> = (0..=16).map(|k| lifted(k, FACE_FLOOR)).collect();
    assert!(lifted.windows(2).all(|w| w[0] <= w[1]), "{lifted:?}");
    // Most levels stay apart: shade keeps its texture.
    let mut distinct = lifted.clone();
    distinct.dedup();
    assert!(distinct.len() >= 14, "{lifted:?}");
}
