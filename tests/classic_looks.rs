//! The seed programs' looks other than seed 000's (tests/classic_listing.rs
//! holds that one): Mountain Terrain 3.0's facings and water, FL3's Filled
//! mode and pseudo-normal deviations, the essay's turns and flat edges.

use std::collections::{BTreeMap, BTreeSet};

use mountains::render::facings;
use mountains::render::palette::Palette;
use mountains::render::{Frame, render_full};
use mountains::settings::Settings;
use mountains::settings::load::apply_set;
use mountains::terrain;

/// Default settings with `sets` applied as `--set` would.
fn with(sets: &[(&str, &str)]) -> Settings {
    let mut s = Settings::default();
    for (k, v) in sets {
        apply_set(&mut s, k, v).unwrap_or_else(|p| panic!("{p}"));
    }
    s
}

/// Every pixel of a `w` x `h` picture of seed `seed` under `s`, counted.
fn histogram(s: &Settings, seed: u64, w: u32, h: u32) -> BTreeMap<u32, usize> {
    let field = terrain::generate(s, seed);
    let mut frame = Frame::new(w, h).unwrap();
    render_full(&field, s, &mut frame);
    let mut counts = BTreeMap::new();
    for y in 0..h {
        for x in 0..w {
            *counts.entry(frame.get(x, y)).or_default() += 1;
        }
    }
    counts
}

/// The help file's nine darknesses, as grey levels.
fn darknesses() -> BTreeSet<u32> {
    let mut d: BTreeSet<u32> = (0..8)
        .map(|k| facings::darkness(facings::Facing::Towards(k)))
        .collect();
    d.insert(facings::darkness(facings::Facing::Flat));
    d
}

#[test]
fn mountain_terrain_land_is_the_colour_preference_anded_with_a_facings_darkness() {
    for (color, preference) in [
        ("gray", 0x00ff_ffff),
        ("purple", 0x00ff_00ff),
        ("yellow", 0x00ff_ff00),
    ] {
        let s = with(&[
            ("look", "mountain-terrain"),
            ("color", color),
            ("relative_depth", "false"),
        ]);
        let counts = histogram(&s, 7, 480, 270);
        let brushes: BTreeSet<u32> = darknesses().iter().map(|d| preference & d).collect();
        let mut land = BTreeSet::new();
        for (&pixel, &n) in &counts {
            match pixel {
                0 => {}
                facings::PURE_BLUE => {}
                p => {
                    assert!(
                        brushes.contains(&p),
                        "{color}: {p:06x} ({n} pixels) is no facing's brush"
                    );
                    land.insert(p);
                }
            }
        }
        // Most of the nine facings show on a real mountain.
        assert!(
            land.len() >= 6,
            "{color}: {} brushes: {land:06x?}",
            land.len()
        );
        assert!(counts.get(&facings::PURE_BLUE).is_some_and(|&n| n > 1000));
        assert!(counts.get(&0).is_some_and(|&n| n > 1000), "a black window");
    }
}

#[test]
fn mountain_terrain_water_is_pure_blue_darker_over_deeper_ground() {
    let s = with(&[("look", "mountain-terrain"), ("relative_depth", "true")]);
    let field = terrain::generate(&s, 7);
    let palette = Palette::new(&s, &field);
    // Pure blue less the depth, one level a unit, at most 0xbf.
    for (depth, blue) in [
        (0.0, 0xff),
        (0.9, 0xff),
        (12.5, 0xff - 12),
        (190.0, 0xff - 190),
        (1e4, 0x40),
    ] {
        assert_eq!(palette.water(depth), blue, "depth {depth}");
    }
    let counts = histogram(&s, 7, 480, 270);
    let waters: Vec<u32> = counts
        .keys()
        .copied()
        .filter(|&p| p >> 8 == 0 && p != 0)
        .collect();
    assert!(waters.len() > 3, "shades of water: {waters:06x?}");
    // Uniform water without Relative Depth.
    let flat = Palette::new(
        &with(&[("look", "mountain-terrain"), ("relative_depth", "false")]),
        &field,
    );
    assert_eq!(flat.water(50.0), facings::PURE_BLUE);
}
