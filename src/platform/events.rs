//! What a window system tells the saver's event loop, in words of no
//! window system: the platform rooms' threads send [`Notice`]s through a
//! [`Notify`], and a `Host` answers the loop's questions with
//! [`Motion`] and [`Tick`].

use std::time::Instant;

use crate::saver::heads::Head;

/// News from a thread of a platform room (X11 full screen: the monitor
/// watch and the input grab's connection).
#[derive(Debug, Clone)]
pub enum Notice {
    /// The monitors are now these.
    Heads(Vec<Head>),
    /// The pointer is at this place on the screen (from the input grab:
    /// warps send no raw motion).
    PointerAt(i16, i16),
    /// A relative pointing device moved by this much (XInput 2 raw
    /// motion: winit's counts absolute devices' places).
    PointerMoved(f64, f64),
    /// The screen changed and the server may have moved the pointer: it
    /// is here now.
    PointerPlaced(i16, i16),
}

/// Passes a [`Notice`] on to the event loop, from any thread.
pub trait Notify: Clone + Send + 'static {
    /// Sends `notice`; a loop that has ended drops it.
    fn notify(&self, notice: Notice);
}

/// What a full-screen saver makes of raw pointer motion.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Motion {
    /// Count its distance as winit reports it.
    Raw,
    /// Already counted another way (the X11 grab's own motion), or the
    /// pointer is still near where it started.
    Handled,
    /// The cursor is here, far enough from where it started (Windows,
    /// which reads the cursor's place): the saver ends.
    MovedTo(i32, i32),
    /// The pointer moved far enough, as the event showed: the saver ends.
    Away,
}

/// What the platform wants of the loop between events.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Tick {
    /// The window the preview lives in is gone: the saver ends.
    pub parent_gone: bool,
    /// When to look again (the preview's parent, a retry of the grab).
    pub wake_at: Option<Instant>,
}
