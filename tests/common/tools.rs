//! What a test does when a tool it needs (Xvfb, xdotool, xmllint,
//! xscreensaver) is not installed: it fails, saying how to install it, so a
//! skip never passes unseen as `ok`. Setting `MOUNTAINS_SKIP_MISSING=1`
//! turns that into a skip the user asked for; `MOUNTAINS_REQUIRE_<TOOL>=1`
//! (as CI sets them) keeps it a failure regardless.
#![allow(dead_code)]

/// Fails the test because `what` is missing (install with `install`), or,
/// with `MOUNTAINS_SKIP_MISSING=1` and `require` unset, skips it aloud.
pub fn missing(what: &str, install: &str, require: &str) {
    let set = |var: &str| std::env::var(var).is_ok_and(|v| v == "1");
    if set(require) {
        panic!("{require}=1 but {what}");
    }
    if !set("MOUNTAINS_SKIP_MISSING") {
        panic!(
            "{what}: install it ({install}), or set MOUNTAINS_SKIP_MISSING=1 to skip the tests that need it"
        );
    }
    eprintln!("skipped (MOUNTAINS_SKIP_MISSING=1): {what}");
}
