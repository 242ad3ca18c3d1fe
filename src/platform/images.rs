//! Frames as plain images, where softbuffer cannot draw in a window or
//! cannot draw there well: on X11, a foreign window of a visual softbuffer
//! does not take, a server without MIT-SHM, a present that failed. The
//! bands of `x11::bands` go out with PutImage instead. Nothing of the
//! kind elsewhere.

use raw_window_handle::HasWindowHandle;

use crate::render::{Damage, Frame};

/// The plain-image path of one window, taken when softbuffer's is not.
pub struct PlainImages {
    /// The window's X id, if it is an X window.
    #[cfg(x11_platform)]
    xid: Option<u32>,
    #[cfg(x11_platform)]
    bands: Option<super::x11::bands::BandPresenter>,
}

impl PlainImages {
    /// Not taken yet, for `window`.
    pub fn for_window(window: &impl HasWindowHandle) -> Self {
        let _ = window;
        PlainImages {
            #[cfg(x11_platform)]
            xid: super::x11::window_id(window),
            #[cfg(x11_platform)]
            bands: None,
        }
    }

    /// Shows the pixels of `damage` if this path is taken (`None`: it is
    /// not, softbuffer presents).
    pub fn present(&mut self, frame: &Frame, damage: &Damage) -> Option<Result<(), String>> {
        #[cfg(x11_platform)]
        if let Some(bands) = self.bands.as_mut() {
            return Some(damage.rects().try_for_each(|r| bands.present(frame, r)));
        }
        let _ = (frame, damage);
        None
    }

    /// softbuffer refused the window (`problem`): a foreign X window
    /// whose visual softbuffer does not take can still get 24- or 32-bit
    /// pixels through plain PutImage. Else the problem stands.
    pub fn instead_of_softbuffer(&mut self, problem: String) -> Result<(), String> {
        #[cfg(x11_platform)]
        if let Some(xid) = self.xid {
            let bands = super::x11::bands::BandPresenter::connect(xid)
                .map_err(|e| format!("{problem}; {e}"))?;
            crate::log::warn(&format!(
                "softbuffer cannot draw in window 0x{xid:x} ({problem}); sending plain images instead"
            ));
            self.bands = Some(bands);
            return Ok(());
        }
        Err(problem)
    }

    /// Without MIT-SHM softbuffer sends the whole frame in one request on
    /// every present: too slow, and over the request limit for 4K frames.
    /// The same look at the server learns the window's depth. Returns the
    /// depth, if known, and whether this path is now taken (softbuffer's
    /// surface is then of no more use).
    pub fn avoid_wire_transfers(&mut self) -> (Option<u8>, bool) {
        #[cfg(x11_platform)]
        if let Some(xid) = self.xid {
            use x11rb::protocol::xproto::ConnectionExt as _;
            let Ok((conn, _)) = x11rb::rust_connection::RustConnection::connect(None) else {
                return (None, false);
            };
            // Sent before the MIT-SHM query, so both answers come in one round trip.
            let geometry = conn.get_geometry(xid);
            let has_shm = super::x11::bands::server_has_shm(&conn);
            let depth = geometry.ok().and_then(|c| c.reply().ok()).map(|g| g.depth);
            if has_shm {
                return (depth, false);
            }
            if let Ok(bands) = super::x11::bands::BandPresenter::with_connection(conn, xid) {
                crate::log::warn(
                    "the X server has no MIT-SHM: sending only the changed bands of each frame",
                );
                self.bands = Some(bands);
                return (depth, true);
            }
            return (depth, false);
        }
        (None, false)
    }

    /// softbuffer failed to present `frame` (`problem`): on an X window
    /// the whole frame goes out in bands, and from then on every frame.
    /// Else the problem stands.
    pub fn fall_back(&mut self, frame: &Frame, problem: String) -> Result<(), String> {
        #[cfg(x11_platform)]
        if let Some(xid) = self.xid {
            let mut bands = super::x11::bands::BandPresenter::connect(xid)?;
            bands.present(frame, frame.bounds())?;
            crate::log::warn(&format!(
                "presenting a {}x{} frame failed ({problem}); presenting in bands instead",
                frame.width(),
                frame.height()
            ));
            self.bands = Some(bands);
            return Ok(());
        }
        let _ = frame;
        Err(problem)
    }
}
