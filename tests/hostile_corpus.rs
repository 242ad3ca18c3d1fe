//! A generated corpus of hostile inputs: a data set of ours and the shipped
//! preferences file, mutated a thousand ways each (bit flips, truncations,
//! chunk-length lies, duplicated and deleted lines, huge values). Every case
//! ends in a value or a message (never a panic), the message names its file
//! and stays short, and no case allocates more than a bound (a counting
//! allocator; the cases run one after another in one test, so the count is
//! theirs alone).

mod heightmap_support;
mod hostile_support;

use std::alloc::{GlobalAlloc, Layout, System};
use std::path::Path;
use std::sync::atomic::{AtomicUsize, Ordering};

use mountains::settings::{Settings, load};
use mountains::terrain::heightmap::decode;

struct Counting;

static CURRENT: AtomicUsize = AtomicUsize::new(0);
static PEAK: AtomicUsize = AtomicUsize::new(0);
static MOST: AtomicUsize = AtomicUsize::new(0);

// SAFETY: every call is passed straight to the system allocator; the
// counters are only arithmetic on the side.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        let now = CURRENT.fetch_add(layout.size(), Ordering::SeqCst) + layout.size();
        PEAK.fetch_max(now, Ordering::SeqCst);
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        CURRENT.fetch_sub(layout.size(), Ordering::SeqCst);
        unsafe { System.dealloc(ptr, layout) }
    }
}

#[global_allocator]
static ALLOCATOR: Counting = Counting;

/// The two corpora take turns: the allocation count is process-wide.
static ONE_AT_A_TIME: std::sync::Mutex<()> = std::sync::Mutex::new(());

/// Most memory one case may take beyond what was in use before it (the
/// most any took was 2 MiB: a 512 KiB text value, inflated and checked).
const CASE_BOUND: usize = 8 << 20;
/// Longest message a case may produce.
const MESSAGE_BOUND: usize = 600;

/// Runs `case`, failing if it takes more than `CASE_BOUND` of new memory.
fn bounded<T>(what: &str, case: impl FnOnce() -> T) -> T {
    let before = CURRENT.load(Ordering::SeqCst);
    PEAK.store(before, Ordering::SeqCst);
    let out = case();
    let used = PEAK.load(Ordering::SeqCst).saturating_sub(before);
    assert!(used <= CASE_BOUND, "{what}: {} KiB", used >> 10);
    MOST.fetch_max(used, Ordering::SeqCst);
    out
}

#[test]
fn a_thousand_spoilt_data_sets_end_in_a_field_or_a_short_message() {
    let _turn = ONE_AT_A_TIME.lock().unwrap_or_else(|e| e.into_inner());
    let (mut refused, mut loaded) = (0, 0);
    for (case, png) in hostile_support::data_sets().into_iter().enumerate() {
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
    let _turn = ONE_AT_A_TIME.lock().unwrap_or_else(|e| e.into_inner());
    let mut with_problems = 0;
    for (case, text) in hostile_support::preference_files().into_iter().enumerate() {
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
