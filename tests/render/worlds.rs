//! The worlds (`world = ...`): each is accepted and draws a picture of its
//! own; a varied world is the world drawn for the seed, the same at every
//! size and at `low_detail`; the temperate world is the picture from
//! before the worlds, pixel for pixel.

use crate::common::golden;
use mountains::quality::facets::{delta_e, lab};
use mountains::quality::image::channels;
use mountains::render::Size;
use mountains::render::{Frame, detail, render_full};
use mountains::settings::{Settings, World, keys, load, worlds};
use mountains::terrain;

/// Every world a person can name.
const NAMED: [World; 6] = [
    World::Temperate,
    World::Alpine,
    World::Winter,
    World::Autumn,
    World::Desert,
    World::Tropical,
];

/// The picture `render` draws of `seed` under `prefs` in a `w` x `h` frame.
fn picture(prefs: &Settings, seed: u64, (w, h): (u32, u32)) -> Frame {
    let chosen = Settings {
        seed: Some(seed),
        ..prefs.clone()
    };
    let settings = detail::for_frame(&chosen, Size::new(w, h));
    let field = terrain::generate(&settings, seed);
    let mut frame = Frame::new(w, h).expect("a frame");
    render_full(&field, &settings, &mut frame);
    frame
}

fn in_world(world: World) -> Settings {
    Settings {
        world,
        ..Settings::default()
    }
}

/// Mean CIE76 dE between two frames of one size.
fn apart(a: &Frame, b: &Frame) -> f32 {
    let n = a.pixels().len() as f32;
    (a.pixels().iter().zip(b.pixels()))
        .map(|(&p, &q)| delta_e(lab(channels(p)), lab(channels(q))))
        .sum::<f32>()
        / n
}

#[test]
fn every_world_is_accepted_by_name_and_varied_is_the_default() {
    assert_eq!(Settings::default().world, World::Varied);
    for name in World::NAMES {
        let mut s = Settings::default();
        load::apply_set(&mut s, keys::WORLD.name, name).expect(name);
        assert_eq!(s.world.name(), *name);
    }
    let mut s = Settings::default();
    let refused = load::apply_set(&mut s, keys::WORLD.name, "moon").unwrap_err();
    assert!(refused.message.contains("alpine"), "{}", refused.message);
}

#[test]
fn each_world_draws_a_picture_of_its_own() {
    for seed in [3, 8] {
        let drawn: Vec<Frame> = NAMED
            .iter()
            .map(|&w| picture(&in_world(w), seed, (192, 108)))
            .collect();
        for (i, a) in drawn.iter().enumerate() {
            for (j, b) in drawn.iter().enumerate().skip(i + 1) {
                let d = apart(a, b);
                assert!(
                    d > 6.0,
                    "seed {seed}: {:?} and {:?} only {d:.1} dE apart",
                    NAMED[i],
                    NAMED[j]
                );
            }
        }
    }
}

#[test]
fn a_key_a_person_sets_wins_over_the_world() {
    let set = Settings {
        height: 3,
        ..in_world(World::Alpine)
    };
    assert_eq!(worlds::drawn(&set, Some(1)).height, 3);
    assert_ne!(worlds::drawn(&in_world(World::Alpine), Some(1)).height, 3);
}

#[test]
fn a_varied_world_is_the_same_at_every_size_and_at_low_detail() {
    let mut seen = std::collections::HashSet::new();
    for seed in 1..=12 {
        let world = worlds::chosen(&Settings::default(), Some(seed));
        assert_ne!(world, World::Varied);
        seen.insert(world.name());
        let named = in_world(world);
        for size in [(96, 54), (192, 108), (384, 216)] {
            for low_detail in [false, true] {
                let varied = Settings {
                    low_detail,
                    ..Settings::default()
                };
                let named = Settings {
                    low_detail,
                    ..named.clone()
                };
                // The temperate coast of the varied draw is lit and framed
                // as its own day (`scene::a_seed_is_one_scene...` holds it
                // one scene at every size); the temperate world named keeps
                // the picture from before the worlds.
                let same = world != World::Temperate;
                assert!(
                    (picture(&varied, seed, size) == picture(&named, seed, size)) == same,
                    "seed {seed} ({world:?}) at {size:?}, low_detail {low_detail}"
                );
            }
        }
    }
    assert!(seen.len() >= 4, "12 seeds drew only {seen:?}");
}

/// The pictures pinned by the build before the worlds (`mountains render
/// --size 160x90 --seed N`; pinned again, after looking, whenever the
/// drawing itself changed: the relief, the steep faces' side views, the
/// far ground's rows kept): `world = "temperate"` draws them unchanged.
/// Seeds whose varied sun is now night (7, for one) are left out: their
/// sky changed with the night, not with the world.
#[test]
fn the_temperate_world_is_the_picture_from_before_the_worlds() {
    for seed in [3, 8, 21] {
        let file = golden::dir().join(format!("world-temperate-seed{seed}.png"));
        let pinned = golden::read_png(&file).expect("a pinned picture");
        let drawn = picture(&in_world(World::Temperate), seed, (160, 90));
        assert!(
            drawn == pinned,
            "seed {seed} differs from {}",
            file.display()
        );
    }
}

/// The seed programs' looks and the other colour modes keep their own
/// pictures: under them "varied" is the temperate world.
#[test]
fn the_looks_and_the_colour_modes_keep_their_pictures() {
    for seed in 1..=6 {
        for extra in ["look=fl3", "color=gray", "color=sonar"] {
            let (k, v) = extra.split_once('=').unwrap();
            let mut varied = Settings::default();
            load::apply_set(&mut varied, k, v).unwrap();
            let temperate = Settings {
                world: World::Temperate,
                ..varied.clone()
            };
            assert!(
                picture(&varied, seed, (96, 54)) == picture(&temperate, seed, (96, 54)),
                "seed {seed}, {extra}"
            );
        }
    }
}

/// A data set records the world its mountain was made in, and is drawn in
/// it again under preferences that leave the world at "varied".
#[test]
fn a_saved_data_set_records_its_world() {
    use mountains::mountain::Mountain;
    use mountains::settings::Detail;
    use mountains::terrain::heightmap;
    let dir = std::env::temp_dir().join(format!("mountains-worlds-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let s = Settings {
        detail: Detail::Level(6),
        ..Settings::default()
    };
    let mut seen = std::collections::HashSet::new();
    for seed in 1..=8 {
        let field = terrain::generate(&s, seed);
        let path = dir.join(format!("{seed}.png"));
        heightmap::save(&path, &field, Some(seed), &s).unwrap();
        let (opened, _) = Mountain::open(&path).unwrap();
        let world = opened.drawn_with(&Settings::default()).world;
        assert_eq!(world, worlds::chosen(&s, Some(seed)), "seed {seed}");
        seen.insert(world.name());
    }
    let _ = std::fs::remove_dir_all(&dir);
    assert!(seen.len() >= 3, "{seen:?}");
}

/// Whatever the world, a slide shows land: the tropical sea and the
/// desert's basin never take the whole view.
#[test]
fn every_varied_slide_shows_land() {
    use mountains::render::classes::{Class, render_classes};
    let (w, h) = (240, 135);
    for seed in 1..=60 {
        let chosen = Settings {
            seed: Some(seed),
            ..Settings::default()
        };
        let s = detail::for_frame(&chosen, Size::new(w, h));
        let field = terrain::generate(&s, seed);
        let mut frame = Frame::new(w, h).unwrap();
        render_classes(&field, &s, &mut frame).unwrap();
        let land = (frame.pixels().iter())
            .filter(|&&p| Class::of(p) == Class::Land)
            .count();
        let share = land as f32 / (w * h) as f32;
        assert!(share >= 0.1, "seed {seed}: land is {share:.3} of the frame");
    }
}

/// The alpine world's camera looks down into its valleys: on at least a
/// third of its slides the lakes in them are seen. A lake is the water
/// of the frame (the renderer's class picture) that the same land without
/// its lakes (`lakes = false`) does not have; seen when it is at least
/// 0.1% of the frame. The vista that looks across the land (the other
/// worlds' camera) saw them on 1 of seeds 1-30.
#[test]
fn the_alpine_camera_sees_the_lakes_in_the_valleys() {
    use mountains::render::classes::{Class, render_classes};
    let (w, h) = (320, 180);
    let water = |s: &Settings, seed: u64| {
        let field = terrain::generate(s, seed);
        let mut frame = Frame::new(w, h).unwrap();
        render_classes(&field, s, &mut frame).unwrap();
        (frame.pixels().iter())
            .map(|&p| Class::of(p) == Class::Water)
            .collect::<Vec<_>>()
    };
    let mut seen = Vec::new();
    for seed in 1..=12 {
        let chosen = Settings {
            seed: Some(seed),
            ..in_world(World::Alpine)
        };
        let s = detail::for_frame(&chosen, mountains::render::Size::new(w, h));
        let dry = Settings {
            lakes: false,
            ..worlds::drawn(&s, Some(seed))
        };
        let (wet, dry) = (water(&s, seed), water(&dry, seed));
        let lakes = wet.iter().zip(&dry).filter(|&(&a, &b)| a && !b).count();
        if lakes * 1000 >= (w * h) as usize {
            seen.push(seed);
        }
    }
    assert!(seen.len() * 3 >= 12, "lakes seen only on seeds {seen:?}");
}

/// Autumn's woods turn by the way a slope faces: two slopes alike but
/// mirrored about the sun's vertical plane (so lit alike) take colours
/// far apart in autumn, and the same colour in the worlds whose ground
/// does not follow facing.
#[test]
fn autumn_colours_its_slopes_by_the_way_they_face() {
    use glam::Vec3;
    use mountains::render::palette::Palette;
    let widest = |world: World, seed: u64| {
        let s = worlds::drawn(
            &Settings {
                seed: Some(seed),
                ..in_world(world)
            },
            Some(seed),
        );
        let field = terrain::generate(&s, seed);
        let palette = Palette::new(&s, &field);
        let sun = palette.light();
        let along = Vec3::new(sun.x, sun.y, 0.0).normalize_or(Vec3::Y);
        let across = Vec3::Z.cross(along);
        let slope = |turn: f32, side: f32| {
            let (sin, cos) = turn.sin_cos();
            (0.4 * (cos * along + side * sin * across) + 0.92 * Vec3::Z).normalize()
        };
        let mut widest = 0;
        for k in 1..=8 {
            let height = field.max() * k as f32 / 20.0;
            for turn in [0.6f32, 1.2, 1.57, 2.0, 2.6] {
                let [a, b] = [1.0, -1.0]
                    .map(|side| palette.land_at_point(height, slope(turn, side), 1.0, 1.0));
                let channel = |c: u32, i: u32| (c >> (8 * i) & 0xff) as i32;
                let apart = (0..3)
                    .map(|i| (channel(a, i) - channel(b, i)).abs())
                    .max()
                    .unwrap();
                widest = widest.max(apart);
            }
        }
        widest
    };
    for seed in [1, 2, 3] {
        let autumn = widest(World::Autumn, seed);
        assert!(
            autumn >= 24,
            "seed {seed}: autumn's facings only {autumn} apart"
        );
        for world in [
            World::Temperate,
            World::Alpine,
            World::Winter,
            World::Desert,
        ] {
            let other = widest(world, seed);
            assert!(other <= 1, "seed {seed}: {world:?}'s facings {other} apart");
        }
    }
}

/// Each world's own cover follows the water: at the same height and on
/// the same slope, the ground where water runs (a stream, wetness 1) is
/// greener than on a dry ridge (0) over the lower land; the temperate
/// world's ground is the same wet or dry (its picture from before).
#[test]
fn wet_ground_is_greener_than_dry_at_the_same_height_and_slope() {
    use glam::Vec3;
    use mountains::render::palette::Palette;
    let greenness = |c: u32| {
        let [r, g, b] = [16, 8, 0].map(|s| (c >> s & 0xff) as f32);
        g - 0.5 * (r + b)
    };
    for world in [World::Alpine, World::Autumn, World::Desert, World::Tropical] {
        for seed in [1, 2, 3] {
            let s = worlds::drawn(&in_world(world), Some(seed));
            let field = terrain::generate(&s, seed);
            let palette = Palette::new(&s, &field);
            let slope = Vec3::new(0.2, 0.1, 0.97).normalize();
            let (mut greener, mut tried) = (0, 0);
            for k in 2..=6 {
                let h = field.max() * k as f32 / 30.0;
                let [dry, wet] =
                    [0.0, 1.0].map(|w| greenness(palette.land_at_wet_point(h, slope, 1.0, 1.0, w)));
                tried += 1;
                greener += usize::from(wet > dry + 4.0);
            }
            assert!(
                greener * 5 >= tried * 4,
                "{world:?} seed {seed}: wet greener at only {greener} of {tried} heights"
            );
        }
    }
    let s = in_world(World::Temperate);
    let field = terrain::generate(&s, 1);
    let palette = Palette::new(&s, &field);
    for k in 1..=10 {
        let h = field.max() * k as f32 / 10.0;
        let n = Vec3::new(0.3, 0.1, 0.95).normalize();
        assert_eq!(
            palette.land_at_wet_point(h, n, 1.0, 1.0, 0.0),
            palette.land_at_wet_point(h, n, 1.0, 1.0, 1.0)
        );
    }
}

/// Nights are not one picture in every world: under `sun = "night"` each
/// pair of worlds' slides of one seed stand apart (their own night skies
/// and a world's moonlit land brighter than the temperate night's), and
/// none is black (its mean lightness L* at least 8).
#[test]
fn the_worlds_nights_differ() {
    for seed in [3, 8] {
        let night = |w: World| {
            let mut s = in_world(w);
            load::apply_set(&mut s, "sun", "night").unwrap();
            picture(&s, seed, (192, 108))
        };
        let drawn: Vec<Frame> = NAMED.iter().map(|&w| night(w)).collect();
        for (i, a) in drawn.iter().enumerate() {
            let l = (a.pixels().iter())
                .map(|&p| lab(channels(p))[0])
                .sum::<f32>()
                / a.pixels().len() as f32;
            assert!(
                l >= 8.0,
                "seed {seed}: {:?}'s night is black (L* {l:.1})",
                NAMED[i]
            );
            for (j, b) in drawn.iter().enumerate().skip(i + 1) {
                let d = apart(a, b);
                assert!(
                    d >= 8.0,
                    "seed {seed}: {:?} and {:?} nights only {d:.1} dE apart",
                    NAMED[i],
                    NAMED[j]
                );
            }
        }
    }
}

/// The desert's low ground lies dry (sand and salt, `cover::dry_basin`):
/// no wind streaks it as they streak water, which drew its basins as
/// golden lakes. A level basin floor (every point as deep) then shows one
/// colour along each row of pixels, but for the air; the temperate sea over
/// the same floor is streaked.
#[test]
fn a_desert_basin_is_not_streaked_as_water_is() {
    use mountains::terrain::Heightfield;
    // The left half a level floor 3 below the sea, the right half rising land.
    let mut field = Heightfield::flat(7, terrain::SQUARE_EXTENT);
    let mid = field.size() / 2;
    for y in 0..field.size() {
        for x in 0..field.size() {
            let land = (x as f32 - mid as f32).max(0.0);
            field.set(x, y, if x < mid { -3.0 } else { 0.5 * land });
        }
    }
    // The spread of lightness along a row, the most of the rows, over the
    // frame's bottom left (the floor near the viewer).
    let (w, h) = (320, 180);
    let streaks = |world: World| {
        let s = Settings {
            world,
            reflections: false,
            ..Settings::default()
        };
        let s = detail::for_frame(&s, Size::new(w, h));
        let mut frame = Frame::new(w, h).expect("a frame");
        render_full(&field, &s, &mut frame);
        let pixels = frame.pixels();
        let spread = |y: u32| {
            let light = (10..80).map(|x| lab(channels(pixels[(y * w + x) as usize]))[0]);
            let (lo, hi) = light.fold((f32::MAX, f32::MIN), |(l, h), v| (l.min(v), h.max(v)));
            hi - lo
        };
        (150..175).map(spread).fold(0.0, f32::max)
    };
    let (desert, temperate) = (streaks(World::Desert), streaks(World::Temperate));
    eprintln!("lightness spread along a row: desert {desert:.2}, temperate {temperate:.2}");
    assert!(
        temperate > 2.0,
        "the sea is not streaked ({temperate:.2}): no test"
    );
    assert!(
        desert < 0.25 * temperate,
        "desert {desert:.2} against {temperate:.2}"
    );
}
