//! Window-mode actions that touch files or settings: saving the data set,
//! screenshots, the next colour, cragginess steps.

use std::path::PathBuf;

use super::input::Action;
use crate::mountain::Mountain;
use crate::render::Frame;
use crate::settings::handles::{COLOR, CRAGGINESS, LOW_DETAIL, RELATIVE_DEPTH};
use crate::settings::keys::{self, Change, Kind, Value};
use crate::settings::{ColorMode, Settings};

/// The colour mode after `color`, wrapping round, in the key table's order
/// (the order the settings file and screen list them).
pub fn next_color(color: ColorMode) -> ColorMode {
    let key = COLOR.row();
    let Kind::Choice(names) = key.kind else {
        return color;
    };
    let mut s = Settings {
        color,
        ..Settings::default()
    };
    let now = keys::get(&s, key);
    let i = names
        .iter()
        .position(|n| Value::Str((*n).into()) == now)
        .unwrap_or(0);
    let next = Value::Str(names[(i + 1) % names.len()].into());
    // Every name in the table is a valid value, so this cannot fail.
    let _ = keys::apply(&mut s, key, &next);
    s.color
}

/// Cragginess one step rougher: doubled, since it is halved at each level.
pub fn craggier(c: u32) -> u32 {
    clamp_cragginess(u64::from(c) * 2)
}

/// Cragginess one step smoother: halved.
pub fn smoother(c: u32) -> u32 {
    clamp_cragginess(u64::from(c / 2))
}

/// Clamps to the range the key table allows for cragginess.
fn clamp_cragginess(c: u64) -> u32 {
    CRAGGINESS.clamp(u32::try_from(c).unwrap_or(u32::MAX))
}

/// The settings a key action leads to, and what the change does to the
/// mountain on screen (the key table's word, as in the settings screen);
/// `None` for actions that do not change settings.
pub fn changed_settings(action: Action, settings: &Settings) -> Option<(Settings, Change)> {
    let mut s = settings.clone();
    let key = match action {
        Action::NextColor => {
            s.color = next_color(s.color);
            COLOR.row()
        }
        Action::ToggleRelativeDepth => {
            s.relative_depth = !s.relative_depth;
            RELATIVE_DEPTH.row()
        }
        Action::ToggleLowDetail => {
            s.low_detail = !s.low_detail;
            LOW_DETAIL.row()
        }
        Action::MoreCraggy => {
            s.cragginess = craggier(s.cragginess);
            CRAGGINESS.row()
        }
        Action::LessCraggy => {
            s.cragginess = smoother(s.cragginess);
            CRAGGINESS.row()
        }
        _ => return None,
    };
    Some((s, key.change))
}

/// What an action whose effect does not show until the next mountain did,
/// to show over the picture for a while (`+` and `-`: the cragginess the
/// next mountain gets); `None` for actions that show at once.
pub fn note(action: Action, settings: &Settings) -> Option<String> {
    matches!(action, Action::MoreCraggy | Action::LessCraggy)
        .then(|| format!("cragginess {} for the next mountain", settings.cragginess))
}

/// The window mode's title, describing the mountain on screen: its seed (to
/// reproduce it), the colours it is drawn in (`now`: they apply at once) and
/// the cragginess and detail it was made with (`made_with`: those keys only
/// shape the next mountain), with the next mountain's cragginess when `+`
/// or `-` changed it.
pub fn window_title(
    now: &Settings,
    made_with: &Settings,
    seed: Option<u64>,
    paused: bool,
) -> String {
    let mut title = match seed {
        Some(seed) => format!("mountains: seed {seed}"),
        None => "mountains".to_string(),
    };
    title.push_str(&format!(
        ", {:?}, cragginess {}",
        now.color, made_with.cragginess
    ));
    if now.cragginess != made_with.cragginess {
        title.push_str(&format!(" (next {})", now.cragginess));
    }
    if made_with.low_detail {
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
        Some(Ok(path)) => crate::console::err(&format!(
            "mountains: saved the {what} as {}",
            path.display()
        )),
        Some(Err(e)) => crate::log::warn(&format!("could not save the {what}: {e}")),
        None => crate::log::warn(&format!("no {what} to save yet")),
    }
}

fn data_dir() -> Result<PathBuf, String> {
    crate::settings::paths::data_dir().ok_or_else(|| "no data directory on this system".into())
}

/// Saves the mountain as a data set in the data directory; returns where.
pub fn save_data_set(mountain: &Mountain, settings: &Settings) -> Result<PathBuf, String> {
    crate::saved::save_data_set(&data_dir()?, &mountain.field, mountain.seed, settings)
}

/// Loads the saved data set after `current` (data directory, then
/// `heightmaps_dir`, by name, wrapping round); returns its path and mountain.
pub fn open_next_data_set(
    current: Option<&std::path::Path>,
    settings: &Settings,
) -> Result<(PathBuf, Mountain), String> {
    let folders = crate::saved::folders(
        crate::settings::paths::data_dir().as_deref(),
        settings.heightmaps_dir.as_deref(),
    );
    let files = crate::saved::list_data_sets(&folders);
    let path =
        crate::saved::next_after(&files, current).ok_or("no saved data sets yet (S saves one)")?;
    let (mountain, _notes) = Mountain::open(path)?;
    Ok((path.clone(), mountain))
}

/// Saves the frame as a PNG screenshot in the data directory; returns where.
pub fn save_screenshot(frame: &Frame, seed: Option<u64>) -> Result<PathBuf, String> {
    crate::saved::save_screenshot(&data_dir()?, frame, seed)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn colours_cycle_through_every_mode() {
        let mut c = ColorMode::Natural;
        let mut seen = vec![c];
        let Kind::Choice(names) = COLOR.row().kind else {
            panic!("color is a choice")
        };
        assert_eq!(names.len(), 13);
        for _ in 0..names.len() - 1 {
            c = next_color(c);
            assert!(!seen.contains(&c));
            seen.push(c);
        }
        assert_eq!(next_color(c), ColorMode::Natural);
    }

    #[test]
    fn colour_depth_and_low_detail_apply_now_cragginess_next() {
        // Mountain Terrain's dialog: Color, Relative Depth and Low Detail
        // apply to the current set; the saver waited for the next mountain
        // on Low Detail while the settings screen remade it at once.
        let s = Settings::default();
        let (c, when) = changed_settings(Action::NextColor, &s).unwrap();
        assert_eq!((c.color, when), (next_color(s.color), Change::Repaint));
        let (d, when) = changed_settings(Action::ToggleRelativeDepth, &s).unwrap();
        assert_eq!(
            (d.relative_depth, when),
            (!s.relative_depth, Change::Repaint)
        );
        let (l, when) = changed_settings(Action::ToggleLowDetail, &s).unwrap();
        assert_eq!((l.low_detail, when), (!s.low_detail, Change::Remake));
        let (m, _) = changed_settings(Action::MoreCraggy, &s).unwrap();
        assert_eq!(m.cragginess, craggier(s.cragginess));
        let (n, when) = changed_settings(Action::LessCraggy, &s).unwrap();
        assert_eq!((n.cragginess, when), (smoother(s.cragginess), Change::Next));
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
            window_title(&s, &s, Some(42), false),
            "mountains: seed 42, Natural, cragginess 64"
        );
        s.low_detail = true;
        s.color = ColorMode::Sonar;
        assert_eq!(
            window_title(&s, &s, None, true),
            "mountains, Sonar, cragginess 64, low detail, paused"
        );
        // Keys for the next mountain do not describe the one on screen; a
        // cragginess changed with + or - says what the next one gets.
        let next = Settings {
            cragginess: 128,
            low_detail: false,
            ..s.clone()
        };
        assert_eq!(
            window_title(&next, &s, Some(7), false),
            "mountains: seed 7, Sonar, cragginess 64 (next 128), low detail"
        );
        assert_eq!(
            note(Action::MoreCraggy, &next).as_deref(),
            Some("cragginess 128 for the next mountain")
        );
        assert_eq!(note(Action::NextColor, &next), None);
    }

    #[test]
    fn cragginess_steps_stay_in_range() {
        assert_eq!(craggier(64), 128);
        assert_eq!(craggier(128), 128);
        assert_eq!(smoother(64), 32);
        assert_eq!(smoother(1), 1);
        assert_eq!(craggier(u32::MAX), 128);
    }
}
