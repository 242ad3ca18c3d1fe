//! The winit saver's Windows side: full screen ends when the cursor
//! moves away from where it started (winit passes absolute devices'
//! coordinates on as deltas), and the Control Panel's preview (`/p
//! HWND`) is a child window that follows its parent and dies with it.

use std::time::Instant;

use winit::dpi::PhysicalPosition;
use winit::window::{Window, WindowAttributes};

use super::embed::{PARENT_POLL, child_attributes, follow_parent, match_parent_dpi, parent_alive};
use super::fullscreen::{cursor_position, take_display_change};
use crate::platform::backend::Backend;
use crate::platform::events::{Motion, Notify, Tick};
use crate::saver::error::SaverError;
use crate::saver::heads::Head;
use crate::saver::input::WakeDetector;
use crate::saver::trace::Trace;

/// The platform state of one winit saver run.
pub struct Host<N: Notify> {
    fullscreen: bool,
    /// The preview's parent window (`/p HWND`).
    parent: Option<u64>,
    _notify: N,
}

impl<N: Notify> Host<N> {
    /// Nothing to ask before the windows open.
    pub fn new(
        _backend: Backend,
        fullscreen: bool,
        parent: Option<u64>,
        notify: N,
    ) -> Result<Self, SaverError> {
        Ok(Host {
            fullscreen,
            parent,
            _notify: notify,
        })
    }

    /// Never a Wayland compositor.
    pub fn wayland(&self) -> bool {
        false
    }

    /// No list of monitors of our own: winit's.
    pub fn server_heads(&self) -> &[Head] {
        &[]
    }

    /// Nothing to add.
    pub fn window_attributes(&self, attrs: WindowAttributes) -> WindowAttributes {
        crate::platform::window::named(attrs, None)
    }

    /// The cursor's place at start (full screen) is the origin a move is
    /// measured from. Taken lazily, a move that arrives before the first
    /// motion event (Wine may deliver none until then) would become the
    /// origin.
    pub fn start_origin(&mut self) -> Option<(f64, f64)> {
        if !self.fullscreen {
            return None;
        }
        cursor_position().map(|(x, y)| (x.into(), y.into()))
    }

    /// winit passes absolute devices' coordinates on as deltas, and Wine
    /// sends one such motion when the window appears: the cursor's
    /// position is what counts, from where it was after the last display
    /// change.
    pub fn motion(&mut self, wake: &mut WakeDetector) -> Motion {
        if take_display_change() {
            wake.reset_origin();
        }
        let Some((x, y)) = cursor_position() else {
            return Motion::Raw;
        };
        match wake.moved_to(x.into(), y.into()) {
            true => Motion::MovedTo(x, y),
            false => Motion::Handled,
        }
    }

    /// Raw motion may not arrive (Wine before its first one); the
    /// window's own pointer event is the second witness, and again the
    /// cursor's place is what counts.
    pub fn cursor_moved(
        &mut self,
        _window: &Window,
        _position: PhysicalPosition<f64>,
        wake: &mut WakeDetector,
    ) -> Motion {
        match self.motion(wake) {
            Motion::Raw => Motion::Handled,
            motion => motion,
        }
    }

    /// winit's own rescaling stands.
    pub fn keeps_size_on_rescale(&self) -> bool {
        false
    }

    /// No grab tells where the pointer went after a display change.
    pub fn pointer_placed(&self) -> bool {
        false
    }

    /// The preview child follows its parent's size and dies with it,
    /// looked at every `PARENT_POLL`.
    pub fn tick(&mut self, first: Option<&Window>, now: Instant) -> Tick {
        let Some(parent) = self.parent else {
            return Tick::default();
        };
        let alive = match first {
            Some(window) => follow_parent(parent, window),
            None => parent_alive(parent),
        };
        Tick {
            parent_gone: !alive,
            wake_at: Some(now + PARENT_POLL),
        }
    }

    /// The preview's window: a child of the parent with its DPI
    /// awareness.
    pub fn child_attributes(
        &self,
        base: WindowAttributes,
        trace: &Trace,
    ) -> Result<WindowAttributes, SaverError> {
        let parent = self
            .parent
            .ok_or_else(|| SaverError::Other("no parent window".into()))?;
        let matched = match_parent_dpi(parent);
        trace.note(&format!("preview DPI awareness as the parent's: {matched}"));
        child_attributes(base, parent)
    }
}
