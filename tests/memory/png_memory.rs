//! A PNG is packed a few parts at a time: encoding a large frame holds
//! those parts, never the frame's whole RGB or its whole packed stream.

use mountains::render::Frame;

use crate::common::counting;

#[test]
fn encoding_a_large_frame_holds_only_the_parts_being_packed() {
    let _alone = counting::alone();
    let (w, h) = (4096, 4096);
    let mut frame = Frame::new(w, h).unwrap();
    // Pixels that do not pack to nothing: a part's packed bytes are then
    // about as many as its pixels' bytes.
    for (i, p) in frame.pixels_mut().iter_mut().enumerate() {
        *p = (i as u32).wrapping_mul(0x9e37_79b9) >> 8;
    }
    let (result, peak) =
        counting::peak_of(|| mountains::snapshot::encode_png(&frame, &mut std::io::sink()));
    result.unwrap();
    let rgb = 3 * (w * h) as usize;
    assert!(
        peak > 1 << 20,
        "the count missed the encoding: {peak} bytes"
    );
    // Eight parts at once at most, about 1.2 MB each: a tenth of the
    // frame's 48 MiB of RGB.
    assert!(
        peak < rgb / 4,
        "encoding a {w}x{h} frame held {:.1} MB at its peak ({:.1} MB of RGB)",
        peak as f64 / 1e6,
        rgb as f64 / 1e6
    );
}
