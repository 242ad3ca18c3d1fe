//! The seed programs' looks other than seed 000's (tests/render/classic_listing.rs
//! holds that one): Mountain Terrain 3.0's facings and water, FL3's Filled
//! mode and pseudo-normal deviations, the essay's turns, flat edges,
//! numbers and camera.

use std::collections::{BTreeMap, BTreeSet};

use mountains::render::Size;
use mountains::render::facings;
use mountains::render::palette::Palette;
use mountains::render::{Frame, render_full};
use mountains::settings::Settings;
use mountains::settings::load::apply_set;
use mountains::terrain;

use crate::common::golden;

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

/// The finest level's horizontal-edge displacements of a triangle field
/// (each point between two others on an even row, less their mean), under
/// contour 1 so the normalising is a scale and they keep their shape; and
/// their kurtosis (1.8 for a uniform density, 2.4 for FL3's triangle).
fn displacements(look: &str) -> (Vec<f64>, f64) {
    let s = with(&[
        ("look", look),
        ("generator", "triangle"),
        ("detail", "8"),
        ("contour", "1"),
        ("erosion", "0"),
        ("cliffs", "0"),
        ("lakes", "false"),
    ]);
    let f = terrain::generate(&s, 11);
    let n = f.size();
    let mut d = Vec::new();
    for y in (0..n).step_by(2) {
        for x in (1..n - 1).step_by(2) {
            let mean = 0.5 * (f.get(x - 1, y) as f64 + f.get(x + 1, y) as f64);
            d.push(f.get(x, y) as f64 - mean);
        }
    }
    let m = d.iter().sum::<f64>() / d.len() as f64;
    let var = d.iter().map(|v| (v - m).powi(2)).sum::<f64>() / d.len() as f64;
    let fourth = d.iter().map(|v| (v - m).powi(4)).sum::<f64>() / d.len() as f64;
    (d, fourth / (var * var))
}

/// Share of `d` within a fifth of its largest size of 0.
fn central_share(d: &[f64]) -> f64 {
    let reach = d.iter().fold(0.0f64, |a, v| a.max(v.abs()));
    d.iter().filter(|v| v.abs() < 0.2 * reach).count() as f64 / d.len() as f64
}

#[test]
fn fl3s_deviations_are_pseudo_normal_where_ours_are_uniform() {
    let (fl3, k_fl3) = displacements("fl3");
    let (ours, k_ours) = displacements("ours");
    assert!(fl3.len() > 16_000);
    // FL3's Rand: the sum of two uniform numbers, a triangle (kurtosis 2.4).
    eprintln!("kurtosis fl3 {k_fl3:.3}, ours {k_ours:.3}");
    assert!((2.2..2.6).contains(&k_fl3), "fl3 kurtosis {k_fl3}");
    // Ours: one uniform number (kurtosis 1.8).
    assert!((1.65..1.95).contains(&k_ours), "ours kurtosis {k_ours}");
    // Bell-shaped: the middle fifth either side of 0 holds 36% of a
    // triangle's values, 20% of a uniform's.
    let (c_fl3, c_ours) = (central_share(&fl3), central_share(&ours));
    assert!((0.32..0.40).contains(&c_fl3), "fl3 central share {c_fl3}");
    assert!(
        (0.17..0.23).contains(&c_ours),
        "ours central share {c_ours}"
    );
}

/// `look`'s square generator at detail 8 with nothing after it that moves
/// points (no sea line, erosion, cliffs or lakes): its displacements as made.
fn bare_square(look: &str) -> Settings {
    with(&[
        ("look", look),
        ("generator", "square"),
        ("detail", "8"),
        ("water_line", "generator"),
        ("erosion", "0"),
        ("cliffs", "0"),
        ("lakes", "false"),
    ])
}

/// The finest level's horizontal-edge displacements of the square
/// generator's field under `look` (each point between two others on an
/// even row, less their mean; not the border's rows, which the essay
/// leaves undisplaced), drawn on `threads` threads.
fn square_displacements(look: &str, threads: usize) -> Vec<f64> {
    let s = bare_square(look);
    let f = terrain::generate_with_threads(&s, 11, threads);
    let n = f.size();
    let mut d = Vec::new();
    for y in (2..n - 1).step_by(2) {
        for x in (1..n - 1).step_by(2) {
            let mean = 0.5 * (f.get(x - 1, y) as f64 + f.get(x + 1, y) as f64);
            d.push(f.get(x, y) as f64 - mean);
        }
    }
    d
}

/// The kurtosis of `d`, and its variance as a share of its largest size
/// squared (the law's amplitude: both laws reach their ends).
fn shape(d: &[f64]) -> (f64, f64) {
    let m = d.iter().sum::<f64>() / d.len() as f64;
    let var = d.iter().map(|v| (v - m).powi(2)).sum::<f64>() / d.len() as f64;
    let fourth = d.iter().map(|v| (v - m).powi(4)).sum::<f64>() / d.len() as f64;
    let reach = d.iter().fold(0.0f64, |a, v| a.max(v.abs()));
    (fourth / (var * var), var / (reach * reach))
}

/// The essay displaces by `side * cos(random * PI) * roughness`: the
/// arcsine law, densest at its ends (kurtosis 1.5, variance half the
/// amplitude squared), where ours is uniform (1.8 and a third); the same
/// numbers on any number of threads.
#[test]
fn the_essays_deviations_are_the_cosine_of_a_random_half_turn() {
    let essay = square_displacements("essay", 1);
    let ours = square_displacements("ours", 1);
    assert!(essay.len() > 16_000, "{}", essay.len());
    let (k_essay, v_essay) = shape(&essay);
    let (k_ours, v_ours) = shape(&ours);
    eprintln!(
        "kurtosis essay {k_essay:.3}, ours {k_ours:.3}; variance / amplitude^2 essay {v_essay:.3}, ours {v_ours:.3}"
    );
    assert!((1.4..1.6).contains(&k_essay), "essay kurtosis {k_essay}");
    assert!((0.47..0.53).contains(&v_essay), "essay variance {v_essay}");
    assert!((1.65..1.95).contains(&k_ours), "ours kurtosis {k_ours}");
    assert!((0.30..0.36).contains(&v_ours), "ours variance {v_ours}");
    // Densest at the ends: a tenth of the amplitude's width at either end
    // holds 2 acos(0.9) / PI = 29% of the arcsine law, 10% of a uniform.
    let ends = |d: &[f64]| {
        let reach = d.iter().fold(0.0f64, |a, v| a.max(v.abs()));
        d.iter().filter(|v| v.abs() > 0.9 * reach).count() as f64 / d.len() as f64
    };
    let (e_essay, e_ours) = (ends(&essay), ends(&ours));
    assert!((0.26..0.32).contains(&e_essay), "essay ends {e_essay}");
    assert!((0.08..0.12).contains(&e_ours), "ours ends {e_ours}");
    let bits = |d: Vec<f64>| d.iter().map(|v| v.to_bits()).collect::<Vec<_>>();
    assert_eq!(bits(essay), bits(square_displacements("essay", 3)));
}

/// The root mean square of the finest level's displacements of the square
/// generator's centres (from their four corners' mean) and of its edge
/// midpoints (from their two ends' mean), under `look`.
fn centre_and_edge_rms(look: &str) -> (f64, f64) {
    let s = bare_square(look);
    let f = terrain::generate(&s, 11);
    let n = f.size();
    let h = |x: usize, y: usize| f64::from(f.get(x, y));
    let (mut centre, mut edge) = ((0.0, 0), (0.0, 0));
    for y in (1..n - 1).step_by(2) {
        for x in (1..n - 1).step_by(2) {
            let corners = h(x - 1, y - 1) + h(x + 1, y - 1) + h(x - 1, y + 1) + h(x + 1, y + 1);
            centre = (centre.0 + (h(x, y) - 0.25 * corners).powi(2), centre.1 + 1);
            // The edge midpoint below this centre (inside the square).
            if y + 1 < n - 1 {
                let ends = 0.5 * (h(x - 1, y + 1) + h(x + 1, y + 1));
                edge = (edge.0 + (h(x, y + 1) - ends).powi(2), edge.1 + 1);
            }
        }
    }
    (
        (centre.0 / f64::from(centre.1)).sqrt(),
        (edge.0 / f64::from(edge.1)).sqrt(),
    )
}

/// The essay displaces an edge's midpoint by `side * cos(random * PI) *
/// side_roughness` (0.15) and a square's centre by the same with
/// `center_roughness` (0.2): its edges three quarters as far as its
/// centres, where ours displaces both alike.
#[test]
fn the_essays_edges_are_displaced_three_quarters_as_far_as_its_centres() {
    let (c, e) = centre_and_edge_rms("essay");
    let (oc, oe) = centre_and_edge_rms("ours");
    eprintln!("edge / centre: essay {:.3}, ours {:.3}", e / c, oe / oc);
    assert!((0.72..0.78).contains(&(e / c)), "essay {}", e / c);
    assert!((0.95..1.05).contains(&(oe / oc)), "ours {}", oe / oc);
}

/// The essay's square, turned, keeps straight edges, as the essay draws
/// them: a cell on the land's edge is cut along the square's side instead
/// of left out. Nearly flat land (height 1) seen from seed 7's turn (56.25
/// degrees): the land's lowest pixel in each column runs straight from the
/// side corners down to the nearest one (before: 5.9 px off it).
#[test]
fn the_essays_turned_square_keeps_straight_edges() {
    let s = with(&[("look", "essay"), ("height", "1")]);
    let (w, h) = (640u32, 384u32);
    let field = terrain::generate(&s, 7);
    let mut frame = Frame::new(w, h).unwrap();
    render_full(&field, &s, &mut frame);
    let page = frame.get(0, 0);
    let bottom: Vec<Option<u32>> = (0..w)
        .map(|x| (0..h).rev().find(|&y| frame.get(x, y) != page))
        .collect();
    let columns: Vec<u32> = (0..w).filter(|&x| bottom[x as usize].is_some()).collect();
    let (left, right) = (columns[0], *columns.last().unwrap());
    let low = |x: u32| bottom[x as usize].unwrap() as f32;
    let front = (left..=right)
        .max_by_key(|&x| bottom[x as usize].unwrap())
        .unwrap();
    assert!(
        front > left + 40 && front + 40 < right,
        "{left} {front} {right}"
    );
    let mut worst = 0.0f32;
    for (a, b) in [(left, front), (front, right)] {
        // Away from the corners, whose pixels a sliver may miss.
        for x in a + 3..b - 2 {
            let t = (x - a) as f32 / (b - a) as f32;
            let line = low(a) + (low(b) - low(a)) * t;
            worst = worst.max((low(x) - line).abs());
        }
    }
    assert!(worst <= 2.0, "the edge strays {worst} px from straight");
}

#[test]
fn fl3s_filled_mode_is_flat_green_and_blue_outlined_in_black() {
    let s = with(&[("look", "fl3")]);
    let counts = histogram(&s, 7, 640, 360);
    let (green, blue) = (0x0000_d000, 0x0030_60ff);
    let total: usize = counts.values().sum();
    let share = |c: u32| counts.get(&c).copied().unwrap_or(0) as f64 / total as f64;
    // Nothing but the two fills and the black pen and window: no shading.
    let others: Vec<u32> = counts
        .keys()
        .copied()
        .filter(|&c| ![0, green, blue].contains(&c))
        .collect();
    assert!(others.is_empty(), "shaded colours: {others:06x?}");
    assert!(share(green) > 0.05 && share(blue) > 0.05, "{counts:06x?}");
    // The pen shows between faces: black inside the land as well.
    let field = terrain::generate(&s, 7);
    let mut frame = Frame::new(640, 360).unwrap();
    render_full(&field, &s, &mut frame);
    let row = 200;
    let runs = (1..640)
        .filter(|&x| frame.get(x - 1, row) == 0 && frame.get(x, row) != 0)
        .count();
    assert!(runs > 10, "{runs} outlined faces across row {row}");
}

#[test]
fn the_essays_square_keeps_its_outer_edges_undisplaced() {
    let border = |look: &str| {
        let s = with(&[("look", look), ("generator", "square"), ("detail", "6")]);
        let f = terrain::generate(&s, 5);
        let n = f.size();
        let edge: Vec<f32> = (0..n)
            .flat_map(|i| [(i, 0), (i, n - 1), (0, i), (n - 1, i)])
            .map(|(x, y)| f.get(x, y))
            .collect();
        let inner: BTreeSet<u32> = (1..n - 1).map(|x| f.get(x, n / 2).to_bits()).collect();
        (edge, inner.len())
    };
    let (edge, inner) = border("essay");
    // The essay's corners all start at its base, so its undisplaced edges
    // are level: every border point at the corners' height.
    assert!(edge.iter().all(|&h| h == edge[0]), "{edge:?}");
    assert!(inner > 40, "the inside is displaced: {inner} heights");
    let (ours, _) = border("ours");
    let distinct: BTreeSet<u32> = ours.iter().map(|h| h.to_bits()).collect();
    assert!(distinct.len() > 40, "our border is displaced");
}

#[test]
fn the_essays_faces_are_its_sunlit_green_on_a_white_page() {
    use glam::Vec3;
    use mountains::render::essay;
    let s = with(&[("look", "essay")]);
    let field = terrain::generate(&s, 7);
    let (w, h) = (480, 270);
    let mut frame = Frame::new(w, h).unwrap();
    render_full(&field, &s, &mut frame);
    assert_eq!(frame.get(0, 0), essay::BACKGROUND);
    // The colours `hsl(100, 80%, L%)` takes for L = 20 cos + 10, rounded.
    let greens: BTreeSet<u32> = (0..=1000)
        .map(|k| {
            let a = std::f32::consts::PI * k as f32 / 1000.0;
            essay::colour(Vec3::new(a.cos(), 0.0, a.sin()))
        })
        .chain([essay::colour(-essay::SUN)])
        .collect();
    assert!(greens.len() >= 30, "{}", greens.len());
    let (mut inside, mut shades) = (0, BTreeSet::new());
    for y in 1..h - 1 {
        for x in 1..w - 1 {
            let around = [(x, y), (x - 1, y), (x + 1, y), (x, y - 1), (x, y + 1)];
            if around
                .iter()
                .any(|&(x, y)| frame.get(x, y) == essay::BACKGROUND)
            {
                continue;
            }
            let p = frame.get(x, y);
            assert!(
                greens.contains(&p),
                "({x}, {y}): {p:06x} is none of the essay's greens"
            );
            inside += 1;
            shades.insert(p);
        }
    }
    assert!(inside > (w * h / 8) as usize, "{inside} land pixels");
    assert!(shades.len() > 15, "{} shades", shades.len());
}

/// How wide the land is a tenth of its height above its lowest pixel, against its
/// widest row, in a rendered essay picture of seed `seed`: small for the
/// corner-on square (the near corner), near 1 for a square edge-on. At
/// the least height: the essay's camera is level and low, so at full
/// relief valleys behind its level front edge are seen below that edge
/// (the essay draws every face, from below too), and the lowest pixel
/// would be a valley's, not the square's outline.
fn essay_front_width(seed: u64) -> f64 {
    use mountains::render::essay;
    let s = with(&[("look", "essay"), ("detail", "6"), ("height", "1")]);
    let field = terrain::generate(&s, seed);
    let (w, h) = (480, 270);
    let mut frame = Frame::new(w, h).unwrap();
    render_full(&field, &s, &mut frame);
    let width = |y: u32| {
        let land: Vec<u32> = (0..w)
            .filter(|&x| frame.get(x, y) != essay::BACKGROUND)
            .collect();
        land.last().map_or(0, |last| last - land[0])
    };
    let lowest = (0..h).rev().find(|&y| width(y) > 0).expect("land");
    let highest = (0..h).find(|&y| width(y) > 0).expect("land");
    let widest = (0..h).map(width).max().unwrap();
    // A tenth of the land's height above its lowest pixel.
    width(lowest - (lowest - highest) / 10) as f64 / widest as f64
}

#[test]
fn the_essay_turns_its_square_in_steps_of_11_25_degrees() {
    use mountains::render::turn;
    // The turn of a seed's mountain, drawn from its identity.
    let degrees_of = |seed: u64| {
        let mut f = mountains::terrain::Heightfield::flat(3, 1.0);
        f.set_seed(Some(seed));
        turn::essay_degrees(f.identity())
    };
    let seed_at = |degrees: f32| {
        (0..10_000u64)
            .find(|&s| degrees_of(s) == degrees)
            .unwrap_or_else(|| panic!("no seed turns {degrees}"))
    };
    let mut seen = BTreeSet::new();
    for s in 0..64 {
        let d = degrees_of(s);
        assert_eq!((d - 45.0) % 11.25, 0.0, "seed {s}: {d}");
        seen.insert(d.to_bits());
    }
    assert!(seen.len() > 12, "{} turns in 64 seeds", seen.len());
    // Corner-on (the essay's first view, 45 degrees): the near corner.
    let corner = essay_front_width(seed_at(45.0));
    assert!(corner < 0.35, "45 degrees: front {corner}");
    // Four steps on (90 degrees): square to the view again, its front
    // edge nearly as wide as the land.
    let edge = essay_front_width(seed_at(90.0));
    eprintln!("front widths: 45 degrees {corner:.3}, 90 degrees {edge:.3}");
    assert!(edge > 0.7, "90 degrees: front {edge}");
}

/// Where the essay's program puts the point of its array at column
/// `i`, row `j` of a `last + 1`-point square (`origin(center)` turned by
/// `theta`, as `terrain()` lays its points out: columns from P1 towards
/// P4, rows from P1 towards P2), `rise` of its units above its base:
/// `projection()` from `camera = [500,100,0]` onto `screen = 600`, in
/// its 1000x600 canvas's pixels.
fn essays_projection(theta: f64, (i, j): (f64, f64), last: f64, rise: f64) -> (f64, f64) {
    let (camera, screen, center) = ([500.0, 100.0, 0.0], 600.0, [500.0, 850.0, 2400.0]);
    let hyp = 2048.0 / 2f64.sqrt();
    let phi = std::f64::consts::FRAC_PI_2 - theta;
    let p1 = [center[0] - hyp * theta.cos(), center[2] + hyp * theta.sin()];
    let p2 = [center[0] - hyp * phi.cos(), center[2] - hyp * phi.sin()];
    let p4 = [center[0] + hyp * phi.cos(), center[2] + hyp * phi.sin()];
    let (u, v) = (i / last, j / last);
    let x = p1[0] + v * (p2[0] - p1[0]) + u * (p4[0] - p1[0]);
    let z = p1[1] + v * (p2[1] - p1[1]) + u * (p4[1] - p1[1]);
    let y = center[1] - rise;
    let r = screen / (z - camera[2]);
    (
        camera[0] - (camera[0] - x) * r,
        camera[1] - (camera[1] - y) * r,
    )
}

/// The essay's camera: in a frame of its canvas's shape (1000x600) the
/// square's corners, centre and a few points between, at their heights,
/// land where the essay's `projection()` puts them, within a pixel; in a
/// wider frame its canvas is centred (moved right by half the difference)
/// at the same scale. Square to the view (a quarter turn), the land's
/// leftmost and rightmost drawn pixels are its front corners' (the camera
/// is level: a point's column does not depend on its height), to within
/// the sliver of a corner no pixel centre falls in.
#[test]
fn the_essays_camera_sees_the_square_as_its_projection_does() {
    use mountains::render::facts::SceneFacts;
    use mountains::render::{essay, turn};
    let s = with(&[("look", "essay"), ("detail", "6")]);
    let degrees_of = |seed: u64| {
        let mut f = mountains::terrain::Heightfield::flat(3, 1.0);
        f.set_seed(Some(seed));
        turn::essay_degrees(f.identity())
    };
    let square_on = (0..10_000u64)
        .find(|&s| degrees_of(s) % 90.0 == 0.0)
        .expect("a seed turned a quarter");
    for seed in [7, 3, square_on] {
        let field = terrain::generate(&s, seed);
        assert_eq!(field.drawn_scale(), 1.0);
        let n = field.size();
        let last = (n - 1) as f64;
        let degrees = turn::essay_degrees(field.identity()) as f64;
        // The essay turns the other way from its first view, edge-on.
        let theta = (45.0 - degrees).to_radians();
        // Its units per field unit, and its base: the corners' height.
        let k = 2048.0 / field.extent() as f64;
        let base = field.get(0, 0) as f64;
        // A source grid point's place in the turned grid the scene draws
        // (src/render/framing/turn.rs), in fractions of its width.
        let (sin, cos) = (degrees.to_radians() as f32).sin_cos();
        let grow = (sin.abs() + cos.abs()) as f64;
        let (sin, cos) = (sin as f64, cos as f64);
        let turned = |i: f64, j: f64| {
            let (dx, dy) = (i - 0.5 * last, j - 0.5 * last);
            let (u, v) = (cos * dx + sin * dy, -sin * dx + cos * dy);
            (0.5 + u / (grow * last), 0.5 + v / (grow * last))
        };
        let points = [
            (0, 0),
            (n - 1, 0),
            (0, n - 1),
            (n - 1, n - 1),
            (n / 2, n / 2),
        ]
        .into_iter()
        .chain((1..8).map(|q| (q * n / 8, (8 - q) * n / 9)));
        for (w, h, shift) in [(1000, 600, 0.0), (1280, 600, 140.0)] {
            let facts = SceneFacts::of(&field, &s, Size::new(w, h));
            for (i, j) in points.clone() {
                let z = field.get(i, j);
                let rise = (z as f64 - base) * k;
                let want = essays_projection(theta, (i as f64, j as f64), last, rise);
                let (fx, fy) = turned(i as f64, j as f64);
                let got = facts.place(fx as f32, fy as f32, z);
                let got = (got.x as f64 * w as f64, got.y as f64 * h as f64);
                let off = ((got.0 - want.0 - shift).powi(2) + (got.1 - want.1).powi(2)).sqrt();
                assert!(
                    off < 1.0,
                    "seed {seed} ({degrees} degrees), {w}x{h}, point ({i}, {j}): \
                     at {got:?}, the essay's {want:?} (+{shift}): {off:.2} px off"
                );
            }
        }
    }
    // Drawn: square to the view, the land spans its front corners.
    let field = terrain::generate(&s, square_on);
    let (w, h) = (1000, 600);
    let mut frame = Frame::new(w, h).unwrap();
    render_full(&field, &s, &mut frame);
    let land: Vec<u32> = (0..w)
        .filter(|&x| (0..h).any(|y| frame.get(x, y) != essay::BACKGROUND))
        .collect();
    let (left, right) = (land[0] as f64, *land.last().unwrap() as f64 + 1.0);
    let degrees = turn::essay_degrees(field.identity()) as f64;
    let theta = (45.0 - degrees).to_radians();
    let last = (field.size() - 1) as f64;
    let xs: Vec<f64> = [(0.0, 0.0), (last, 0.0), (0.0, last), (last, last)]
        .iter()
        .map(|&c| essays_projection(theta, c, last, 0.0).0)
        .collect();
    let (lo, hi) = xs
        .iter()
        .fold((f64::MAX, f64::MIN), |(lo, hi), &x| (lo.min(x), hi.max(x)));
    eprintln!(
        "square-on ({degrees} degrees): land {left}..{right}, the essay's corners {lo:.1}..{hi:.1}"
    );
    // No pixel centre outside the corners; and the land reaches them but
    // for the sliver at each corner that the rows of pixel centres miss
    // (the side edges climb about a row for each 1.4 columns there).
    assert!(
        (lo - 0.5..lo + 2.0).contains(&left),
        "left edge {left}, the essay's {lo}"
    );
    assert!(
        (hi - 2.0..hi + 0.5).contains(&right),
        "right edge {right}, the essay's {hi}"
    );
}

/// Each look's picture is the same drawn at once (in bands of columns on
/// all cores) or strip by strip as the slide show draws it: the essay's
/// turned square with its undrawn outside, FL3's filled cells, the
/// listing's and Mountain Terrain's colours.
#[test]
fn every_look_steps_to_the_same_pixels_as_the_full_frame() {
    use mountains::render::Painter;
    use std::sync::Arc;
    for look in [
        "fractal-mountain-climbing",
        "mountain-terrain",
        "fl3",
        "essay",
    ] {
        let s = with(&[("look", look), ("detail", "6")]);
        let field = terrain::generate(&s, 3);
        let (w, h) = (700, 300);
        let mut all = Frame::new(w, h).unwrap();
        render_full(&field, &s, &mut all);
        for budget in [1, 5, usize::MAX] {
            let mut frame = Frame::new(w, h).unwrap();
            frame.clear(0x00ab_cdef);
            let mut p = Painter::new(Arc::new(field.clone()), &s, Size::new(w, h));
            while !p.is_done() {
                p.step(&mut frame, budget);
            }
            assert!(
                frame == all,
                "{look}: budget {budget} differs from the full frame"
            );
        }
    }
}

/// The pinned picture of each look: 160x90 of seed 7 at detail 5 under
/// tests/golden/look-*.png (the look's own generator: its numbers, FL3's
/// deviations and the essay's edges and turn are part of it). When a look
/// changes on purpose, look at target/golden-actual/ and pin them again
/// with `MOUNTAINS_PIN_GOLDEN=1`, as tests/render/painter.rs says.
#[test]
fn golden_pictures_pin_each_look() {
    let pictures = [
        "fractal-mountain-climbing",
        "mountain-terrain",
        "fl3",
        "essay",
    ]
    .map(|look| {
        let s = with(&[("look", look), ("detail", "5")]);
        let field = terrain::generate(&s, 7);
        let mut got = Frame::new(160, 90).unwrap();
        render_full(&field, &s, &mut got);
        (format!("look-{look}.png"), got)
    });
    let wrong = golden::compare(pictures);
    assert!(
        wrong.is_empty(),
        "a look changed: {wrong:?}; compare target/golden-actual/ with tests/golden/"
    );
}

/// FL3 draws "filled vertical quadrilaterals" down to sea level along the
/// front edges in the filled modes: in Filled, halfway down from a front
/// point above the sea to its foot, the picture is the land's green.
#[test]
fn fl3s_filled_mode_hangs_green_sides_from_the_front_edge() {
    use mountains::render::facts::SceneFacts;
    let s = with(&[("look", "fl3"), ("sea_level", "-1"), ("detail", "6")]);
    let field = terrain::generate(&s, 7);
    let (w, h) = (640, 360);
    let mut frame = Frame::new(w, h).unwrap();
    render_full(&field, &s, &mut frame);
    let facts = SceneFacts::of(&field, &s, Size::new(w, h));
    let n = field.size() - 1;
    let mut sides = 0;
    for k in 1..8 {
        let x = n * k / 8;
        let z = field.get(x, n);
        let (fx, fy) = (x as f32 / n as f32, 1.0);
        let (top, foot) = (facts.place(fx, fy, z), facts.place(fx, fy, 0.0));
        if (foot.y - top.y) * (h as f32) < 8.0 {
            continue;
        }
        let mid = (top + foot) * 0.5;
        let (px, py) = ((mid.x * w as f32) as u32, (mid.y * h as f32) as u32);
        let green = (px - 2..=px + 2).any(|x| frame.get(x, py) == 0x0000_d000);
        assert!(green, "column {x}: no side at ({px}, {py})");
        sides += 1;
    }
    assert!(
        sides >= 4,
        "{sides} front points stand high enough to check"
    );
}
