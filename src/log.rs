//! Messages for a person: stderr, and a log file in the data directory,
//! because a Windows .scr has no console and xscreensaver hides stderr.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::Mutex;
use std::sync::atomic::{AtomicU32, Ordering};

/// The log file is started afresh (the old one kept as `.old`) past this size.
const MAX_LOG_BYTES: u64 = 256 * 1024;

static LOG_PATH: Mutex<Option<PathBuf>> = Mutex::new(None);

/// Sends later messages to `path` as well as stderr. `None` turns the file off.
pub fn set_file(path: Option<PathBuf>) {
    if let Ok(mut p) = LOG_PATH.lock() {
        *p = path;
    }
}

/// The log file messages go to, if any.
pub fn file() -> Option<PathBuf> {
    LOG_PATH.lock().ok().and_then(|p| p.clone())
}

/// Reports a problem the program works around (e.g. a broken config key).
pub fn warn(message: &str) {
    crate::console::err(&format!("mountains: {message}"));
    record(message);
}

/// Reports a problem that stops what was asked (a bad flag, no display),
/// worded by [`crate::console::error`].
pub fn error(message: &str) {
    crate::console::error(message);
    record(&crate::console::error_text(message));
}

/// The result of a worker thread, or `None` if it panicked: then the panic
/// is reported (a Windows .scr has no stderr for the default report) and
/// the caller carries on without it.
pub fn joined<T>(handle: std::thread::JoinHandle<T>, what: &str) -> Option<T> {
    handle
        .join()
        .map_err(|payload| {
            let why = payload
                .downcast_ref::<&str>()
                .map(|s| s.to_string())
                .or_else(|| payload.downcast_ref::<String>().cloned())
                .unwrap_or_else(|| "no message".into());
            warn(&format!(
                "{what} failed (a panic: {why}); carrying on without it"
            ));
        })
        .ok()
}

/// Writes `message` to the log file only (if one is set).
pub fn record(message: &str) {
    if let Some(path) = file() {
        // Logging must never stop the screensaver: a failed write is dropped.
        let _ = append(&path, message);
    }
}

/// Windows: the program is built for the GUI subsystem (so a .scr opens no
/// console window), which leaves it without stdout and stderr. Started from
/// a console, it attaches to that console so `--help`, `render` and errors
/// print there; output already redirected to a file or pipe stays where it
/// is. Elsewhere, and without a parent console, this does nothing.
pub fn use_parent_console() {
    crate::platform::os::use_parent_console();
}

/// Longest message kept in the log: a line can never take the log far past
/// its rotation size.
const MAX_LINE_BYTES: usize = 4096;

fn append(path: &Path, message: &str) -> std::io::Result<()> {
    let message = cut(message, MAX_LINE_BYTES);
    if let Some(dir) = path.parent() {
        std::fs::create_dir_all(dir)?;
    }
    // Local time with its offset: a person reads the log by their clock.
    let line = format!("[{}] {message}\n", crate::clock::local(crate::clock::now()));
    // Rotate before a line that would take the log past its size, so the
    // log itself never exceeds it.
    let full =
        |p: &Path| std::fs::metadata(p).is_ok_and(|m| m.len() + line.len() as u64 > MAX_LOG_BYTES);
    if full(path) {
        rotate(path, full)?;
    }
    let mut f = std::fs::OpenOptions::new()
        .create(true)
        .append(true)
        .open(path)?;
    f.write_all(line.as_bytes())?;
    // Another instance may have taken this file aside between our open and
    // our write, read it and given its lines to a log started since: our
    // line would go with the file taken. Written again, a line may show
    // twice, but is never lost.
    if !still_kept(f, path) {
        let mut again = std::fs::OpenOptions::new()
            .create(true)
            .append(true)
            .open(path)?;
        again.write_all(line.as_bytes())?;
    }
    Ok(())
}

/// Whether the file open as `f` is the log at `path` or its `.old`.
fn still_kept(f: std::fs::File, path: &Path) -> bool {
    let Ok(written) = same_file::Handle::from_file(f) else {
        return true;
    };
    [path.to_path_buf(), path.with_extension("log.old")]
        .iter()
        .any(|p| same_file::Handle::from_path(p).is_ok_and(|h| h == written))
}

/// Keeps the full log at `path` as `.old`. Instances that find it full at
/// the same moment must not each rename it there: the second would put
/// the log the first has just started over the history. So each takes
/// the log under a name of its own (a rename is atomic: only one takes a
/// given file), and looks at what it took: the full log becomes `.old`;
/// a log another instance has just started is given back.
fn rotate(path: &Path, full: impl Fn(&Path) -> bool) -> std::io::Result<()> {
    static TAKEN: AtomicU32 = AtomicU32::new(0);
    let n = TAKEN.fetch_add(1, Ordering::Relaxed);
    let taken = path.with_extension(format!("log.{}-{n}", std::process::id()));
    match std::fs::rename(path, &taken) {
        // Another instance took it first.
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(()),
        other => other?,
    }
    if full(&taken) {
        return std::fs::rename(&taken, path.with_extension("log.old"));
    }
    give_back(&taken, path)
}

/// Puts the log at `taken` back at `path`. A link never replaces a file:
/// if an instance has started yet another log there, the lines are added
/// to it instead.
fn give_back(taken: &Path, path: &Path) -> std::io::Result<()> {
    if std::fs::hard_link(taken, path).is_err() {
        let lines = std::fs::read(taken)?;
        let mut f = std::fs::OpenOptions::new()
            .create(true)
            .append(true)
            .open(path)?;
        f.write_all(&lines)?;
    }
    std::fs::remove_file(taken)
}

/// `message` cut to at most `max` bytes, at a character boundary, saying so.
fn cut(message: &str, max: usize) -> std::borrow::Cow<'_, str> {
    if message.len() <= max {
        return message.into();
    }
    let mut end = max;
    while !message.is_char_boundary(end) {
        end -= 1;
    }
    format!("{}... ({} bytes in all)", &message[..end], message.len()).into()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_huge_message_is_cut_at_a_character_boundary() {
        assert_eq!(cut("short", 10), "short");
        let long = "é".repeat(5000);
        let c = cut(&long, MAX_LINE_BYTES);
        assert!(c.len() < MAX_LINE_BYTES + 40, "{}", c.len());
        assert!(
            c.ends_with("... (10000 bytes in all)"),
            "{}",
            &c[c.len() - 30..]
        );
    }

    #[test]
    fn a_panicked_worker_is_reported_not_swallowed() {
        let dir = std::env::temp_dir().join(format!("mountains-joined-{}", std::process::id()));
        let path = dir.join("mountains.log");
        set_file(Some(path.clone()));
        let ok = std::thread::spawn(|| 7);
        assert_eq!(joined(ok, "counting"), Some(7));
        let bad = std::thread::spawn(|| -> u32 { panic!("boom {}", 42) });
        assert_eq!(joined(bad, "making the next mountain"), None);
        set_file(None);
        let log = std::fs::read_to_string(&path).unwrap();
        assert!(
            log.contains("making the next mountain failed (a panic: boom 42)"),
            "{log}"
        );
        assert!(!log.contains("counting"), "{log}");
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    fn the_log_never_exceeds_its_rotation_size() {
        let dir = std::env::temp_dir().join(format!("mountains-log-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        let path = dir.join("mountains.log");
        let huge = "x".repeat(1 << 20);
        for i in 0..400 {
            append(&path, if i % 3 == 0 { &huge } else { "a short line" }).unwrap();
            let len = std::fs::metadata(&path).unwrap().len();
            assert!(len <= MAX_LOG_BYTES, "line {i}: {len} bytes");
        }
        let old = std::fs::metadata(path.with_extension("log.old"))
            .unwrap()
            .len();
        assert!(old <= MAX_LOG_BYTES && old > MAX_LOG_BYTES / 2, "{old}");
        let _ = std::fs::remove_dir_all(&dir);
    }

    /// Six instances that find the log full at the same moment rotate it
    /// once: `.old` is the full log, and every instance's line is kept
    /// (one used to rotate the log another had just started, putting that
    /// log's few lines over the history).
    #[test]
    fn instances_rotating_at_once_keep_the_history() {
        const WRITERS: usize = 6;
        let dir = std::env::temp_dir().join(format!("mountains-log6-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("mountains.log");
        let old = path.with_extension("log.old");
        for round in 0..60 {
            // A log one short line from full, with this round's mark.
            let mark = format!("history of round {round}\n");
            let fill = MAX_LOG_BYTES as usize - mark.len() - 8;
            std::fs::write(&path, mark.clone() + &"h".repeat(fill)).unwrap();
            let start = std::sync::Arc::new(std::sync::Barrier::new(WRITERS));
            let writers: Vec<_> = (0..WRITERS)
                .map(|w| {
                    let (path, start) = (path.clone(), start.clone());
                    std::thread::spawn(move || {
                        start.wait();
                        append(&path, &format!("round {round} writer {w}"))
                    })
                })
                .collect();
            for writer in writers {
                let wrote = writer.join().unwrap();
                assert!(wrote.is_ok(), "round {round}: {wrote:?}");
            }
            let history = std::fs::read_to_string(&old).unwrap();
            assert!(
                history.starts_with(&mark),
                "round {round}: .old holds {} bytes, not the full log",
                history.len()
            );
            let log = std::fs::read_to_string(&path).unwrap();
            for w in 0..WRITERS {
                let line = format!("round {round} writer {w}\n");
                assert!(
                    log.contains(&line) || history.contains(&line),
                    "round {round}: writer {w}'s line is lost"
                );
            }
            let strays = std::fs::read_dir(&dir).unwrap().count();
            assert_eq!(strays, 2, "round {round}: files left beside the log");
        }
        let _ = std::fs::remove_dir_all(&dir);
    }
}
