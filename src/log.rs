//! Messages for a person: stderr, and a log file in the data directory
//! (a .scr has no console).
//!
//! STUB: prints to stderr; the file part is being written.

/// Reports a problem the program works around (e.g. a broken config key).
pub fn warn(message: &str) {
    eprintln!("mountains: {message}");
}
