//! A complete redraw of the mountain on screen, after a resize or a change
//! of colours, drawn on other threads (on all cores) while the event loop
//! goes on answering input and the old picture stays up.

use std::sync::Arc;
use std::thread::JoinHandle;

use crate::render::{Frame, Painter};
use crate::settings::Settings;
use crate::terrain::Heightfield;

/// A finished redraw: the frame (none for a window without area) and the
/// painter that drew it, done.
pub struct Drawn {
    /// The new pixels.
    pub frame: Option<Frame>,
    /// The painter, every strip drawn.
    pub painter: Painter,
    /// The heights drawn (new ones after a remake).
    pub field: Arc<Heightfield>,
    /// After a remake, the generator's settings that made `field`.
    pub made: Option<Settings>,
}

/// A redraw under way.
pub struct Redraw {
    handle: JoinHandle<Drawn>,
}

impl Redraw {
    /// Starts drawing `field` under `settings` into a new `size` frame on
    /// another thread; without a thread it is drawn here and given back
    /// (boxed: a finished frame is the rare, large case).
    pub fn start(
        field: Arc<Heightfield>,
        settings: &Settings,
        size: (u32, u32),
    ) -> Result<Self, Box<Drawn>> {
        let settings = settings.clone();
        Redraw::run("redraw", move || draw(field, &settings, size, None))
    }

    /// Starts making the mountain of `seed` again under `made` (the
    /// generator's settings, detail fitted), then drawing it under
    /// `settings`, as [`Redraw::start`] does.
    pub fn remake(
        seed: u64,
        made: Settings,
        settings: &Settings,
        size: (u32, u32),
    ) -> Result<Self, Box<Drawn>> {
        let settings = settings.clone();
        Redraw::run("remake", move || {
            let field = Arc::new(crate::terrain::generate(&made, seed));
            draw(field, &settings, size, Some(made))
        })
    }

    /// `work` on a thread of its own, or here if none can be started.
    fn run(
        name: &str,
        work: impl FnOnce() -> Drawn + Clone + Send + 'static,
    ) -> Result<Self, Box<Drawn>> {
        match std::thread::Builder::new()
            .name(name.into())
            .spawn(work.clone())
        {
            Ok(handle) => Ok(Redraw { handle }),
            Err(_) => Err(Box::new(work())),
        }
    }

    /// True once the redraw is finished (`wait` will not block).
    pub fn is_done(&self) -> bool {
        self.handle.is_finished()
    }

    /// The finished redraw, waiting for it if need be; `None` if it failed.
    pub fn wait(self) -> Option<Drawn> {
        crate::log::joined(self.handle, "redrawing the mountain")
    }
}

/// Draws a whole frame: in bands on all cores (`Painter::finish`).
fn draw(
    field: Arc<Heightfield>,
    settings: &Settings,
    size: (u32, u32),
    made: Option<Settings>,
) -> Drawn {
    let mut painter = Painter::new(field.clone(), settings, size.0, size.1);
    let mut frame = Frame::new(size.0, size.1);
    if let Some(frame) = frame.as_mut() {
        painter.finish(frame);
    }
    Drawn {
        frame,
        painter,
        field,
        made,
    }
}
