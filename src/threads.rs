//! Two jobs at once, one here and one on a scoped thread: the scene's
//! start, the clean edges, the lakes and the erosion beside the
//! subdivision split their work this way when there are cores for it
//! (`cores.rs` says how many); and the joining of a scoped thread whose
//! panic goes on up.

/// `a()` here and `b()` on a thread of its own, at once.
pub(crate) fn both<A: Send, B: Send>(
    a: impl FnOnce() -> A + Send,
    b: impl FnOnce() -> B + Send,
) -> (A, B) {
    std::thread::scope(|s| {
        let theirs = s.spawn(b);
        (a(), joined(theirs))
    })
}

/// [`both`] if `at_once`, else `a()` and then `b()` here.
pub(crate) fn both_if<A: Send, B: Send>(
    at_once: bool,
    a: impl FnOnce() -> A + Send,
    b: impl FnOnce() -> B + Send,
) -> (A, B) {
    if at_once { both(a, b) } else { (a(), b()) }
}

/// What a scoped thread returned; its panic goes on up.
pub(crate) fn joined<T>(thread: std::thread::ScopedJoinHandle<'_, T>) -> T {
    thread
        .join()
        .unwrap_or_else(|p| std::panic::resume_unwind(p))
}
