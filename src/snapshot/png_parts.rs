//! A frame as an 8-bit RGB PNG whose pixels are filtered and packed in
//! parts, on as many threads as there are cores: the encoding was a
//! whole `render`'s last step on one core.
//!
//! Every row is filtered against the row above ("Up": a picture's rows
//! are much alike, and it is as cheap as filters get). The parts are runs
//! of pixels in reading order, the same whatever the number of threads,
//! so one frame always gives the same file; each is an IDAT chunk of its
//! own, and the chunks read one after the other are one zlib stream. Only
//! the parts being packed are held (a 16384x16384 frame's 768 MiB of RGB
//! never exists at once).

use std::io::Write;
use std::ops::Range;

use super::deflate;
use crate::render::Frame;

/// Pixels in a part: enough that a part's block header and code are a
/// small share of it, few enough that the parts of one round are small
/// beside the frame.
const PART_PIXELS: u64 = 1 << 17;

/// Parts packed at once at most: a round's parts are what the encoding
/// holds (about 1.2 MB each), and a picture is packed in a few
/// milliseconds by far fewer threads than a large machine has.
const MOST_AT_ONCE: usize = 8;

/// The zlib stream's header: deflate with a 32 KiB window, no dictionary.
const ZLIB_HEADER: [u8; 2] = [0x78, 0x01];

/// PNG's filter type "Up", the first byte of each filtered row.
const UP: u8 = 2;

/// Encodes `frame` into `out`, packing up to `threads` parts at once (at
/// most [`MOST_AT_ONCE`]).
pub(crate) fn encode(
    frame: &Frame,
    out: &mut dyn Write,
    threads: usize,
) -> Result<(), png::EncodingError> {
    let mut encoder = png::Encoder::new(out, frame.width(), frame.height());
    encoder.set_color(png::ColorType::Rgb);
    encoder.set_depth(png::BitDepth::Eight);
    let mut writer = encoder.write_header()?;
    let total = frame.pixels().len() as u64;
    let parts: Vec<Range<u64>> = (0..total.div_ceil(PART_PIXELS))
        .map(|k| k * PART_PIXELS..((k + 1) * PART_PIXELS).min(total))
        .collect();
    let at_once = threads.clamp(1, MOST_AT_ONCE);
    let mut packers: Vec<Packer> = (0..at_once).map(|_| Packer::default()).collect();
    let mut sum = deflate::adler(&[]);
    for round in parts.chunks(packers.len()) {
        pack_at_once(frame, round, &mut packers[..round.len()]);
        for (part, packer) in round.iter().zip(&mut packers) {
            sum = deflate::adler_joined(sum, packer.adler, packer.filtered.len() as u64);
            if part.end == total {
                packer.packed.extend_from_slice(&deflate::LAST_BLOCK);
                packer.packed.extend_from_slice(&sum.to_be_bytes());
            }
            writer.write_chunk(png::chunk::IDAT, &packer.packed)?;
        }
    }
    writer.finish()
}

/// Packs each part of `round` with a packer of its own, the first here
/// and the others on threads.
fn pack_at_once(frame: &Frame, round: &[Range<u64>], packers: &mut [Packer]) {
    let Some((here, others)) = packers.split_first_mut() else {
        return;
    };
    std::thread::scope(|s| {
        let threads: Vec<_> = others
            .iter_mut()
            .zip(&round[1..])
            .map(|(packer, part)| s.spawn(|| packer.pack(frame, part.clone())))
            .collect();
        here.pack(frame, round[0].clone());
        threads.into_iter().for_each(crate::threads::joined);
    });
}

/// One part's filtered bytes, their checksum and their deflate blocks,
/// kept from part to part for their memory.
#[derive(Default)]
struct Packer {
    filtered: Vec<u8>,
    adler: u32,
    packed: Vec<u8>,
}

impl Packer {
    /// Filters and packs the pixels `part` (indices in reading order).
    fn pack(&mut self, frame: &Frame, part: Range<u64>) {
        self.filtered.clear();
        filter(frame, part.clone(), &mut self.filtered);
        self.adler = deflate::adler(&self.filtered);
        self.packed.clear();
        if part.start == 0 {
            self.packed.extend_from_slice(&ZLIB_HEADER);
        }
        deflate::part(&self.filtered, &mut self.packed);
    }
}

/// Appends to `out` the filtered bytes of pixels `part`: a row's filter
/// type before its first pixel, then each pixel's red, green and blue
/// less the pixel's above (0 above the first row).
fn filter(frame: &Frame, part: Range<u64>, out: &mut Vec<u8>) {
    let width = u64::from(frame.width());
    let pixels = frame.pixels();
    let mut at = part.start;
    while at < part.end {
        let (y, x0) = (at / width, at % width);
        let x1 = width.min(x0 + part.end - at);
        if x0 == 0 {
            out.push(UP);
        }
        let row = (y * width) as usize;
        let span = row + x0 as usize..row + x1 as usize;
        let start = out.len();
        out.resize(start + 3 * span.len(), 0);
        let bytes = out[start..].chunks_exact_mut(3);
        if y == 0 {
            for (o, &p) in bytes.zip(&pixels[span]) {
                o.copy_from_slice(&p.to_be_bytes()[1..]);
            }
        } else {
            let above = span.start - width as usize..span.end - width as usize;
            for ((o, &p), &u) in bytes.zip(&pixels[span]).zip(&pixels[above]) {
                let d = bytewise_difference(p, u);
                o.copy_from_slice(&d.to_be_bytes()[1..]);
            }
        }
        at += x1 - x0;
    }
}

/// Each byte of `a` less the same byte of `b`, modulo 256: the high bit
/// of each byte is set aside so that no byte borrows from the next.
#[inline(always)]
fn bytewise_difference(a: u32, b: u32) -> u32 {
    const HIGH: u32 = 0x8080_8080;
    ((a | HIGH) - (b & !HIGH)) ^ ((a ^ !b) & HIGH)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::Size;

    /// A frame of `size` whose pixels `pixel(x, y)` gives.
    fn frame(size: Size, pixel: impl Fn(u32, u32) -> u32) -> Frame {
        let mut f = Frame::new(size.width, size.height).unwrap();
        let w = size.width;
        for (i, p) in f.pixels_mut().iter_mut().enumerate() {
            *p = pixel(i as u32 % w, i as u32 / w) & 0xff_ffff;
        }
        f
    }

    /// The pixels the png crate reads back from `file`, as `0x00RRGGBB`.
    fn decoded(file: &[u8]) -> (u32, u32, Vec<u32>) {
        let mut reader = png::Decoder::new(std::io::Cursor::new(file))
            .read_info()
            .unwrap();
        let mut rgb = vec![0; reader.output_buffer_size().unwrap()];
        let info = reader.next_frame(&mut rgb).unwrap();
        assert_eq!(
            (info.color_type, info.bit_depth),
            (png::ColorType::Rgb, png::BitDepth::Eight)
        );
        let pixels = rgb
            .chunks_exact(3)
            .map(|c| u32::from_be_bytes([0, c[0], c[1], c[2]]))
            .collect();
        (info.width, info.height, pixels)
    }

    /// A pixel of a test frame at (x, y).
    type Pixel<'a> = &'a dyn Fn(u32, u32) -> u32;

    fn encoded(f: &Frame, threads: usize) -> Vec<u8> {
        let mut out = Vec::new();
        encode(f, &mut out, threads).unwrap();
        out
    }

    fn noise(x: u32, y: u32) -> u32 {
        let h = (u64::from(x) << 32 | u64::from(y)).wrapping_mul(0x9e37_79b9_7f4a_7c15);
        (h >> 29) as u32
    }

    #[test]
    fn a_frame_reads_back_pixel_for_pixel_at_every_shape() {
        let shapes = [(1, 1), (1, 300_000), (300_000, 1), (641, 479), (1920, 137)];
        for (w, h) in shapes {
            let sky = |x: u32, y: u32| (y / 3) << 16 | (y % 256) << 8 | ((x / 97) % 2);
            let kinds: [(&str, Pixel); 3] = [
                ("noise", &noise),
                ("flat", &|_, _| 0x33_6699),
                ("sky", &sky),
            ];
            for (name, pixel) in kinds {
                let f = frame(Size::new(w, h), pixel);
                let (dw, dh, pixels) = decoded(&encoded(&f, 3));
                assert_eq!((dw, dh), (w, h));
                assert!(pixels == f.pixels(), "{name} {w}x{h}");
            }
        }
    }

    #[test]
    fn one_frame_gives_one_file_whatever_the_threads() {
        let f = frame(Size::new(700, 600), |x, y| noise(x / 5, y / 7));
        let one = encoded(&f, 1);
        for threads in [2, 3, 8] {
            assert!(encoded(&f, threads) == one, "{threads} threads");
        }
    }

    #[test]
    fn the_stream_inflates_to_the_filtered_rows_with_its_checksum() {
        use std::io::Read;
        let f = frame(Size::new(513, 700), |x, y| noise(x / 3, y / 2));
        let file = encoded(&f, 2);
        let mut reader = png::Decoder::new(std::io::Cursor::new(&file[..]))
            .read_info()
            .unwrap();
        let mut rgb = vec![0; reader.output_buffer_size().unwrap()];
        reader.next_frame(&mut rgb).unwrap();
        // The IDAT chunks' data joined, as an inflater that checks the
        // Adler-32 reads them (png reads past a wrong one).
        let mut stream = Vec::new();
        let mut at = 8;
        let mut idats = 0;
        while at < file.len() {
            let len = u32::from_be_bytes(file[at..at + 4].try_into().unwrap()) as usize;
            if &file[at + 4..at + 8] == b"IDAT" {
                stream.extend_from_slice(&file[at + 8..at + 8 + len]);
                idats += 1;
            }
            at += 12 + len;
        }
        assert!(idats > 2, "{idats} parts");
        let mut filtered = Vec::new();
        flate2::read::ZlibDecoder::new(&stream[..])
            .read_to_end(&mut filtered)
            .expect("a valid zlib stream");
        let mut want = Vec::new();
        filter(&f, 0..f.pixels().len() as u64, &mut want);
        assert!(filtered == want);
        assert_eq!(filtered.len(), 700 * (1 + 3 * 513));
    }

    #[test]
    fn bytes_are_taken_apart_without_borrowing() {
        let (a, b) = (0x00_10_00_ff, 0x00_11_01_00);
        assert_eq!(bytewise_difference(a, b), 0x00_ff_ff_ff);
        assert_eq!(bytewise_difference(b, a), 0x00_01_01_01);
    }
}
