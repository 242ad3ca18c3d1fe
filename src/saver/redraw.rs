//! A complete redraw of the mountain on screen, after a resize or a change
//! of colours, drawn on other threads (on all cores) while the event loop
//! goes on answering input and the old picture stays up.
//!
//! A redraw nobody waits for any more (its window closed, a new slide came)
//! is called off when dropped: its thread stops at the next stage instead of
//! drawing a frame no one will see. Under a storm of monitor changes such
//! threads piled up, each with a frame and a scene of its own.

use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::thread::JoinHandle;

use crate::render::{Frame, Painter, Size};
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

/// A redraw under way; dropping it calls it off.
pub struct Redraw {
    /// `None` once waited for.
    handle: Option<JoinHandle<Option<Drawn>>>,
    /// Set when the redraw is no longer wanted.
    called_off: Arc<AtomicBool>,
}

impl Redraw {
    /// Starts drawing `field` under `settings` into a new `size` frame on
    /// another thread; without a thread it is drawn here and given back
    /// (boxed: a finished frame is the rare, large case).
    pub fn start(
        field: Arc<Heightfield>,
        settings: &Settings,
        size: Size,
    ) -> Result<Self, Box<Drawn>> {
        let settings = settings.clone();
        Redraw::run("redraw", move |off: &AtomicBool| {
            draw(field, &settings, size, None, off)
        })
    }

    /// Starts making the mountain of `seed` again under `made` (the
    /// generator's settings, detail fitted), then drawing it under
    /// `settings`, as [`Redraw::start`] does.
    pub fn remake(
        seed: u64,
        made: Settings,
        settings: &Settings,
        size: Size,
    ) -> Result<Self, Box<Drawn>> {
        let settings = settings.clone();
        Redraw::run("remake", move |off: &AtomicBool| {
            if off.load(Ordering::Relaxed) {
                return None;
            }
            let field = Arc::new(crate::terrain::generate(&made, seed));
            draw(field, &settings, size, Some(made), off)
        })
    }

    /// `work` on a thread of its own, or here if none can be started.
    fn run(
        name: &str,
        work: impl FnOnce(&AtomicBool) -> Option<Drawn> + Clone + Send + 'static,
    ) -> Result<Self, Box<Drawn>> {
        let called_off = Arc::new(AtomicBool::new(false));
        let off = called_off.clone();
        let mine = work.clone();
        match std::thread::Builder::new()
            .name(name.into())
            .spawn(move || mine(&off))
        {
            Ok(handle) => Ok(Redraw {
                handle: Some(handle),
                called_off,
            }),
            // Here nobody can call it off: it always ends with a frame.
            Err(_) => Err(Box::new(
                work(&AtomicBool::new(false)).expect("a redraw not called off"),
            )),
        }
    }

    /// True once the redraw is finished (`wait` will not block).
    pub fn is_done(&self) -> bool {
        self.handle.as_ref().is_none_or(JoinHandle::is_finished)
    }

    /// The finished redraw, waiting for it if need be; `None` if it failed.
    pub fn wait(mut self) -> Option<Drawn> {
        let handle = self.handle.take()?;
        crate::log::joined(handle, "redrawing the mountain").flatten()
    }
}

impl Drop for Redraw {
    fn drop(&mut self) {
        self.called_off.store(true, Ordering::Relaxed);
    }
}

/// Draws a whole frame: in bands on all cores (`Painter::finish`); `None`
/// when called off (`off`) before the scene or the frame was begun.
fn draw(
    field: Arc<Heightfield>,
    settings: &Settings,
    size: Size,
    made: Option<Settings>,
    off: &AtomicBool,
) -> Option<Drawn> {
    if off.load(Ordering::Relaxed) {
        return None;
    }
    let hour = crate::solar::now_for(settings);
    let mut painter = Painter::at_hour(field.clone(), settings, size, hour);
    if off.load(Ordering::Relaxed) {
        return None;
    }
    let mut frame = Frame::new(size.width, size.height);
    if let Some(frame) = frame.as_mut() {
        painter.finish(frame);
    }
    Some(Drawn {
        frame,
        painter,
        field,
        made,
    })
}
