//! Lakes drawn: a basin above the sea shows water at its lip's level in
//! the filled looks, the same whether painted strip by strip or at once,
//! from every side; without lakes the same field shows its dry floor.

use std::sync::Arc;

use mountains::render::Size;
use mountains::render::classes::{Class, render_classes};
use mountains::render::{Frame, Painter, render_full};
use mountains::settings::{ColorMode, Settings, ViewKind};
use mountains::terrain::{Heightfield, Lakes};

/// A high valley behind a ridge: a round basin standing well above the
/// sea, whose lowest lip is lower than the ridge in front of it, and the
/// sea in front of the ridge.
fn valley(exponent: u32) -> Heightfield {
    let mut f = Heightfield::flat(exponent, 250.0);
    let n = f.size();
    for y in 0..n {
        for x in 0..n {
            let (u, v) = (x as f32 / (n - 1) as f32, y as f32 / (n - 1) as f32);
            let r2 = (u - 0.5).powi(2) + (v - 0.35).powi(2);
            // A crater: a rim 40 high at radius 0.25, a floor 10 high.
            let crater = 10.0 + 30.0 * (r2 / 0.0625).min(1.0);
            let outside = 40.0 - 120.0 * (r2.sqrt() - 0.25).max(0.0);
            // The sea in front.
            let front = -60.0 * (v - 0.75).max(0.0);
            f.set(x, y, crater.min(outside.max(crater)) + front);
        }
    }
    f
}

fn with_lakes(mut f: Heightfield) -> Heightfield {
    let lakes = Lakes::of(f.heights(), f.size());
    assert_eq!(lakes.count(), 1, "the valley holds one lake");
    f.set_lakes(Some(Arc::new(lakes)));
    f
}

fn water_pixels(f: &Heightfield, s: &Settings) -> usize {
    let mut frame = Frame::new(320, 180).unwrap();
    render_classes(f, s, &mut frame).expect("a shaded look");
    frame
        .pixels()
        .iter()
        .filter(|&&p| Class::of(p) == Class::Water)
        .count()
}

#[test]
fn a_lake_is_drawn_as_water_and_only_where_asked() {
    let dry = valley(7);
    let wet = with_lakes(dry.clone());
    for view in [ViewKind::Vista, ViewKind::Perspective, ViewKind::Oblique] {
        let s = Settings {
            view,
            ..Settings::default()
        };
        let (before, after) = (water_pixels(&dry, &s), water_pixels(&wet, &s));
        assert!(
            after > before + 500,
            "{view:?}: {before} water pixels without the lake, {after} with it"
        );
    }
}

#[test]
fn stepping_equals_the_full_frame_with_a_lake_from_every_side() {
    let f = with_lakes(valley(6));
    for color in [ColorMode::Natural, ColorMode::Mono, ColorMode::Sonar] {
        for rotation in [0, 90, 180, 270] {
            let s = Settings {
                color,
                rotation,
                ..Settings::default()
            };
            let mut all = Frame::new(160, 120).unwrap();
            render_full(&f, &s, &mut all);
            let mut stepped = Frame::new(160, 120).unwrap();
            stepped.clear(0x00ab_cdef);
            let mut p = Painter::new(Arc::new(f.clone()), &s, Size::new(160, 120));
            while !p.is_done() {
                p.step(&mut stepped, 3);
            }
            assert!(stepped == all, "{color:?} turned {rotation}");
        }
    }
}

/// A turned view shows the same lake: as much water from each side.
#[test]
fn the_lake_turns_with_the_view() {
    let f = with_lakes(valley(7));
    let dry = valley(7);
    for rotation in [90, 180, 270] {
        let s = Settings {
            rotation,
            view: ViewKind::Perspective,
            ..Settings::default()
        };
        let (before, after) = (water_pixels(&dry, &s), water_pixels(&f, &s));
        assert!(
            after > before + 300,
            "turned {rotation}: {before} -> {after}"
        );
    }
}
