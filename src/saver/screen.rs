//! One window of the saver and the slide show drawn in it: presenting it,
//! its title, and what the window's keys do to it.

use std::rc::Rc;
use std::time::Instant;

use winit::window::Window;

use super::actions;
use super::heads::Head;
use super::input::Action;
use super::present::Presenter;
use super::show::Show;
use crate::render::{Damage, Rect};

/// One window and the slide show drawn in it.
pub(super) struct Screen {
    pub(super) window: Rc<Window>,
    pub(super) presenter: Presenter<Rc<Window>>,
    pub(super) show: Show,
    /// The data set the O key opened last, so the next O opens the one after.
    pub(super) opened_path: Option<std::path::PathBuf>,
    /// Full screen: the monitor this window covers.
    pub(super) head: Option<Head>,
    /// The title last given to the window.
    title: String,
}

impl Screen {
    /// A window showing `show`, on `head` when it covers a monitor.
    pub(super) fn new(
        window: Rc<Window>,
        presenter: Presenter<Rc<Window>>,
        show: Show,
        head: Option<Head>,
    ) -> Self {
        Screen {
            window,
            presenter,
            show,
            opened_path: None,
            head,
            title: String::new(),
        }
    }

    /// Puts the `damage` part of the show's frame on the window; `Ok(false)`
    /// when there was nothing to put.
    pub(super) fn present(&mut self, damage: &Damage) -> Result<bool, String> {
        let Some(frame) = self.show.frame().filter(|_| !damage.is_empty()) else {
            return Ok(false);
        };
        self.presenter
            .present(frame, damage)
            .map(|()| true)
            .map_err(|e| format!("cannot present: {e}"))
    }

    /// The whole of the show's frame.
    pub(super) fn bounds(&self) -> Rect {
        self.show.frame().map(|f| f.bounds()).unwrap_or_default()
    }

    /// Gives the window the show's title if it changed (sent only then:
    /// a window manager redraws the title bar each time).
    pub(super) fn update_title(&mut self) {
        let title = self.show.title();
        if title != self.title {
            self.window.set_title(&title);
            self.title = title;
        }
    }

    /// Carries out a window key's `action` on this window's show (saving
    /// and opening files included); the part of the frame that changed, or
    /// `None` when the action ends the saver.
    pub(super) fn act(&mut self, action: Action, now: Instant) -> Option<Rect> {
        let show = &mut self.show;
        if let Some((settings, change)) = actions::changed_settings(action, show.settings()) {
            let note = actions::note(action, &settings);
            let damage = show.change_settings(settings, change, now);
            return Some(match note {
                Some(line) => damage.union(&show.note(line, now)),
                None => damage,
            });
        }
        Some(match action {
            Action::Quit => return None,
            Action::NewMountain => show.new_mountain(now),
            Action::ToggleHelp => show.toggle_help(now),
            Action::TogglePause => {
                show.toggle_pause(now);
                Rect::default()
            }
            Action::SaveDataSet => {
                let saved = show
                    .current()
                    .map(|m| actions::save_data_set(&m, &m.saved_with(&show.saved_settings())));
                actions::report(saved, "data set");
                Rect::default()
            }
            Action::OpenDataSet => self.open_next(now),
            Action::Screenshot => {
                let seed = show.seed();
                actions::report(
                    show.frame().map(|f| actions::save_screenshot(f, seed)),
                    "screenshot",
                );
                Rect::default()
            }
            _ => Rect::default(),
        })
    }

    /// The O key: the saved data set after the one opened last.
    fn open_next(&mut self, now: Instant) -> Rect {
        let current = self.opened_path.as_deref();
        match actions::open_next_data_set(current, self.show.settings()) {
            Ok((path, mountain)) => {
                crate::console::err(&format!("mountains: showing {}", path.display()));
                self.opened_path = Some(path);
                self.show.open(mountain, now)
            }
            Err(e) => {
                crate::log::warn(&format!("cannot open a data set: {e}"));
                Rect::default()
            }
        }
    }
}
