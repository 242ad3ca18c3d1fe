//! Mountain lakes: basins above the sea filled to their lowest lip. A lake
//! never spills (no lake point above its surface, the surface exactly the
//! basin's lip, found here by a slow search of its own), holds its whole
//! basin, and never covers the sea.

use std::cmp::Reverse;
use std::collections::{BinaryHeap, VecDeque};

use mountains::settings::{Generator, Settings};
use mountains::terrain::{Heightfield, Lakes, generate, generate_with_threads};

const AROUND: [(isize, isize); 8] = [
    (-1, -1),
    (0, -1),
    (1, -1),
    (-1, 0),
    (1, 0),
    (-1, 1),
    (0, 1),
    (1, 1),
];

fn neighbours(n: usize, x: usize, y: usize) -> impl Iterator<Item = (usize, usize)> {
    AROUND.into_iter().filter_map(move |(dx, dy)| {
        let (x, y) = (x as isize + dx, y as isize + dy);
        (x >= 0 && y >= 0 && (x as usize) < n && (y as usize) < n)
            .then_some((x as usize, y as usize))
    })
}

/// The points of each lake, as (x, y).
fn points_of(lakes: &Lakes) -> Vec<Vec<(usize, usize)>> {
    let mut out = vec![Vec::new(); lakes.count()];
    for y in 0..lakes.size() {
        for run in lakes.row(y) {
            for x in run.start..run.end {
                out[run.lake as usize].push((x as usize, y));
            }
        }
    }
    out
}

/// The lowest height water at (x, y) must rise to before it can leave the
/// grid or reach the sea: over every path to the border or to a point at or
/// below sea level, the least of the path's highest point (Dijkstra on the
/// path's maximum, with a binary heap: slow and plain).
fn lip_by_search(f: &Heightfield, start: (usize, usize)) -> f32 {
    let n = f.size();
    let mut best = vec![f32::INFINITY; n * n];
    let mut heap = BinaryHeap::new();
    let h0 = f.get(start.0, start.1);
    best[start.1 * n + start.0] = h0;
    heap.push(Reverse((h0.to_bits(), start)));
    while let Some(Reverse((bits, (x, y)))) = heap.pop() {
        let level = f32::from_bits(bits);
        if level > best[y * n + x] {
            continue;
        }
        let border = x == 0 || y == 0 || x == n - 1 || y == n - 1;
        if border || f.get(x, y) <= 0.0 {
            return level;
        }
        for (nx, ny) in neighbours(n, x, y) {
            let through = level.max(f.get(nx, ny).max(0.0));
            if through < best[ny * n + nx] {
                best[ny * n + nx] = through;
                heap.push(Reverse((through.to_bits(), (nx, ny))));
            }
        }
    }
    f32::INFINITY
}

/// Every law of a lake, checked on `field`'s lakes.
fn check_lakes(field: &Heightfield, what: &str) -> usize {
    let lakes = field.lakes().expect("lakes were asked for");
    let n = field.size();
    for (lake, points) in points_of(lakes).iter().enumerate() {
        let level = lakes.level(lake as u32);
        assert!(
            level > 0.0,
            "{what}: lake {lake} at {level}, not above the sea"
        );
        for &(x, y) in points {
            let h = field.get(x, y);
            assert!(
                h < level,
                "{what}: lake {lake} spills: {h} at ({x}, {y}) over {level}"
            );
            assert!(h > 0.0, "{what}: lake {lake} covers the sea at ({x}, {y})");
        }
        // The surface is the basin's lowest lip.
        let lip = lip_by_search(field, points[0]);
        assert_eq!(level, lip, "{what}: lake {lake}'s surface is not its lip");
        // The lake is the whole basin: every point joined to it below the lip.
        let mut basin = vec![false; n * n];
        let mut queue = VecDeque::from([points[0]]);
        basin[points[0].1 * n + points[0].0] = true;
        let mut size = 0;
        while let Some((x, y)) = queue.pop_front() {
            size += 1;
            for (nx, ny) in neighbours(n, x, y) {
                if !basin[ny * n + nx] && field.get(nx, ny) < level {
                    basin[ny * n + nx] = true;
                    queue.push_back((nx, ny));
                }
            }
        }
        assert_eq!(
            size,
            points.len(),
            "{what}: lake {lake} is not its whole basin"
        );
        assert!(points.iter().all(|&(x, y)| basin[y * n + x]));
    }
    lakes.count()
}

/// A paraboloid bowl standing above the sea: its lowest lip is the middle
/// of each edge, so it holds one lake, a disc, at that height.
#[test]
fn a_bowl_holds_one_lake_at_its_lip() {
    let n = 33;
    let c = 16.0f32;
    let heights: Vec<f32> = (0..n * n)
        .map(|i| {
            let (x, y) = ((i % n) as f32 - c, (i / n) as f32 - c);
            1.0 + 10.0 * (x * x + y * y) / (c * c)
        })
        .collect();
    let mut field = Heightfield::from_heights(n, 100.0, heights).unwrap();
    let lakes = Lakes::of(field.heights(), n);
    assert_eq!(lakes.count(), 1);
    assert_eq!(lakes.level(0), 11.0, "the lip: the middle of an edge");
    assert_eq!(lakes.lake_at(16, 16), Some(0));
    assert_eq!(lakes.lake_at(0, 16), None, "the lip itself is dry");
    assert_eq!(lakes.surface_at(16, 16), 11.0);
    assert_eq!(lakes.surface_at(1, 1), 0.0);
    // Every point below the lip is under water: the disc of radius c.
    let wet = field.heights().iter().filter(|&&h| h < 11.0).count();
    assert_eq!(lakes.areas(), vec![wet]);
    field.set_lakes(Some(lakes.into()));
    assert_eq!(check_lakes(&field, "bowl"), 1);
}

/// A pit of a few points is filled, not drawn; the same pit counts once
/// the least area is lowered to it.
#[test]
fn a_small_pit_is_no_lake() {
    let n = 65;
    let mut heights = vec![5.0f32; n * n];
    heights[30 * n + 30] = 1.0;
    heights[30 * n + 31] = 2.0;
    assert_eq!(Lakes::of(&heights, n).count(), 0);
    let lakes = Lakes::at_least(&heights, n, 2);
    assert_eq!((lakes.count(), lakes.level(0)), (1, 5.0));
    assert_eq!(lakes.areas(), vec![2]);
}

/// Sea below a basin's rim drains it: a basin reaching below sea level is
/// sea (as Fractal Mountain Climbing drew it), never a lake over the sea.
#[test]
fn the_sea_is_an_outlet_not_a_lake() {
    let n = 33;
    let c = 16.0f32;
    let heights: Vec<f32> = (0..n * n)
        .map(|i| {
            let (x, y) = ((i % n) as f32 - c, (i / n) as f32 - c);
            -2.0 + 10.0 * (x * x + y * y) / (c * c)
        })
        .collect();
    assert_eq!(Lakes::of(&heights, n).count(), 0);
}

#[test]
fn generated_lakes_never_spill_and_fill_their_basins() {
    let mut total = 0;
    for generator in [
        Generator::Diamond,
        Generator::Square,
        Generator::Triangle,
        Generator::Brownian,
    ] {
        for seed in 1..=6 {
            let s = Settings {
                generator,
                detail: mountains::settings::Detail::Level(8),
                ..crate::common::terrain_setup::temperate()
            };
            let field = generate(&s, seed);
            total += check_lakes(&field, &format!("{generator:?} seed {seed}"));
        }
    }
    // The laws above would hold trivially with no lakes at all.
    assert!(total >= 5, "only {total} lakes in 24 mountains");
}

#[test]
fn lakes_are_asked_for_and_the_same_on_any_thread_count() {
    let s = Settings {
        detail: mountains::settings::Detail::Level(10),
        ..crate::common::terrain_setup::temperate()
    };
    assert!(s.lakes, "lakes are on by default");
    let one = generate_with_threads(&s, 3, 1);
    let two = generate_with_threads(&s, 3, 2);
    assert_eq!(one.lakes(), two.lakes());
    let dry = generate(
        &Settings {
            lakes: false,
            ..s.clone()
        },
        3,
    );
    assert!(dry.lakes().is_none());
    assert_eq!(dry.heights(), one.heights(), "lakes change no height");
}

use crate::common::lakes_reference::{self, Reference};

/// The lakes of `heights` equal the first flood's, lake by lake and run by
/// run, at the least area `Lakes::of` keeps and at a few points.
fn same_as_reference(heights: &[f32], n: usize, what: &str) -> usize {
    let same = |lakes: &Lakes| Reference::from_lakes(lakes).numbered_by_first_point();
    let ours = same(&Lakes::of(heights, n));
    let theirs = lakes_reference::lakes(heights, n, lakes_reference::least(heights.len()))
        .numbered_by_first_point();
    assert_eq!(ours, theirs, "{what}: not the first flood's lakes");
    for least in [1, 3] {
        let ours = same(&Lakes::at_least(heights, n, least));
        let theirs = lakes_reference::lakes(heights, n, least).numbered_by_first_point();
        assert_eq!(
            ours, theirs,
            "{what}, least {least}: not the first flood's lakes"
        );
    }
    ours.levels.len()
}

#[test]
fn generated_lakes_are_the_first_floods() {
    let mut total = 0;
    for generator in [
        Generator::Diamond,
        Generator::Square,
        Generator::Triangle,
        Generator::Brownian,
    ] {
        for (detail, seeds) in [(6, 1..=8), (8, 1..=4), (10, 1..=1)] {
            for seed in seeds {
                for sea_level in [None, Some(0.1), Some(0.6)] {
                    let mut s = Settings {
                        generator,
                        detail: mountains::settings::Detail::Level(detail),
                        ..Settings::default()
                    };
                    if let Some(sea) = sea_level {
                        s.sea_level = sea;
                    }
                    let field = generate(&s, seed);
                    let what = format!("{generator:?} {detail} seed {seed} sea {sea_level:?}");
                    total += same_as_reference(field.heights(), field.size(), &what);
                }
            }
        }
    }
    assert!(total >= 20, "only {total} lakes to compare");
}

/// Hand-made fields where the order of equal heights decides: flats,
/// terraces, nested basins, plateaus with pits, the sea inside, lips on
/// the border.
#[test]
fn hand_made_lakes_are_the_first_floods() {
    let n = 65;
    let at = |f: &dyn Fn(usize, usize) -> f32| -> Vec<f32> {
        (0..n * n).map(|i| f(i % n, i / n)).collect()
    };
    let r = |x: usize, y: usize| {
        let (dx, dy) = (x as f32 - 32.0, y as f32 - 32.0);
        (dx * dx + dy * dy).sqrt()
    };
    let hash = |x: usize, y: usize| (((x * 73_856_093) ^ (y * 19_349_663)) % 1000) as f32 / 1000.0;
    let fields: Vec<(&str, Vec<f32>)> = vec![
        ("flat", at(&|_, _| 3.0)),
        (
            "flat with a sea",
            at(&|x, y| if r(x, y) < 5.0 { -1.0 } else { 3.0 }),
        ),
        (
            "nested basins",
            at(&|x, y| {
                10.0 - (r(x, y) / 4.0).floor().min(6.0)
                    * ((r(x, y) as usize % 8) as f32 / 4.0 + 0.5)
            }),
        ),
        (
            "terraces",
            at(&|x, y| 1.0 + ((r(x, y) + hash(x, y) * 6.0) / 3.0).floor()),
        ),
        (
            "plateau with pits",
            at(&|x, y| if (x / 7 + y / 5) % 3 == 0 { 2.0 } else { 4.0 }),
        ),
        ("rough", at(&|x, y| 1.0 + hash(x, y) * 5.0)),
        (
            "quantised rough",
            at(&|x, y| 1.0 + (hash(x, y) * 4.0).floor()),
        ),
        (
            "rings",
            at(&|x, y| 2.0 + ((r(x, y) / 2.0) as usize % 2) as f32 * 3.0),
        ),
        (
            "low border",
            at(&|x, y| {
                if x == 0 || y == n - 1 {
                    0.5
                } else {
                    1.0 + hash(y, x)
                }
            }),
        ),
        ("sea and land", at(&|x, y| hash(x, y) * 4.0 - 1.0)),
    ];
    let mut total = 0;
    for (what, heights) in &fields {
        total += same_as_reference(heights, n, what);
        let mut field = Heightfield::from_heights(n, 100.0, heights.clone()).unwrap();
        field.set_lakes(Some(Lakes::at_least(heights, n, 1).into()));
        check_lakes(&field, what);
    }
    assert!(total >= 10, "only {total} lakes to compare");
}

/// Many small random fields, where the pits lie close together and spill
/// into one another: smooth and rough, with heights rounded to a few
/// values (ties and flats everywhere) or to none, with and without sea.
/// The lakes are the first flood's at every least area.
#[test]
fn random_fields_are_the_first_floods() {
    let mut total = 0;
    for case in 0..240u64 {
        let n = [9, 17, 33, 47][case as usize % 4];
        let steps = [0.0, 1.0, 4.0, 64.0][(case / 4) as usize % 4];
        let sea = [0.0, 0.15][(case / 16) as usize % 2];
        let mut state = case.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1;
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 40) as f32 / (1u64 << 24) as f32
        };
        let heights: Vec<f32> = (0..n * n)
            .map(|i| {
                let (x, y) = ((i % n) as f32 / n as f32, (i / n) as f32 / n as f32);
                // A bowl or a ridge under the noise, by the case.
                let shape = if case % 3 == 0 {
                    (x - 0.5).powi(2) + (y - 0.5).powi(2)
                } else {
                    0.3 - (x - 0.5).abs() * 0.4
                };
                let h = 1.0 + shape + 0.3 * next() - sea * 8.0 * next();
                if steps > 0.0 {
                    (h * steps).round() / steps
                } else {
                    h
                }
            })
            .collect();
        total += same_as_reference(&heights, n, &format!("case {case} ({n} a side)"));
    }
    assert!(total >= 100, "only {total} lakes to compare");
}
