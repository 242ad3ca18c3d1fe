//! Ending cleanly on SIGTERM (how xscreensaver stops a hack), SIGINT and
//! SIGHUP (the terminal or session going away).

/// Calls `notify` on a watcher thread each time SIGTERM, SIGINT or SIGHUP
/// arrives, instead of letting the signal kill the process with a failure
/// status. A signal the parent set to be ignored (`nohup`) stays ignored.
#[cfg(unix)]
pub fn on_terminate(notify: impl Fn() + Send + 'static) -> std::io::Result<()> {
    use signal_hook::consts::{SIGHUP, SIGINT, SIGTERM};
    let wanted: Vec<i32> = [SIGTERM, SIGINT, SIGHUP]
        .into_iter()
        .filter(|&s| !inherited_ignore(s))
        .collect();
    let mut signals = signal_hook::iterator::Signals::new(wanted)?;
    std::thread::Builder::new()
        .name("signals".into())
        .spawn(move || {
            for _ in signals.forever() {
                notify();
            }
        })
        .map(drop)
}

/// Whether `signal` was set to be ignored when we were started (`nohup`
/// does that for SIGHUP): such a signal is left alone.
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
