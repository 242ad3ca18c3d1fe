//! The mirrored outline of the land against the sky is smooth (issue 33):
//! one colour a water cell, and the mirror's samples, drew it as a
//! staircase of cells, treads 4-8 px long at 4K.

use mountains::render::{Frame, Size, render_full};
use mountains::settings::{Clouds, ColorMode, Settings, Sun, ViewKind, World};
use mountains::terrain::Heightfield;

/// The field's width in height units: small beside the wind's streaks,
/// which are sized in the world, so that they run smoothly across many
/// cells and the outline measured is the mirror's, not the streaks'.
const EXTENT: f32 = 10.0;
/// Grid row (from the back) of the ridge's crest, and its half width.
const CREST: f32 = 40.0;
const HALF_WIDTH: f32 = 10.0;
/// The crest's height at the left and right ends of the ridge.
const LOW: f32 = 0.2;
const HIGH: f32 = 2.0;
/// Grid columns the ridge spans.
const FROM: f32 = 56.0;
const TO: f32 = 72.0;
/// The sea's depth.
const DEPTH: f32 = 0.15;

/// A sea with a ridge across it whose crest climbs from left to right, so
/// that its image in the water ends at a slanting line, on a 129-point
/// grid: cells several pixels wide in the frames drawn.
fn shore() -> Heightfield {
    let mut f = Heightfield::flat(7, EXTENT);
    let n = f.size();
    for y in 0..n {
        for x in 0..n {
            let along = ((x as f32 - FROM) / (TO - FROM)).clamp(0.0, 1.0);
            let crest = LOW + (HIGH - LOW) * along;
            let inside = (FROM..=TO).contains(&(x as f32));
            let across = 1.0 - (y as f32 - CREST).abs() / HALF_WIDTH;
            let h = if inside { crest * across } else { -DEPTH };
            f.set(x, y, h.max(-DEPTH));
        }
    }
    f
}

fn rgb(c: u32) -> [f32; 3] {
    [(c >> 16) & 0xff, (c >> 8) & 0xff, c & 0xff].map(|v| v as f32)
}

/// How far colour `c` lies from `from` towards `to` (0 at `from`, 1 at
/// `to`), along the line between them.
fn towards(c: u32, from: [f32; 3], to: [f32; 3]) -> f32 {
    let c = rgb(c);
    let d: Vec<f32> = (0..3).map(|i| to[i] - from[i]).collect();
    let along: f32 = (0..3).map(|i| (c[i] - from[i]) * d[i]).sum();
    along / d.iter().map(|v| v * v).sum::<f32>()
}

/// The mirrored outline in each column of the middle of the ridge's image
/// in a `w` x `h` frame: the row (to a fraction of a pixel) where the
/// land's image gives way to the sky's, going down from the shore, i.e.
/// where the colour crosses halfway from the land's image to the sky's.
/// Also the mean slope of the crest's image there, in rows a column.
fn outline(w: u32, h: u32) -> (Vec<f32>, f32) {
    let field = shore();
    let s = Settings {
        view: ViewKind::Vista,
        color: ColorMode::Natural,
        world: World::Temperate,
        sun: Sun::Midday,
        reflections: true,
        shadows: false,
        clouds: Clouds::Amount(0.0),
        ..Settings::default()
    };
    let mut frame = Frame::new(w, h).unwrap();
    render_full(&field, &s, &mut frame);
    let view = super::reflections::vista_view(&field, Size::new(w, h));
    let crest = |gx: f32| LOW + (HIGH - LOW) * (gx - FROM) / (TO - FROM);
    let px = |x: u32, y: u32| frame.pixels()[(y * w + x) as usize];
    let (a, b) = (FROM + 0.25 * (TO - FROM), FROM + 0.75 * (TO - FROM));
    let (xa, xb) = (view.project(a, CREST, 0.0).x, view.project(b, CREST, 0.0).x);
    let mut rows = Vec::new();
    for x in xa.ceil() as u32..xb.floor() as u32 {
        // The grid column under screen column x, on the crest's line.
        let gx = a + (b - a) * (x as f32 - xa) / (xb - xa);
        let foot = view.project(gx, CREST + HALF_WIDTH, 0.0).y;
        let image = view.project(gx, CREST, -crest(gx)).y;
        let (land_at, sky_at) = (foot + 0.4 * (image - foot), image + 0.4 * (image - foot));
        assert!(
            sky_at < h as f32 - 1.0,
            "the crest's image is below the frame"
        );
        let (land, sky) = (rgb(px(x, land_at as u32)), rgb(px(x, sky_at as u32)));
        let apart: f32 = (0..3).map(|i| (sky[i] - land[i]).abs()).sum();
        assert!(
            apart > 30.0,
            "column {x}: the land's image {land:?} is too like the sky's {sky:?}"
        );
        let t = |y: u32| towards(px(x, y), land, sky);
        let first = (land_at as u32..sky_at as u32)
            .find(|&y| t(y) >= 0.5)
            .expect("the sky's image below the land's");
        let (t0, t1) = (t(first - 1), t(first));
        rows.push(first as f32 - 1.0 + (0.5 - t0) / (t1 - t0) + 0.5);
    }
    let image = |gx: f32| view.project(gx, CREST, -crest(gx));
    let (ia, ib) = (image(a), image(b));
    (rows, (ib.y - ia.y) / (ib.x - ia.x))
}

/// The longest tread of an outline climbing `slope` rows a column (its
/// rows column by column): the most columns running along which it stays
/// flat, moving less than a third of its slope from one column to the
/// next. A smooth line has treads of one column; a staircase, treads as
/// long as its steps.
fn longest_tread(rows: &[f32], slope: f32) -> usize {
    let flat = |p: &[f32]| (p[1] - p[0]).abs() < slope.abs() / 3.0;
    let mut longest = 1;
    let mut run = 1;
    for pair in rows.windows(2) {
        run = if flat(pair) { run + 1 } else { 1 };
        longest = longest.max(run);
    }
    longest
}

#[test]
fn a_staircase_has_treads_as_long_as_its_steps() {
    let stairs: Vec<f32> = (0..40).map(|x| (x / 5 * 5) as f32 * 1.5).collect();
    assert_eq!(longest_tread(&stairs, 1.5), 5);
    let smooth: Vec<f32> = (0..40).map(|x| x as f32 * 1.5 + 0.3).collect();
    assert_eq!(longest_tread(&smooth, 1.5), 1);
}

#[test]
fn the_mirrored_outline_has_no_tread_longer_than_2_px() {
    for (w, h) in [(960, 720), (1440, 1080)] {
        let (rows, slope) = outline(w, h);
        let shown: Vec<f32> = rows.iter().map(|r| (r * 10.0).round() / 10.0).collect();
        eprintln!("{w}x{h}: slope {slope} rows a column, outline {shown:?}");
        assert!(rows.len() > 40, "only {} columns measured", rows.len());
        assert!(
            slope.abs() > 0.6,
            "the test shore's image climbs {slope} px a column: too flat to see its treads"
        );
        let longest = longest_tread(&rows, slope);
        assert!(
            longest <= 2,
            "{w}x{h}: the mirrored outline has a tread {longest} px long (rows {shown:?})"
        );
    }
}
