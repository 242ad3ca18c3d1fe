//! How many threads the machine runs at once, asked once.
//!
//! On Linux the standard library answers from the process's CPU affinity
//! and its cgroup's quota, reading three files each time; the frame asked
//! twice and each new mountain once more.

use std::sync::OnceLock;

/// The threads this process may run at once (at least 1), as the first
/// call found it.
pub fn cores() -> usize {
    static CORES: OnceLock<usize> = OnceLock::new();
    *CORES.get_or_init(|| std::thread::available_parallelism().map_or(1, |n| n.get()))
}
