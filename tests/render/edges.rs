//! Sonar and Outline: one-pixel lines, each shared edge once.

use std::collections::HashSet;

use mountains::render::Size;
use mountains::render::raster::{Clip, draw_line, to_fixed};
use mountains::render::view::{self, View};
use mountains::render::{Frame, render_full};
use mountains::settings::{ColorMode, Settings, ViewKind};
use mountains::terrain::Heightfield;

const WHITE: u32 = 0x00ff_ffff;

/// Every grid edge of `field` in the oblique view, each drawn once on its
/// own: the pixels a correct one-pixel outline may use.
fn edge_pixels(field: &Heightfield, w: u32, h: u32) -> HashSet<(u32, u32)> {
    let n = field.size();
    // Fitted as the renderer fits it: to each row's highest point.
    let row_top: Vec<f32> = (0..n)
        .map(|y| field.row(y).iter().fold(0.0f32, |m, &h| m.max(h)))
        .collect();
    let floor = view::near_floor(field);
    let view = View::fitted(
        ViewKind::Oblique,
        n,
        field.extent(),
        (&row_top, floor),
        Size::new(w, h),
    );
    let at = |x: usize, y: usize| {
        let p = view.project(x as f32, y as f32, field.get(x, y).max(0.0));
        to_fixed(p.x, p.y)
    };
    let clip = Clip::frame(w, h);
    let mut set = HashSet::new();
    for y in 0..n {
        for x in 0..n {
            // Right, down, and the oblique view's diagonal: seed 000's,
            // back left to front right.
            let mut ends = vec![];
            if x + 1 < n {
                ends.push((x + 1, y));
            }
            if y + 1 < n {
                ends.push((x, y + 1));
            }
            if x + 1 < n && y + 1 < n {
                ends.push((x + 1, y + 1));
            }
            for (ex, ey) in ends {
                draw_line(at(x, y), at(ex, ey), &clip, |px, py| {
                    set.insert((px, py));
                });
            }
        }
    }
    set
}

fn white_pixels(frame: &Frame) -> HashSet<(u32, u32)> {
    let w = frame.width();
    (0..frame.pixels().len() as u32)
        .filter(|&i| frame.pixels()[i as usize] == WHITE)
        .map(|i| (i % w, i / w))
        .collect()
}

fn sonar(field: &Heightfield, w: u32, h: u32) -> Frame {
    // Oblique: `edge_pixels` projects the mesh with that view.
    let s = Settings {
        color: ColorMode::Sonar,
        view: ViewKind::Oblique,
        ..Settings::default()
    };
    let mut frame = Frame::new(w, h).unwrap();
    render_full(field, &s, &mut frame);
    frame
}

#[test]
fn sonar_outlines_of_a_flat_mesh_are_exactly_its_one_pixel_edges() {
    let mut field = Heightfield::flat(4, 160.0);
    field.heights_mut().fill(1.0);
    for (w, h) in [(300, 200), (640, 200), (97, 131)] {
        let frame = sonar(&field, w, h);
        let white = white_pixels(&frame);
        let edges = edge_pixels(&field, w, h);
        let extra = white.difference(&edges).count();
        let missing = edges.difference(&white).count();
        assert_eq!(
            (extra, missing),
            (0, 0),
            "{w}x{h}: white pixels differ from single edges"
        );
        let other = frame
            .pixels()
            .iter()
            .filter(|&&p| p != WHITE && p != 0)
            .count();
        assert_eq!(
            other, 0,
            "{w}x{h}: sonar drew a colour other than black and white"
        );
    }
}

#[test]
fn sonar_on_relief_draws_no_pixel_off_an_edge() {
    let mut field = Heightfield::flat(4, 160.0);
    let n = field.size();
    for y in 0..n {
        for x in 0..n {
            let (u, v) = (x as f32 - 8.0, y as f32 - 8.0);
            field.set(
                x,
                y,
                30.0 - 0.3 * (u * u + v * v) + ((x * 7 + y * 3) % 5) as f32,
            );
        }
    }
    let frame = sonar(&field, 400, 300);
    let white = white_pixels(&frame);
    let edges = edge_pixels(&field, 400, 300);
    assert!(white.len() > 1000, "too few outline pixels");
    let extra: Vec<_> = white.difference(&edges).take(5).collect();
    assert!(extra.is_empty(), "white pixels off every edge: {extra:?}");
}

#[test]
fn outline_uses_green_for_land_and_blue_for_water_only() {
    let mut field = Heightfield::flat(4, 160.0);
    let n = field.size();
    for y in 0..n {
        for x in 0..n {
            field.set(x, y, 3.0 * (x as f32 - 6.5));
        }
    }
    let s = Settings {
        color: ColorMode::Outline,
        ..Settings::default()
    };
    let mut frame = Frame::new(320, 200).unwrap();
    render_full(&field, &s, &mut frame);
    let colours: HashSet<u32> = frame.pixels().iter().copied().collect();
    assert_eq!(colours.len(), 3, "outline colours: {colours:x?}");
    assert!(colours.contains(&0), "outline is drawn on black");
    // The lines are the palette's outline colours (the renderer kept its
    // own copies, which disagreed with the palette's, tested elsewhere).
    let palette = mountains::render::palette::Palette::new(&s, &field);
    assert!(colours.contains(&palette.outline_land()), "{colours:x?}");
    assert!(colours.contains(&palette.outline_water()), "{colours:x?}");
}
