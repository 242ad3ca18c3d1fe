//! One seed, one scene: the light, the sky, the sea and the framing of a
//! mountain are the same at every frame size and with `low_detail`; only
//! the grid (picked per frame by `detail = "auto"`) changes.

use mountains::render::Size;
use mountains::render::detail::for_frame;
use mountains::render::facts::SceneFacts;
use mountains::render::palette::Palette;
use mountains::settings::{Settings, Sun, ViewKind, World};
use mountains::terrain::{self, Heightfield, heightmap};

/// The frames a seed is held against: three sizes, and low detail.
const FRAMES: [(u32, u32, bool); 4] = [
    (1920, 1080, false),
    (960, 540, false),
    (3840, 2160, false),
    (1920, 1080, true),
];

/// `settings` for a frame, its auto detail resolved as the saver does.
fn fitted(settings: &Settings, (w, h, low_detail): (u32, u32, bool)) -> Settings {
    let s = Settings {
        low_detail,
        ..settings.clone()
    };
    for_frame(&s, Size::new(w, h))
}

/// The mountain of `seed` drawn for a frame, and its scene.
fn scene(settings: &Settings, seed: u64, frame: (u32, u32, bool)) -> (Heightfield, SceneFacts) {
    let s = fitted(settings, frame);
    let field = terrain::generate(&s, seed);
    let facts = SceneFacts::of(&field, &s, Size::new(frame.0, frame.1));
    (field, facts)
}

/// Where the back edge, the near edge and the land in between appear, as
/// fractions of the frame: the camera, its pitch and its focal length.
const MARKS: [(f32, f32, f32); 6] = [
    (0.5, 0.0, 0.0),
    (0.5, 1.0, 0.0),
    (0.0, 0.0, 0.0),
    (1.0, 0.0, 0.0),
    (0.3, 0.6, 0.0),
    (0.7, 0.4, 40.0),
];

/// Framing differences up to this, in fractions of the frame, are rounding
/// (a hundredth of a pixel at 1080p).
const FRAMING: f32 = 1e-5;

/// Differences between two scenes of one seed, or none.
fn differences(a: &SceneFacts, b: &SceneFacts) -> Vec<String> {
    let mut out = Vec::new();
    let (la, lb) = (&a.lighting, &b.lighting);
    if (la.sun - lb.sun).length() > 1e-6 {
        out.push(format!("sun {:?} vs {:?}", la.sun, lb.sun));
    }
    let colours =
        |l: &mountains::render::light::Lighting| [l.direct, l.ambient, l.zenith, l.horizon];
    if colours(la) != colours(lb) {
        out.push(format!(
            "light colours {:?} vs {:?}",
            colours(la),
            colours(lb)
        ));
    }
    if a.sky != b.sky {
        out.push(format!("sky {:06x?} vs {:06x?}", a.sky, b.sky));
    }
    if a.has_weather() != b.has_weather() {
        out.push("clouds or glow in one sky only".into());
    }
    // The clouds and the glow: the same colour at the same place of the
    // frame, to a level of rounding.
    for k in 0..400 {
        let (x, y) = ((k * 37 % 400) as f32 / 400.0, (k * 91 % 397) as f32 / 397.0);
        let (ca, cb) = (a.sky_at(x, y), b.sky_at(x, y));
        let off = [16, 8, 0]
            .map(|s| ((ca >> s) & 0xff).abs_diff((cb >> s) & 0xff))
            .into_iter()
            .max()
            .unwrap_or(0);
        if off > 2 {
            out.push(format!("sky at ({x}, {y}): {ca:06x} vs {cb:06x}"));
            break;
        }
    }
    match (&a.ripples, &b.ripples) {
        (Some(ra), Some(rb)) => {
            if ra.seed != rb.seed {
                out.push(format!("sea drawn from {:x} vs {:x}", ra.seed, rb.seed));
            }
            let worst = (0..400)
                .map(|k| {
                    let (x, y) = ((k * 37 % 400) as f32 / 400.0, (k * 91 % 397) as f32 / 397.0);
                    (ra.at(x, y) - rb.at(x, y)).abs()
                })
                .fold(0.0, f32::max);
            if worst > 1e-3 {
                out.push(format!("ripples differ by {worst} at one place"));
            }
        }
        (None, None) => {}
        _ => out.push("a sea with wind and one without".into()),
    }
    for (x, y, z) in MARKS {
        let (pa, pb) = (a.place(x, y, z), b.place(x, y, z));
        let off = (pa - pb).abs().max_element();
        if off > FRAMING || off.is_nan() {
            out.push(format!("({x}, {y}, {z}) at {pa} vs {pb}"));
        }
    }
    out
}

/// The seeds the issue names (2 changed with `low_detail`, 3, 4 and 8 were
/// framed differently, 9 had three times of day) and a few more (11 a
/// temperate coast of the varied draw, its day and camera drawn).
#[test]
fn a_seed_is_one_scene_at_three_sizes_and_with_low_detail() {
    let s = Settings::default();
    let mut wrong = Vec::new();
    let mut weathered = 0;
    for seed in [2u64, 3, 4, 8, 9, 11, 21] {
        let (reference, base) = scene(&s, seed, FRAMES[0]);
        weathered += usize::from(base.has_weather());
        for frame in &FRAMES[1..] {
            let (field, facts) = scene(&s, seed, *frame);
            assert!(
                field.size() != reference.size(),
                "seed {seed} {frame:?}: the same grid as at 1920x1080 proves nothing"
            );
            for d in differences(&base, &facts) {
                wrong.push(format!("seed {seed} {frame:?}: {d}"));
            }
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
    assert!(
        weathered >= 2,
        "clouds on {weathered} of the seeds: too few to judge"
    );
}

/// A rotated view of a seed is still that seed's scene: the light.
#[test]
fn turning_the_mountain_keeps_its_time_of_day() {
    let s = fitted(&Settings::default(), (480, 270, false));
    let field = terrain::generate(&s, 9);
    let light = |rotation: u32| {
        let turned = Settings {
            rotation,
            ..s.clone()
        };
        SceneFacts::of(&field, &turned, Size::new(480, 270)).lighting
    };
    let (a, b) = (light(0), light(90));
    assert_eq!((a.sun, a.horizon), (b.sun, b.horizon));
}

/// Over 40 seeds, the time of day and the sea's pattern agree at every
/// frame size and with low detail, and they still vary from seed to seed:
/// the temperate world named by its five times of day (the slide show
/// from before the worlds), the varied worlds by hours of their own
/// drawing (the temperate coast of the varied draw's among them).
#[test]
fn forty_seeds_keep_their_time_of_day_and_sea_at_every_size() {
    for (world, least, most) in [(World::Temperate, 5, 5), (World::Varied, 25, 40)] {
        let s = Settings {
            // The shadows take no part in the light or the sea.
            shadows: false,
            world,
            ..Settings::default()
        };
        let (times, seas) = forty_seeds_at_every_size(&s);
        let kinds = |v: Vec<String>| {
            v.into_iter()
                .collect::<std::collections::BTreeSet<_>>()
                .len()
        };
        let times = kinds(times.iter().map(|t| format!("{t:?}")).collect());
        assert!(
            (least..=most).contains(&times),
            "{world:?}: {times} times of day over 40 seeds, not {least}..={most} \
             (morning, midday, evening, sunset, night; or a world's own hours)"
        );
        // A desert's dry basin has no sea to streak (`cover::dry_basin`).
        let streaked: Vec<_> = seas.iter().flatten().collect();
        let patterns = kinds(streaked.iter().map(|t| format!("{t:?}")).collect());
        assert!(
            streaked.len() >= 30 && patterns + 1 >= streaked.len(),
            "{world:?}: 40 seeds, {} with a sea, {patterns} patterns",
            streaked.len()
        );
    }
}

/// The time of day (the sky's horizon colour) and the sea's pattern of
/// seeds 1-40 under `s`, checked to be the same at every frame size and
/// with low detail.
fn forty_seeds_at_every_size(s: &Settings) -> (Vec<[f32; 3]>, Vec<Option<u64>>) {
    let mut wrong = Vec::new();
    let mut times = Vec::new();
    let mut seas = Vec::new();
    for seed in 1..=40u64 {
        let draws: Vec<_> = FRAMES
            .iter()
            .map(|&frame| {
                let fs = fitted(s, frame);
                let field = terrain::generate(&fs, seed);
                let light = Palette::lighting_for(&fs, &field);
                let sea = SceneFacts::of(&field, &fs, Size::new(frame.0, frame.1))
                    .ripples
                    .map(|r| r.seed);
                (light.sun, light.horizon, sea)
            })
            .collect();
        for (frame, d) in FRAMES.iter().zip(&draws).skip(1) {
            if *d != draws[0] {
                wrong.push(format!("seed {seed} {frame:?}: {d:?} vs {:?}", draws[0]));
            }
        }
        times.push(draws[0].1);
        seas.push(draws[0].2);
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
    (times, seas)
}

/// A saved mountain opened again is its seed's scene; a data set without a
/// seed still gets a varied light of its own, the same every time.
#[test]
fn a_saved_mountain_keeps_its_seeds_light_and_a_foreign_one_its_own() {
    let s = fitted(&Settings::default(), (480, 270, false));
    let made = terrain::generate(&s, 9);
    let dir = std::env::temp_dir().join(format!("mountains-scene-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("nine.png");
    heightmap::save(&path, &made, Some(9), &s).unwrap();
    let opened = heightmap::load(&path).unwrap().field;
    let _ = std::fs::remove_dir_all(&dir);
    let varied = |f: &Heightfield| {
        let l = mountains::render::light::Lighting::new(Sun::Varied, f);
        (l.sun, l.horizon)
    };
    assert_eq!(varied(&opened), varied(&made));
    let mut foreign = made.clone();
    foreign.set_seed(None);
    assert_eq!(varied(&foreign), varied(&foreign.clone()));
    let light = |seed: u64| {
        let mut f = terrain::generate(&s, seed);
        f.set_seed(None);
        varied(&f).1
    };
    let mut horizons: Vec<_> = (1..=12u64).map(light).collect();
    horizons.sort_by(|a, b| a.partial_cmp(b).unwrap());
    horizons.dedup();
    assert!(horizons.len() >= 2, "data sets without a seed all alike");
}

/// The sight line a measurement traces through a frame point passes
/// through the land placed there (the reflections' figure traces its own
/// mirrored lines from it), and the oblique view has none.
#[test]
fn the_sight_line_through_a_placed_point_meets_it() {
    let settings = Settings::default();
    for view in [ViewKind::Vista, ViewKind::Perspective] {
        let settings = Settings {
            view,
            ..settings.clone()
        };
        placed_points_on_their_sight_lines(&settings);
    }
    let oblique = Settings {
        view: ViewKind::Oblique,
        ..settings
    };
    let (_, facts) = scene(&oblique, 3, FRAMES[0]);
    assert!(facts.sight_line(0.5, 0.5).is_none());
}

/// [`MARKS`] of seed 3 in a 1080p frame drawn with `settings` lie on the
/// sight lines through the places the facts give them.
fn placed_points_on_their_sight_lines(settings: &Settings) {
    let (field, facts) = scene(settings, 3, FRAMES[0]);
    let cells = (field.size() - 1) as f32;
    for (x, y, z) in MARKS {
        let at = facts.place(x, y, z);
        let (eye, sight) = facts.sight_line(at.x, at.y).expect("the vista has an eye");
        let point = glam::Vec3::new(x * cells * facts.cell(), y * cells * facts.cell(), z);
        // The sine of the angle between (its cosine is too near 1 in f32):
        // a pixel of the 1080p vista spans about 3e-4 of a radian, so at
        // most a fifth of one off.
        let off = (point - eye).normalize().cross(sight).length();
        let view = settings.view;
        assert!(
            off < 7e-5,
            "{view:?} ({x}, {y}, {z}): {off} rad off the point"
        );
    }
}

/// The field the measurements trace over is the one drawn: turned with
/// the mountain, coarsened where Sonar needs a legible grid, the field
/// itself otherwise.
#[test]
fn the_drawn_field_is_the_field_as_the_frame_lays_it_out() {
    use mountains::render::facts::drawn_field;
    use mountains::settings::{ColorMode, Detail};
    let settings = Settings {
        detail: Detail::Level(6),
        ..Settings::default()
    };
    let field = terrain::generate(&settings, 3);
    let n = field.size();
    let same = drawn_field(&field, &settings, Size::new(640, 360));
    assert_eq!(same.size(), n);
    assert_eq!(same.row(17), field.row(17));
    // A quarter turn brings the old right edge to the back.
    let turned = Settings {
        rotation: 90,
        ..settings.clone()
    };
    let drawn = drawn_field(&field, &turned, Size::new(640, 360));
    for (x, y) in [(0, 0), (5, 40), (63, 2), (30, 64)] {
        assert_eq!(drawn.get(x, y), field.get(n - 1 - y, x), "({x}, {y})");
    }
    // Sonar in a preview draws a coarser grid.
    let sonar = Settings {
        color: ColorMode::Sonar,
        ..settings
    };
    assert!(drawn_field(&field, &sonar, Size::new(152, 112)).size() < n);
}
