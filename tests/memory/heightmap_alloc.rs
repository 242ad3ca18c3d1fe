//! Memory stays bounded: lying headers allocate nothing big, and real images
//! are streamed (no full-image buffer). A counting allocator measures it.

use crate::common::counting::{alone, peak_of};
use crate::common::heightmaps;

use std::path::Path;

use heightmaps::{gray_png, hand_png, ihdr};
use mountains::terrain::heightmap::{ErrorKind, decode};

const MIB: usize = 1 << 20;

// One test function: the counters are global, parallel tests would mix.
#[test]
fn memory_is_bounded() {
    let _alone = alone();
    for (w, h) in [(1_000_000, 1_000_000), (16384, 16384), (16385, 16385)] {
        let bytes = hand_png(ihdr(w, h, 16, 0, 0), &[0, 0, 0], &[]);
        let (result, peak) = peak_of(|| decode(&bytes, Path::new("lie.png")));
        let e = result.unwrap_err();
        assert!(
            matches!(e.kind, ErrorKind::TooLarge | ErrorKind::Truncated),
            "{e}"
        );
        assert!(peak < MIB, "{w}x{h} header made us allocate {peak} bytes");
    }

    // 6000x600 16-bit: a full decode buffer alone would be 7.2 MB; the
    // fitted 513x513 grid is 1 MB.
    let (w, h) = (6000u32, 600u32);
    // Noise, so the file is big too (it barely compresses).
    let mut state = 0x9e37_79b9_7f4a_7c15u64;
    let samples: Vec<u16> = (0..w * h)
        .map(|_| {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 48) as u16
        })
        .collect();
    let bytes = gray_png(w, h, 16, &samples, &[]);
    drop(samples);
    let (result, peak) = peak_of(|| decode(&bytes, Path::new("wide.png")));
    let d = result.unwrap();
    assert_eq!(d.field.size(), 513);
    let grid = 513 * 513 * 4;
    eprintln!("peak {peak} bytes for a {grid}-byte grid");

    // Loading from a file streams it: the 3+ MB file is never held whole.
    let path = heightmaps::temp_dir("alloc").join("wide.png");
    std::fs::write(&path, &bytes).unwrap();
    let file_len = bytes.len();
    drop(bytes);
    let (result, peak) = peak_of(|| mountains::terrain::heightmap::load(&path));
    assert_eq!(result.unwrap().field, d.field);
    assert!(
        peak < grid + MIB,
        "load took {peak} bytes; the file is {file_len}"
    );
    eprintln!("load peak {peak} bytes, file {file_len} bytes");
    assert!(
        peak < grid + 3 * MIB,
        "decoding took {} MiB at its peak",
        peak / MIB
    );
}
