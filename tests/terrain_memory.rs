//! Peak memory of a 4097x4097 generation: the field itself plus at most 10%
//! (no second full-size buffer), measured by a counting allocator.

use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicUsize, Ordering};

use mountains::settings::Detail;
use mountains::settings::{Generator, Settings};
use mountains::terrain::generate_with_threads;

/// The system allocator, counting live bytes and their peak.
struct Counting;

static LIVE: AtomicUsize = AtomicUsize::new(0);
static PEAK: AtomicUsize = AtomicUsize::new(0);

// SAFETY: every call is forwarded unchanged to the system allocator; the
// counters only observe sizes.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        let live = LIVE.fetch_add(layout.size(), Ordering::SeqCst) + layout.size();
        PEAK.fetch_max(live, Ordering::SeqCst);
        // SAFETY: forwarded with the caller's layout.
        unsafe { System.alloc(layout) }
    }

    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        let live = LIVE.fetch_add(layout.size(), Ordering::SeqCst) + layout.size();
        PEAK.fetch_max(live, Ordering::SeqCst);
        // SAFETY: forwarded with the caller's layout.
        unsafe { System.alloc_zeroed(layout) }
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        LIVE.fetch_sub(layout.size(), Ordering::SeqCst);
        // SAFETY: `ptr` came from `alloc` with this layout.
        unsafe { System.dealloc(ptr, layout) }
    }
}

#[global_allocator]
static ALLOCATOR: Counting = Counting;

#[test]
fn a_4097_field_needs_at_most_a_tenth_more_than_itself() {
    let field_bytes = 4097 * 4097 * std::mem::size_of::<f32>();
    for generator in [Generator::Square, Generator::Diamond, Generator::Triangle] {
        let s = Settings {
            generator,
            detail: Detail::Level(12),
            contour: 1.5,
            sea_level: 0.1,
            ..Settings::default()
        };
        let before = LIVE.load(Ordering::SeqCst);
        PEAK.store(before, Ordering::SeqCst);
        let field = generate_with_threads(&s, 3, 2);
        let extra = PEAK.load(Ordering::SeqCst) - before;
        assert_eq!(field.size(), 4097);
        assert!(extra >= field_bytes, "the count missed the field itself");
        assert!(
            extra <= field_bytes + field_bytes / 10,
            "{generator:?}: peak {extra} bytes for a {field_bytes}-byte field"
        );
    }
}
