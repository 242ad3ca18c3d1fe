//! The winit saver's side on the desktop Unixes, X11 or Wayland as chosen
//! at run time. On X11 full screen: the server's monitors and their
//! changes, the pointer's place before the windows map, and the keyboard
//! and pointer grab, whose connection also reports the pointer's moves.
//! On Wayland the compositor does all of that: nothing is asked.

use std::time::Instant;

use winit::dpi::PhysicalPosition;
use winit::window::{Window, WindowAttributes};

use super::grab::{InputGrab, Pointer};
use super::pointer::FirstLook;
use crate::platform::backend::Backend;
use crate::platform::events::{Motion, Notice, Notify, Tick};
use crate::saver::error::SaverError;
use crate::saver::heads::Head;
use crate::saver::input::WakeDetector;
use crate::saver::trace::Trace;

/// The platform state of one winit saver run.
pub struct Host<N: Notify> {
    backend: Backend,
    fullscreen: bool,
    notify: N,
    /// The monitors the X server listed at start (empty: ask winit).
    server_heads: Vec<Head>,
    /// The X visual windows are made with, when not the screen's own.
    visual: Option<u32>,
    /// Full screen: the pointer's place before the windows opened.
    pointer_origin: Option<(f64, f64)>,
    /// Full screen: the keyboard and pointer grab, until it holds.
    grab: Option<InputGrab>,
    /// Whether the grab's pointer motion is passed on yet.
    watching_pointer: bool,
    /// Whether relative devices' raw motion comes from the grab's thread
    /// (`Notice::PointerMoved`), so winit's own is not counted.
    raw_motion_watched: bool,
}

impl<N: Notify> Host<N> {
    /// Looks at the server before any window opens: for full screen its
    /// monitors (followed from then on) and the pointer; the visual to
    /// draw with, or why nothing can be drawn on this screen. `parent`
    /// is a Windows preview's and means nothing here.
    pub fn new(
        backend: Backend,
        fullscreen: bool,
        _parent: Option<u64>,
        notify: N,
    ) -> Result<Self, SaverError> {
        let x11 = backend == Backend::X11;
        let server_heads = match fullscreen && x11 {
            true => watch_heads(notify.clone()),
            false => Vec::new(),
        };
        // The pointer's place is the origin its moves (warps too, which
        // no device reports as raw motion) are measured from.
        let first_look = match x11 {
            true => super::pointer::first_look(fullscreen),
            false => FirstLook::default(),
        };
        if let Some(why) = first_look.refusal {
            return Err(SaverError::Unsupported(why));
        }
        Ok(Host {
            backend,
            fullscreen,
            notify,
            server_heads,
            visual: first_look.visual,
            pointer_origin: first_look.pointer,
            grab: None,
            watching_pointer: false,
            raw_motion_watched: false,
        })
    }

    /// Running on a Wayland compositor: no window positions, no grabs,
    /// full screen is the compositor's to give.
    pub fn wayland(&self) -> bool {
        self.backend == Backend::Wayland
    }

    /// The monitors the server listed at start (empty: ask winit).
    pub fn server_heads(&self) -> &[Head] {
        &self.server_heads
    }

    /// `attrs` with what every window of the saver needs here: the
    /// Wayland app_id and the X11 class "mountains" (as the desktop entry
    /// is named), and the visual to draw with on an X screen whose own
    /// one softbuffer cannot take (see visual.rs).
    pub fn window_attributes(&self, attrs: WindowAttributes) -> WindowAttributes {
        crate::platform::window::named(attrs, self.visual)
    }

    /// Where the pointer started, taken before the windows mapped.
    pub fn start_origin(&mut self) -> Option<(f64, f64)> {
        self.pointer_origin.take()
    }

    /// Raw motion the grab's own connection already counts is not
    /// counted twice.
    pub fn motion(&mut self, _wake: &mut WakeDetector) -> Motion {
        match self.raw_motion_watched {
            true => Motion::Handled,
            false => Motion::Raw,
        }
    }

    /// Full screen: the pointer's place on one of our windows. Wayland
    /// sends no raw motion without the relative-pointer protocol; the
    /// place tells as well. X11: raw motion misses a warped pointer
    /// (`xdotool mousemove`, remote desktops); the place on the screen
    /// does not. Once the grab reports the pointer in root coordinates
    /// (`Notice::PointerAt`) this witness stands down: its place is
    /// relative to a window, and a window a monitor change moved would
    /// turn a pointer that stayed into a move.
    pub fn cursor_moved(
        &mut self,
        window: &Window,
        position: PhysicalPosition<f64>,
        wake: &mut WakeDetector,
    ) -> Motion {
        let at = match self.backend {
            Backend::Wayland => Some((position.x, position.y)),
            _ if self.watching_pointer => None,
            _ => window
                .inner_position()
                .ok()
                .map(|at| (f64::from(at.x) + position.x, f64::from(at.y) + position.y)),
        };
        match at {
            Some((x, y)) if wake.moved_to(x, y) => Motion::Away,
            _ => Motion::Handled,
        }
    }

    /// Whether a window winit rescales (after RandR or Xft.dpi changes,
    /// thinking it moved to a monitor of another scale) is to keep its
    /// size: an X11 full-screen window keeps covering its monitor.
    pub fn keeps_size_on_rescale(&self) -> bool {
        self.backend == Backend::X11
    }

    /// After the monitors changed: whether the grab's connection says
    /// where the server put the pointer (`Notice::PointerPlaced`).
    pub fn pointer_placed(&self) -> bool {
        self.watching_pointer
    }

    /// Full screen on X11: grabs keyboard and pointer for the first
    /// window, and retries soon while the grab does not hold.
    pub fn tick(&mut self, first: Option<&Window>, now: Instant) -> Tick {
        let grabbing = self.grab_input(first);
        Tick {
            parent_gone: false,
            wake_at: grabbing.then(|| now + crate::saver::slideshow::FRAME_INTERVAL),
        }
    }

    /// A Windows preview's child window: not on this platform.
    pub fn child_attributes(
        &self,
        _base: WindowAttributes,
        _trace: &Trace,
    ) -> Result<WindowAttributes, SaverError> {
        Err(SaverError::Unsupported(
            "a child of a Windows window needs Windows".into(),
        ))
    }

    /// True while the grab is still being attempted.
    fn grab_input(&mut self, first: Option<&Window>) -> bool {
        if !self.fullscreen {
            return false;
        }
        if self.grab.is_none() {
            match first.and_then(super::window_id) {
                Some(xid) => self.grab = Some(InputGrab::new(xid)),
                None => return false,
            }
        }
        let Some(grab) = self.grab.as_mut() else {
            return false;
        };
        let held = grab.try_grab();
        if held && !self.watching_pointer {
            self.watching_pointer = true;
            let notify = self.notify.clone();
            self.raw_motion_watched = grab.watch_motion(move |pointer| {
                notify.notify(match pointer {
                    Pointer::At(x, y) => Notice::PointerAt(x, y),
                    Pointer::Moved(dx, dy) => Notice::PointerMoved(dx, dy),
                    Pointer::Placed(x, y) => Notice::PointerPlaced(x, y),
                })
            });
        }
        !held
    }
}

/// X11 full screen: the server's monitors at start and, from then on,
/// `Notice::Heads` whenever they change. Without RandR: Xinerama's list,
/// not followed.
fn watch_heads(notify: impl Notify) -> Vec<Head> {
    let watched = super::heads::watch(move |heads| notify.notify(Notice::Heads(heads)));
    watched.unwrap_or_else(|e| {
        crate::log::warn(&format!("monitor changes will not be followed: {e}"));
        super::heads::query().unwrap_or_default()
    })
}
