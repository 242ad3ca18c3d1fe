//! The relief below the grid (issue 33): where the land is near and a
//! cell spans many pixels, each pixel is lit from a finer terrain than the
//! grid. It is the same on every thread count and at every strip budget;
//! it changes only the light, so the coarse land (its shape, its classes
//! of pixel, its colours seen from afar) stays the same and no crack opens
//! between a refined face and its neighbours.

use std::sync::Arc;

use mountains::render::classes::{Class, render_classes};
use mountains::render::{Frame, Painter, Size, colour, render_full};
use mountains::settings::{Detail, Settings, Sun, World};
use mountains::terrain::{self, Heightfield};

const W: u32 = 640;
const H: u32 = 360;
/// What a pixel no face covers keeps.
const MARKER: u32 = 0x00ff_00ff;

/// A temperate mountain at midday on a coarse grid: its near cells span
/// tens of pixels at this size.
fn settings(fine_relief: bool) -> Settings {
    Settings {
        world: World::Temperate,
        sun: Sun::Midday,
        detail: Detail::Level(6),
        fine_relief,
        ..Settings::default()
    }
}

fn field() -> Heightfield {
    terrain::generate(&settings(true), 8)
}

fn full(field: &Heightfield, settings: &Settings) -> Frame {
    let mut frame = Frame::new(W, H).unwrap();
    render_full(field, settings, &mut frame);
    frame
}

/// `field` drawn by a painter (one thread) in steps of `budget` strips
/// over a frame of [`MARKER`] (the painter draws the sky first).
fn stepped(field: &Heightfield, settings: &Settings, budget: usize) -> Frame {
    let mut frame = Frame::new(W, H).unwrap();
    frame.clear(MARKER);
    let mut p = Painter::new(Arc::new(field.clone()), settings, Size::new(W, H));
    while !p.is_done() {
        p.step(&mut frame, budget);
    }
    frame
}

fn luma(c: u32) -> f64 {
    f64::from(colour::luminance(colour::unpack(c))) * 255.0
}

/// The mean |Laplacian| of the luminance over the frame's lower half (the
/// near land).
fn near_detail(frame: &Frame) -> f64 {
    let (w, h) = (W as usize, H as usize);
    let l: Vec<f64> = frame.pixels().iter().map(|&p| luma(p)).collect();
    let (mut sum, mut n) = (0.0, 0);
    for y in h / 2..h - 1 {
        for x in 1..w - 1 {
            let i = y * w + x;
            sum += (l[i - 1] + l[i + 1] + l[i - w] + l[i + w] - 4.0 * l[i]).abs();
            n += 1;
        }
    }
    sum / n as f64
}

#[test]
fn the_relief_lights_the_near_land_finer_than_its_grid() {
    let field = field();
    let (with, without) = (
        full(&field, &settings(true)),
        full(&field, &settings(false)),
    );
    let (a, b) = (near_detail(&with), near_detail(&without));
    eprintln!("near detail: {a:.3} with the relief, {b:.3} without");
    assert!(a > 1.5 * b, "the relief adds little: {a:.3} against {b:.3}");
}

#[test]
fn the_relief_is_the_same_at_every_strip_budget_and_on_every_thread() {
    let field = field();
    let s = settings(true);
    // The full frame is drawn in bands on all cores, the painter's steps
    // on one thread.
    let whole = full(&field, &s);
    assert!(
        whole.pixels() != full(&field, &settings(false)).pixels(),
        "no relief drawn"
    );
    for budget in [1, 3, usize::MAX] {
        let got = stepped(&field, &s, budget);
        let differ = got
            .pixels()
            .iter()
            .zip(whole.pixels())
            .filter(|(a, b)| a != b)
            .count();
        assert_eq!(
            differ, 0,
            "budget {budget}: {differ} pixels differ from the full frame's"
        );
    }
}

#[test]
fn the_coarse_land_is_the_same_with_or_without_the_relief() {
    // The terrain does not know the key.
    let made = |relief| terrain::generate(&settings(relief), 8);
    let (a, b) = (made(true), made(false));
    assert!(a.heights() == b.heights(), "the relief changed the heights");
    let field = a;
    // Seen from afar (blocks of 80x72 pixels averaged, a few of the first
    // level's bumps where the cells are largest; they tile the frame, so
    // the nearest rows count), the colours are the same within a few
    // levels: the finer bumps lighten and darken about the grid's own
    // light.
    let (with, without) = (
        full(&field, &settings(true)),
        full(&field, &settings(false)),
    );
    let (mut worst, mut differ) = (0.0f64, 0);
    const BW: u32 = 80;
    const BH: u32 = 72;
    for by in 0..H / BH {
        for bx in 0..W / BW {
            let mean = |f: &Frame| {
                let sum: f64 = (0..BH)
                    .flat_map(|y| (0..BW).map(move |x| (bx * BW + x, by * BH + y)))
                    .map(|(x, y)| luma(f.get(x, y)))
                    .sum();
                sum / (BW * BH) as f64
            };
            let d = (mean(&with) - mean(&without)).abs();
            worst = worst.max(d);
            differ += usize::from(d > 0.0);
        }
    }
    eprintln!(
        "blocks of {BW}x{BH} px: worst |mean luma difference| {worst:.2}, {differ} blocks differ"
    );
    assert!(differ > 0, "the relief changed nothing");
    assert!(
        worst < 4.0,
        "a block's mean light moved by {worst:.2} levels"
    );
}

#[test]
fn no_crack_opens_between_a_refined_face_and_its_neighbours() {
    // The same pixels are land, water and sky with the relief and
    // without: a crack between a refined face and its neighbour would let
    // the sky's or the water's class colour through.
    let field = field();
    let classes = |relief| {
        let mut f = Frame::new(W, H).unwrap();
        render_classes(&field, &settings(relief), &mut f).expect("a shaded look");
        f.pixels().iter().map(|&p| Class::of(p)).collect::<Vec<_>>()
    };
    let (with, without) = (classes(true), classes(false));
    let land = without.iter().filter(|&&c| c == Class::Land).count();
    assert!(land > (W * H / 4) as usize, "only {land} land pixels");
    let open = with.iter().zip(&without).filter(|(a, b)| a != b).count();
    assert_eq!(open, 0, "{open} pixels change class with the relief");
}
