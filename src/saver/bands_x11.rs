//! Presenting without shared memory: the damaged rectangle goes to the X
//! server as a few `PutImage` requests, each small enough for any server.
//!
//! softbuffer sends the whole frame as one request when MIT-SHM is missing
//! (remote X, sandboxes): a 4K frame then exceeds the maximum request length
//! and every frame costs the full 33 MB. This path sends only what changed.

use x11rb::connection::{Connection, RequestConnection};
use x11rb::protocol::xproto::{ConnectionExt as _, CreateGCAux, ImageFormat, ImageOrder};
use x11rb::rust_connection::RustConnection;

use crate::render::{Frame, Rect};

/// Upper bound of one request's pixel data: keeps the staging buffer small.
const BAND_BYTES: usize = 1 << 20;

/// Bytes of a PutImage request before its pixel data.
const PUT_IMAGE_HEADER: usize = 24;

/// Draws rectangles of a `Frame` into one X window over its own connection.
pub struct BandPresenter {
    conn: RustConnection,
    window: u32,
    gc: u32,
    depth: u8,
    lsb_first: bool,
    /// Opaque alpha for 32-bit (ARGB) windows, nothing for 24-bit ones.
    alpha: u32,
    staging: Vec<u8>,
}

/// True when the server offers MIT-SHM (softbuffer then presents cheaply).
pub fn server_has_shm(conn: &RustConnection) -> bool {
    matches!(conn.extension_information("MIT-SHM"), Ok(Some(_)))
}

impl BandPresenter {
    /// Connects to `$DISPLAY` and prepares drawing into `window`.
    pub fn connect(window: u32) -> Result<Self, String> {
        let (conn, _) = RustConnection::connect(None).map_err(|e| e.to_string())?;
        Self::with_connection(conn, window)
    }

    /// Prepares drawing into `window` over an open connection.
    pub fn with_connection(conn: RustConnection, window: u32) -> Result<Self, String> {
        let err = |e: &dyn std::fmt::Display| format!("window 0x{window:x}: {e}");
        let depth = conn
            .get_geometry(window)
            .map_err(|e| err(&e))?
            .reply()
            .map_err(|e| err(&e))?
            .depth;
        if depth != 24 && depth != 32 {
            return Err(err(&format!("{depth}-bit windows are not supported")));
        }
        let gc = conn.generate_id().map_err(|e| err(&e))?;
        conn.create_gc(gc, window, &CreateGCAux::new().graphics_exposures(0))
            .map_err(|e| err(&e))?;
        let lsb_first = conn.setup().image_byte_order == ImageOrder::LSB_FIRST;
        Ok(BandPresenter {
            conn,
            window,
            gc,
            depth,
            lsb_first,
            alpha: if depth == 32 { 0xff00_0000 } else { 0 },
            staging: Vec::new(),
        })
    }

    /// Sends the pixels of `damage` (clipped to the frame) to the window.
    pub fn present(&mut self, frame: &Frame, damage: Rect) -> Result<(), String> {
        let rect = clip(damage, frame);
        if rect.is_empty() {
            return Ok(());
        }
        let width = (rect.x1 - rect.x0) as usize;
        let max = self
            .conn
            .maximum_request_bytes()
            .saturating_sub(PUT_IMAGE_HEADER);
        let rows = (max.min(BAND_BYTES) / (width * 4)).max(1) as u32;
        let mut y = rect.y0;
        while y < rect.y1 {
            let y1 = (y + rows).min(rect.y1);
            self.put_rows(frame, rect.x0, rect.x1, y, y1)?;
            y = y1;
        }
        self.conn.flush().map_err(|e| e.to_string())
    }

    fn put_rows(
        &mut self,
        frame: &Frame,
        x0: u32,
        x1: u32,
        y0: u32,
        y1: u32,
    ) -> Result<(), String> {
        self.staging.clear();
        let stride = frame.width() as usize;
        for y in y0..y1 {
            let start = y as usize * stride;
            let row = &frame.pixels()[start + x0 as usize..start + x1 as usize];
            for &p in row {
                let p = p | self.alpha;
                let bytes = if self.lsb_first {
                    p.to_le_bytes()
                } else {
                    p.to_be_bytes()
                };
                self.staging.extend_from_slice(&bytes);
            }
        }
        self.conn
            .put_image(
                ImageFormat::Z_PIXMAP,
                self.window,
                self.gc,
                (x1 - x0) as u16,
                (y1 - y0) as u16,
                x0 as i16,
                y0 as i16,
                0,
                self.depth,
                &self.staging,
            )
            .map(|cookie| cookie.ignore_error())
            .map_err(|e| e.to_string())
    }
}

/// `damage` limited to the frame and to X's 16-bit coordinates.
fn clip(damage: Rect, frame: &Frame) -> Rect {
    let x_max = i16::MAX as u32;
    let x_space = Rect::sized(0, 0, x_max, x_max);
    damage.intersect(&frame.bounds()).intersect(&x_space)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn clip_keeps_damage_inside_the_frame() {
        let frame = Frame::new(100, 50).unwrap();
        let r = clip(
            Rect {
                x0: 90,
                y0: 40,
                x1: 500,
                y1: 70,
            },
            &frame,
        );
        assert_eq!(
            r,
            Rect {
                x0: 90,
                y0: 40,
                x1: 100,
                y1: 50
            }
        );
        assert!(
            clip(
                Rect {
                    x0: 200,
                    y0: 0,
                    x1: 300,
                    y1: 10
                },
                &frame
            )
            .is_empty()
        );
    }
}
