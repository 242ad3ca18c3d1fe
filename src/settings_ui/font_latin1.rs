//! The Latin-1 letters and signs (U+00A0 to U+00FF) for the embedded font, so
//! a user's name in a path (José, Müller, Søren) shows as written.
//!
//! Accented letters are composed: a lower-case letter gets its mark in the
//! two empty rows above it; a capital is drawn a row shorter (its rows 0 and
//! 2-6) under a one-row mark, for a 7-row font has no room above a full
//! capital (five rows would make Ò the same drawing as ò). The rest are
//! drawn here like the ASCII ones.

use super::font_ascii::{GLYPH_H, Glyph, ascii, parse};

/// An accent: two rows over a lower-case letter, one over a capital.
#[derive(Clone, Copy)]
struct Mark {
    small: [u8; 2],
    capital: u8,
}

const fn mark(top: &str, bottom: &str, capital: &str) -> Mark {
    Mark {
        small: [parse(top)[0], parse(bottom)[0]],
        capital: parse(capital)[0],
    }
}

const GRAVE: Mark = mark(".#...", "..#..", ".#...");
const ACUTE: Mark = mark("...#.", "..#..", "...#.");
const CIRCUMFLEX: Mark = mark("..#..", ".#.#.", "..#..");
const TILDE: Mark = mark(".##.#", "#..#.", "##.##");
const DIAERESIS: Mark = mark(".....", ".#.#.", ".#.#.");
const RING: Mark = mark(".###.", ".#.#.", ".##..");

/// The cedilla, in the two descender rows.
const CEDILLA: [u8; 2] = [parse("..#..")[0], parse(".##..")[0]];

/// `base` (a letter) under `m`.
const fn accented(base: char, m: Mark) -> Glyph {
    let b = ascii(base);
    let mut g = [0u8; GLYPH_H as usize];
    if (base as u8).is_ascii_uppercase() {
        // Six of the capital's seven rows, in rows 1-6, under a one-row mark.
        let rows = [0, 2, 3, 4, 5, 6];
        let mut i = 0;
        while i < 6 {
            g[i + 1] = b[rows[i]];
            i += 1;
        }
        g[0] = m.capital;
        return g;
    } else {
        // Lower case sits in rows 2-6 (and descends): keep all but the top
        // two rows (which drops the dot of an i).
        let mut i = 2;
        while i < GLYPH_H as usize {
            g[i] = b[i];
            i += 1;
        }
    }
    g[0] = m.small[0];
    g[1] = m.small[1];
    g
}

/// `base` with a cedilla below.
const fn cedilla(base: char) -> Glyph {
    let mut g = *ascii(base);
    g[7] = CEDILLA[0];
    g[8] = CEDILLA[1];
    g
}

/// U+00A0 to U+00FF, in order.
pub(super) static LATIN1: [Glyph; 96] = [
    parse("..... ..... ..... ..... ..... ..... ....."), // no-break space
    parse("..#.. ..... ..#.. ..#.. ..#.. ..#.. ..#.."), // ¡
    parse("..#.. .###. #.#.. #.#.. #.#.. .###. ..#.."), // ¢
    parse("..##. .#..# .#... ###.. .#... .#..# #.##."), // £
    parse("..... #...# .###. .#.#. .###. #...# ....."), // ¤
    parse("#...# .#.#. ..#.. ##### ..#.. ##### ..#.."), // ¥
    parse("..#.. ..#.. ..#.. ..... ..#.. ..#.. ..#.."), // ¦
    parse(".###. #.... .##.. .#.#. ..##. ....# .###."), // §
    parse(".#.#. ..... ..... ..... ..... ..... ....."), // ¨
    parse(".###. #...# #.### #.#.. #.### #...# .###."), // ©
    parse(".###. ...## .#.## ..... .###. ..... ....."), // ª
    parse("..... ..#.# .#.#. #.#.. .#.#. ..#.# ....."), // «
    parse("..... ..... ##### ....# ....# ..... ....."), // ¬
    parse("..... ..... ..... .###. ..... ..... ....."), // soft hyphen
    parse(".###. #...# ###.# ##.## ###.# #.#.# .###."), // ®
    parse("##### ..... ..... ..... ..... ..... ....."), // ¯
    parse(".##.. #..#. .##.. ..... ..... ..... ....."), // °
    parse("..#.. ..#.. ##### ..#.. ..#.. ..... #####"), // ±
    parse(".##.. ...#. ..#.. .###. ..... ..... ....."), // ²
    parse(".##.. ..##. ...#. .##.. ..... ..... ....."), // ³
    parse("...#. ..#.. ..... ..... ..... ..... ....."), // ´
    parse("..... ..... #...# #...# #...# ##.## #.#.. #.... #...."), // µ
    parse(".#### ###.# ###.# .##.# ..#.# ..#.# ..#.#"), // ¶
    parse("..... ..... ..... ..#.. ..... ..... ....."), // ·
    parse("..... ..... ..... ..... ..... ..... ..... ..#.. .##.."), // ¸
    parse("..#.. .##.. ..#.. .###. ..... ..... ....."), // ¹
    parse(".###. #...# .###. ..... ##### ..... ....."), // º
    parse("..... #.#.. .#.#. ..#.# .#.#. #.#.. ....."), // »
    parse("#.... #...# #..#. ..#.. .#.#. #.### ...#."), // ¼
    parse("#.... #...# #..#. ..#.. .#.## #...# ..##."), // ½
    parse("##... .#..# ##.#. ..#.. .#.#. #.### ...#."), // ¾
    parse("..#.. ..... ..#.. .#... #.... #...# .###."), // ¿
    accented('A', GRAVE),
    accented('A', ACUTE),
    accented('A', CIRCUMFLEX),
    accented('A', TILDE),
    accented('A', DIAERESIS),
    accented('A', RING),
    parse(".#### #.#.. #.#.. ##### #.#.. #.#.. #.###"), // Æ
    cedilla('C'),
    accented('E', GRAVE),
    accented('E', ACUTE),
    accented('E', CIRCUMFLEX),
    accented('E', DIAERESIS),
    accented('I', GRAVE),
    accented('I', ACUTE),
    accented('I', CIRCUMFLEX),
    accented('I', DIAERESIS),
    parse("###.. #..#. #...# ###.# #...# #..#. ###.."), // Ð
    accented('N', TILDE),
    accented('O', GRAVE),
    accented('O', ACUTE),
    accented('O', CIRCUMFLEX),
    accented('O', TILDE),
    accented('O', DIAERESIS),
    parse("..... #...# .#.#. ..#.. .#.#. #...# ....."), // ×
    parse(".###. #..## #.#.# #.#.# #.#.# ##..# .###."), // Ø
    accented('U', GRAVE),
    accented('U', ACUTE),
    accented('U', CIRCUMFLEX),
    accented('U', DIAERESIS),
    accented('Y', ACUTE),
    parse("#.... ####. #...# #...# ####. #.... #...."), // Þ
    parse(".##.. #..#. #.#.. #..#. #...# #...# #.##."), // ß
    accented('a', GRAVE),
    accented('a', ACUTE),
    accented('a', CIRCUMFLEX),
    accented('a', TILDE),
    accented('a', DIAERESIS),
    accented('a', RING),
    parse("..... ..... ##.#. ..#.# ##### #.#.. ##.##"), // æ
    cedilla('c'),
    accented('e', GRAVE),
    accented('e', ACUTE),
    accented('e', CIRCUMFLEX),
    accented('e', DIAERESIS),
    accented('i', GRAVE),
    accented('i', ACUTE),
    accented('i', CIRCUMFLEX),
    accented('i', DIAERESIS),
    parse(".#.#. ..#.. .#.#. ....# .#### #...# .###."), // ð
    accented('n', TILDE),
    accented('o', GRAVE),
    accented('o', ACUTE),
    accented('o', CIRCUMFLEX),
    accented('o', TILDE),
    accented('o', DIAERESIS),
    parse("..... ..#.. ..... ##### ..... ..#.. ....."), // ÷
    parse("..... ..... .###. #..## #.#.# ##..# .###."), // ø
    accented('u', GRAVE),
    accented('u', ACUTE),
    accented('u', CIRCUMFLEX),
    accented('u', DIAERESIS),
    accented('y', ACUTE),
    parse("#.... #.... ####. #...# #...# ####. #.... #.... ....."), // þ
    accented('y', DIAERESIS),
];
