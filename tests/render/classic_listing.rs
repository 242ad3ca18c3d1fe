//! Seed 000's listing (MacTech's *Fractal Mountain Climbing*,
//! MountainsAlgorithm.c) re-implemented for single triangles: its view
//! transform (`CalcPoint3`), its normal, its light and its brightness
//! (`_DrawTriangle`), and its split of each cell (`DrawMountains`), held
//! against the faces our renderer draws under `sun = "classic"` in the
//! oblique view. docs/classics.md works the light through by hand.

use glam::{DVec3, Vec3};
use mountains::render::Size;
use mountains::render::facts::SceneFacts;
use mountains::render::palette::Palette;
use mountains::render::{Frame, render_full};
use mountains::settings::{ColorMode, Settings, Sun, ViewKind};
use mountains::terrain::Heightfield;

/// The listing's `maxIter`, and the iterations of our test field (17 points
/// a side, the listing's `mapS`).
const MAX_ITER: i32 = 9;
const N_ITER: i32 = 4;
/// The listing's `xTh`.
const X_TH: f64 = -1.396;

/// The listing's drawing state: `xc`, `sc` and the matrix `tm`.
struct Listing {
    xc: f64,
    sc: f64,
    tm: [[f64; 3]; 3],
    map_d: f64,
}

impl Listing {
    /// `DrawMountains`' set-up, for a window `wd` pixels wide.
    fn new(wd: f64) -> Self {
        let mut tm = [[0.0; 3]; 3];
        tm[0][0] = 1.0;
        tm[1][1] = X_TH.cos();
        tm[2][1] = X_TH.sin();
        tm[1][2] = -X_TH.sin();
        tm[2][2] = X_TH.cos();
        Listing {
            xc: 0.4073 * (1 << (MAX_ITER - N_ITER)) as f64,
            sc: wd / 630.0,
            tm,
            map_d: (1 << N_ITER) as f64,
        }
    }

    /// `CalcPoint3`: map point (`x`, `y`, height `z`) to viewing space.
    fn calc_point3(&self, p: DVec3) -> DVec3 {
        let xp = (p.x * 2.0 - p.y + self.map_d) * self.xc;
        let yp = (p.y * 2.0) * self.xc;
        let zp = p.z * 0.00217;
        DVec3::new(
            xp * self.sc,
            (yp * self.tm[1][1] + zp * self.tm[2][1] + 230.0) * self.sc,
            (yp * self.tm[1][2] + zp * self.tm[2][2]) * self.sc,
        )
    }

    /// `_DrawTriangle`'s normal (not normalised), light and brightness `i`
    /// for a land triangle given as map points.
    fn shade(&self, p: [DVec3; 3]) -> (DVec3, f64) {
        let p = p.map(|p| self.calc_point3(p));
        let (v1, v2) = (p[1] - p[0], p[2] - p[0]);
        let n = DVec3::new(
            v1.y * v2.z - v1.z * v2.y,
            v1.z * v2.x - v1.x * v2.z,
            v1.x * v2.y - v1.y * v2.x,
        );
        let lx = -1.0 / 3f64.sqrt();
        let (ly, lz) = (-lx, -lx);
        let i = (lx * n.x + ly * n.y + lz * n.z) / (n.x * n.x + n.y * n.y + n.z * n.z).sqrt() * 0.5
            + 0.5;
        (n, i)
    }

    /// A viewing-space normal turned back through the tilt (the transpose
    /// of `tm`), flipped to point up out of the ground, in our palette's
    /// frame (x right, y towards the back, z up).
    fn to_palette_frame(&self, n: DVec3) -> Vec3 {
        let t = &self.tm;
        let world = DVec3::new(
            n.x,
            t[1][1] * n.y + t[1][2] * n.z,
            t[2][1] * n.y + t[2][2] * n.z,
        );
        let up = -world;
        // The listing's y grows towards the viewer.
        DVec3::new(up.x, -up.y, up.z).normalize().as_vec3()
    }
}

/// Mildly rugged land, all above the sea: faces of many slopes, none hiding
/// another in the oblique view.
fn field() -> Heightfield {
    let mut f = Heightfield::flat(N_ITER as u32, 160.0);
    let n = f.size();
    for y in 0..n {
        for x in 0..n {
            let bumps = ((x * 7 + y * 13) % 5) as f32 * 0.6;
            f.set(x, y, 20.0 + bumps + 0.5 * x as f32 - 0.4 * y as f32);
        }
    }
    f
}

fn settings() -> Settings {
    Settings {
        color: ColorMode::Natural,
        view: ViewKind::Oblique,
        sun: Sun::Classic,
        shadows: false,
        rotation: 0,
        ..Settings::default()
    }
}

/// Our height `h` in the listing's height units: its relief stands to its
/// grid as ours does (a column is `2 xc` wide there, `cell` here).
fn listing_z(listing: &Listing, f: &Heightfield, h: f32) -> f64 {
    let cell = (f.extent() / (f.size() - 1) as f32) as f64;
    h as f64 * 2.0 * listing.xc / cell / 0.00217
}

/// The cell's two faces as `DrawMountains` passes them to `DrawTriangle`,
/// each with a point well inside it (local coordinates in the cell) that
/// the other diagonal would put in a different face.
fn listing_faces(x: usize, y: usize) -> [([[usize; 2]; 3], [f32; 2]); 2] {
    [
        ([[x, y], [x, y + 1], [x + 1, y + 1]], [0.25, 0.85]),
        ([[x, y], [x + 1, y + 1], [x + 1, y]], [0.75, 0.15]),
    ]
}

/// A pixel inside face `corners` of `f` (drawn in `frame` of `w` x `h`):
/// the point `inside` (fractions of cell (`cx`, `cy`)) on the face's plane,
/// where `facts` place it.
fn face_pixel(
    facts: &SceneFacts,
    (w, h): (u32, u32),
    (f, corners): (&Heightfield, [[usize; 2]; 3]),
    (cx, cy): (usize, usize),
    inside: [f32; 2],
) -> (u32, u32) {
    let g = corners.map(|[x, y]| (x as f32, y as f32, f.get(x, y)));
    let at = (cx as f32 + inside[0], cy as f32 + inside[1]);
    let z = plane_height(g, at);
    let n = (f.size() - 1) as f32;
    let p = facts.place(at.0 / n, at.1 / n, z);
    ((p.x * w as f32) as u32, (p.y * h as f32) as u32)
}

/// The listing's brightness `i` of face `corners` of `f` and its corners'
/// mean height `az`, both in the listing's own heights: `NormalizeMap`'s,
/// the highest point at `normal_height` (the look draws them at its relief).
fn listing_face(
    listing: &Listing,
    f: &Heightfield,
    corners: [[usize; 2]; 3],
    normal_height: f64,
) -> (f64, f64) {
    let highest = f.min_max().1 as f64;
    let heights = corners.map(|[x, y]| f.get(x, y) as f64 * normal_height / highest);
    let points: [DVec3; 3] =
        std::array::from_fn(|k| DVec3::new(corners[k][0] as f64, corners[k][1] as f64, heights[k]));
    let (_, i) = listing.shade(points);
    (i, heights.iter().sum::<f64>() / 3.0)
}

/// Height of the plane through `corners` (grid points, heights) at `at`.
fn plane_height(corners: [(f32, f32, f32); 3], at: (f32, f32)) -> f32 {
    let [a, b, c] = corners;
    let det = (b.0 - a.0) * (c.1 - a.1) - (c.0 - a.0) * (b.1 - a.1);
    let u = ((at.0 - a.0) * (c.1 - a.1) - (c.0 - a.0) * (at.1 - a.1)) / det;
    let v = ((b.0 - a.0) * (at.1 - a.1) - (at.0 - a.0) * (b.1 - a.1)) / det;
    a.2 + u * (b.2 - a.2) + v * (c.2 - a.2)
}

#[test]
fn the_listings_light_on_a_flat_face_is_0_734_from_the_back_right() {
    let listing = Listing::new(630.0);
    let flat = [
        DVec3::ZERO,
        DVec3::new(0.0, 1.0, 0.0),
        DVec3::new(1.0, 1.0, 0.0),
    ];
    let (n, i) = listing.shade(flat);
    assert!((i - 0.7341).abs() < 1e-3, "flat face: {i}");
    // Our light is the direction the listing's brightness grows towards.
    let f = field();
    let lighting = SceneFacts::of(&f, &settings(), Size::new(64, 48)).lighting;
    assert!(lighting.classic);
    assert!(
        lighting.sun.x > 0.5 && lighting.sun.y > 0.5,
        "{}",
        lighting.sun
    );
    let up = listing.to_palette_frame(n);
    assert!((up - Vec3::Z).length() < 1e-6, "flat normal {up}");
    // Tilting a face towards our sun brightens it in the listing too.
    for towards in [Vec3::X, Vec3::Y, lighting.sun] {
        let d = 0.2 * DVec3::new(towards.x as f64, towards.y as f64, 0.0);
        // Falling away towards `d` (our y is the listing's -y), in the
        // listing's world: X = 2 xc (x - y / 2), Y = 2 xc y, Z = 0.00217 z.
        let fall = |p: DVec3| -(d.x * (p.x - 0.5 * p.y) - d.y * p.y) * 2.0 * listing.xc / 0.00217;
        let tri = [
            DVec3::ZERO,
            DVec3::new(0.0, 1.0, 0.0),
            DVec3::new(1.0, 1.0, 0.0),
        ]
        .map(|p| DVec3::new(p.x, p.y, fall(p)));
        let (_, tilted) = listing.shade(tri);
        assert!(tilted > i, "tilted towards {towards}: {tilted} <= {i}");
    }
}

/// The rendered oblique view's faces, read at a point inside each, against
/// the listing's brightness for the same triangle: the colour our palette
/// gives the face's base colour (its height and steepness) at the listing's
/// normal, and our light on that normal equals the listing's `i`.
#[test]
fn a_rendered_face_has_the_listings_brightness_and_split() {
    let f = field();
    let s = settings();
    let (w, h) = (1280, 960);
    let mut frame = Frame::new(w, h).unwrap();
    render_full(&f, &s, &mut frame);
    let facts = SceneFacts::of(&f, &s, Size::new(w, h));
    let palette = Palette::new(&s, &f);
    let listing = Listing::new(w as f64);
    let mut checked = 0;
    for (cx, cy) in [(8, 8), (3, 11), (12, 4), (6, 2)] {
        for (corners, inside) in listing_faces(cx, cy) {
            let heights = corners.map(|[x, y]| f.get(x, y));
            let map = corners.map(|[x, y]| [x as f64, y as f64]);
            let points: [DVec3; 3] = std::array::from_fn(|k| {
                DVec3::new(map[k][0], map[k][1], listing_z(&listing, &f, heights[k]))
            });
            let (n, i) = listing.shade(points);
            let normal = listing.to_palette_frame(n);
            assert!(normal.z > 0.0, "cell ({cx}, {cy}): {normal}");
            // Our light on the listing's normal is the listing's brightness.
            let ours = palette.lighting().on(normal, 1.0);
            for c in ours {
                assert!(
                    (c as f64 - i).abs() < 1e-4,
                    "cell ({cx}, {cy}): {ours:?} vs {i}"
                );
            }
            // The face's pixel: its base colour at that brightness. Our
            // painter sums the corners in its own order (far face tl, tr,
            // br; near face tl, br, bl: both the listing's first, third,
            // second), which the mean's last bits keep.
            let [a, b, c] = heights;
            let mean = (a + c + b) / 3.0;
            let want = palette.land(mean, normal, 1.0);
            let (px, py) = face_pixel(&facts, (w, h), (&f, corners), (cx, cy), inside);
            let got = frame.get(px, py);
            assert_eq!(
                got, want,
                "cell ({cx}, {cy}) face {corners:?} at pixel ({px}, {py}): \
                 {got:06x}, the listing's brightness {i:.4} gives {want:06x}"
            );
            checked += 1;
        }
    }
    assert_eq!(checked, 8);
}

/// `_DrawTriangle`'s colour for a land triangle whose corners' mean map
/// height is `az`, at brightness `i`, under `normalHeight`: the colour
/// class against the treeline, the HSV blend in unsigned 32-bit integers,
/// `c.blue *= i`, then `HSV2RGB` (here by chroma, hue sixths and the
/// smallest channel), each 16-bit channel shown by its high byte.
fn listing_colour(az: f64, normal_height: f64, i: f64) -> u32 {
    let color = listing_class(az, normal_height);
    let mut cv: [u32; 3] = [0x5555, 0xFFFF, 0xAAAA];
    cv[0] = (150 - color) * (cv[0] - 0x2000) / 150 + 0x2000;
    cv[1] = (cv[1] * (150 - color)) / 150;
    cv[2] = 0xEFFF - (150 - color) * (0xEFFF - cv[2]) / 150;
    let (hue, sat) = (cv[0] as u16, cv[1] as u16);
    let value = ((cv[2] as u16) as f64 * i) as u16;
    let v = value as f64 / 65535.0;
    let chroma = v * sat as f64 / 65535.0;
    let sixth = hue as f64 / 65536.0 * 6.0;
    let x = chroma * (1.0 - ((sixth % 2.0) - 1.0).abs());
    let m = v - chroma;
    let (r, g, b) = match sixth as u32 {
        0 => (chroma, x, 0.0),
        1 => (x, chroma, 0.0),
        2 => (0.0, chroma, x),
        3 => (0.0, x, chroma),
        4 => (x, 0.0, chroma),
        _ => (chroma, 0.0, x),
    };
    let high = |c: f64| (((c + m) * 65535.0 + 0.5) as u32) >> 8;
    (high(r) << 16) | (high(g) << 8) | high(b)
}

/// `_DrawTriangle`'s colour class: 0 (green) below the treeline, 150
/// (grey) 9000 above it, `(az - treeline) / 60` between.
fn listing_class(az: f64, normal_height: f64) -> u32 {
    let treeline = 0.4 * normal_height + 10000.0;
    if az > treeline + 9000.0 {
        150
    } else if az < treeline {
        0
    } else {
        ((az - treeline) / 60.0) as u32
    }
}

/// `_DrawTriangle`'s black-and-white pattern for the same triangle: the
/// HSV value of its class times `i` (`c.blue *= i`), `pat = c.blue * 36 /
/// 0x10000 - 10`, at least 0, capped at 15, or 16 in the grey class.
fn listing_pattern(az: f64, normal_height: f64, i: f64) -> u8 {
    let color = listing_class(az, normal_height);
    let value = 0xEFFF - (150 - color) * (0xEFFF - 0xAAAA) / 150;
    let blue = ((value as u16) as f64 * i) as u16;
    let mut pat = (blue as i64 * 36) / 0x10000 - 10;
    if pat < 0 {
        pat = 0;
    }
    if color == 150 {
        pat.min(16) as u8
    } else {
        pat.min(15) as u8
    }
}

fn fmc_settings() -> Settings {
    let mut s = Settings::default();
    mountains::settings::load::apply_set(&mut s, "look", "fractal-mountain-climbing").unwrap();
    s
}

/// Seed 000's HSV ramp, class by class and light by light, from green
/// (hue 0x5555) through brown to grey: ours and the listing's agree to
/// the bit.
#[test]
fn the_listings_hsv_ramp_is_ours_at_every_class_and_brightness() {
    use mountains::render::listing::Ramp;
    for height in [1, 5, 10] {
        let normal_height = 10000.0 * height as f64;
        let highest = 37.5f32;
        let ramp = Ramp::new(height, highest);
        let mut classes = std::collections::BTreeSet::new();
        for k in 0..=2000 {
            let mean = highest * k as f32 / 2000.0;
            let az = mean as f64 * normal_height / highest as f64;
            for i in [0.0, 0.013, 0.25, 0.5, 0.7341, 0.9, 1.0] {
                let want = listing_colour(az, normal_height, i);
                assert_eq!(
                    ramp.colour(mean, i),
                    want,
                    "height {height}, mean {mean} (az {az}), i {i}"
                );
            }
            classes.insert(ramp.class(mean));
        }
        // Below the treeline only green at height 1; every class above it
        // at 5 and 10.
        if height > 1 {
            assert_eq!(classes.len(), 151, "height {height}");
        }
    }
    // Full light on the listing's first and last colours.
    assert_eq!(listing_colour(0.0, 50000.0, 1.0), 0x00aa00);
    assert_eq!(listing_colour(1e9, 50000.0, 1.0), 0xefefef);
}

/// Under `look = "fractal-mountain-climbing"` a rendered face has the
/// listing's colour for the same triangle, the field's heights normalised
/// as `NormalizeMap` does (the highest point at `normalHeight`): its class
/// from the mean of its corners, its brightness from the listing's normal
/// at the listing's own relief (`0.00217 z` against `2 xc` a column).
/// Water is the listing's light blue and the window behind is black.
/// Land rising towards the back at every step, so that at the listing's
/// relief, seen 10 degrees above the horizon, no face hides another: small
/// bumps on a slope up to the back right, green at the front, grey at the
/// back.
fn rising_field() -> Heightfield {
    let mut f = Heightfield::flat(N_ITER as u32, 160.0);
    let n = f.size();
    for y in 0..n {
        for x in 0..n {
            let bumps = ((x * 7 + y * 13) % 5) as f32 * 0.12;
            f.set(x, y, 20.0 + bumps + 0.5 * x as f32 - 1.2 * y as f32);
        }
    }
    f
}

#[test]
fn a_rendered_face_has_the_listings_colour() {
    let f = rising_field();
    let s = fmc_settings();
    assert_eq!(
        (s.view, s.sun, s.height),
        (ViewKind::Oblique, Sun::Classic, 5)
    );
    let (w, h) = (1280, 960);
    let mut frame = Frame::new(w, h).unwrap();
    render_full(&f, &s, &mut frame);
    let facts = SceneFacts::of(&f, &s, Size::new(w, h));
    assert_eq!(facts.sky, (0, 0));
    assert_eq!(frame.get(2, 2), 0, "the window behind the land is black");
    let listing = Listing::new(w as f64);
    let normal_height = 10000.0 * s.height as f64;
    let mut colours = std::collections::BTreeSet::new();
    for cy in (1..15).step_by(3) {
        for cx in (1..15).step_by(2) {
            for (corners, inside) in listing_faces(cx, cy) {
                let (i, az) = listing_face(&listing, &f, corners, normal_height);
                let want = listing_colour(az, normal_height, i);
                let (px, py) = face_pixel(&facts, (w, h), (&f, corners), (cx, cy), inside);
                let got = frame.get(px, py);
                assert_eq!(
                    got, want,
                    "cell ({cx}, {cy}) face {corners:?} at ({px}, {py}): {got:06x}, \
                     the listing's {want:06x} (i {i:.5}, az {az:.0})"
                );
                colours.insert(want);
            }
        }
    }
    // Green, brown and grey faces, many shades.
    assert!(colours.len() > 20, "{} colours", colours.len());
}

/// The listing's water, RGB (0x9FFF, 0x9FFF, 0xFFFF): a field all below
/// the sea is drawn in it, one colour, unshaded.
#[test]
fn the_listings_water_is_one_light_blue() {
    let mut f = Heightfield::flat(N_ITER as u32, 160.0);
    let n = f.size();
    for y in 0..n {
        for x in 0..n {
            f.set(x, y, -1.0 - ((x * 3 + y * 5) % 7) as f32);
        }
    }
    f.set(8, 8, 4.0);
    let (w, h) = (640, 480);
    let mut frame = Frame::new(w, h).unwrap();
    render_full(&f, &fmc_settings(), &mut frame);
    let pixels: Vec<u32> = (0..h)
        .flat_map(|y| (0..w).map(move |x| (x, y)))
        .map(|(x, y)| frame.get(x, y))
        .collect();
    let water = pixels.iter().filter(|&&p| p == 0x9f9fff).count();
    assert!(water > (w * h / 20) as usize, "{water} water pixels");
    // Nothing else bluish: no depth shading, no reflected sky.
    let other_blue = pixels
        .iter()
        .filter(|&&p| p != 0x9f9fff && (p & 0xff) > ((p >> 16) & 0xff) + 8)
        .count();
    assert_eq!(other_blue, 0);
}

/// The look's view is tipped back as the listing's code tips it, `xTh =
/// -1.396` (80 degrees; the article's "-70 degree" is not what its code
/// does), at its relief: a step back along the ground (`2 xc`) rises `2 xc
/// cos xTh` on screen, a step up of the same size in the map's own heights
/// `0.00217 z sin xTh` with `z` normalised as `NormalizeMap` does, as
/// `CalcPoint3` has it. Our own oblique view keeps 70 degrees and the
/// field's relief.
#[test]
fn the_looks_tilt_and_relief_are_the_listings() {
    let f = field();
    let rise = |s: &Settings| {
        let facts = SceneFacts::of(&f, s, Size::new(1280, 960));
        let cell = f.extent() / (f.size() - 1) as f32;
        let o = facts.place(0.5, 0.5, 0.0);
        // One grid step back, one grid step's length up.
        let back = facts.place(0.5, 0.5 - 1.0 / (f.size() - 1) as f32, 0.0);
        let up = facts.place(0.5, 0.5, cell);
        ((o.y - back.y) / (o.y - up.y)) as f64
    };
    let listing = Listing::new(1280.0);
    // A grid step up, in the field's units, in the listing's height units.
    let cell = (f.extent() / (f.size() - 1) as f32) as f64;
    let up = cell * 10000.0 * fmc_settings().height as f64 / f.min_max().1 as f64;
    let (o, b, u) = (
        listing.calc_point3(DVec3::new(8.0, 8.0, 0.0)),
        listing.calc_point3(DVec3::new(8.0, 7.0, 0.0)),
        listing.calc_point3(DVec3::new(8.0, 8.0, up)),
    );
    let ratio = (o.y - b.y) / (o.y - u.y);
    let ours = rise(&fmc_settings());
    assert!(
        (ours / ratio - 1.0).abs() < 1e-4,
        "{ours} vs the listing's {ratio}"
    );
    let seventy = rise(&settings());
    let want = 70f64.to_radians().cos() / 70f64.to_radians().sin();
    assert!((seventy - want).abs() < 1e-4, "{seventy} vs {want}");
}

/// `DrawTriangle`'s split of a triangle crossing the water line (`z < 0`
/// at one or two corners): the lone corner `ap`, the other two `s0`,
/// `s1` in the triangle's winding, the crossings `m0`, `m1` at `z = 0`,
/// the wet corners set to 0, and three triangles `(ap, m0, m1)`, `(m0, s0,
/// s1)`, `(m0, s1, m1)`, each coloured by `_DrawTriangle` on its own: the
/// land ones by the mean of their own corners (the crossings' zeros
/// counted) and their own normal.
fn listing_split(p: [DVec3; 3]) -> [[DVec3; 3]; 3] {
    let w = p.map(|p| p.z < 0.0);
    let (mut ap, mut s) = if w[0] != w[1] && w[0] != w[2] {
        (p[0], [p[1], p[2]])
    } else if w[1] != w[0] {
        (p[1], [p[2], p[0]])
    } else {
        (p[2], [p[0], p[1]])
    };
    let m = s.map(|s| {
        let f = -ap.z / (s.z - ap.z);
        DVec3::new(ap.x - (ap.x - s.x) * f, ap.y - (ap.y - s.y) * f, 0.0)
    });
    if ap.z < 0.0 {
        ap.z = 0.0;
    } else {
        s[0].z = 0.0;
        s[1].z = 0.0;
    }
    [[ap, m[0], m[1]], [m[0], s[0], s[1]], [m[0], s[1], m[1]]]
}

/// A face crossing the water line under `look = "fractal-mountain-climbing"`
/// is cut as the listing cuts it: each land part has the listing's colour
/// for that part alone (its class from the mean of its own corners, the
/// crossings at 0, so a sliver of land by the shore is greener than its
/// corner), and the water part is the listing's blue.
#[test]
fn a_face_crossing_the_water_line_is_coloured_part_by_part_as_the_listing() {
    // An island with cliffs in a shallow sea: its front edge (row 7)
    // stands near the highest point, the row before it under water, so
    // the parts of the faces between them have means on both sides of the
    // treeline: the two land corners' part above it, the whole face's mean
    // (its wet corner counted) below. Nothing but water lies in front.
    let mut f = Heightfield::flat(N_ITER as u32, 160.0);
    let n = f.size();
    for y in 0..n {
        for x in 0..n {
            let bumps = ((x * 7 + y * 13) % 5) as f32 * 0.3;
            let island = (3..=7).contains(&x) && (4..=7).contains(&y);
            f.set(x, y, if island { 20.0 + bumps } else { -3.0 - bumps });
        }
    }
    let s = fmc_settings();
    let (w, h) = (1280, 960);
    let mut frame = Frame::new(w, h).unwrap();
    render_full(&f, &s, &mut frame);
    let facts = SceneFacts::of(&f, &s, Size::new(w, h));
    let listing = Listing::new(w as f64);
    let normal_height = 10000.0 * s.height as f64;
    let highest = f.min_max().1 as f64;
    let (mut land_parts, mut lone_wet, mut differ) = (0, 0, 0);
    // The island's front cliff and its front corners' sides.
    for cy in [7] {
        for cx in 2..=7 {
            for (corners, _) in listing_faces(cx, cy) {
                let points: [DVec3; 3] = corners.map(|[x, y]| {
                    let z = f.get(x, y) as f64 * normal_height / highest;
                    DVec3::new(x as f64, y as f64, z)
                });
                let wet = points.iter().filter(|p| p.z < 0.0).count();
                if wet == 0 || wet == 3 {
                    continue;
                }
                let whole_az = points.iter().map(|p| p.z).sum::<f64>() / 3.0;
                for part in listing_split(points) {
                    if part.iter().all(|p| p.z == 0.0) {
                        continue;
                    }
                    // The part's own screen size: only parts a pixel can
                    // sit well inside of.
                    let screen = part.map(|p| listing.calc_point3(p));
                    let area = ((screen[1].x - screen[0].x) * (screen[2].y - screen[0].y)
                        - (screen[2].x - screen[0].x) * (screen[1].y - screen[0].y))
                        .abs()
                        / 2.0;
                    if area < 60.0 {
                        continue;
                    }
                    let (_, i) = listing.shade(part);
                    let az = part.iter().map(|p| p.z).sum::<f64>() / 3.0;
                    let want = listing_colour(az, normal_height, i);
                    let centre = (part[0] + part[1] + part[2]) / 3.0;
                    let z = centre.z * highest / normal_height;
                    let nn = (n - 1) as f32;
                    let p = facts.place(centre.x as f32 / nn, centre.y as f32 / nn, z as f32);
                    let (px, py) = ((p.x * w as f32) as u32, (p.y * h as f32) as u32);
                    let got = frame.get(px, py);
                    assert_eq!(
                        got, want,
                        "cell ({cx}, {cy}) face {corners:?}, land part {part:?} at \
                         ({px}, {py}): {got:06x}, the listing's {want:06x} (az {az:.0})"
                    );
                    land_parts += 1;
                    lone_wet += usize::from(wet == 1);
                    let (_, whole_i) = listing.shade(points);
                    differ += usize::from(listing_colour(whole_az, normal_height, whole_i) != want);
                }
            }
        }
    }
    // Parts of both kinds of cut, and many whose colour the whole face's
    // mean would have got wrong.
    assert!(land_parts >= 8, "{land_parts} land parts checked");
    assert!(lone_wet >= 4, "{lone_wet} parts beside a lone wet corner");
    assert!(differ >= 3, "{differ} parts unlike their whole face");
}

/// Under seed 000's look in black and white (`color = "mono"`), a
/// rendered face is filled with the listing's pattern for the same
/// triangle (`bwPat[pat]`, lined up with the frame's origin): every pixel
/// of a whole 8x8 tile inside the face, which tells the 17 patterns apart.
/// The water is `bwPat[8]` and the window black.
#[test]
fn a_rendered_mono_face_has_the_listings_pattern() {
    use mountains::render::dither::is_on;
    let f = rising_field();
    let s = Settings {
        color: ColorMode::Mono,
        ..fmc_settings()
    };
    let (w, h) = (1280, 960);
    let mut frame = Frame::new(w, h).unwrap();
    render_full(&f, &s, &mut frame);
    let facts = SceneFacts::of(&f, &s, Size::new(w, h));
    assert_eq!(frame.get(2, 2), 0, "the window behind the land is black");
    let listing = Listing::new(w as f64);
    let normal_height = 10000.0 * s.height as f64;
    let n = (f.size() - 1) as f32;
    let (mut tiles, mut patterns) = (0, std::collections::BTreeSet::new());
    for cy in 1..15 {
        for cx in 1..15 {
            for (corners, _) in listing_faces(cx, cy) {
                let heights = corners.map(|[x, y]| f.get(x, y));
                let (i, az) = listing_face(&listing, &f, corners, normal_height);
                let want = listing_pattern(az, normal_height, i);
                let screen: [(f32, f32); 3] = std::array::from_fn(|k| {
                    let [x, y] = corners[k];
                    let p = facts.place(x as f32 / n, y as f32 / n, heights[k]);
                    (p.x * w as f32, p.y * h as f32)
                });
                let Some((tx, ty)) = whole_tile_inside(screen) else {
                    continue;
                };
                for y in ty..ty + 8 {
                    for x in tx..tx + 8 {
                        let white = frame.get(x, y) == 0x00ff_ffff;
                        assert_eq!(
                            white,
                            is_on(want, x, y),
                            "cell ({cx}, {cy}) face {corners:?}, pixel ({x}, {y}): \
                             not the listing's pattern {want} (i {i:.5}, az {az:.0})"
                        );
                    }
                }
                tiles += 1;
                patterns.insert(want);
            }
        }
    }
    assert!(tiles >= 40, "only {tiles} faces hold a whole tile");
    assert!(patterns.len() >= 6, "patterns {patterns:?}");
}

/// The top left of an 8x8 tile (lined up with the frame's origin) whose
/// pixel centres all lie at least a pixel inside the screen triangle `t`.
fn whole_tile_inside(t: [(f32, f32); 3]) -> Option<(u32, u32)> {
    let edge = |a: (f32, f32), b: (f32, f32), p: (f32, f32)| {
        let (dx, dy) = (b.0 - a.0, b.1 - a.1);
        ((p.0 - a.0) * dy - (p.1 - a.1) * dx) / (dx * dx + dy * dy).sqrt()
    };
    let area = edge(t[0], t[1], t[2]);
    let inside =
        |p: (f32, f32)| (0..3).all(|k| edge(t[k], t[(k + 1) % 3], p) * area.signum() >= 1.0);
    let lo = |k: usize| {
        t.iter()
            .map(|p| if k == 0 { p.0 } else { p.1 })
            .fold(f32::MAX, f32::min)
    };
    let hi = |k: usize| {
        t.iter()
            .map(|p| if k == 0 { p.0 } else { p.1 })
            .fold(f32::MIN, f32::max)
    };
    let first = |v: f32| (v.max(0.0) as u32).div_ceil(8) * 8;
    for ty in (first(lo(1))..hi(1).max(0.0) as u32).step_by(8) {
        for tx in (first(lo(0))..hi(0).max(0.0) as u32).step_by(8) {
            let corners = [(0, 0), (7, 0), (0, 7), (7, 7)];
            if corners
                .iter()
                .all(|&(dx, dy)| inside(((tx + dx) as f32 + 0.5, (ty + dy) as f32 + 0.5)))
            {
                return Some((tx, ty));
            }
        }
    }
    None
}
