//! Printing to stdout and stderr without a panic. `println!` and
//! `eprintln!` panic (exit 101) when their stream is a pipe whose reader
//! has gone, as `mountains --help | head -1` leaves stdout; Rust ignores
//! SIGPIPE, so such a write fails with EPIPE instead of ending the program.
//! SIGPIPE stays ignored: the saver's X connection breaking must be an
//! error it reports, not a signal that kills it.
//!
//! The rule (ripgrep's): what goes to stdout is for a reader; a reader
//! that has left is no failure, so the rest is dropped quietly and the
//! command ends with the status it would have had (a file written is
//! still written, a check's verdict still its verdict). Any other failure
//! to write stdout (a full disk: `> /dev/full`) is said on stderr and ends
//! with status 1, as coreutils do. A message stderr cannot take is lost
//! (the window modes keep theirs in `mountains.log` as well).

use std::io::{self, Write};
use std::process::ExitCode;

/// Writes `text` to stdout. A closed pipe is not an error (see the module
/// comment); any other failure is returned.
pub fn out(text: &str) -> io::Result<()> {
    let mut stdout = io::stdout().lock();
    match stdout
        .write_all(text.as_bytes())
        .and_then(|()| stdout.flush())
    {
        Err(e) if e.kind() == io::ErrorKind::BrokenPipe => Ok(()),
        other => other,
    }
}

/// Writes `line` and a newline to stdout, as [`out`].
pub fn outln(line: &str) -> io::Result<()> {
    out(&format!("{line}\n"))
}

/// Writes `line` and a newline to stderr; a stderr that cannot take it
/// loses it.
pub fn err(line: &str) {
    // `eprintln!`, not a write of our own: a test harness captures what it
    // writes (a test's expected messages stay in its captured output). Its
    // panic on a failed write is caught, and [`quiet_failed_messages`]
    // keeps that panic from being reported (on the same broken stderr).
    QUIET.with(|q| q.set(true));
    #[allow(clippy::print_stderr)]
    let _ = std::panic::catch_unwind(|| eprintln!("{line}"));
    QUIET.with(|q| q.set(false));
}

std::thread_local! {
    /// Set while [`err`] writes: a panic then is its failed write.
    static QUIET: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}

/// Installs a panic hook that reports every panic as before, except a
/// failed write inside [`err`]. Called once at the start of `main`.
pub fn quiet_failed_messages() {
    let report = std::panic::take_hook();
    std::panic::set_hook(Box::new(move |info| {
        if !QUIET.with(std::cell::Cell::get) {
            report(info);
        }
    }));
}

/// Says on stderr why the program cannot do what it was asked, as every
/// such message is said: `mountains: error: ` and then `message`, which
/// names the flag, file or key it is about.
pub fn error(message: &str) {
    err(&error_line(message));
}

/// `message` as [`error`] writes it on stderr.
pub fn error_line(message: &str) -> String {
    format!("mountains: {}", error_text(message))
}

/// `message` as an error without the program's name, as the log keeps it.
pub fn error_text(message: &str) -> String {
    format!("error: {message}")
}

/// `code`, or 1 with a message when stdout failed other than by a reader
/// leaving.
pub fn status(printed: io::Result<()>, code: ExitCode) -> ExitCode {
    match printed {
        Ok(()) => code,
        Err(e) => {
            error(&format!("cannot write to standard output: {e}"));
            ExitCode::FAILURE
        }
    }
}
