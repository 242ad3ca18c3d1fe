//! Wire modes stay legible: a dense grid in a small frame is thinned to a
//! coarser nested grid instead of becoming a solid sheet of lines.

use std::sync::Arc;

use mountains::render::Size;
use mountains::render::{Frame, Painter};
use mountains::settings::{ColorMode, Settings};
use mountains::terrain::Heightfield;

fn ridge_field(exponent: u32) -> Heightfield {
    let mut f = Heightfield::flat(exponent, 400.0);
    let n = f.size();
    for y in 0..n {
        for x in 0..n {
            let (u, v) = (x as f32 / (n - 1) as f32, y as f32 / (n - 1) as f32);
            f.set(x, y, 40.0 * (u * 9.0).sin() * (v * 7.0).cos() + 10.0);
        }
    }
    f
}

fn lit_fraction(field: &Heightfield, color: ColorMode, w: u32, h: u32) -> f64 {
    let settings = Settings {
        color,
        ..Settings::default()
    };
    let mut frame = Frame::new(w, h).unwrap();
    Painter::new(Arc::new(field.clone()), &settings, Size::new(w, h)).step(&mut frame, usize::MAX);
    let lit = frame.pixels().iter().filter(|&&p| p != 0).count();
    lit as f64 / (w * h) as f64
}

#[test]
fn coarsened_takes_every_nth_point() {
    let f = ridge_field(6);
    let c = f.coarsened(2);
    assert_eq!(c.size(), 17);
    assert_eq!(c.extent(), f.extent());
    for y in 0..17 {
        for x in 0..17 {
            assert_eq!(c.get(x, y), f.get(4 * x, 4 * y));
        }
    }
    // Never below the smallest grid.
    assert_eq!(f.coarsened(10).size(), 17);
}

#[test]
fn sonar_and_outline_of_a_dense_grid_look_like_a_coarse_one() {
    for color in [ColorMode::Sonar, ColorMode::Outline] {
        let dense = lit_fraction(&ridge_field(10), color, 480, 270);
        let coarse = lit_fraction(&ridge_field(6), color, 480, 270);
        // Both fields sample the same surface, so once thinned to the same
        // grid they light the same pixels; unthinned, the dense one lights
        // a quarter more of the frame here, and the whole mountain at
        // larger grid-to-pixel ratios.
        assert!(
            dense <= coarse * 1.05,
            "{color:?}: dense grid lights {dense:.3} of the frame, coarse {coarse:.3}"
        );
    }
}
