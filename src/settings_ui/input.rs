//! What a person did on the settings screen: keys and clicks, already
//! translated from the window system's events.

/// One input, already translated from the window system's events.
#[derive(Debug, Clone, PartialEq)]
pub enum Input {
    /// Tab (or Shift+Tab when `back`).
    Tab {
        /// Shift was held.
        back: bool,
    },
    /// Arrow up.
    Up,
    /// Arrow down.
    Down,
    /// Arrow left.
    Left,
    /// Arrow right.
    Right,
    /// Page up: a big step up.
    PageUp,
    /// Page down: a big step down.
    PageDown,
    /// Home: the smallest value.
    Home,
    /// End: the largest value.
    End,
    /// Enter / Return.
    Enter,
    /// Space bar.
    Space,
    /// Escape.
    Escape,
    /// Backspace.
    Backspace,
    /// A typed character.
    Char(char),
    /// Left mouse button pressed at a pixel.
    Press(f64, f64),
    /// The pointer moved to a pixel.
    Move(f64, f64),
    /// Left mouse button released at a pixel.
    Release(f64, f64),
    /// Wheel turned at a pixel; positive lines are away from the user.
    Wheel(f64, f64, i32),
}

impl Input {
    /// True for a key; false for the pointer's presses, moves and wheel.
    pub fn is_key(&self) -> bool {
        !matches!(
            self,
            Input::Press(..) | Input::Move(..) | Input::Release(..) | Input::Wheel(..)
        )
    }
}
