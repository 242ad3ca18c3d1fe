//! Presenting without shared memory: the damaged rectangle goes to the X
//! server as a few `PutImage` requests, each small enough for any server.
//!
//! softbuffer sends the whole frame as one request when MIT-SHM is missing
//! (remote X, sandboxes): a 4K frame then exceeds the maximum request length
//! and every frame costs the full 33 MB. This path sends only what changed.
//! It is also how a window softbuffer cannot take is drawn: a 30-bit or a
//! 16-bit true-colour window gets each pixel packed into its visual's masks.

use x11rb::connection::{Connection, RequestConnection};
use x11rb::protocol::xproto::{
    ConnectionExt as _, CreateGCAux, ImageFormat, ImageOrder, Setup, VisualClass,
};
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
    format: Format,
    staging: Vec<u8>,
}

/// How a frame pixel (`0x00RRGGBB`) is written for a window's visual.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Format {
    /// Bytes a pixel takes in the image: 4, or 2 for 16-bit windows.
    bytes: usize,
    /// Each channel's (shift, bits) in the window's pixel, red first; `None`
    /// for the frame's own layout (24- and 32-bit windows).
    channels: Option<[(u32, u32); 3]>,
    /// ORed into every pixel: opaque alpha for 32-bit (ARGB) windows.
    alpha: u32,
    /// Each image row is padded to a multiple of this many bytes.
    pad: usize,
}

impl Format {
    /// The window's pixel for frame pixel `p`.
    #[inline]
    fn pack(&self, p: u32) -> u32 {
        let Some(channels) = self.channels else {
            return p | self.alpha;
        };
        let mut out = self.alpha;
        for (i, (shift, bits)) in channels.into_iter().enumerate() {
            let v = (p >> (16 - 8 * i)) & 0xff;
            let top = (1u32 << bits) - 1;
            out |= ((v * top + 127) / 255) << shift;
        }
        out
    }
}

/// The format of a window of `depth` bits and visual `visual` on a server
/// set up as `setup`; why not, for one this path cannot draw into.
fn format_of(setup: &Setup, depth: u8, visual: u32) -> Result<Format, String> {
    let refused = || format!("{depth}-bit windows are not supported");
    let pixmap = setup
        .pixmap_formats
        .iter()
        .find(|f| f.depth == depth)
        .ok_or_else(refused)?;
    let bytes = match pixmap.bits_per_pixel {
        32 => 4,
        16 => 2,
        _ => return Err(refused()),
    };
    let pad = usize::from(pixmap.scanline_pad / 8).max(1);
    let alpha = if depth == 32 { 0xff00_0000 } else { 0 };
    if depth == 24 || depth == 32 {
        return Ok(Format {
            bytes,
            channels: None,
            alpha,
            pad,
        });
    }
    let v = setup
        .roots
        .iter()
        .flat_map(|r| r.allowed_depths.iter())
        .flat_map(|d| d.visuals.iter())
        .find(|v| v.visual_id == visual)
        .filter(|v| v.class == VisualClass::TRUE_COLOR)
        .ok_or_else(refused)?;
    let channel = |mask: u32| (mask.trailing_zeros(), mask.count_ones());
    let channels = [v.red_mask, v.green_mask, v.blue_mask].map(channel);
    if channels.iter().any(|&(_, bits)| bits == 0 || bits > 10) {
        return Err(refused());
    }
    Ok(Format {
        bytes,
        channels: Some(channels),
        alpha,
        pad,
    })
}

/// True when a window of `depth` bits and visual `visual` can be drawn
/// into, by softbuffer or by this path.
pub fn can_draw(setup: &Setup, depth: u8, visual: u32) -> bool {
    format_of(setup, depth, visual).is_ok()
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
        let visual = conn
            .get_window_attributes(window)
            .map_err(|e| err(&e))?
            .reply()
            .map_err(|e| err(&e))?
            .visual;
        let format = format_of(conn.setup(), depth, visual).map_err(|e| err(&e))?;
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
            format,
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
        let rows = (max.min(BAND_BYTES) / self.row_bytes(width)).max(1) as u32;
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
        let (bytes, row_bytes) = (self.format.bytes, self.row_bytes((x1 - x0) as usize));
        for y in y0..y1 {
            let start = y as usize * stride;
            let row = &frame.pixels()[start + x0 as usize..start + x1 as usize];
            let end = self.staging.len() + row_bytes;
            for &p in row {
                let p = self.format.pack(p);
                let all = if self.lsb_first {
                    p.to_le_bytes()
                } else {
                    p.to_be_bytes()
                };
                // The low bytes: at the front little-endian, at the back big.
                let part = if self.lsb_first {
                    &all[..bytes]
                } else {
                    &all[4 - bytes..]
                };
                self.staging.extend_from_slice(part);
            }
            self.staging.resize(end, 0);
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

impl BandPresenter {
    /// Bytes of one image row `width` pixels wide, padded.
    fn row_bytes(&self, width: usize) -> usize {
        (width * self.format.bytes).next_multiple_of(self.format.pad)
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
    fn pixels_are_packed_into_30_and_16_bit_masks() {
        let ten = Format {
            bytes: 4,
            channels: Some([(20, 10), (10, 10), (0, 10)]),
            alpha: 0,
            pad: 4,
        };
        assert_eq!(ten.pack(0x00ff_0000), 0x3ff0_0000);
        assert_eq!(ten.pack(0x0000_ff00), 0x000f_fc00);
        assert_eq!(ten.pack(0x0000_0080), 514, "128 of 255 is 514 of 1023");
        let sixteen = Format {
            bytes: 2,
            channels: Some([(11, 5), (5, 6), (0, 5)]),
            alpha: 0,
            pad: 4,
        };
        assert_eq!(sixteen.pack(0x00ff_ffff), 0xffff);
        assert_eq!(sixteen.pack(0x0000_ff00), 0x07e0);
        assert_eq!(
            sixteen.pack(0x0008_0000),
            1 << 11,
            "8 of 255 rounds to 1 of 31"
        );
        let argb = Format {
            bytes: 4,
            channels: None,
            alpha: 0xff00_0000,
            pad: 4,
        };
        assert_eq!(argb.pack(0x0012_3456), 0xff12_3456);
    }

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
