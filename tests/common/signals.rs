//! Children a test signals start with SIGTERM, SIGINT and SIGHUP at their
//! default action, as from a terminal. A test run as a background job
//! (POSIX shells start those with SIGINT ignored) or under `nohup` (SIGHUP)
//! would otherwise pass the ignore on, and `mountains`, which rightly
//! leaves a signal ignored when it was started alone (src/platform/signals.rs),
//! would not end: the test would depend on how it was started.
#![allow(dead_code)]

use std::process::Command;

/// The signals `mountains` ends on.
pub const ENDING: [(&str, i32); 3] = [("TERM", 15), ("INT", 2), ("HUP", 1)];

/// Makes `command` start its child with every signal in [`ENDING`] at its
/// default action.
pub fn as_from_a_terminal(command: &mut Command) -> &mut Command {
    with_action(command, Action::Default)
}

/// Makes `command` start its child with `signal` ignored, as a shell does
/// for a background job (SIGINT) or `nohup` (SIGHUP); the others at their
/// default action.
pub fn ignoring(command: &mut Command, signal: i32) -> &mut Command {
    with_action(command, Action::IgnoreOne(signal))
}

#[derive(Clone, Copy)]
enum Action {
    Default,
    IgnoreOne(i32),
}

/// Sets the actions between fork and exec. Only Linux: elsewhere
/// `mountains` catches these signals whatever it inherited.
#[cfg(target_os = "linux")]
fn with_action(command: &mut Command, action: Action) -> &mut Command {
    use std::os::unix::process::CommandExt;
    // SAFETY: signal() is async-signal-safe, and the closure touches no
    // memory the parent's other threads could hold locked.
    unsafe {
        command.pre_exec(move || {
            for (_, number) in ENDING {
                let handler = match action {
                    Action::IgnoreOne(s) if s == number => libc::SIG_IGN,
                    _ => libc::SIG_DFL,
                };
                if libc::signal(number, handler) == libc::SIG_ERR {
                    return Err(std::io::Error::last_os_error());
                }
            }
            Ok(())
        })
    }
}

#[cfg(not(target_os = "linux"))]
fn with_action(command: &mut Command, _action: Action) -> &mut Command {
    command
}
