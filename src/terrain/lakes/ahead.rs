//! Asking for a point's neighbourhood before it is taken: the points come
//! in height order, scattered over the field, so each would otherwise wait
//! on a cache miss per row it touches.

/// Asks for the cache line holding `items[at]` (if there is one), ahead of
/// its use. Only a hint: the same results without it.
#[inline(always)]
pub(super) fn fetch<T>(items: &[T], at: usize) {
    #[cfg(target_arch = "x86_64")]
    if let Some(p) = items.get(at) {
        use std::arch::x86_64::{_MM_HINT_T0, _mm_prefetch};
        // SAFETY: SSE is part of every x86-64 processor, and a prefetch
        // never faults or changes memory; the pointer lies in `items`.
        unsafe { _mm_prefetch::<_MM_HINT_T0>((p as *const T).cast()) };
    }
    #[cfg(not(target_arch = "x86_64"))]
    let _ = (items, at);
}
