//! The row passes in wider vector registers where the processor has them:
//! the same comparisons and selects, twice the lanes (8 floats in AVX2's
//! 256 bits against SSE2's 4, which every x86-64 build may assume).

/// Calls `f`, compiled for AVX2 where the processor has it. `f` must be
/// inlined into it (an `#[inline(always)]` closure over an
/// `#[inline(always)]` function) to gain from it; the results are the
/// same either way.
#[inline(always)]
pub(super) fn wide<R>(f: impl FnOnce() -> R) -> R {
    #[cfg(target_arch = "x86_64")]
    if std::is_x86_feature_detected!("avx2") {
        // SAFETY: the processor has AVX2, asked just above.
        return unsafe { avx2(f) };
    }
    f()
}

/// `f()` with AVX2.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn avx2<R>(f: impl FnOnce() -> R) -> R {
    f()
}
