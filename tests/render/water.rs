//! Sea level: the water-line split and the depth of water.

use glam::Vec2;
use mountains::render::Size;
use mountains::render::palette::Palette;
use mountains::render::view::View;
use mountains::render::{Frame, Painter, render_full};
use mountains::settings::{Settings, ViewKind};
use mountains::terrain::Heightfield;
use std::sync::Arc;

/// A plane rising along x: `slope` height units per grid step, at sea level
/// at column `shore` (between grid points, so every crossing cell is split).
fn ramp(shore: f32, slope: f32) -> Heightfield {
    let mut f = Heightfield::flat(4, 160.0);
    for y in 0..f.size() {
        for x in 0..f.size() {
            f.set(x, y, slope * (x as f32 - shore));
        }
    }
    f
}

/// The frame with only the sky painted (a painter's first step, no strips).
fn sky_only(field: &Heightfield, s: &Settings, w: u32, h: u32) -> Frame {
    let mut frame = Frame::new(w, h).unwrap();
    Painter::new(Arc::new(field.clone()), s, Size::new(w, h)).step(&mut frame, 0);
    frame
}

fn luminance(c: u32) -> u32 {
    ((c >> 16) & 0xff) * 77 + ((c >> 8) & 0xff) * 150 + (c & 0xff) * 29
}

#[test]
fn no_land_pixel_lies_on_the_sea_side_of_the_shore() {
    let (w, h) = (320u32, 200u32);
    for shore in [7.3, 3.61, 11.9] {
        let field = ramp(shore, 2.0);
        // The oblique view has no haze: water is drawn in palette colours.
        let s = Settings {
            view: ViewKind::Oblique,
            ..Settings::default()
        };
        let mut frame = Frame::new(w, h).unwrap();
        render_full(&field, &s, &mut frame);
        let sky = sky_only(&field, &s, w, h);
        let palette = Palette::new(&s, &field);
        let depths = (0..=8000).map(|i| i as f32 * 0.005);
        let water: std::collections::HashSet<u32> = depths.map(|d| palette.water(d)).collect();
        let zmax = field.max().max(0.0);
        let view = View::new(
            ViewKind::Oblique,
            field.size(),
            field.extent(),
            zmax,
            Size::new(w, h),
        );
        let a = view.project(shore, 0.0, 0.0);
        let b = view.project(shore, 16.0, 0.0);
        let sea = view.project(0.0, 8.0, 0.0);
        let side = |p: Vec2| {
            let d = b - a;
            let n = Vec2::new(d.y, -d.x).normalize();
            (p - a).dot(n)
        };
        let sea_sign = side(sea).signum();
        let (mut wet, mut dry) = (0, 0);
        for y in 0..h {
            for x in 0..w {
                let c = frame.pixels()[(y * w + x) as usize];
                let dist = side(Vec2::new(x as f32 + 0.5, y as f32 + 0.5)) * sea_sign;
                if dist > 1.5 && c != sky.pixels()[(y * w + x) as usize] {
                    assert!(
                        water.contains(&c),
                        "shore {shore}: land colour {c:06x} at ({x}, {y}) in the sea"
                    );
                    wet += 1;
                } else if dist < -1.5 {
                    assert!(
                        !water.contains(&c),
                        "shore {shore}: water at ({x}, {y}) on land"
                    );
                    dry += 1;
                }
            }
        }
        assert!(
            wet > 500 && dry > 500,
            "shore {shore}: too little of either ({wet}, {dry})"
        );
    }
}

#[test]
fn deeper_water_is_never_lighter_in_the_palette() {
    for relative_depth in [true, false] {
        let s = Settings {
            relative_depth,
            ..Settings::default()
        };
        let field = ramp(20.0, 3.0);
        let palette = Palette::new(&s, &field);
        let mut last = luminance(palette.water(0.0));
        for i in 1..=2000 {
            let l = luminance(palette.water(i as f32 * 0.05));
            assert!(
                l <= last,
                "water at depth {} is lighter than above it",
                i as f32 * 0.05
            );
            last = l;
        }
    }
}

#[test]
fn deeper_water_is_never_lighter_on_screen() {
    // Everything under water, deeper towards the front.
    let mut field = Heightfield::flat(4, 160.0);
    for y in 0..field.size() {
        for x in 0..field.size() {
            field.set(x, y, -1.0 - 2.0 * y as f32 - 0.1 * x as f32);
        }
    }
    let (w, h) = (300u32, 200u32);
    let s = Settings {
        view: ViewKind::Oblique,
        ..Settings::default()
    };
    let mut frame = Frame::new(w, h).unwrap();
    render_full(&field, &s, &mut frame);
    let view = View::new(
        ViewKind::Oblique,
        field.size(),
        field.extent(),
        0.0,
        Size::new(w, h),
    );
    let mut last = u32::MAX;
    // Sample the centroid of each row's lower-left triangle: a point on a
    // grid line may belong to either neighbour, and neighbours in x differ
    // in depth too (the floor slopes both ways).
    for i in 0..15 {
        let p = view.project(8.0 + 1.0 / 3.0, i as f32 + 2.0 / 3.0, 0.0);
        let c = frame.pixels()[(p.y as u32 * w + p.x as u32) as usize];
        let l = luminance(c);
        assert!(l <= last, "water at row {i} is lighter than behind it");
        last = l;
    }
}

/// The palette of `world` on a small island under a sun `elevation`
/// degrees up, and its shallowest water's luminance.
fn shallow_water_under(world: mountains::settings::World, elevation: f32) -> u32 {
    use mountains::render::hour::SunAt;
    use mountains::render::light::Lighting;
    let field = ramp(7.3, 2.0);
    let s = Settings {
        world,
        ..Settings::default()
    };
    let light = Lighting::at_hour(SunAt {
        elevation,
        azimuth: 60.0,
        afternoon: false,
    });
    luminance(Palette::lit_by(&s, &field, light).water(0.0))
}

/// A world's water takes the light the land does: under a sun two degrees
/// up it is darker than at midday (its colour was the midday's at every
/// hour, and an alpine tarn at dawn shone turquoise out of a dim valley).
/// The temperate world's water keeps its pixels.
#[test]
fn a_worlds_water_is_dimmer_under_a_low_sun() {
    use mountains::settings::World;
    for world in [World::Alpine, World::Winter, World::Tropical, World::Autumn] {
        let (low, high) = (
            shallow_water_under(world, 2.0),
            shallow_water_under(world, 40.0),
        );
        assert!(
            (low as f32) < 0.85 * high as f32,
            "{world:?}: {low} at 2 degrees against {high} at 40"
        );
    }
    let (low, high) = (
        shallow_water_under(World::Temperate, 2.0),
        shallow_water_under(World::Temperate, 40.0),
    );
    assert!(
        (low as f32) > 0.9 * high as f32,
        "temperate: {low} against {high}"
    );
}
