//! Night: a varied draw makes some slides night, `sun = "night"` asks for
//! one; the frame is dark but never black, the land stands out from the
//! sky, stars show where the sky is clear and the moon glitters on the
//! water. The clock's light darkens from day through twilight into night.

use mountains::render::classes::{Class, render_classes};
use mountains::render::detail::for_frame;
use mountains::render::hour::SunAt;
use mountains::render::light::Lighting;
use mountains::render::palette::Palette;
use mountains::render::{Frame, render_full};
use mountains::render::{Size, colour};
use mountains::settings::{Clouds, ColorMode, Detail, Look, Settings, Sun};
use mountains::terrain::{self, Heightfield};

fn luma(c: u32) -> f32 {
    colour::luminance(colour::unpack(c)) * 255.0
}

fn night(w: u32, h: u32, clouds: f32) -> Settings {
    let s = Settings {
        sun: Sun::Night,
        clouds: Clouds::Amount(clouds),
        ..Settings::default()
    };
    for_frame(&s, Size::new(w, h))
}

fn drawn(field: &Heightfield, s: &Settings, w: u32, h: u32) -> (Frame, Frame) {
    let mut frame = Frame::new(w, h).unwrap();
    render_full(field, s, &mut frame);
    let mut classes = Frame::new(w, h).unwrap();
    render_classes(field, s, &mut classes).unwrap();
    (frame, classes)
}

#[test]
fn night_is_part_of_the_varied_draw_in_our_look_only() {
    let s = Settings {
        detail: Detail::Level(4),
        ..Settings::default()
    };
    let gray = Settings {
        color: ColorMode::Gray,
        ..s.clone()
    };
    let classic = Settings {
        look: Look::MountainTerrain,
        ..s.clone()
    };
    let mut nights = 0;
    for seed in 1..=120u64 {
        let field = terrain::generate(&s, seed);
        let light = Palette::lighting_for(&s, &field);
        if light.night > 0.0 {
            nights += 1;
        }
        // The colour filters and the seed programs' looks keep their pictures.
        assert_eq!(
            Palette::lighting_for(&gray, &field).night,
            0.0,
            "seed {seed}"
        );
        assert_eq!(
            Palette::lighting_for(&classic, &field).night,
            0.0,
            "seed {seed}"
        );
    }
    assert!(nights * 20 >= 120, "{nights} nights in 120 slides");
    assert!(nights * 4 <= 120, "{nights} nights in 120 slides");
    let asked = Lighting::new(Sun::Night, &terrain::generate(&s, 1));
    assert_eq!(asked.night, 1.0);
}

/// Of the varied draw's full nights, some see the moon rise ahead, low
/// in the view (its disc and glow in the sky, `moonrise.rs`), and some
/// keep it high to the side; the temperate world named keeps its nights
/// (all of them high moons). A rising moon's slide draws its disc: the
/// sky's brightest pixel is the moon's pale white.
#[test]
fn some_varied_nights_see_the_moon_rise_and_the_temperate_world_none() {
    let s = Settings {
        detail: Detail::Level(6),
        ..Settings::default()
    };
    let temperate = Settings {
        world: mountains::settings::World::Temperate,
        ..s.clone()
    };
    let (mut rising, mut high) = (Vec::new(), 0);
    for seed in 1..=400u64 {
        let field = terrain::generate(&s, seed);
        let drawn = mountains::settings::worlds::drawn(&s, Some(seed));
        let light = Palette::lighting_for(&drawn, &field);
        if light.night >= 1.0 {
            match light.sun.z < 0.1 {
                true => rising.push(seed),
                false => high += 1,
            }
        }
        let named = Palette::lighting_for(&temperate, &field);
        assert!(
            named.night < 1.0 || named.sun.z > 0.1,
            "seed {seed}: a rising moon in the temperate world named"
        );
    }
    assert!(
        rising.len() >= 2 && high >= 2,
        "{rising:?} rising, {high} high"
    );
    let moon_in_sight = rising.iter().any(|&seed| {
        let at = for_frame(
            &Settings {
                clouds: Clouds::Amount(0.0),
                ..s.clone()
            },
            Size::new(480, 270),
        );
        let field = terrain::generate(&at, seed);
        let (frame, classes) = drawn(&field, &at, 480, 270);
        (frame.pixels().iter().zip(classes.pixels()))
            .filter(|&(_, &c)| Class::of(c) == Class::Sky)
            .any(|(&p, _)| colour::unpack(p).iter().all(|&v| v > 0.85))
    });
    assert!(
        moon_in_sight,
        "no rising moon's disc in sight on {rising:?}"
    );
}

/// Dark but never black, and the land can be told from the sky: along
/// the skyline the land's pixels just below differ from the sky's just
/// above, column by column.
#[test]
fn a_night_frame_is_dark_not_black_and_its_land_stands_out_from_its_sky() {
    let (w, h) = (480, 270);
    for seed in [1u64, 2, 3, 4] {
        let s = night(w, h, 0.3);
        let field = terrain::generate(&s, seed);
        let (frame, classes) = drawn(&field, &s, w, h);
        let px = frame.pixels();
        let mean = px.iter().map(|&c| luma(c)).sum::<f32>() / px.len() as f32;
        assert!(
            (8.0..70.0).contains(&mean),
            "seed {seed}: mean level {mean:.1}"
        );
        let black = px.iter().filter(|&&c| luma(c) < 3.0).count();
        assert!(black * 100 < px.len(), "seed {seed}: {black} black pixels");
        let (mut gap, mut columns) = (0.0, 0);
        for x in 0..w {
            let class = |y: u32| Class::of(classes.pixels()[(y * w + x) as usize]);
            let Some(top) = (0..h).find(|&y| class(y) == Class::Land) else {
                continue;
            };
            if top < 6 || top + 6 > h || (top - 6..top).any(|y| class(y) != Class::Sky) {
                continue;
            }
            let at = |y: u32| luma(px[(y * w + x) as usize]);
            let sky = (top - 6..top - 2).map(at).sum::<f32>() / 4.0;
            let land = (top + 2..top + 6).map(at).sum::<f32>() / 4.0;
            gap += (sky - land).abs();
            columns += 1;
        }
        assert!(
            columns > w / 4,
            "seed {seed}: a skyline in {columns} columns"
        );
        let gap = gap / columns as f32;
        assert!(
            gap >= 6.0,
            "seed {seed}: land and sky {gap:.1} levels apart"
        );
    }
}

/// An overcast night is a night: its clouds, lit by the moon, are about
/// two stops or more under an overcast midday's (as the night's light is
/// under the day's) and darker than half-way to white, yet lighter than a
/// clear night's sky. Lit at 0.6 of the moon's light with the horizon's
/// glow added, an overcast night's sky was 0.3-1.8 stops under its day's
/// and 119-131 levels: seed 1010's read as a grey-blue day with dark gaps.
#[test]
fn an_overcast_night_sky_is_two_stops_under_an_overcast_day() {
    let (w, h) = (480, 270);
    // Linear luminance of the sky pixels.
    let sky = |s: &Settings, field: &Heightfield| {
        let (frame, classes) = drawn(field, s, w, h);
        let skies = frame.pixels().iter().zip(classes.pixels());
        let linear = |c: u32| (luma(c) / 255.0).powf(2.2);
        let lit: Vec<f32> = skies
            .filter(|(_, k)| Class::of(**k) == Class::Sky)
            .map(|(&c, _)| linear(c))
            .collect();
        lit.iter().sum::<f32>() / lit.len().max(1) as f32
    };
    for seed in [1u64, 2, 3, 5, 8, 1010, 1014] {
        let night_sky = night(w, h, 1.0);
        let field = terrain::generate(&night_sky, seed);
        let day = Settings {
            sun: Sun::Midday,
            ..night_sky.clone()
        };
        let (overcast, clear) = (sky(&night_sky, &field), sky(&night(w, h, 0.0), &field));
        let by_day = sky(&day, &field);
        let stops = (by_day / overcast).log2();
        let levels = 255.0 * overcast.powf(1.0 / 2.2);
        assert!(
            (1.4..4.0).contains(&stops) && levels < 100.0,
            "seed {seed}: an overcast night {stops:.2} stops under the day, {levels:.1} levels"
        );
        assert!(
            overcast > 1.5 * clear,
            "seed {seed}: overcast {overcast:.4}, clear {clear:.4}"
        );
    }
}

/// Points of light in a clear sky, far fewer under an overcast one.
#[test]
fn stars_show_where_the_sky_is_clear() {
    let (w, h) = (960, 540);
    let count = |clouds: f32| {
        let s = night(w, h, clouds);
        let field = terrain::generate(&s, 3);
        let (frame, classes) = drawn(&field, &s, w, h);
        let (px, cls) = (frame.pixels(), classes.pixels());
        let mut stars = 0;
        for y in 1..h - 1 {
            for x in 1..w - 1 {
                let i = (y * w + x) as usize;
                let around = [i - 1, i + 1, i - w as usize, i + w as usize];
                if around
                    .iter()
                    .chain([&i])
                    .all(|&j| Class::of(cls[j]) == Class::Sky)
                    && around.iter().all(|&j| luma(px[i]) >= luma(px[j]) + 10.0)
                {
                    stars += 1;
                }
            }
        }
        stars
    };
    let (clear, overcast) = (count(0.0), count(1.0));
    assert!(clear >= 40, "{clear} stars in a clear sky");
    assert!(
        overcast * 4 <= clear,
        "{overcast} stars overcast, {clear} clear"
    );
}

/// The moon's glitter: water the moon's light falls on off the ripples is
/// brighter than any water without the reflections, and than the sky's
/// light there.
#[test]
fn the_moon_glitters_on_the_water() {
    let (w, h) = (960, 540);
    let mut glints = 0;
    for seed in [1u64, 2, 3, 4, 5, 6] {
        let s = night(w, h, 0.0);
        let field = terrain::generate(&s, seed);
        let (frame, classes) = drawn(&field, &s, w, h);
        let plain = Settings {
            reflections: false,
            ..s.clone()
        };
        let (flat, _) = drawn(&field, &plain, w, h);
        let water = |f: &Frame| -> Vec<f32> {
            let (px, cls) = (f.pixels(), classes.pixels());
            (0..px.len())
                .filter(|&i| Class::of(cls[i]) == Class::Water)
                .map(|i| luma(px[i]))
                .collect()
        };
        let brightest_plain = water(&flat).into_iter().fold(0.0, f32::max);
        glints += water(&frame)
            .into_iter()
            .filter(|&l| l > brightest_plain + 40.0)
            .count();
    }
    assert!(glints >= 30, "{glints} glinting water pixels in six nights");
}

fn at(elevation: f32, afternoon: bool) -> Lighting {
    Lighting::at_hour(SunAt {
        elevation,
        azimuth: 120.0,
        afternoon,
    })
}

#[test]
fn the_clock_light_darkens_through_twilight_into_night() {
    let brightness = |l: &Lighting| l.zenith.iter().sum::<f32>();
    let hours = [40.0, 10.0, 0.0, -4.0, -8.0, -12.0, -30.0].map(|e| at(e, true));
    for pair in hours.windows(2) {
        assert!(brightness(&pair[1]) <= brightness(&pair[0]) + 1e-6);
        assert!(pair[1].night >= pair[0].night);
    }
    assert_eq!(hours[0].night, 0.0);
    assert_eq!(hours[6].night, 1.0);
    assert!(hours[0].sun.z > hours[1].sun.z);
    let (am, pm) = (at(8.0, false), at(8.0, true));
    assert_eq!(am.sun, pm.sun);
    assert_ne!(am.direct, pm.direct, "dawn and dusk in their own colours");
}
