//! A generated corpus of hostile inputs: a data set of ours and the shipped
//! preferences file, mutated a thousand ways each (bit flips, truncations,
//! chunk-length lies, duplicated and deleted lines, huge values). Every case
//! ends in a value or a message (never a panic), the message names its file
//! and stays short, and no case allocates more than a bound (a counting
//! allocator; the cases run one after another in one test, so the count is
//! theirs alone).

use crate::common::counting;
use crate::common::hostile;

use std::path::Path;
use std::sync::atomic::{AtomicUsize, Ordering};

use mountains::settings::{Settings, load};
use mountains::terrain::heightmap::decode;

/// The most memory any one case took, for the log.
static MOST: AtomicUsize = AtomicUsize::new(0);

/// Most memory one case may take beyond what was in use before it (the
/// most any took was 2 MiB: a 512 KiB text value, inflated and checked).
const CASE_BOUND: usize = 8 << 20;
/// Longest message a case may produce.
const MESSAGE_BOUND: usize = 600;

/// Runs `case`, failing if it takes more than `CASE_BOUND` of new memory.
fn bounded<T>(what: &str, case: impl FnOnce() -> T) -> T {
    let (out, used) = counting::peak_of(case);
    assert!(used <= CASE_BOUND, "{what}: {} KiB", used >> 10);
    MOST.fetch_max(used, Ordering::SeqCst);
    out
}

#[test]
fn a_thousand_spoilt_data_sets_end_in_a_field_or_a_short_message() {
    let _turn = counting::alone();
    let (mut refused, mut loaded) = (0, 0);
    for (case, png) in hostile::data_sets().into_iter().enumerate() {
        match bounded(&format!("data set {case}"), || {
            decode(&png, Path::new("spoilt.png"))
        }) {
            Ok(d) => {
                loaded += 1;
                assert!(
                    d.field.heights().iter().all(|h| h.is_finite()),
                    "case {case}"
                );
            }
            Err(e) => {
                refused += 1;
                let text = e.to_string();
                assert!(text.starts_with("spoilt.png"), "case {case}: {text}");
                assert!(
                    text.len() <= MESSAGE_BOUND,
                    "case {case}: {} bytes",
                    text.len()
                );
                assert!(!text.contains("ChunkType {"), "case {case}: {text}");
            }
        }
    }
    // Both outcomes occur: the corpus exercises the checks, not just the happy path.
    assert!(
        refused > 100 && loaded > 10,
        "{refused} refused, {loaded} loaded"
    );
    eprintln!(
        "most memory a case took: {} KiB",
        MOST.load(Ordering::SeqCst) >> 10
    );
}

#[test]
fn a_thousand_spoilt_preference_files_end_in_settings_or_short_messages() {
    let _turn = counting::alone();
    let mut with_problems = 0;
    for (case, text) in hostile::preference_files().into_iter().enumerate() {
        let mut settings = Settings::default();
        let problems = bounded(&format!("preferences {case}"), || {
            load::apply_toml(&mut settings, &text, "spoilt.toml")
        });
        with_problems += usize::from(!problems.is_empty());
        for line in load::report(&problems) {
            assert!(
                line.len() <= MESSAGE_BOUND,
                "case {case}: {} bytes",
                line.len()
            );
        }
        for p in &problems {
            assert!(p.to_string().starts_with("spoilt.toml"), "case {case}: {p}");
            assert!(p.position.is_some(), "case {case}: {p} has no line");
        }
    }
    assert!(
        with_problems > 200,
        "{with_problems} spoilt files had problems"
    );
}
