//! Ending cleanly on SIGTERM (how xscreensaver stops a hack), SIGINT and
//! SIGHUP (the terminal or session going away).

use std::sync::atomic::{AtomicBool, Ordering};

/// How long the main loop has to end after `on_terminate`'s notice before
/// the process ends without it. A signal must end every window mode within
/// half a second (xscreensaver sends SIGTERM when it switches hacks), and
/// on a loaded machine ending a process (its threads, its memory) takes
/// a good part of that.
pub const GRACE: std::time::Duration = std::time::Duration::from_millis(250);

/// Set once a signal asked the window modes to end.
static ENDING: AtomicBool = AtomicBool::new(false);

/// True once SIGTERM, SIGINT or SIGHUP asked the window modes to end: long
/// work on the main loop (strips being drawn) stops early, so that the
/// loop reads the notice now rather than after the work.
pub fn ending() -> bool {
    ENDING.load(Ordering::Relaxed)
}

/// Calls `notify` on a watcher thread each time SIGTERM, SIGINT or SIGHUP
/// arrives, instead of letting the signal kill the process with a failure
/// status. A signal the parent set to be ignored (`nohup`) stays ignored.
///
/// If the process is still running [`GRACE`] after the first notice, it
/// ends with status 0 from the watcher thread: the main loop can be stuck
/// waiting for a reply from an X server that is stopped (SIGSTOP) or hung,
/// and a screensaver told to stop must stop. Temporary files of writes in
/// progress are removed first, so no file is left half made.
#[cfg(unix)]
pub fn on_terminate(notify: impl Fn() + Send + 'static) -> std::io::Result<()> {
    mark_ending_at_once()?;
    watch(move |_| {
        ENDING.store(true, Ordering::Relaxed);
        notify();
        std::thread::sleep(GRACE);
        crate::fsutil::partial::remove_all();
        // `_exit`, not `exit`: atexit handlers might wait for a lock the
        // stuck main thread holds (Xlib's display lock among them).
        // SAFETY: ends the process; nothing after it runs.
        unsafe { libc::_exit(0) }
    })
}

/// For one-shot commands (`render`, `heightmap`): on SIGTERM, SIGINT or
/// SIGHUP the temporary file of a write in progress is removed, then the
/// program ends by that signal as if it had not been caught, so a script
/// sees that no file was made (a clean exit 0 would claim one was).
#[cfg(unix)]
pub fn end_cleanly() -> std::io::Result<()> {
    watch(|signal| {
        crate::fsutil::partial::remove_all();
        let _ = signal_hook::low_level::emulate_default_handler(signal);
        // Only reached if the signal could not be raised again.
        std::process::exit(128 + signal);
    })
}

/// Sets [`ending`] in the signal handler itself, on the thread the signal
/// interrupts (the main thread, when it runs): on a loaded machine the
/// watcher thread can wait a fifth of a second for the processor before
/// it reads the signal, and the main loop looks at the flag between
/// strips and after each turn.
#[cfg(unix)]
fn mark_ending_at_once() -> std::io::Result<()> {
    for signal in wanted() {
        // SAFETY: the action only stores to an atomic, which is
        // async-signal-safe; it allocates nothing and takes no lock.
        unsafe {
            signal_hook::low_level::register(signal, || ENDING.store(true, Ordering::Relaxed))?;
        }
    }
    Ok(())
}

/// SIGTERM, SIGINT and SIGHUP, less those ignored when we were started.
#[cfg(unix)]
fn wanted() -> Vec<i32> {
    use signal_hook::consts::{SIGHUP, SIGINT, SIGTERM};
    [SIGTERM, SIGINT, SIGHUP]
        .into_iter()
        .filter(|&s| !inherited_ignore(s))
        .collect()
}

/// Calls `on_signal` on a watcher thread for each SIGTERM, SIGINT or SIGHUP
/// not ignored when we were started.
#[cfg(unix)]
fn watch(on_signal: impl Fn(i32) + Send + 'static) -> std::io::Result<()> {
    let mut signals = signal_hook::iterator::Signals::new(wanted())?;
    std::thread::Builder::new()
        .name("signals".into())
        .spawn(move || {
            for signal in signals.forever() {
                on_signal(signal);
            }
        })
        .map(drop)
}

/// Whether `signal` was set to be ignored when we were started (`nohup`
/// does that for SIGHUP, a POSIX shell for SIGINT in a background job, so
/// that Ctrl+C at the terminal leaves the job running): such a signal is
/// left alone, as the parent asked. SIGTERM, how xscreensaver and `kill`
/// end a program, is not ignored that way.
#[cfg(target_os = "linux")]
fn inherited_ignore(signal: i32) -> bool {
    // SAFETY: with a null new action, sigaction only reads the current one
    // into `old`, which we own.
    unsafe {
        let mut old: libc::sigaction = std::mem::zeroed();
        libc::sigaction(signal, std::ptr::null(), &mut old) == 0
            && old.sa_sigaction == libc::SIG_IGN
    }
}

/// Elsewhere the current action is not looked at: every signal is watched.
#[cfg(all(unix, not(target_os = "linux")))]
fn inherited_ignore(_signal: i32) -> bool {
    false
}

/// Windows ends a screensaver by window messages, not signals: nothing to watch.
#[cfg(not(unix))]
pub fn on_terminate(_notify: impl Fn() + Send + 'static) -> std::io::Result<()> {
    Ok(())
}

/// Not watched on Windows: Ctrl+C there ends the console program at once
/// (a temporary `.NAME.PID.tmp` file may be left beside the output).
#[cfg(not(unix))]
pub fn end_cleanly() -> std::io::Result<()> {
    Ok(())
}
