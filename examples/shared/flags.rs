//! The flags the survey examples share (`--size WxH`, `--seeds A-B`,
//! `--set KEY=VALUE`), read one way.

use mountains::settings::{Settings, load};

/// The width and height of `--size WxH`.
pub fn size(v: &str) -> (u32, u32) {
    let (w, h) = v.split_once('x').expect("--size WxH");
    (w.parse().expect("width"), h.parse().expect("height"))
}

/// The seeds of `--seeds A-B`, A to B inclusive.
pub fn seeds(v: &str) -> Vec<u64> {
    let (a, b) = v.split_once('-').expect("--seeds A-B");
    (a.parse().expect("first")..=b.parse().expect("last")).collect()
}

/// Applies `--set KEY=VALUE` to `prefs`.
pub fn set(prefs: &mut Settings, v: &str) {
    let (k, raw) = v.split_once('=').expect("--set KEY=VALUE");
    load::apply_set(prefs, k, raw).expect("a key and its value");
}
