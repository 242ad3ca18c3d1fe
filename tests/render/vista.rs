//! The default picture: the vista's framing at every aspect, land and water
//! on every slide, a sky that is a gradient, visible shadows, auto detail,
//! and Sonar's cell size with and without low detail.

use std::collections::HashMap;

use mountains::render::Size;
use mountains::render::detail::{auto_level, for_frame};
use mountains::render::light::Lighting;
use mountains::render::view::View;
use mountains::render::{Frame, render_full};
use mountains::settings::{ColorMode, Detail, Settings, Sun, ViewKind, World};
use mountains::terrain::{self, Heightfield};

/// 16:9, 21:9, 4:3, portrait and the Control Panel preview.
const ASPECTS: [(u32, u32); 6] = [
    (1920, 1080),
    (3440, 1440),
    (1024, 768),
    (1080, 1920),
    (152, 112),
    (3840, 2160),
];

/// A vista of a 1025 grid 250 wide whose land rises at most `zmax`.
fn vista_over(zmax: f32, w: u32, h: u32) -> View {
    View::new(ViewKind::Vista, 1025, 250.0, zmax, Size::new(w, h))
}

/// A vista of low land: the framing rules without the room for tall peaks.
fn vista(w: u32, h: u32) -> View {
    vista_over(10.0, w, h)
}

#[test]
fn tall_land_keeps_a_strip_of_sky() {
    for (w, h) in ASPECTS {
        let (low, tall) = (vista(w, h), vista_over(80.0, w, h));
        let hf = h as f32;
        let low_edge = low.project(512.0, 0.0, 0.0).y;
        let tall_edge = tall.project(512.0, 0.0, 0.0).y;
        assert!(tall_edge >= low_edge, "{w}x{h}: the back edge moved up");
        let top = (0..=1024)
            .step_by(16)
            .map(|gy| tall.project(512.0, gy as f32, 80.0).y)
            .fold(f32::INFINITY, f32::min);
        let lowest = tall_edge >= 0.71 * hf;
        assert!(
            top >= 0.11 * hf || lowest,
            "{w}x{h}: land reaches {top} of {hf} rows"
        );
    }
}

#[test]
fn the_back_edge_spans_the_width_and_no_side_edge_shows() {
    for (w, h) in ASPECTS {
        let v = vista(w, h);
        let (wf, hf) = (w as f32, h as f32);
        let (left, right) = (v.project(0.0, 0.0, 0.0), v.project(1024.0, 0.0, 0.0));
        let what = format!("{w}x{h}");
        assert!(left.x.abs() < 0.5, "{what}: back edge starts at {}", left.x);
        assert!(
            (right.x - wf).abs() < 0.5,
            "{what}: back edge ends at {}",
            right.x
        );
        // Every row's ends, at sea level and above, lie outside the frame.
        for gy in (0..=1024).step_by(64) {
            for z in [0.0, 30.0, 60.0] {
                let (a, b) = (
                    v.project(0.0, gy as f32, z),
                    v.project(1024.0, gy as f32, z),
                );
                assert!(
                    a.x <= 0.5 && b.x >= wf - 0.5,
                    "{what}: row {gy} at {z} shows"
                );
            }
        }
        let skyline = left.y / hf;
        assert!(
            (0.3..0.45).contains(&skyline),
            "{what}: back edge at {skyline:.3} of the height"
        );
        let near = v.project(512.0, 1024.0, 0.0).y;
        assert!(near >= hf, "{what}: near edge at {near}, inside the frame");
        assert!(
            near < hf + 0.02 * hf + 3.0,
            "{what}: near edge far below ({near})"
        );
    }
}

/// Default settings for a frame, with the auto detail resolved, in the
/// temperate world: the vista's fit and sky are measured on the coast it
/// was made for (the other worlds raise or drop the water on purpose:
/// tests/render/worlds.rs).
fn slide(w: u32, h: u32) -> Settings {
    let temperate = Settings {
        world: World::Temperate,
        ..Settings::default()
    };
    for_frame(&temperate, Size::new(w, h))
}

/// Share of land among the land and water a vista shows, estimated on the
/// grid: each cell counts with its projected area, if its centre is in view.
fn land_share(field: &Heightfield, w: u32, h: u32) -> f32 {
    let n = field.size();
    let v = View::new(ViewKind::Vista, n, field.extent(), 0.0, Size::new(w, h));
    let (mut land, mut water) = (0.0f64, 0.0f64);
    for y in 0..n - 1 {
        for x in 0..n - 1 {
            let c = v.project(x as f32 + 0.5, y as f32 + 0.5, 0.0);
            if !(c.x >= 0.0 && c.x < w as f32 && c.y >= 0.0 && c.y < h as f32) {
                continue;
            }
            let a = v.project(x as f32, y as f32, 0.0);
            let b = v.project(x as f32 + 1.0, y as f32 + 1.0, 0.0);
            let area = f64::from(((b.x - a.x) * (b.y - a.y)).abs());
            let mean = (field.get(x, y) + field.get(x + 1, y) + field.get(x, y + 1)) / 3.0;
            if mean > 0.0 {
                land += area;
            } else {
                water += area;
            }
        }
    }
    (land / (land + water).max(1e-9)) as f32
}

/// Pixels that change when water loses its depth colours: the water shown.
fn water_pixels(field: &Heightfield, s: &Settings, w: u32, h: u32) -> usize {
    let flat = Settings {
        relative_depth: false,
        ..s.clone()
    };
    let (a, b) = (draw(field, s, w, h), draw(field, &flat, w, h));
    a.pixels()
        .iter()
        .zip(b.pixels())
        .filter(|(p, q)| p != q)
        .count()
}

fn draw(field: &Heightfield, s: &Settings, w: u32, h: u32) -> Frame {
    let mut frame = Frame::new(w, h).unwrap();
    render_full(field, s, &mut frame);
    frame
}

#[test]
fn every_slide_has_land_and_nearly_every_one_water() {
    let (w, h) = (480, 270);
    let s = slide(w, h);
    let seeds = 1..=60u64;
    let mut with_water = 0;
    for seed in seeds.clone() {
        let field = terrain::generate(&s, seed);
        let share = land_share(&field, w, h);
        assert!(share >= 0.2, "seed {seed}: land is {share:.3} of the view");
        if water_pixels(&field, &s, w, h) > 100 {
            with_water += 1;
        }
    }
    let n = seeds.count();
    assert!(
        with_water * 10 >= n * 8,
        "water on {with_water} of {n} slides"
    );
}

#[test]
fn the_sky_is_a_gradient_and_no_colour_covers_a_large_area() {
    let (w, h) = (960, 540);
    let s = slide(w, h);
    let (mut gradients, mut sunsets) = (0, 0);
    for seed in [1u64, 2, 3, 5, 6] {
        let field = terrain::generate(&s, seed);
        let frame = draw(&field, &s, w, h);
        let mut counts: HashMap<u32, usize> = HashMap::new();
        for &p in frame.pixels() {
            *counts.entry(p).or_default() += 1;
        }
        let most = counts.values().copied().max().unwrap_or(0);
        assert!(
            most * 20 < (w * h) as usize,
            "seed {seed}: one colour covers {most} pixels"
        );
        let light = |y: u32, x: std::ops::Range<u32>| {
            let n = x.len() as u32;
            let row = &frame.pixels()[(y * w) as usize..((y + 1) * w) as usize];
            row[x.start as usize..x.end as usize]
                .iter()
                .map(|&c| luminance(c))
                .sum::<u32>()
                / n
        };
        let sun = Lighting::new(s.sun, &field).sun;
        if sun.y > 0.9 {
            // Looking into the sun (a sunset): its glow lights the top of
            // the sky, more in the middle third than at the sides.
            let (middle, side) = (w / 3..2 * w / 3, 0..w / 6);
            assert!(
                light(0, middle) > light(0, side),
                "seed {seed}: no glow where the sun stands ahead"
            );
            sunsets += 1;
        } else {
            // The top row is the zenith; lower sky rows are lighter.
            assert!(
                light(20, 0..w) > light(0, 0..w),
                "seed {seed}: sky not lighter lower down"
            );
            gradients += 1;
        }
    }
    assert!(
        gradients >= 3 && sunsets >= 1,
        "{gradients} gradients, {sunsets} sunsets"
    );
}

fn luminance(c: u32) -> u32 {
    ((c >> 16) & 0xff) * 77 + ((c >> 8) & 0xff) * 150 + (c & 0xff) * 29
}

#[test]
fn shadows_change_a_visible_part_of_a_typical_slide() {
    let (w, h) = (480, 270);
    let s = slide(w, h);
    let mut changed: Vec<f32> = (1..=9u64)
        .map(|seed| {
            let field = terrain::generate(&s, seed);
            let off = Settings {
                shadows: false,
                ..s.clone()
            };
            let (a, b) = (draw(&field, &s, w, h), draw(&field, &off, w, h));
            let n = a.pixels().iter().zip(b.pixels()).filter(|(p, q)| p != q);
            n.count() as f32 / (w * h) as f32
        })
        .collect();
    changed.sort_by(f32::total_cmp);
    let median = changed[changed.len() / 2];
    assert!(
        median >= 0.03,
        "shadows change {median:.4} of the frame (median)"
    );
}

#[test]
fn a_varied_sun_follows_the_mountain_and_varies_between_mountains() {
    let s = Settings {
        detail: Detail::Level(6),
        ..Settings::default()
    };
    let mut suns = Vec::new();
    for seed in 1..=12u64 {
        let field = terrain::generate(&s, seed);
        let a = Lighting::new(Sun::Varied, &field);
        let b = Lighting::new(Sun::Varied, &field);
        assert_eq!(
            a.sun, b.sun,
            "seed {seed}: the same mountain, another light"
        );
        suns.push(a.horizon);
    }
    suns.sort_by(|a, b| a.partial_cmp(b).unwrap());
    suns.dedup();
    assert!(
        suns.len() >= 3,
        "only {} times of day in 12 slides",
        suns.len()
    );
    let fixed = Lighting::new(Sun::Evening, &terrain::generate(&s, 1));
    assert!(fixed.sun.x > 0.0, "evening light comes from the right");
}

/// A varied sun turns from its time's place only towards the viewer's side:
/// never further behind the range (a low sun from behind leaves the whole
/// foreground in one dark shadow).
#[test]
fn a_varied_sun_never_stands_further_behind_than_its_time() {
    let s = Settings {
        detail: Detail::Level(6),
        ..Settings::default()
    };
    let field = terrain::generate(&s, 1);
    let times = [
        Sun::Morning,
        Sun::Midday,
        Sun::Evening,
        Sun::Sunset,
        Sun::Night,
    ]
    .map(|t| Lighting::new(t, &field));
    for seed in 1..=40u64 {
        let varied = Lighting::new(Sun::Varied, &terrain::generate(&s, seed));
        let time = times
            .iter()
            .find(|t| t.horizon == varied.horizon)
            .expect("a varied sun is one of the times of day");
        assert!(
            varied.sun.y <= time.sun.y + 1e-6,
            "seed {seed}: sun {:?} stands further back than {:?}",
            varied.sun,
            time.sun
        );
    }
}

#[test]
fn auto_detail_follows_the_frame() {
    let s = Settings::default();
    assert_eq!(auto_level(&s, Size::new(1920, 1080)), 10, "1080p");
    assert_eq!(auto_level(&s, Size::new(3840, 2160)), 11, "4K");
    let preview = auto_level(&s, Size::new(152, 112));
    assert!(preview <= 7, "preview level {preview}");
    let low = Settings {
        low_detail: true,
        ..s.clone()
    };
    let fitted = for_frame(&low, Size::new(1920, 1080));
    assert_eq!(fitted.detail, Detail::Level(10));
    assert_eq!(fitted.grid_exponent(), 9, "low detail halves the grid");
    let fixed = Settings {
        detail: Detail::Level(7),
        ..s
    };
    assert_eq!(
        for_frame(&fixed, Size::new(3840, 2160)).detail,
        Detail::Level(7)
    );
}

/// White pixels of a Sonar frame: fewer, larger faces have fewer edges.
fn sonar_white(low_detail: bool) -> usize {
    let (w, h) = (1920, 1080);
    let s = for_frame(
        &Settings {
            color: ColorMode::Sonar,
            low_detail,
            seed: Some(3),
            ..Settings::default()
        },
        Size::new(w, h),
    );
    let field = terrain::generate(&s, 3);
    let frame = draw(&field, &s, w, h);
    frame.pixels().iter().filter(|&&p| p == 0x00ff_ffff).count()
}

#[test]
fn low_detail_visibly_enlarges_sonar_faces() {
    let (fine, coarse) = (sonar_white(false), sonar_white(true));
    assert!(fine > 0 && coarse > 0);
    assert!(
        (coarse as f32) < 0.7 * fine as f32,
        "low detail: {coarse} white pixels against {fine}"
    );
}
