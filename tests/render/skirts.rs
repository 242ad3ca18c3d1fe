//! Skirts: the cut faces along the right and front edges, down to sea level.

use glam::{Vec2, Vec3};
use mountains::render::Size;
use mountains::render::palette::Palette;
use mountains::render::view::View;
use mountains::render::{Frame, Painter, render_full};
use mountains::settings::{Settings, ViewKind};
use mountains::terrain::Heightfield;
use std::sync::Arc;

const H: f32 = 20.0;

fn plateau() -> Heightfield {
    let mut f = Heightfield::flat(4, 160.0);
    f.heights_mut().fill(H);
    f
}

/// Whether `p` lies inside the quadrilateral `q` (convex, any winding),
/// at least `margin` pixels from its sides.
fn inside(q: [Vec2; 4], p: Vec2, margin: f32) -> bool {
    let side = |a: Vec2, b: Vec2| {
        let d = (b - a).normalize();
        (p - a).perp_dot(d)
    };
    let s: Vec<f32> = (0..4).map(|i| side(q[i], q[(i + 1) % 4])).collect();
    s.iter().all(|&v| v > margin) || s.iter().all(|&v| v < -margin)
}

fn render(field: &Heightfield, view: ViewKind, w: u32, h: u32) -> (Frame, View, Palette) {
    let s = Settings {
        view,
        ..Settings::default()
    };
    let mut frame = Frame::new(w, h).unwrap();
    render_full(field, &s, &mut frame);
    let zmax = field.max().max(0.0);
    let v = View::new(view, field.size(), field.extent(), zmax, Size::new(w, h));
    (frame, v, Palette::new(&s, field))
}

/// Whether packed `c` lies, channel by channel, between `a` and `b` (a
/// colour faded part way towards the haze).
fn between(c: u32, a: u32, b: u32) -> bool {
    [16, 8, 0].iter().all(|&s| {
        let ch = |v: u32| ((v >> s) & 0xff) as i32;
        let (lo, hi) = (ch(a).min(ch(b)), ch(a).max(ch(b)));
        (lo - 1..=hi + 1).contains(&ch(c))
    })
}

/// Counts pixels inside `q` and checks they all have `colour`, faded
/// towards `haze` by aerial perspective at most (`haze == colour`: exactly).
fn check_face(frame: &Frame, q: [Vec2; 4], colour: u32, haze: u32, what: &str) -> usize {
    let (w, h) = (frame.width(), frame.height());
    let mut n = 0;
    for y in 0..h {
        for x in 0..w {
            if inside(q, Vec2::new(x as f32 + 0.5, y as f32 + 0.5), 1.0) {
                let c = frame.pixels()[(y * w + x) as usize];
                if haze == colour {
                    assert_eq!(c, colour, "{what}: pixel ({x}, {y})");
                } else {
                    assert!(
                        between(c, colour, haze),
                        "{what}: pixel ({x}, {y}) {c:06x} is not {colour:06x} faded to {haze:06x}"
                    );
                }
                n += 1;
            }
        }
    }
    n
}

/// The plateau's front cut face (the row nearest the viewer, from its top
/// down to sea level) is drawn in the skirt colour.
fn check_front_face(frame: &Frame, v: &View, palette: &Palette, last: f32, hazy: bool) {
    let front = [
        v.project(0.0, last, H),
        v.project(last, last, H),
        v.project(last, last, 0.0),
        v.project(0.0, last, 0.0),
    ];
    let colour = palette.skirt(Vec3::NEG_Y);
    let haze = if hazy { palette.sky().1 } else { colour };
    let n = check_face(frame, front, colour, haze, "front skirt");
    assert!(n > 200, "front skirt too small: {n} pixels");
}

#[test]
fn a_plateau_shows_its_front_and_right_cut_faces() {
    let f = plateau();
    let last = (f.size() - 1) as f32;
    let (frame, v, palette) = render(&f, ViewKind::Oblique, 320, 240);
    check_front_face(&frame, &v, &palette, last, false);
    let right = [
        v.project(last, 0.0, H),
        v.project(last, last, H),
        v.project(last, last, 0.0),
        v.project(last, 0.0, 0.0),
    ];
    let n = check_face(
        &frame,
        right,
        palette.skirt(Vec3::X),
        palette.skirt(Vec3::X),
        "right skirt",
    );
    assert!(n > 100, "right skirt too small: {n} pixels");
}

#[test]
fn perspective_shows_the_front_cut_face() {
    let f = plateau();
    let last = (f.size() - 1) as f32;
    let (frame, v, palette) = render(&f, ViewKind::Perspective, 320, 240);
    check_front_face(&frame, &v, &palette, last, true);
}

#[test]
fn no_cut_face_below_the_sea() {
    // Sunk below sea level: all water, nothing hangs below the sea plane.
    let mut f = Heightfield::flat(4, 160.0);
    f.heights_mut().fill(-H);
    let (frame, v, _) = render(&f, ViewKind::Oblique, 320, 240);
    let s = Settings {
        view: ViewKind::Oblique,
        ..Settings::default()
    };
    let mut sky = Frame::new(320, 240).unwrap();
    Painter::new(Arc::new(f.clone()), &s, Size::new(320, 240)).step(&mut sky, 0);
    let last = (f.size() - 1) as f32;
    let below = v.project(last * 0.5, last, 0.0).y.ceil() as u32 + 2;
    let w = frame.width();
    for y in below..frame.height() {
        for x in 0..w {
            let i = (y * w + x) as usize;
            assert_eq!(
                frame.pixels()[i],
                sky.pixels()[i],
                "pixel ({x}, {y}) below the sea"
            );
        }
    }
}
