//! Messages for a person: stderr, and a log file in the data directory,
//! because a Windows .scr has no console and xscreensaver hides stderr.

use std::io::Write;
use std::path::PathBuf;
use std::sync::Mutex;
use std::time::{SystemTime, UNIX_EPOCH};

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
    eprintln!("mountains: {message}");
    if let Some(path) = file() {
        // Logging must never stop the screensaver: a failed write is dropped.
        let _ = append(&path, message);
    }
}

fn append(path: &PathBuf, message: &str) -> std::io::Result<()> {
    if let Some(dir) = path.parent() {
        std::fs::create_dir_all(dir)?;
    }
    if std::fs::metadata(path).is_ok_and(|m| m.len() > MAX_LOG_BYTES) {
        std::fs::rename(path, path.with_extension("log.old"))?;
    }
    let secs = SystemTime::now()
        .duration_since(UNIX_EPOCH)
        .map_or(0, |d| d.as_secs());
    let mut f = std::fs::OpenOptions::new()
        .create(true)
        .append(true)
        .open(path)?;
    writeln!(f, "[{}] {message}", format_utc(secs))
}

/// `YYYY-MM-DD HH:MM:SS` in UTC, without a date crate.
pub fn format_utc(secs: u64) -> String {
    let (days, rem) = (secs / 86_400, secs % 86_400);
    let (y, m, d) = civil_from_days(days as i64);
    format!(
        "{y:04}-{m:02}-{d:02} {:02}:{:02}:{:02}",
        rem / 3600,
        rem % 3600 / 60,
        rem % 60
    )
}

/// Days since 1970-01-01 to a calendar date (Howard Hinnant's algorithm).
fn civil_from_days(z: i64) -> (i64, u32, u32) {
    let z = z + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z.rem_euclid(146_097);
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let d = (doy - (153 * mp + 2) / 5 + 1) as u32;
    let m = if mp < 10 { mp + 3 } else { mp - 9 } as u32;
    (yoe + era * 400 + i64::from(m <= 2), m, d)
}
