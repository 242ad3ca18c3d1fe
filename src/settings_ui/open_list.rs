//! The Open list: the data sets Open can load, shown over the screen and
//! taking the keys and clicks until one is picked or the list is closed.

use std::path::PathBuf;

use super::input::Input;
use super::layout::{Hit, Layout};

/// The listed data sets and the highlighted one.
#[derive(Debug, Clone, PartialEq)]
pub struct OpenList {
    /// The files, as found on disk.
    pub files: Vec<PathBuf>,
    /// Index of the highlighted entry.
    pub pick: usize,
}

/// What an input did to the list.
#[derive(Debug, Clone, PartialEq)]
pub enum Outcome {
    /// The list stays (the highlight may have moved).
    Stays,
    /// Closed without a choice (Esc).
    Closed,
    /// Closed by a click elsewhere, which the screen handles as usual.
    ClosedPassing,
    /// This data set was chosen.
    Picked(PathBuf),
    /// Not for the list: the screen handles it as usual.
    Passes,
}

impl OpenList {
    /// A list of `files` with the first highlighted.
    pub fn new(files: Vec<PathBuf>) -> Self {
        OpenList { files, pick: 0 }
    }

    /// Takes one input (arrows move, Enter or a click picks, Esc closes).
    pub fn handle(&mut self, input: &Input, layout: &Layout) -> Outcome {
        let n = self.files.len();
        let shown = n.min(layout.list_capacity());
        match input {
            Input::Up | Input::Left => self.pick = self.pick.saturating_sub(1),
            Input::Down | Input::Right | Input::Tab { .. } => {
                self.pick = (self.pick + 1).min(shown.saturating_sub(1))
            }
            Input::Escape => return Outcome::Closed,
            Input::Enter | Input::Space => return self.picked(self.pick),
            Input::Press(x, y) => {
                return match layout.hit(*x, *y, Some(n)) {
                    Some(Hit::ListItem(i)) => self.picked(i),
                    _ => Outcome::ClosedPassing,
                };
            }
            _ => return Outcome::Passes,
        }
        Outcome::Stays
    }

    fn picked(&self, i: usize) -> Outcome {
        match self.files.get(i) {
            Some(path) => Outcome::Picked(path.clone()),
            None => Outcome::Closed,
        }
    }
}
