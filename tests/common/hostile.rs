//! The hostile corpus, shared by tests/memory/hostile_corpus.rs (every case ends
//! in a value or a short message, within a memory bound) and
//! benches/hostile.rs (how long the cases take): a data set of ours and the
//! shipped preferences file, each spoilt a thousand ways.

use std::path::Path;

use super::heightmaps::{field, gray_png};
use mountains::settings::{Settings, load};
use mountains::terrain::heightmap::{encode, meta};

/// Cases in each half of the corpus.
pub const CASES: usize = 1000;

/// A thousand spoilt copies of one of our data sets (33x33 points).
pub fn data_sets() -> Vec<Vec<u8>> {
    let good = encode(
        &field(5, 250.0),
        Some(7),
        &Settings::default(),
        Path::new("m.png"),
    )
    .unwrap();
    let mut mix = Mix(1);
    (0..CASES)
        .map(|_| {
            let mut png = good.clone();
            spoil(&mut png, &mut mix);
            png
        })
        .collect()
}

/// A thousand spoilt copies of the shipped preferences file.
pub fn preference_files() -> Vec<String> {
    let mut mix = Mix(2);
    (0..CASES)
        .map(|_| spoil_text(load::DEFAULT_TOML, &mut mix))
        .collect()
}

/// SplitMix64: the same corpus on every run and platform.
pub struct Mix(u64);

impl Mix {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    fn below(&mut self, n: usize) -> usize {
        (self.next() % n.max(1) as u64) as usize
    }
}

/// One way to spoil a PNG.
fn spoil(png: &mut Vec<u8>, mix: &mut Mix) {
    match mix.below(4) {
        // Flip a few bytes.
        0 => {
            for _ in 0..1 + mix.below(6) {
                let i = mix.below(png.len());
                png[i] ^= 1 << mix.below(8);
            }
        }
        // Cut it short.
        1 => png.truncate(mix.below(png.len())),
        // A chunk length that lies (chunks start after the 8-byte signature).
        2 => {
            let at = 8 + 4 * mix.below((png.len() - 12) / 4);
            let lie =
                [0x7f, 0xff, 0xff, 0xff, 0x00, 0x10, 0x00, 0x00][mix.below(2) * 4..][..4].to_vec();
            png[at..at + 4].copy_from_slice(&lie);
        }
        // A huge value of ours in a text chunk.
        _ => {
            let big = "9".repeat(1 << (10 + mix.below(10)));
            let samples: Vec<u16> = (0..33 * 33).map(|i| (i * 61 % 65536) as u16).collect();
            *png = gray_png(33, 33, 16, &samples, &[(meta::KEY_SCALE, &big)]);
        }
    }
}

/// One way to spoil a preferences file.
fn spoil_text(text: &str, mix: &mut Mix) -> String {
    let mut lines: Vec<String> = text.lines().map(String::from).collect();
    match mix.below(5) {
        0 => {
            let i = mix.below(lines.len());
            lines.remove(i);
        }
        1 => {
            let i = mix.below(lines.len());
            let copy = lines[i].clone();
            lines.insert(i, copy);
        }
        2 => {
            let i = mix.below(lines.len());
            lines[i] = format!("color = \"{}\"", "x".repeat(1 << (8 + mix.below(12))));
        }
        3 => {
            let i = mix.below(lines.len());
            let cut = mix.below(lines[i].len() + 1);
            // Back to a character boundary (the file has non-ASCII text).
            let mut cut = cut;
            while !lines[i].is_char_boundary(cut) {
                cut -= 1;
            }
            lines[i].truncate(cut);
        }
        _ => {
            let i = mix.below(lines.len());
            lines.insert(i, format!("unknown_{} = {}", mix.next(), mix.next()));
        }
    }
    lines.join("\n")
}
