//! Palette: Lambert floor, natural zones, filters, water depth, wire modes.

use glam::Vec3;
use mountains::render::palette::Palette;
use mountains::settings::{ColorMode, Settings, Sun};
use mountains::terrain::Heightfield;

const FILTERS: [ColorMode; 7] = [
    ColorMode::Gray,
    ColorMode::Red,
    ColorMode::Green,
    ColorMode::Blue,
    ColorMode::Yellow,
    ColorMode::Cyan,
    ColorMode::Purple,
];

/// A pyramid from -50 (corners) to 100 (centre) on a 65-point grid.
fn pyramid() -> Heightfield {
    let mut f = Heightfield::flat(6, 64.0);
    for y in 0..65 {
        for x in 0..65 {
            let d = (x as f32 - 32.0).abs().max((y as f32 - 32.0).abs()) / 32.0;
            f.set(x, y, 100.0 - 150.0 * d);
        }
    }
    f
}

/// Seed 000's palette under its own light (`sun = "classic"`); the other
/// suns are tested in tests/colour_light.rs.
fn palette(color: ColorMode, height: u32, relative_depth: bool) -> Palette {
    let settings = Settings {
        color,
        height,
        relative_depth,
        sun: Sun::Classic,
        ..Settings::default()
    };
    Palette::new(&settings, &pyramid())
}

fn rgb(c: u32) -> [i32; 3] {
    [
        (c >> 16) as i32 & 0xff,
        (c >> 8) as i32 & 0xff,
        c as i32 & 0xff,
    ]
}

/// A normal with the same steepness as the light but facing away from it.
fn away(light: Vec3) -> Vec3 {
    Vec3::new(-light.x, -light.y, light.z)
}

fn heights() -> impl Iterator<Item = f32> {
    (0..=100).map(|i| i as f32)
}

/// Seed 000's listing: brightness `0.5 + 0.5 cos`, below half on faces
/// turned away from the light, 0 on one turned fully away.
#[test]
fn face_turned_away_follows_the_listings_cosine() {
    for mode in [
        ColorMode::Natural,
        ColorMode::Gray,
        ColorMode::Red,
        ColorMode::Cyan,
    ] {
        let p = palette(mode, 5, true);
        let l = p.light();
        let cos = l.dot(away(l));
        assert!(cos < -0.3, "test needs a light well below 45 degrees");
        for h in heights() {
            let lit = rgb(p.land(h, l, 1.0));
            let dim = rgb(p.land(h, away(l), 1.0));
            for ch in 0..3 {
                let want = lit[ch] as f32 * (0.5 + 0.5 * cos);
                assert!(
                    (dim[ch] as f32 - want).abs() <= 2.0,
                    "{mode:?} h {h}: {lit:?} vs {dim:?}, want {want} in channel {ch}"
                );
            }
            assert!(dim.iter().sum::<i32>() > 0, "{mode:?} h {h}: black face");
            assert_eq!(rgb(p.land(h, -l, 1.0)), [0; 3], "{mode:?} h {h}");
        }
    }
}

/// A cast shadow takes away what the light adds: a lit face in shadow is
/// half as bright, one turned away keeps its own darkness.
#[test]
fn cast_shadow_leaves_half_and_faces_turned_away_alone() {
    let p = palette(ColorMode::Natural, 5, true);
    let l = p.light();
    for h in heights() {
        let (lit, shaded) = (rgb(p.land(h, l, 1.0)), rgb(p.land(h, l, 0.0)));
        for ch in 0..3 {
            assert!(
                (2 * shaded[ch] - lit[ch]).abs() <= 2,
                "h {h}: {lit:?} {shaded:?}"
            );
        }
        assert_eq!(p.land(h, away(l), 0.0), p.land(h, away(l), 1.0), "h {h}");
        let half = rgb(p.land(h, l, 0.5));
        let (full, none) = (rgb(p.land(h, l, 1.0)), rgb(p.land(h, l, 0.0)));
        for ch in 0..3 {
            assert!(none[ch] <= half[ch] && half[ch] <= full[ch]);
        }
    }
}

#[test]
fn brightness_grows_with_the_cosine() {
    let p = palette(ColorMode::Gray, 5, true);
    let l = p.light();
    let mut last = -1;
    for i in 0..=20 {
        // Rotate the normal from facing away towards the light, same steepness.
        let t = i as f32 / 20.0;
        let n = (away(l) * (1.0 - t) + l * t).normalize();
        let n = Vec3::new(n.x, n.y, l.z).normalize();
        let g = rgb(p.land(50.0, n, 1.0))[1];
        assert!(g >= last, "step {i}: {g} < {last}");
        last = g;
    }
}

#[test]
fn deeper_water_is_never_lighter_and_stays_blue() {
    for relative in [true, false] {
        let p = palette(ColorMode::Natural, 5, relative);
        let mut last = rgb(p.water(0.0));
        for i in 0..=400 {
            let c = rgb(p.water(i as f32 * 0.25)); // 0 to twice the deepest point
            assert!(c[2] > c[0] && c[2] > c[1], "depth {i}: {c:?} is not blue");
            for ch in 0..3 {
                assert!(c[ch] <= last[ch], "depth {i}: {c:?} lighter than {last:?}");
            }
            last = c;
        }
        let (shore, deep) = (p.water(0.0), p.water(50.0));
        if relative {
            assert!(
                rgb(deep)[2] + 40 < rgb(shore)[2],
                "relative depth must darken"
            );
        } else {
            assert_eq!(shore, deep, "relative depth off is one blue");
        }
    }
}

#[test]
fn bad_inputs_give_colours_not_panics() {
    let p = palette(ColorMode::Natural, 5, true);
    for v in [f32::NAN, f32::INFINITY, f32::NEG_INFINITY, -1e30, 1e30] {
        p.land(v, Vec3::Z, 1.0);
        p.land(50.0, Vec3::splat(v), v);
        p.water(v);
        p.skirt(Vec3::splat(v));
    }
    let mut weird = Heightfield::flat(4, 0.0);
    for settings_height in [0, 1, 10, 99] {
        let settings = Settings {
            height: settings_height,
            ..Settings::default()
        };
        Palette::new(&settings, &weird).land(0.0, Vec3::Z, 1.0);
        weird.heights_mut().fill(f32::NAN);
        Palette::new(&settings, &weird).water(1.0);
        weird.heights_mut().fill(-5.0);
        Palette::new(&settings, &weird).land(1.0, Vec3::Z, 1.0);
    }
}

fn in_family(mode: ColorMode, [r, g, b]: [i32; 3]) -> bool {
    match mode {
        ColorMode::Gray => r == g && g == b,
        ColorMode::Red => r >= g && r >= b,
        ColorMode::Green => g >= r && g >= b,
        ColorMode::Blue => b >= r && b >= g,
        ColorMode::Yellow => r >= b && g >= b,
        ColorMode::Cyan => g >= r && b >= r,
        ColorMode::Purple => r >= g && b >= g,
        _ => unreachable!(),
    }
}

#[test]
fn each_filter_keeps_its_hue_family() {
    for mode in FILTERS {
        let p = palette(mode, 10, true);
        let normals = [
            Vec3::Z,
            p.light(),
            away(p.light()),
            Vec3::new(0.6, 0.0, 0.8),
        ];
        let mut colours = vec![p.sky().0, p.sky().1];
        for h in heights() {
            for n in normals {
                colours.push(p.land(h * 1.2, n, 1.0));
                colours.push(p.land(h, n, 0.3));
                colours.push(p.skirt(n));
            }
            colours.push(p.water(h * 0.5));
        }
        for c in colours {
            assert!(in_family(mode, rgb(c)), "{mode:?}: {:06x}", c);
        }
    }
}

#[test]
fn filters_keep_the_shading() {
    for mode in FILTERS {
        let p = palette(mode, 5, true);
        let bright = rgb(p.land(20.0, p.light(), 1.0)).iter().sum::<i32>();
        let dim = rgb(p.land(20.0, away(p.light()), 1.0)).iter().sum::<i32>();
        assert!(bright > dim + 20, "{mode:?}: {bright} vs {dim}");
    }
}

/// How many of 100 heights from 0 to the peak come out as snow in full sun.
fn snowy_heights(height: u32) -> usize {
    let p = palette(ColorMode::Natural, height, true);
    heights()
        .filter(|&h| {
            let [r, g, b] = rgb(p.land(h, p.light(), 1.0));
            r.min(g).min(b) > 215
        })
        .count()
}

#[test]
fn higher_height_setting_gives_more_snow() {
    let counts: Vec<usize> = (1..=10).map(snowy_heights).collect();
    assert_eq!(counts[0], 0, "height 1 has no snow: {counts:?}");
    assert!(
        counts[9] >= 25,
        "height 10 snows on the upper peaks: {counts:?}"
    );
    for w in counts.windows(2) {
        assert!(w[1] >= w[0], "more height, less snow: {counts:?}");
    }
    assert!(counts[9] > counts[4] && counts[4] > counts[1], "{counts:?}");
}

#[test]
fn lowlands_are_green_and_water_blue() {
    let p = palette(ColorMode::Natural, 5, true);
    for h in [10.0, 20.0, 30.0, 40.0] {
        let [r, g, b] = rgb(p.land(h, Vec3::Z, 1.0));
        assert!(g > r && g > b, "h {h}: {r},{g},{b}");
    }
    let [r, g, b] = rgb(p.water(10.0));
    assert!(b > r && b > g);
}

#[test]
fn land_colours_vary_subtly_within_a_zone() {
    let p = palette(ColorMode::Natural, 5, true);
    let mut seen: Vec<u32> = (0..200)
        .map(|i| p.land(20.0 + i as f32 * 0.05, Vec3::Z, 1.0))
        .collect();
    seen.sort_unstable();
    seen.dedup();
    assert!(seen.len() >= 5, "flat band: {} colours", seen.len());
    for c in &seen {
        let [r, g, b] = rgb(*c);
        assert!(g > r && g > b, "jitter left the green zone: {c:06x}");
    }
}

#[test]
fn mono_gives_greys_that_use_the_whole_range() {
    let p = palette(ColorMode::Mono, 10, true);
    let mut lo = 255;
    let mut hi = 0;
    for h in heights() {
        for n in [p.light(), away(p.light()), Vec3::Z] {
            for c in [p.land(h, n, 1.0), p.water(h * 0.5), p.skirt(n)] {
                let [r, g, b] = rgb(c);
                assert!(r == g && g == b, "{c:06x} is not grey");
                lo = lo.min(g);
                hi = hi.max(g);
            }
        }
    }
    assert!(lo < 40 && hi > 230, "grey range {lo}..{hi}");
}

#[test]
fn wire_modes_fill_black_and_outline_in_colour() {
    for mode in [ColorMode::Sonar, ColorMode::Outline] {
        let p = palette(mode, 5, true);
        assert_eq!(p.land(50.0, Vec3::Z, 1.0), 0);
        assert_eq!(p.water(5.0), 0);
        assert_eq!(p.sky(), (0, 0));
    }
    let sonar = palette(ColorMode::Sonar, 5, true);
    assert_eq!(sonar.outline_land(), 0xffffff);
    assert_eq!(sonar.outline_water(), 0xffffff);
    let outline = palette(ColorMode::Outline, 5, true);
    let [r, g, b] = rgb(outline.outline_land());
    assert!(g > r && g > b);
    let [r, g, b] = rgb(outline.outline_water());
    assert!(b > r && b > g);
}

#[test]
fn light_is_a_unit_vector_from_the_back_right_28_degrees_up() {
    // Seed 000's listing, worked through (docs/classics.md; the listing
    // itself is re-implemented in tests/render/classic_listing.rs).
    let l = palette(ColorMode::Natural, 5, true).light();
    assert!((l.length() - 1.0).abs() < 1e-5);
    assert!(l.x > 0.0 && l.y > 0.0, "{l}");
    let up = l.z.asin().to_degrees();
    assert!((27.0..29.0).contains(&up), "{l}: {up} degrees up");
}
