//! Writes the Linux desktop icons, `assets/hicolor/NxN/apps/mountains.png`,
//! from the pictures of `assets/mountains.ico` (the Windows icon,
//! scripts/windows_icon.sh): one icon on both systems, and no image tool
//! needed. `sh scripts/linux_icons.sh` runs this; tests/platforms/packages.rs fails
//! while the PNGs differ from the icon.
//!
//! cargo run --example hicolor_icons

mod ico;

use std::io::Write;
use std::path::{Path, PathBuf};

fn main() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let icon = root.join("assets/mountains.ico");
    let bytes = std::fs::read(&icon).unwrap_or_else(|e| fail(&icon, e));
    let pictures = ico::pictures(&bytes).unwrap_or_else(|e| fail(&icon, e));
    for picture in pictures {
        let path = png_path(root, picture.size);
        let dir = path.parent().expect("a folder");
        std::fs::create_dir_all(dir).unwrap_or_else(|e| fail(dir, e));
        mountains::fsutil::write_atomic_with(&path, |out| write_png(out, &picture))
            .unwrap_or_else(|e| fail(&path, e));
        println!("{}", path.display());
    }
}

/// Where the hicolor icon of `size` pixels lives in the source tree.
fn png_path(root: &Path, size: u32) -> PathBuf {
    root.join(format!("assets/hicolor/{size}x{size}/apps/mountains.png"))
}

/// The picture as an 8-bit RGBA PNG.
fn write_png(out: &mut dyn Write, picture: &ico::Picture) -> std::io::Result<()> {
    let mut encoder = png::Encoder::new(out, picture.size, picture.size);
    encoder.set_color(png::ColorType::Rgba);
    encoder.set_depth(png::BitDepth::Eight);
    encoder.set_compression(png::Compression::High);
    let mut writer = encoder.write_header()?;
    writer.write_image_data(&picture.rgba)?;
    writer.finish()?;
    Ok(())
}

fn fail(path: &Path, error: impl std::fmt::Display) -> ! {
    eprintln!("{}: {error}", path.display());
    std::process::exit(1)
}
