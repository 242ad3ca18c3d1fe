//! Window-mode actions that touch files or settings: saving the data set,
//! screenshots, the next colour, cragginess steps.

use std::path::{Path, PathBuf};

use super::input::Action;
use super::show::Mountain;
use crate::render::Frame;
use crate::settings::{ColorMode, Settings};

/// Every colour mode, in the order the C key steps through them.
const COLORS: [ColorMode; 12] = [
    ColorMode::Natural,
    ColorMode::Gray,
    ColorMode::Red,
    ColorMode::Green,
    ColorMode::Blue,
    ColorMode::Yellow,
    ColorMode::Cyan,
    ColorMode::Purple,
    ColorMode::Sonar,
    ColorMode::Outline,
    ColorMode::Mono,
    ColorMode::Ridges,
];

/// The colour mode after `color`, wrapping round.
pub fn next_color(color: ColorMode) -> ColorMode {
    let i = COLORS.iter().position(|&c| c == color).unwrap_or(0);
    COLORS[(i + 1) % COLORS.len()]
}

/// Cragginess range the square generators accept (seed 003: 1-128).
const CRAGGINESS: std::ops::RangeInclusive<u32> = 1..=128;

/// Cragginess one step rougher: doubled, since it is halved at each level.
pub fn craggier(c: u32) -> u32 {
    c.saturating_mul(2)
        .clamp(*CRAGGINESS.start(), *CRAGGINESS.end())
}

/// Cragginess one step smoother: halved.
pub fn smoother(c: u32) -> u32 {
    (c / 2).clamp(*CRAGGINESS.start(), *CRAGGINESS.end())
}

/// Whether a settings change affects the mountain on screen or only the next one.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Applies {
    /// Colours: redraw the current mountain at once.
    Now,
    /// Terrain: the next mountain is generated with it.
    Next,
}

/// The settings a key action leads to, and when they apply; `None` for
/// actions that do not change settings.
pub fn changed_settings(action: Action, settings: &Settings) -> Option<(Settings, Applies)> {
    let mut s = settings.clone();
    let applies = match action {
        Action::NextColor => {
            s.color = next_color(s.color);
            Applies::Now
        }
        Action::ToggleRelativeDepth => {
            s.relative_depth = !s.relative_depth;
            Applies::Now
        }
        Action::ToggleLowDetail => {
            s.low_detail = !s.low_detail;
            Applies::Next
        }
        Action::MoreCraggy => {
            s.cragginess = craggier(s.cragginess);
            Applies::Next
        }
        Action::LessCraggy => {
            s.cragginess = smoother(s.cragginess);
            Applies::Next
        }
        _ => return None,
    };
    Some((s, applies))
}

/// The window mode's title: the seed (to reproduce a mountain) and the
/// settings the keys change.
pub fn window_title(settings: &Settings, seed: Option<u64>, paused: bool) -> String {
    let mut title = match seed {
        Some(seed) => format!("mountains: seed {seed}"),
        None => "mountains".to_string(),
    };
    title.push_str(&format!(
        ", {:?}, cragginess {}",
        settings.color, settings.cragginess
    ));
    if settings.low_detail {
        title.push_str(", low detail");
    }
    if paused {
        title.push_str(", paused");
    }
    title
}

/// Tells the person where a file went, or why it did not.
pub fn report(result: Option<Result<PathBuf, String>>, what: &str) {
    match result {
        Some(Ok(path)) => eprintln!("mountains: saved the {what} as {}", path.display()),
        Some(Err(e)) => crate::log::warn(&format!("could not save the {what}: {e}")),
        None => crate::log::warn(&format!("no {what} to save yet")),
    }
}

/// A readable file stem: `mountain-2026-11-22-023512-seed-42`.
pub fn file_stem(unix_seconds: u64, seed: Option<u64>) -> String {
    let (y, m, d) = civil_date(unix_seconds / 86_400);
    let s = unix_seconds % 86_400;
    let time = format!("{:02}{:02}{:02}", s / 3600, s / 60 % 60, s % 60);
    match seed {
        Some(seed) => format!("mountain-{y:04}-{m:02}-{d:02}-{time}-seed-{seed}"),
        None => format!("mountain-{y:04}-{m:02}-{d:02}-{time}"),
    }
}

/// Year, month, day (UTC) of a day count since 1970-01-01 (Howard Hinnant's algorithm).
fn civil_date(days: u64) -> (u64, u64, u64) {
    let z = days + 719_468;
    let era = z / 146_097;
    let doe = z % 146_097;
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let d = doy - (153 * mp + 2) / 5 + 1;
    let m = if mp < 10 { mp + 3 } else { mp - 9 };
    let y = yoe + era * 400 + u64::from(m <= 2);
    (y, m, d)
}

/// A path in `dir` for `stem` + `suffix` (e.g. `.png`) that names no existing file.
fn free_path(dir: &Path, stem: &str, suffix: &str) -> Option<PathBuf> {
    (1..100)
        .map(|n| match n {
            1 => dir.join(format!("{stem}{suffix}")),
            n => dir.join(format!("{stem}-{n}{suffix}")),
        })
        .find(|p| !p.exists())
}

fn output_path(suffix: &str, seed: Option<u64>) -> Result<PathBuf, String> {
    let dir = crate::settings::paths::data_dir().ok_or("no data directory on this system")?;
    std::fs::create_dir_all(&dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    let now = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.as_secs());
    free_path(&dir, &file_stem(now, seed), suffix)
        .ok_or_else(|| format!("{}: too many files with the same name", dir.display()))
}

/// Saves the mountain as a data set in the data directory; returns where.
pub fn save_data_set(mountain: &Mountain, settings: &Settings) -> Result<PathBuf, String> {
    let path = output_path(".png", mountain.seed)?;
    crate::terrain::heightmap::save(&path, &mountain.field, mountain.seed, settings)
        .map_err(|e| e.to_string())?;
    Ok(path)
}

/// Saves the frame as a PNG screenshot in the data directory; returns where.
pub fn save_screenshot(frame: &Frame, seed: Option<u64>) -> Result<PathBuf, String> {
    let path = output_path("-screenshot.png", seed)?;
    crate::snapshot::write_png(&path, frame)?;
    Ok(path)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn colours_cycle_through_every_mode() {
        let mut c = ColorMode::Natural;
        let mut seen = vec![c];
        for _ in 0..COLORS.len() - 1 {
            c = next_color(c);
            assert!(!seen.contains(&c));
            seen.push(c);
        }
        assert_eq!(next_color(c), ColorMode::Natural);
    }

    #[test]
    fn colour_and_depth_apply_now_terrain_changes_next() {
        let s = Settings::default();
        let (c, when) = changed_settings(Action::NextColor, &s).unwrap();
        assert_eq!((c.color, when), (next_color(s.color), Applies::Now));
        let (d, when) = changed_settings(Action::ToggleRelativeDepth, &s).unwrap();
        assert_eq!((d.relative_depth, when), (!s.relative_depth, Applies::Now));
        let (l, when) = changed_settings(Action::ToggleLowDetail, &s).unwrap();
        assert_eq!((l.low_detail, when), (!s.low_detail, Applies::Next));
        let (m, _) = changed_settings(Action::MoreCraggy, &s).unwrap();
        assert_eq!(m.cragginess, craggier(s.cragginess));
        let (n, when) = changed_settings(Action::LessCraggy, &s).unwrap();
        assert_eq!(
            (n.cragginess, when),
            (smoother(s.cragginess), Applies::Next)
        );
        assert!(changed_settings(Action::Quit, &s).is_none());
        assert!(changed_settings(Action::Screenshot, &s).is_none());
    }

    #[test]
    fn the_title_tells_seed_colour_cragginess_and_state() {
        let mut s = Settings {
            color: ColorMode::Natural,
            cragginess: 64,
            low_detail: false,
            ..Settings::default()
        };
        assert_eq!(
            window_title(&s, Some(42), false),
            "mountains: seed 42, Natural, cragginess 64"
        );
        s.low_detail = true;
        s.color = ColorMode::Sonar;
        assert_eq!(
            window_title(&s, None, true),
            "mountains, Sonar, cragginess 64, low detail, paused"
        );
    }

    #[test]
    fn cragginess_steps_stay_in_range() {
        assert_eq!(craggier(64), 128);
        assert_eq!(craggier(128), 128);
        assert_eq!(smoother(64), 32);
        assert_eq!(smoother(1), 1);
        assert_eq!(craggier(u32::MAX), 128);
    }

    #[test]
    fn file_names_hold_date_time_and_seed() {
        assert_eq!(file_stem(0, Some(7)), "mountain-1970-01-01-000000-seed-7");
        // 2026-11-22 02:35:12 UTC
        assert_eq!(file_stem(1_795_314_912, None), "mountain-2026-11-22-023512");
        // Leap day.
        assert!(file_stem(951_782_400, None).starts_with("mountain-2000-02-29-"));
    }

    #[test]
    fn free_path_never_names_an_existing_file() {
        let dir = std::env::temp_dir().join(format!("mountains-free-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::write(dir.join("a.png"), b"x").unwrap();
        let p = free_path(&dir, "a", ".png").unwrap();
        assert_eq!(p, dir.join("a-2.png"));
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
