//! `MOUNTAINS_TRACE=1`: how long the first frame took and what ended the
//! saver, on stderr.

use std::fmt;
use std::time::Instant;

/// The zero of the start-up trace: `main`'s first line (see `mark_start`),
/// else when `run` was entered.
static START: std::sync::OnceLock<Instant> = std::sync::OnceLock::new();

/// Starts the start-up trace's clock; `main` calls it first, so the traced
/// time to the first present includes reading the settings and the data set.
pub fn mark_start() {
    START.get_or_init(Instant::now);
}

/// With `MOUNTAINS_TRACE=1`, reports on stderr how long the first present
/// took and what ended the saver (to tell a real wake from a spurious one).
#[derive(Debug, Clone, Copy)]
pub struct Trace {
    on: bool,
    start: Option<Instant>,
}

impl Trace {
    /// Starts the clock if `MOUNTAINS_TRACE=1`.
    pub fn from_env() -> Self {
        let on = std::env::var("MOUNTAINS_TRACE").is_ok_and(|v| v == "1");
        Trace {
            on,
            start: on.then(|| *START.get_or_init(Instant::now)),
        }
    }

    /// Reports what ended the saver.
    pub fn ended_by(&self, why: &dyn fmt::Debug) {
        if self.on {
            crate::console::err(&format!("mountains: trace: ended by {why:?}"));
        }
    }

    /// Reports a fact worth knowing when a platform misbehaves.
    pub fn note(&self, fact: &str) {
        if self.on {
            crate::console::err(&format!("mountains: trace: {fact}"));
        }
    }

    /// Call after each present; the first one prints the time since start.
    pub fn presented(&mut self) {
        if let Some(start) = self.start.take() {
            let ms = start.elapsed().as_secs_f64() * 1000.0;
            crate::console::err(&format!(
                "mountains: trace: first frame presented after {ms:.1} ms"
            ));
        }
    }
}
