//! What input means: window-mode keys to actions, and what ends the full-screen saver.

use winit::event::{DeviceEvent, ElementState};
use winit::keyboard::{Key, KeyCode, NamedKey, PhysicalKey};

/// Something a key asks the window mode to do.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Action {
    /// N: start a new mountain now.
    NewMountain,
    /// Space: pause or resume the drawing and the slide show.
    TogglePause,
    /// S: save the current data set into the data directory.
    SaveDataSet,
    /// O: open the next saved data set (data directory, then heightmaps_dir).
    OpenDataSet,
    /// P: save a PNG screenshot into the data directory.
    Screenshot,
    /// C: the next colour mode (redraws at once).
    NextColor,
    /// D: relative water depth on or off (redraws at once).
    ToggleRelativeDepth,
    /// L: low detail on or off (the mountain on screen made again).
    ToggleLowDetail,
    /// +: more cragginess (next mountain).
    MoreCraggy,
    /// -: less cragginess (next mountain).
    LessCraggy,
    /// Esc, Q: quit.
    Quit,
    /// H, F1: show or hide the list of keys.
    ToggleHelp,
}

/// One window-mode key: what it is called, the characters that press it,
/// what it does. `--help` and the H overlay list this table, and key presses
/// are looked up in it, so the three never disagree.
#[derive(Debug, Clone, Copy)]
pub struct Binding {
    /// The key's name for people.
    pub label: &'static str,
    /// The characters it types (lower case); named keys are matched apart.
    pub chars: &'static [char],
    /// What it does.
    pub action: Action,
    /// What it does, in words.
    pub doc: &'static str,
}

const fn bind(
    label: &'static str,
    chars: &'static [char],
    action: Action,
    doc: &'static str,
) -> Binding {
    Binding {
        label,
        chars,
        action,
        doc,
    }
}

/// Every key of the window mode, in the order they are listed.
pub const WINDOW_KEYS: &[Binding] = &[
    bind("N", &['n'], Action::NewMountain, "a new mountain now"),
    bind("Space", &[' '], Action::TogglePause, "pause or resume"),
    bind("S", &['s'], Action::SaveDataSet, "save the data set"),
    bind(
        "O",
        &['o'],
        Action::OpenDataSet,
        "open the next saved data set",
    ),
    bind("P", &['p'], Action::Screenshot, "save a screenshot"),
    bind("C", &['c'], Action::NextColor, "next colour (now)"),
    bind(
        "D",
        &['d'],
        Action::ToggleRelativeDepth,
        "relative depth on/off (now)",
    ),
    bind(
        "L",
        &['l'],
        Action::ToggleLowDetail,
        "low detail on/off (remakes this one)",
    ),
    // '=' is + without Shift on most layouts.
    bind(
        "+",
        &['+', '='],
        Action::MoreCraggy,
        "craggier (next mountain)",
    ),
    bind(
        "-",
        &['-', '_'],
        Action::LessCraggy,
        "smoother (next mountain)",
    ),
    bind("H, F1", &['h'], Action::ToggleHelp, "this list on/off"),
    bind("Esc, Q", &['q'], Action::Quit, "quit"),
];

/// The action a key press asks for in window mode, if any.
pub fn action_for_key(key: &Key) -> Option<Action> {
    match key {
        Key::Named(NamedKey::Escape) => Some(Action::Quit),
        Key::Named(NamedKey::Space) => Some(Action::TogglePause),
        Key::Named(NamedKey::F1) => Some(Action::ToggleHelp),
        Key::Character(text) => action_for_char(text.chars().next()?),
        _ => None,
    }
}

fn action_for_char(c: char) -> Option<Action> {
    let c = c.to_ascii_lowercase();
    WINDOW_KEYS
        .iter()
        .find(|b| b.chars.contains(&c))
        .map(|b| b.action)
}

/// Net pointer travel, in pixels, that counts as the user coming back.
/// Small enough for a deliberate nudge, larger than a desk vibration.
pub const MOTION_THRESHOLD: f64 = 10.0;

/// Decides when raw device input ends the full-screen saver: any key or
/// button press, a wheel turn, or net pointer travel beyond `MOTION_THRESHOLD`.
#[derive(Debug, Clone, Default)]
pub struct WakeDetector {
    dx: f64,
    dy: f64,
    /// The first pointer position `moved_to` saw.
    origin: Option<(f64, f64)>,
    /// Alt presses still to be taken as winit's own (see `expect_injected_alt`).
    injected_alts: u32,
}

impl WakeDetector {
    /// A detector that has seen nothing yet.
    pub fn new() -> Self {
        Self::default()
    }

    /// Announces that winit is about to tap Alt: on Windows, creating a
    /// full-screen window sends a synthetic Alt press and release
    /// (`SendInput`) to be allowed to take the foreground, and raw input
    /// reports it like a real key. The next Alt press is then not a wake.
    pub fn expect_injected_alt(&mut self) {
        self.injected_alts += 1;
    }

    /// Feeds one device event; true when it ends the saver.
    pub fn device_event(&mut self, event: &DeviceEvent) -> bool {
        match event {
            DeviceEvent::Key(raw) if raw.state == ElementState::Pressed => {
                !self.injected_alt(raw.physical_key)
            }
            DeviceEvent::Key(_) => false,
            DeviceEvent::Button { state, .. } => *state == ElementState::Pressed,
            DeviceEvent::MouseWheel { .. } => true,
            DeviceEvent::MouseMotion { delta } => self.moved(delta.0, delta.1),
            _ => false,
        }
    }

    /// True (and counted) if this press is an Alt that winit injected.
    fn injected_alt(&mut self, key: PhysicalKey) -> bool {
        let alt = matches!(key, PhysicalKey::Code(KeyCode::AltLeft | KeyCode::AltRight));
        if alt && self.injected_alts > 0 {
            self.injected_alts -= 1;
            return true;
        }
        false
    }

    /// Takes the pointer's position on screen; true once it is further than
    /// the threshold from the first position seen. For platforms whose
    /// motion deltas cannot be trusted (winit on Windows reports absolute
    /// devices' coordinates as deltas: remote desktops, virtual machines,
    /// tablets, Wine), where the cursor's position is the truth.
    pub fn moved_to(&mut self, x: f64, y: f64) -> bool {
        if !x.is_finite() || !y.is_finite() {
            return false;
        }
        let (x0, y0) = *self.origin.get_or_insert((x, y));
        (x - x0).hypot(y - y0) > MOTION_THRESHOLD
    }

    /// Forgets the first position: the display changed and the system may
    /// have moved the cursor itself; the next position is the new origin.
    pub fn reset_origin(&mut self) {
        self.origin = None;
    }

    /// Takes (x, y) as the new origin: the display changed and the system
    /// says where it has put the cursor.
    pub fn origin_at(&mut self, x: f64, y: f64) {
        if x.is_finite() && y.is_finite() {
            self.origin = Some((x, y));
        }
    }

    /// Adds relative pointer motion; true once the net travel passes the threshold.
    pub fn moved(&mut self, dx: f64, dy: f64) -> bool {
        if !dx.is_finite() || !dy.is_finite() {
            return false;
        }
        self.dx += dx;
        self.dy += dy;
        self.dx.hypot(self.dy) > MOTION_THRESHOLD
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each key in the table, typed, does what the table says (in either
    /// case); named keys do what their labels say.
    #[test]
    fn the_key_table_is_what_the_keys_do() {
        for b in WINDOW_KEYS {
            for &c in b.chars {
                for typed in [c, c.to_ascii_uppercase()] {
                    let key = Key::Character(typed.to_string().into());
                    assert_eq!(action_for_key(&key), Some(b.action), "{typed:?}");
                }
            }
        }
        assert_eq!(
            action_for_key(&Key::Named(NamedKey::F1)),
            Some(Action::ToggleHelp)
        );
        assert_eq!(
            action_for_key(&Key::Named(NamedKey::Escape)),
            Some(Action::Quit)
        );
        assert_eq!(action_for_key(&Key::Character("z".into())), None);
        let mut seen = std::collections::HashSet::new();
        for b in WINDOW_KEYS {
            assert!(seen.insert(b.action), "{:?} listed twice", b.action);
        }
    }
    use winit::event::RawKeyEvent;

    fn ch(s: &str) -> Key {
        Key::Character(s.into())
    }

    #[test]
    fn window_keys_map_to_their_actions() {
        let cases = [
            ("n", Action::NewMountain),
            ("N", Action::NewMountain),
            ("s", Action::SaveDataSet),
            ("o", Action::OpenDataSet),
            ("O", Action::OpenDataSet),
            ("p", Action::Screenshot),
            ("c", Action::NextColor),
            ("d", Action::ToggleRelativeDepth),
            ("l", Action::ToggleLowDetail),
            ("+", Action::MoreCraggy),
            ("=", Action::MoreCraggy),
            ("-", Action::LessCraggy),
            ("q", Action::Quit),
            ("Q", Action::Quit),
        ];
        for (text, action) in cases {
            assert_eq!(action_for_key(&ch(text)), Some(action), "key {text}");
        }
        assert_eq!(
            action_for_key(&Key::Named(NamedKey::Escape)),
            Some(Action::Quit)
        );
        assert_eq!(
            action_for_key(&Key::Named(NamedKey::Space)),
            Some(Action::TogglePause)
        );
    }

    #[test]
    fn other_keys_do_nothing() {
        assert_eq!(action_for_key(&ch("x")), None);
        assert_eq!(action_for_key(&ch("")), None);
        // F1 shows the list of keys now; other function keys do nothing.
        assert_eq!(action_for_key(&Key::Named(NamedKey::F2)), None);
    }

    #[test]
    fn jitter_does_not_wake_but_a_real_move_does() {
        let mut w = WakeDetector::new();
        for _ in 0..100 {
            assert!(!w.moved(3.0, -2.0));
            assert!(!w.moved(-3.0, 2.0));
        }
        assert!(!w.moved(6.0, 0.0));
        assert!(w.moved(5.0, 0.0));
    }

    #[test]
    fn slow_steady_motion_adds_up() {
        let mut w = WakeDetector::new();
        let woke = (0..20).map(|_| w.moved(0.0, 1.0)).position(|b| b);
        assert_eq!(woke, Some(10));
    }

    #[test]
    fn presses_wake_and_releases_do_not() {
        let mut w = WakeDetector::new();
        let key = |state| {
            DeviceEvent::Key(RawKeyEvent {
                physical_key: PhysicalKey::Code(KeyCode::KeyA),
                state,
            })
        };
        assert!(!w.device_event(&key(ElementState::Released)));
        assert!(w.device_event(&key(ElementState::Pressed)));
        let button = |state| DeviceEvent::Button { button: 1, state };
        assert!(!w.device_event(&button(ElementState::Released)));
        assert!(w.device_event(&button(ElementState::Pressed)));
        assert!(!w.device_event(&DeviceEvent::Added));
    }

    fn raw_key(code: KeyCode, state: ElementState) -> DeviceEvent {
        DeviceEvent::Key(RawKeyEvent {
            physical_key: PhysicalKey::Code(code),
            state,
        })
    }

    #[test]
    fn announced_alt_taps_do_not_wake_but_the_next_alt_does() {
        let mut w = WakeDetector::new();
        w.expect_injected_alt();
        w.expect_injected_alt();
        // Two monitors, two windows, two taps; releases use up nothing.
        for _ in 0..2 {
            assert!(!w.device_event(&raw_key(KeyCode::AltRight, ElementState::Pressed)));
            assert!(!w.device_event(&raw_key(KeyCode::AltRight, ElementState::Released)));
        }
        assert!(w.device_event(&raw_key(KeyCode::AltLeft, ElementState::Pressed)));
    }

    #[test]
    fn an_announced_alt_does_not_hide_other_keys() {
        let mut w = WakeDetector::new();
        w.expect_injected_alt();
        assert!(w.device_event(&raw_key(KeyCode::KeyA, ElementState::Pressed)));
        assert!(!w.device_event(&raw_key(KeyCode::AltLeft, ElementState::Pressed)));
        assert!(w.device_event(&raw_key(KeyCode::AltLeft, ElementState::Pressed)));
    }

    #[test]
    fn without_an_announcement_alt_wakes() {
        let mut w = WakeDetector::new();
        assert!(w.device_event(&raw_key(KeyCode::AltRight, ElementState::Pressed)));
    }

    #[test]
    fn nonsense_motion_is_ignored() {
        let mut w = WakeDetector::new();
        assert!(!w.moved(f64::NAN, 0.0));
        assert!(!w.moved(f64::INFINITY, 0.0));
        assert!(!w.moved(1.0, 0.0));
    }

    #[test]
    fn positions_wake_only_beyond_the_threshold_from_the_first() {
        let mut w = WakeDetector::new();
        // The first position is the origin, however far from 0,0 it is.
        assert!(!w.moved_to(320.0, 240.0));
        for _ in 0..50 {
            assert!(!w.moved_to(323.0, 238.0));
            assert!(!w.moved_to(317.0, 242.0));
        }
        assert!(!w.moved_to(330.0, 240.0));
        assert!(w.moved_to(331.0, 240.0));
        // After a display change the cursor may sit elsewhere: a new origin.
        w.reset_origin();
        assert!(!w.moved_to(960.0, 540.0));
        assert!(!w.moved_to(965.0, 540.0));
        assert!(w.moved_to(971.0, 540.0));
        assert!(!WakeDetector::new().moved_to(f64::NAN, 0.0));
    }

    #[test]
    fn a_place_the_system_gives_is_the_new_origin() {
        let mut w = WakeDetector::new();
        assert!(!w.moved_to(960.0, 540.0));
        // The screen shrank to 640x480: the pointer was put in its corner.
        w.origin_at(639.0, 479.0);
        assert!(!w.moved_to(639.0, 479.0));
        assert!(!w.moved_to(630.0, 479.0));
        assert!(w.moved_to(620.0, 479.0));
        w.origin_at(f64::NAN, 0.0);
        assert!(w.moved_to(620.0, 479.0), "a nonsense place changes nothing");
    }
}
