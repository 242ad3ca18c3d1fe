//! Smooth land and clean edges (issue 18): under smooth shading ground of
//! gently changing slope has gently changing colour, with no step at the
//! faces' edges; a skyline that runs across the pixel rows is mixed from
//! sky and land, not a staircase of whole pixels.

use mountains::render::classes::{Class, render_classes};
use mountains::render::{Frame, render_full};
use mountains::settings::{Settings, Shading, Sun};
use mountains::terrain::Heightfield;

const W: u32 = 320;
const H: u32 = 180;

/// A field of `2^exponent + 1` points a side, 250 wide, heights `h(x, y)`
/// with x and y in 0..=1 (y towards the viewer).
fn field(exponent: u32, h: impl Fn(f32, f32) -> f32) -> Heightfield {
    let mut f = Heightfield::flat(exponent, 250.0);
    let n = f.size();
    for y in 0..n {
        for x in 0..n {
            let (u, v) = (x as f32 / (n - 1) as f32, y as f32 / (n - 1) as f32);
            f.set(x, y, h(u, v));
        }
    }
    f
}

/// The frame and each pixel's class.
fn drawn(field: &Heightfield, settings: &Settings) -> (Frame, Vec<Class>) {
    let mut frame = Frame::new(W, H).unwrap();
    render_full(field, settings, &mut frame);
    let mut classes = Frame::new(W, H).unwrap();
    render_classes(field, settings, &mut classes).expect("a shaded look");
    let classes = classes.pixels().iter().map(|&p| Class::of(p)).collect();
    (frame, classes)
}

fn settings(shading: Shading) -> Settings {
    Settings {
        shading,
        sun: Sun::Midday,
        shadows: false,
        ..Settings::default()
    }
}

/// How many pairs of neighbouring land pixels, away from every edge of
/// the land and above the front cut face (the bottom rows), differ by more
/// than `levels` in some channel.
fn steps_inside_land(frame: &Frame, classes: &[Class], levels: u32) -> usize {
    let (w, h) = (W as usize, H as usize);
    let land = |x: usize, y: usize| classes[y * w + x] == Class::Land;
    let step = |a: u32, b: u32| {
        [16, 8, 0]
            .map(|s| ((a >> s) & 0xff).abs_diff((b >> s) & 0xff))
            .into_iter()
            .max()
            .unwrap()
    };
    let mut count = 0;
    for y in 2..h * 4 / 5 {
        for x in 2..w - 2 {
            let inside = (y - 2..=y + 2).all(|yy| (x - 2..=x + 2).all(|xx| land(xx, yy)));
            if !inside {
                continue;
            }
            let here = frame.get(x as u32, y as u32);
            let right = frame.get(x as u32 + 1, y as u32);
            let below = frame.get(x as u32, y as u32 + 1);
            count +=
                usize::from(step(here, right) > levels) + usize::from(step(here, below) > levels);
        }
    }
    count
}

#[test]
fn neighbouring_faces_with_nearly_equal_normals_get_nearly_equal_colours() {
    // A broad low dome on a coarse grid: big faces, each turned a little
    // from the next.
    let dome = field(4, |u, v| {
        let (du, dv) = (u - 0.5, v - 0.5);
        12.0 - 15.0 * (du * du + dv * dv)
    });
    // No treeline on the dome (height 1): the colours change with the
    // light, not across the palette's zones. The grid's own light blended
    // across the faces, without the finer relief's texture (relief.rs).
    let lowland = |shading| Settings {
        height: 1,
        fine_relief: false,
        ..settings(shading)
    };
    let (smooth, classes) = drawn(&dome, &lowland(Shading::Smooth));
    let (flat, _) = drawn(&dome, &lowland(Shading::Flat));
    let land = classes.iter().filter(|&&c| c == Class::Land).count();
    assert!(land > (W * H / 3) as usize, "the dome covers {land} pixels");
    // Flat faces step at every edge; smooth ones only where the colours
    // change fastest (the snow line), a few levels a pixel elsewhere.
    let (s, f) = (
        steps_inside_land(&smooth, &classes, 3),
        steps_inside_land(&flat, &classes, 3),
    );
    eprintln!("steps over 3 levels inside the dome: smooth {s}, flat {f}");
    assert!(
        f >= 200,
        "flat faces show few steps ({f}): the test sees nothing"
    );
    assert!(
        s * 10 <= f,
        "smooth shading: {s} steps over 3 levels, flat {f}"
    );
}

#[test]
fn a_slanted_skyline_is_mixed_from_sky_and_land() {
    // Land rising from left to right: its back edge crosses the rows.
    let ramp = field(5, |u, _| 4.0 + 40.0 * u);
    let (frame, classes) = drawn(&ramp, &settings(Shading::Smooth));
    let w = W as usize;
    let (mut columns, mut mixed) = (0, 0);
    for x in 4..w - 4 {
        let Some(top) = (0..H as usize).find(|&y| classes[y * w + x] != Class::Sky) else {
            continue;
        };
        if top < 2 {
            continue;
        }
        columns += 1;
        // The sky's own colour in this row and dither phase, where land is
        // at least three rows further down.
        let row = top - 1;
        let clear = |o: usize| (row..row + 3).all(|y| classes[y * w + o] == Class::Sky);
        let sky_here = (0..w)
            .find(|&o| o % 4 == x % 4 && clear(o))
            .map(|o| frame.get(o as u32, row as u32));
        let above = frame.get(x as u32, row as u32);
        let land = frame.get(x as u32, top as u32 + 1);
        match sky_here {
            Some(sky) if above != sky && above != land => mixed += 1,
            Some(_) => {}
            None => columns -= 1,
        }
    }
    assert!(columns > 100, "only {columns} columns of skyline measured");
    assert!(
        mixed * 3 >= columns,
        "{mixed} of {columns} skyline columns mix sky and land: a staircase"
    );
}

/// The green channel of a packed colour.
fn green(c: u32) -> f32 {
    ((c >> 8) & 0xff) as f32
}

/// Whether packed colour `c` is clearly green (near land here).
fn greenish(c: u32) -> bool {
    green(c) > ((c >> 16) & 0xff) as f32 + 20.0
}

/// A near ridge whose crest climbs from left to right, in front of a
/// valley and a far, higher plateau: the ridge's crest is drawn against the
/// plateau's face, land against farther land.
fn ridge_before_a_plateau(u: f32, v: f32) -> f32 {
    if v < 0.35 {
        70.0
    } else if v < 0.6 {
        4.0
    } else {
        let crest = 12.0 + 30.0 * u;
        4.0 + (crest - 4.0) * (1.0 - ((v - 0.75) / 0.15).abs()).max(0.0)
    }
}

#[test]
fn a_crest_against_farther_land_is_mixed_not_a_staircase() {
    let f = field(6, ridge_before_a_plateau);
    let (frame, classes) = drawn(&f, &settings(Shading::Smooth));
    if let Some(path) = std::env::var_os("MOUNTAINS_DUMP_CREST") {
        mountains::snapshot::write_png(std::path::Path::new(&path), &frame).unwrap();
    }
    let w = W as usize;
    let (mut columns, mut mixed) = (0, 0);
    for x in 8..w - 8 {
        let land = |y: usize| classes[y * w + x] == Class::Land;
        let px = |y: usize| frame.get(x as u32, y as u32);
        // The crest: the first row of the green ridge below the grey
        // plateau, with plateau three rows above it.
        let Some(t) = (3..H as usize - 2).find(|&y| land(y - 3) && greenish(px(y))) else {
            continue;
        };
        let (far, near) = (green(px(t - 3)), green(px(t + 1)));
        if near - far < 20.0 || greenish(px(t - 3)) {
            continue;
        }
        columns += 1;
        // A staircase goes from plateau to ridge in one row; an edge pixel
        // mixed from both lies between them.
        let between = |y: usize| {
            let f = (green(px(y)) - far) / (near - far);
            (0.15..0.85).contains(&f)
        };
        if between(t - 1) || between(t) {
            mixed += 1;
        }
    }
    assert!(columns > 80, "only {columns} columns with a crest measured");
    assert!(
        mixed * 3 >= columns,
        "{mixed} of {columns} crest columns mix near and far land: a staircase"
    );
}
