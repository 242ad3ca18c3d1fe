//! Golden pictures: the hand-made field they are drawn from, reading a
//! pinned PNG, and the pin-or-compare step. When a picture changes on
//! purpose, look at target/golden-actual/ beside tests/golden/ and run the
//! test again with `MOUNTAINS_PIN_GOLDEN=1` to pin it.
#![allow(dead_code)]

use std::path::{Path, PathBuf};

use mountains::render::Frame;
use mountains::terrain::Heightfield;

/// A hand-made rugged field: a ridge, a bay below sea level, some ripples.
pub fn rugged_field(exponent: u32) -> Heightfield {
    let mut f = Heightfield::flat(exponent, 400.0);
    let n = f.size();
    for y in 0..n {
        for x in 0..n {
            let (u, v) = (x as f32 / (n - 1) as f32, y as f32 / (n - 1) as f32);
            let ridge = 70.0 * (1.0 - (2.0 * (u - 0.6)).powi(2) - (1.6 * (v - 0.4)).powi(2));
            // Triangle waves: plain arithmetic, the same on every platform.
            let wave = |t: f32| 2.0 * (t - t.floor() - 0.5).abs() - 0.5;
            let ripple = 18.0 * wave(u * 3.7) * wave(v * 2.9 + 0.2);
            f.set(x, y, ridge + ripple - 15.0);
        }
    }
    f
}

/// The folder of pinned pictures, tests/golden/.
pub fn dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/golden")
}

/// An 8-bit RGB PNG as a frame (`None` if missing or not one).
pub fn read_png(path: &Path) -> Option<Frame> {
    let file = std::fs::File::open(path).ok()?;
    let mut reader = png::Decoder::new(std::io::BufReader::new(file))
        .read_info()
        .ok()?;
    let mut buf = vec![0; reader.output_buffer_size()?];
    let info = reader.next_frame(&mut buf).ok()?;
    if info.color_type != png::ColorType::Rgb || info.bit_depth != png::BitDepth::Eight {
        return None;
    }
    let mut frame = Frame::new(info.width, info.height)?;
    for (px, rgb) in frame.pixels_mut().iter_mut().zip(buf.chunks_exact(3)) {
        *px = u32::from(rgb[0]) << 16 | u32::from(rgb[1]) << 8 | u32::from(rgb[2]);
    }
    Some(frame)
}

/// Compares each drawn picture (file name, frame) with the one pinned in
/// tests/golden/ (or pins them all under `MOUNTAINS_PIN_GOLDEN`); a
/// changed one is written to target/golden-actual/. The names that differ.
pub fn compare(pictures: impl IntoIterator<Item = (String, Frame)>) -> Vec<String> {
    let actual = Path::new(env!("CARGO_MANIFEST_DIR")).join("target/golden-actual");
    let pin = std::env::var_os("MOUNTAINS_PIN_GOLDEN").is_some();
    let mut wrong = Vec::new();
    for (name, got) in pictures {
        let file = dir().join(&name);
        if pin {
            mountains::snapshot::write_png(&file, &got).unwrap();
            continue;
        }
        if read_png(&file).as_ref() != Some(&got) {
            std::fs::create_dir_all(&actual).unwrap();
            mountains::snapshot::write_png(&actual.join(&name), &got).unwrap();
            wrong.push(name);
        }
    }
    wrong
}
