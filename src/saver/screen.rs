//! One window of the saver and the slide show drawn in it.

use std::rc::Rc;

use winit::window::Window;

use super::heads::Head;
use super::present::Presenter;
use super::show::Show;
use crate::render::Rect;

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
    pub(super) fn present(&mut self, damage: Rect) -> Result<bool, String> {
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
}
