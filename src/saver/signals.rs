//! Ending cleanly on SIGTERM (how xscreensaver stops a hack) and SIGINT.

/// Calls `notify` on a watcher thread each time SIGTERM or SIGINT arrives,
/// instead of letting the signal kill the process with a failure status.
#[cfg(unix)]
pub fn on_terminate(notify: impl Fn() + Send + 'static) -> std::io::Result<()> {
    use signal_hook::consts::{SIGINT, SIGTERM};
    let mut signals = signal_hook::iterator::Signals::new([SIGTERM, SIGINT])?;
    std::thread::Builder::new()
        .name("signals".into())
        .spawn(move || {
            for _ in signals.forever() {
                notify();
            }
        })
        .map(drop)
}

/// Windows ends a screensaver by window messages, not signals: nothing to watch.
#[cfg(not(unix))]
pub fn on_terminate(_notify: impl Fn() + Send + 'static) -> std::io::Result<()> {
    Ok(())
}
