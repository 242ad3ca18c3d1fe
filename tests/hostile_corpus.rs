//! A generated corpus of hostile inputs: a data set of ours and the shipped
//! preferences file, mutated a thousand ways each (bit flips, truncations,
//! chunk-length lies, duplicated and deleted lines, huge values). Every case
//! ends in a value or a message (never a panic), the message names its file
//! and stays short, and no case allocates more than a bound (a counting
//! allocator; the cases run one after another in one test, so the count is
//! theirs alone).

mod heightmap_support;

use std::alloc::{GlobalAlloc, Layout, System};
use std::path::Path;
use std::sync::atomic::{AtomicUsize, Ordering};

use heightmap_support::{field, gray_png};
use mountains::settings::{Settings, load};
use mountains::terrain::heightmap::{decode, encode, meta};

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

/// SplitMix64: the same corpus on every run and platform.
struct Mix(u64);

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

#[test]
fn a_thousand_spoilt_data_sets_end_in_a_field_or_a_short_message() {
    let _turn = ONE_AT_A_TIME.lock().unwrap_or_else(|e| e.into_inner());
    let good = encode(
        &field(5, 250.0),
        Some(7),
        &Settings::default(),
        Path::new("m.png"),
    )
    .unwrap();
    let mut mix = Mix(1);
    let (mut refused, mut loaded) = (0, 0);
    for case in 0..1000 {
        let mut png = good.clone();
        spoil(&mut png, &mut mix);
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

#[test]
fn a_thousand_spoilt_preference_files_end_in_settings_or_short_messages() {
    let _turn = ONE_AT_A_TIME.lock().unwrap_or_else(|e| e.into_inner());
    let mut mix = Mix(2);
    let mut with_problems = 0;
    for case in 0..1000 {
        let text = spoil_text(load::DEFAULT_TOML, &mut mix);
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
