//! Shared helpers of the heightmap tests: PNG builders (via the png crate,
//! and by hand for what it cannot write: interlacing, lying headers), fields.
#![allow(dead_code)]

use std::path::PathBuf;

use mountains::terrain::Heightfield;

/// A field of `2^n + 1` points whose heights are a smooth, non-trivial function.
pub fn field(exponent: u32, extent: f32) -> Heightfield {
    let mut f = Heightfield::flat(exponent, extent);
    let n = f.size();
    for y in 0..n {
        for x in 0..n {
            let (u, v) = (x as f32 / n as f32, y as f32 / n as f32);
            let h = 40.0 * (u * 7.3).sin() * (v * 5.1).cos() + 25.0 * u - 12.5 + 0.013 * x as f32;
            f.set(x, y, h);
        }
    }
    f
}

/// A grayscale PNG from the png crate: `samples` row-major, 8 or 16 bits.
pub fn gray_png(
    width: u32,
    height: u32,
    bits: u8,
    samples: &[u16],
    text: &[(&str, &str)],
) -> Vec<u8> {
    let data: Vec<u8> = if bits == 16 {
        samples.iter().flat_map(|s| s.to_be_bytes()).collect()
    } else {
        samples.iter().map(|&s| s as u8).collect()
    };
    let depth = if bits == 16 {
        png::BitDepth::Sixteen
    } else {
        png::BitDepth::Eight
    };
    encode(width, height, png::ColorType::Grayscale, depth, &data, text)
}

/// Any PNG the png crate can write.
pub fn encode(
    width: u32,
    height: u32,
    color: png::ColorType,
    depth: png::BitDepth,
    data: &[u8],
    text: &[(&str, &str)],
) -> Vec<u8> {
    let mut out = Vec::new();
    let mut enc = png::Encoder::new(&mut out, width, height);
    enc.set_color(color);
    enc.set_depth(depth);
    if color == png::ColorType::Indexed {
        enc.set_palette(vec![0u8; 3 * 256]);
    }
    for (k, v) in text {
        enc.add_text_chunk(k.to_string(), v.to_string()).unwrap();
    }
    let mut w = enc.write_header().unwrap();
    w.write_image_data(data).unwrap();
    w.finish().unwrap();
    out
}

/// CRC-32 as PNG chunks use it.
pub fn crc32(bytes: &[u8]) -> u32 {
    let mut crc = 0xffff_ffffu32;
    for &b in bytes {
        crc ^= u32::from(b);
        for _ in 0..8 {
            crc = if crc & 1 != 0 {
                (crc >> 1) ^ 0xedb8_8320
            } else {
                crc >> 1
            };
        }
    }
    !crc
}

/// One PNG chunk with its length and CRC.
pub fn chunk(kind: &[u8; 4], data: &[u8]) -> Vec<u8> {
    let mut out = (data.len() as u32).to_be_bytes().to_vec();
    let mut body = kind.to_vec();
    body.extend_from_slice(data);
    out.extend_from_slice(&body);
    out.extend_from_slice(&crc32(&body).to_be_bytes());
    out
}

/// A zlib stream of stored (uncompressed) deflate blocks.
pub fn zlib_stored(data: &[u8]) -> Vec<u8> {
    let mut out = vec![0x78, 0x01];
    let blocks: Vec<&[u8]> = if data.is_empty() {
        vec![&[]]
    } else {
        data.chunks(65535).collect()
    };
    for (i, block) in blocks.iter().enumerate() {
        out.push(u8::from(i + 1 == blocks.len()));
        let len = block.len() as u16;
        out.extend_from_slice(&len.to_le_bytes());
        out.extend_from_slice(&(!len).to_le_bytes());
        out.extend_from_slice(block);
    }
    let (mut a, mut b) = (1u32, 0u32);
    for &byte in data {
        a = (a + u32::from(byte)) % 65521;
        b = (b + a) % 65521;
    }
    out.extend_from_slice(&((b << 16) | a).to_be_bytes());
    out
}

/// The IHDR chunk: any values, true or not.
pub fn ihdr(width: u32, height: u32, depth: u8, color: u8, interlace: u8) -> Vec<u8> {
    let mut d = width.to_be_bytes().to_vec();
    d.extend_from_slice(&height.to_be_bytes());
    d.extend_from_slice(&[depth, color, 0, 0, interlace]);
    chunk(b"IHDR", &d)
}

/// A PNG assembled by hand from an IHDR and raw (filter-byte-prefixed) scanlines.
pub fn hand_png(ihdr_chunk: Vec<u8>, scanlines: &[u8], extra: &[Vec<u8>]) -> Vec<u8> {
    let mut out = vec![0x89, b'P', b'N', b'G', b'\r', b'\n', 0x1a, b'\n'];
    out.extend(ihdr_chunk);
    for c in extra {
        out.extend_from_slice(c);
    }
    out.extend(chunk(b"IDAT", &zlib_stored(scanlines)));
    out.extend(chunk(b"IEND", &[]));
    out
}

/// An Adam7-interlaced 8-bit grayscale PNG of `samples`.
pub fn interlaced_gray8(width: u32, height: u32, samples: &[u8]) -> Vec<u8> {
    const PASSES: [(u32, u32, u32, u32); 7] = [
        (0, 0, 8, 8),
        (4, 0, 8, 8),
        (0, 4, 4, 8),
        (2, 0, 4, 4),
        (0, 2, 2, 4),
        (1, 0, 2, 2),
        (0, 1, 1, 2),
    ];
    let mut raw = Vec::new();
    for (x0, y0, dx, dy) in PASSES {
        if x0 >= width || y0 >= height {
            continue;
        }
        for y in (y0..height).step_by(dy as usize) {
            raw.push(0);
            for x in (x0..width).step_by(dx as usize) {
                raw.push(samples[(y * width + x) as usize]);
            }
        }
    }
    hand_png(ihdr(width, height, 8, 0, 1), &raw, &[])
}

/// A fresh empty directory for one test.
pub fn temp_dir(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(format!("heightmap-{name}"));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}
