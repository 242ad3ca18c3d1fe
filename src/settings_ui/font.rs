//! An embedded bitmap font, drawn by us so the settings screen and the
//! window's overlays need no font files and no GUI toolkit: ASCII
//! (font_ascii.rs) and Latin-1 (font_latin1.rs, composed from ASCII).

use super::font_ascii::ascii;
pub use super::font_ascii::{ADVANCE, GLYPH_H, GLYPH_W, Glyph};
use super::font_latin1::LATIN1;

/// The glyph for `c`: ASCII and Latin-1; characters the font lacks are drawn as `?`.
pub fn glyph(c: char) -> &'static Glyph {
    match c {
        ' '..='~' => ascii(c),
        '\u{a0}'..='\u{ff}' => &LATIN1[c as usize - 0xa0],
        _ => ascii('?'),
    }
}

/// Width of `text` in font pixels.
pub fn text_width(text: &str) -> u32 {
    text.chars().count() as u32 * ADVANCE
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every printable Latin-1 character has a glyph of its own: none falls
    /// back to `?`, and no two share a drawing (so é and è stay apart).
    #[test]
    fn latin1_letters_have_glyphs_of_their_own() {
        let question = glyph('?');
        let mut seen = std::collections::HashMap::new();
        for code in (0x20u32..0x7f).chain(0xa1..=0xff) {
            let c = char::from_u32(code).unwrap();
            let g = glyph(c);
            if c != '?' {
                assert_ne!(g, question, "{c:?} is drawn as ?");
            }
            if c != ' ' {
                assert!(g.iter().any(|&row| row != 0), "{c:?} is blank");
            }
            if let Some(other) = seen.insert(*g, c) {
                panic!("{c:?} and {other:?} share a glyph");
            }
        }
        assert_eq!(glyph('\u{100}'), question, "beyond Latin-1 is ?");
    }

    #[test]
    fn letters_have_ink_and_space_has_none() {
        assert!(glyph(' ').iter().all(|r| *r == 0));
        for c in ('A'..='Z').chain('a'..='z').chain('0'..='9') {
            assert!(glyph(c).iter().any(|r| *r != 0), "{c}");
        }
        // Beyond Latin-1 (é has a glyph of its own now: see below).
        assert_eq!(glyph('\u{101}'), glyph('?'));
    }

    #[test]
    fn descenders_reach_below_the_baseline() {
        for c in ['g', 'j', 'p', 'q', 'y'] {
            assert_ne!(glyph(c)[7] | glyph(c)[8], 0, "{c}");
        }
        assert_eq!(glyph('a')[7] | glyph('a')[8], 0);
    }
}
