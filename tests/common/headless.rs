//! What `mountains render` makes, for tests that compare a window's
//! pixels with it.
#![allow(dead_code)]

use std::path::Path;

/// Decodes an 8-bit RGB PNG into 0x00RRGGBB pixels.
pub fn read_rgb_png(path: &Path) -> Vec<u32> {
    let (_, _, rgb, pixels) = read_png(path);
    assert!(rgb, "{} is not an RGB PNG", path.display());
    pixels
}

/// Decodes an 8-bit RGB or RGBA PNG (a screenshot) into 0x00RRGGBB pixels:
/// width, height, whether it was RGB, the pixels.
pub fn read_png(path: &Path) -> (u32, u32, bool, Vec<u32>) {
    let file = std::io::BufReader::new(std::fs::File::open(path).unwrap());
    let mut reader = png::Decoder::new(file).read_info().unwrap();
    let mut buf = vec![0; reader.output_buffer_size().unwrap()];
    let info = reader.next_frame(&mut buf).unwrap();
    let step = match info.color_type {
        png::ColorType::Rgb => 3,
        png::ColorType::Rgba => 4,
        other => panic!("{}: a {other:?} PNG", path.display()),
    };
    let pixels = buf[..info.buffer_size()]
        .chunks_exact(step)
        .map(|c| u32::from(c[0]) << 16 | u32::from(c[1]) << 8 | u32::from(c[2]))
        .collect();
    (info.width, info.height, step == 3, pixels)
}

/// What `mountains render` makes for seed 5 at `w` x `h`.
pub fn headless_render(w: u16, h: u16) -> Vec<u32> {
    // Tests run in parallel: each render gets a folder of its own.
    static RENDERS: std::sync::atomic::AtomicU32 = std::sync::atomic::AtomicU32::new(0);
    let n = RENDERS.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let dir = std::env::temp_dir().join(format!("mountains-render-{}-{n}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let png = dir.join("render.png");
    let size = format!("{w}x{h}");
    // Its output is captured: the seed line it prints is the test's own.
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_mountains"))
        .args([
            "render",
            "-o",
            png.to_str().unwrap(),
            "--size",
            &size,
            "--set",
            "seed=5",
        ])
        .env("XDG_CONFIG_HOME", dir.join("config"))
        .output()
        .unwrap();
    let said = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(said.starts_with("seed 5 -> "), "{said}");
    let pixels = read_rgb_png(&png);
    let _ = std::fs::remove_dir_all(&dir);
    pixels
}
