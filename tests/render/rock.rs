//! Steep faces that read as rock (issue 33): a cliff is a cell or two of
//! the grid tall and hundreds of pixels high at 4K, and each column's light
//! blended down all of it drew curtains one grid column wide. The strata
//! run across the face instead, the same on every thread count and at
//! every strip budget.

use std::sync::Arc;

use mountains::render::classes::{Class, render_classes};
use mountains::render::{Frame, Painter, Size, render_full};
use mountains::settings::{Settings, Sun};
use mountains::terrain::Heightfield;

const W: u32 = 960;
const H: u32 = 540;
/// How far below the crest the face is measured: the crest's rough skyline
/// and its snow are no part of it.
const BELOW_CREST: i64 = 40;

/// A white-noise value in -1..=1 for column `x` (plain integer
/// arithmetic: the same on every platform).
fn noise(x: usize, key: u32) -> f32 {
    let mut z = (x as u32).wrapping_mul(0x9e37_79b9) ^ key;
    z ^= z >> 16;
    z = z.wrapping_mul(0x85eb_ca6b);
    z ^= z >> 13;
    z = z.wrapping_mul(0xc2b2_ae35);
    z ^= z >> 16;
    (z >> 8) as f32 / (1u32 << 23) as f32 - 1.0
}

/// A sea cliff: a wall three grid rows deep rising from the sea to a
/// crest and falling behind it, as the desert's terraces stand (a face one
/// to three cells deep, tens of cells high), rough from point to point as
/// a fractal face is at its finest scale.
fn sea_cliff() -> Heightfield {
    let mut f = Heightfield::flat(7, 250.0);
    let n = f.size();
    let foot = n * 7 / 10;
    for y in 0..n {
        for x in 0..n {
            let rough = 8.0 * noise(x * n + y, 1);
            let h = match foot.saturating_sub(y) {
                0 => -6.0,
                up @ 1..=3 => -6.0 + 22.0 * up as f32 + rough,
                4 => 64.0 + rough * 0.5,
                up => 64.0 - 30.0 * (up - 4) as f32,
            };
            f.set(x, y, h.max(-6.0));
        }
    }
    f
}

fn settings() -> Settings {
    Settings {
        sun: Sun::Morning,
        ..Settings::default()
    }
}

/// The cliff drawn, and which of its pixels are the face's: land pixels
/// at least 4 pixels from anything else and [`BELOW_CREST`] below the sky.
fn drawn(field: &Heightfield) -> (Frame, Vec<bool>) {
    let s = settings();
    let mut frame = Frame::new(W, H).unwrap();
    render_full(field, &s, &mut frame);
    let mut classes = Frame::new(W, H).unwrap();
    render_classes(field, &s, &mut classes).expect("a shaded look");
    let (w, h) = (W as i64, H as i64);
    let land = |x: i64, y: i64| {
        (0..w).contains(&x)
            && (0..h).contains(&y)
            && Class::of(classes.get(x as u32, y as u32)) == Class::Land
    };
    let face = (0..h)
        .flat_map(|y| (0..w).map(move |x| (x, y)))
        .map(|(x, y)| {
            (-4..=4).all(|d| land(x + d, y) && land(x, y + d)) && land(x, y - BELOW_CREST)
        })
        .collect();
    (frame, face)
}

/// Luminance of a packed colour, 0..=255.
fn luma(c: u32) -> f64 {
    let ch = |s: u32| f64::from((c >> s) & 0xff);
    0.299 * ch(16) + 0.587 * ch(8) + 0.114 * ch(0)
}

/// The energy of the luminance's steps between neighbouring face pixels
/// across the rows (left to right) over that down the columns: above 1
/// where streaks run down the face, below where bands run across it.
fn across_over_down(frame: &Frame, face: &[bool]) -> f64 {
    let (w, h) = (W as usize, H as usize);
    let (mut across, mut down) = (0.0, 0.0);
    for y in 0..h - 1 {
        for x in 0..w - 1 {
            let i = y * w + x;
            if !face[i] {
                continue;
            }
            let here = luma(frame.get(x as u32, y as u32));
            if face[i + 1] {
                across += (luma(frame.get(x as u32 + 1, y as u32)) - here).powi(2);
            }
            if face[i + w] {
                down += (luma(frame.get(x as u32, y as u32 + 1)) - here).powi(2);
            }
        }
    }
    across / down.max(1e-9)
}

#[test]
fn a_rough_cliff_shows_bands_across_it_not_curtains_down_it() {
    let (frame, face) = drawn(&sea_cliff());
    let pixels = face.iter().filter(|&&f| f).count();
    assert!(
        pixels > (W * H / 20) as usize,
        "the face covers {pixels} pixels: the test sees no cliff"
    );
    let ratio = across_over_down(&frame, &face);
    eprintln!("the cliff's {pixels} pixels: steps across / down {ratio:.3}");
    // Before the strata the columns' light ran down the face: steps
    // across were many times those down it.
    assert!(ratio < 2.0, "steps across the face / down it: {ratio:.3}");
}

/// `field` drawn by a painter in steps of `budget` strips.
fn stepped(field: &Heightfield, budget: usize) -> Frame {
    let mut frame = Frame::new(W, H).unwrap();
    frame.clear(0x00ab_cdef);
    let mut p = Painter::new(Arc::new(field.clone()), &settings(), Size::new(W, H));
    while !p.is_done() {
        p.step(&mut frame, budget);
    }
    frame
}

#[test]
fn the_strata_are_the_same_at_every_strip_budget_and_on_every_thread() {
    let field = sea_cliff();
    // The full frame is drawn in bands on all cores, the painter's steps
    // on one thread.
    let (full, face) = drawn(&field);
    assert!(across_over_down(&full, &face) < 2.0, "no strata to compare");
    for budget in [1, 5, usize::MAX] {
        let got = stepped(&field, budget);
        assert!(
            got.pixels() == full.pixels(),
            "budget {budget}: the strata differ from the full frame's"
        );
    }
}
