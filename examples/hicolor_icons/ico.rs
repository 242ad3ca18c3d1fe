//! The pictures of a Windows .ico file as RGBA: a PNG entry decoded, a
//! 32-bit BMP entry (BITMAPINFOHEADER, BGRA rows bottom up, then the AND
//! mask) turned the right way up. Only what `assets/mountains.ico` holds
//! (scripts/windows_icon.sh writes every size 32-bit); anything else is an
//! error naming the entry.

/// One picture of the icon: its size and its pixels, RGBA, top row first.
pub struct Picture {
    /// Width and height in pixels.
    pub size: u32,
    /// `size * size * 4` bytes.
    pub rgba: Vec<u8>,
}

/// Every picture of the icon in `bytes`, in the file's order.
pub fn pictures(bytes: &[u8]) -> Result<Vec<Picture>, String> {
    let u16_at = |at: usize| {
        bytes
            .get(at..at + 2)
            .map(|b| u16::from_le_bytes([b[0], b[1]]))
    };
    if u16_at(0) != Some(0) || u16_at(2) != Some(1) {
        return Err("not an icon file (ICONDIR reserved 0, type 1)".into());
    }
    let count = u16_at(4).unwrap_or(0) as usize;
    (0..count).map(|i| entry(bytes, i)).collect()
}

/// The `i`th picture: its directory entry is 16 bytes after the 6-byte header.
fn entry(bytes: &[u8], i: usize) -> Result<Picture, String> {
    let at = 6 + 16 * i;
    let dir = bytes
        .get(at..at + 16)
        .ok_or(format!("entry {i}: directory cut short"))?;
    // A width byte of 0 means 256.
    let size = if dir[0] == 0 { 256 } else { u32::from(dir[0]) };
    let len = u32::from_le_bytes(dir[8..12].try_into().unwrap()) as usize;
    let offset = u32::from_le_bytes(dir[12..16].try_into().unwrap()) as usize;
    let data = bytes
        .get(offset..offset + len)
        .ok_or(format!("entry {i}: data outside the file"))?;
    let rgba = if data.starts_with(b"\x89PNG") {
        png_rgba(data, size)
    } else {
        bmp_rgba(data, size)
    }
    .map_err(|e| format!("entry {i} ({size} px): {e}"))?;
    Ok(Picture { size, rgba })
}

/// A PNG entry's pixels; it must be 8-bit RGBA of the entry's size.
fn png_rgba(data: &[u8], size: u32) -> Result<Vec<u8>, String> {
    let mut reader = png::Decoder::new(std::io::Cursor::new(data))
        .read_info()
        .map_err(|e| e.to_string())?;
    let mut rgba = vec![0; reader.output_buffer_size().ok_or("no size")?];
    let info = reader.next_frame(&mut rgba).map_err(|e| e.to_string())?;
    let rgba8 = (info.color_type, info.bit_depth) == (png::ColorType::Rgba, png::BitDepth::Eight);
    if !rgba8 || (info.width, info.height) != (size, size) {
        return Err(format!(
            "a PNG {:?} {:?} {}x{}",
            info.color_type, info.bit_depth, info.width, info.height
        ));
    }
    rgba.truncate(info.buffer_size());
    Ok(rgba)
}

/// A 32-bit BMP entry's pixels (its alpha is in the fourth byte, so the
/// AND mask after them adds nothing).
fn bmp_rgba(data: &[u8], size: u32) -> Result<Vec<u8>, String> {
    let field = |at: usize| i32::from_le_bytes(data[at..at + 4].try_into().unwrap());
    if data.len() < 40 || field(0) != 40 {
        return Err("neither a PNG nor a BITMAPINFOHEADER".into());
    }
    let bits = u16::from_le_bytes([data[14], data[15]]);
    // The height counts the picture and its mask.
    if field(4) != size as i32 || field(8) != 2 * size as i32 || bits != 32 || field(16) != 0 {
        return Err(format!(
            "a BMP {}x{} of {bits} bits, compression {}",
            field(4),
            field(8),
            field(16)
        ));
    }
    let row = size as usize * 4;
    let pixels = data
        .get(40..40 + row * size as usize)
        .ok_or("pixels cut short")?;
    let mut rgba = Vec::with_capacity(pixels.len());
    for line in pixels.chunks_exact(row).rev() {
        for bgra in line.chunks_exact(4) {
            rgba.extend_from_slice(&[bgra[2], bgra[1], bgra[0], bgra[3]]);
        }
    }
    Ok(rgba)
}
