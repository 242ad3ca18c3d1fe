//! Ridges mode: deterministic, strip by strip, any frame size.

use mountains::render::ridges::Ridges;
use mountains::render::{Frame, Rect};
use mountains::render::{Size, colour};
use mountains::settings::{ColorMode, Settings};
use mountains::terrain::Heightfield;

fn settings() -> Settings {
    Settings {
        color: ColorMode::Ridges,
        ..Settings::default()
    }
}

fn field(phase: f32) -> Heightfield {
    let mut f = Heightfield::flat(6, 64.0);
    for y in 0..65 {
        for x in 0..65 {
            let (u, v) = (x as f32, y as f32);
            let h = 20.0 * (u * 0.13 + phase).sin() * (v * 0.11).cos() + 5.0 * (u * 0.7 + v).sin();
            f.set(x, y, h);
        }
    }
    f
}

fn draw_all(r: &Ridges, frame: &mut Frame) -> Vec<Rect> {
    (0..r.strips_total())
        .map(|i| r.draw_strip(frame, i))
        .collect()
}

fn render(field: &Heightfield, w: u32, h: u32) -> Frame {
    let mut frame = Frame::new(w, h).unwrap();
    draw_all(
        &Ridges::new(field, &settings(), Size::new(w, h)),
        &mut frame,
    );
    frame
}

#[test]
fn same_field_same_picture_other_field_other_picture() {
    let a = render(&field(0.0), 320, 200);
    assert_eq!(a, render(&field(0.0), 320, 200));
    assert_ne!(a, render(&field(1.0), 320, 200));
}

#[test]
fn strips_in_order_give_the_whole_picture_over_anything() {
    let f = field(0.5);
    let r = Ridges::new(&f, &settings(), Size::new(300, 180));
    assert!(r.strips_total() >= 4);
    let whole = render(&f, 300, 180);
    let mut frame = Frame::new(300, 180).unwrap();
    for (i, p) in frame.pixels_mut().iter_mut().enumerate() {
        *p = (i as u32).wrapping_mul(2_654_435_761) & 0xff_ffff;
    }
    draw_all(&r, &mut frame);
    assert_eq!(frame, whole);
}

#[test]
fn each_strip_reports_every_pixel_it_changed() {
    let f = field(0.2);
    let r = Ridges::new(&f, &settings(), Size::new(257, 143));
    let mut frame = Frame::new(257, 143).unwrap();
    for i in 0..r.strips_total() {
        let before = frame.clone();
        let rect = r.draw_strip(&mut frame, i);
        let mut changed = 0;
        for y in 0..143u32 {
            for x in 0..257u32 {
                let k = (y * 257 + x) as usize;
                if before.pixels()[k] != frame.pixels()[k] {
                    changed += 1;
                    assert!(
                        x >= rect.x0 && x < rect.x1 && y >= rect.y0 && y < rect.y1,
                        "strip {i} at {x},{y} outside {rect:?}"
                    );
                }
            }
        }
        assert!(changed > 0, "strip {i} drew nothing");
    }
}

fn luminance(c: u32) -> f32 {
    colour::luminance(colour::unpack(c)) * 255.0
}

#[test]
fn far_ranges_are_paler_and_bluer_than_near_ones() {
    let f = field(0.3);
    let r = Ridges::new(&f, &settings(), Size::new(400, 300));
    let mut frame = Frame::new(400, 300).unwrap();
    let mut crest = Vec::new();
    for i in 0..r.strips_total() {
        let before = frame.clone();
        r.draw_strip(&mut frame, i);
        // The colour just under the crest, where this range shows in the end.
        let top = (0..400u32)
            .filter_map(|x| {
                (0..300u32)
                    .find(|&y| {
                        let k = (y * 400 + x) as usize;
                        before.pixels()[k] != frame.pixels()[k] && (i > 0 || y > 0)
                    })
                    .map(|y| frame.pixels()[((y + 2).min(299) * 400 + x) as usize])
            })
            .next()
            .unwrap();
        crest.push(top);
    }
    // Strip 0 also paints the sky, so compare the ranges of strips 1 and last.
    let (far, near) = (crest[1], crest[crest.len() - 1]);
    assert!(
        luminance(far) > luminance(near) + 40.0,
        "{far:06x} vs {near:06x}"
    );
    assert!(
        (far & 0xff) > (near & 0xff),
        "far must be bluer: {far:06x} vs {near:06x}"
    );
}

#[test]
fn wrong_size_or_index_draws_nothing() {
    let r = Ridges::new(&field(0.0), &settings(), Size::new(64, 48));
    let mut other = Frame::new(65, 48).unwrap();
    assert!(r.draw_strip(&mut other, 0).is_empty());
    assert!(other.pixels().iter().all(|&p| p == 0));
    let mut frame = Frame::new(64, 48).unwrap();
    assert!(r.draw_strip(&mut frame, r.strips_total()).is_empty());
    assert!(frame.pixels().iter().all(|&p| p == 0));
}

#[test]
fn tiny_and_huge_frames_and_flat_fields() {
    let flat = Heightfield::flat(4, 16.0);
    for (w, h) in [(1, 1), (1, 50), (50, 1), (2, 2)] {
        let frame = render(&field(0.0), w, h);
        assert_eq!(frame, render(&field(0.0), w, h));
        render(&flat, w, h);
    }
    // No frame can be this size, so nothing may be allocated for it either.
    let absurd = Ridges::new(&flat, &settings(), Size::new(u32::MAX, u32::MAX));
    assert_eq!(
        absurd.strips_total(),
        Ridges::new(&flat, &settings(), Size::new(8, 8)).strips_total()
    );
    let big = render(&field(0.0), 7680, 2160);
    assert!(big.pixels().iter().any(|&p| p != big.pixels()[0]));
}

#[test]
fn a_higher_height_setting_raises_the_ranges() {
    let f = field(0.4);
    let top_of_front = |height: u32| {
        let s = Settings {
            height,
            ..settings()
        };
        let r = Ridges::new(&f, &s, Size::new(320, 240));
        let mut frame = Frame::new(320, 240).unwrap();
        draw_all(&r, &mut frame).last().unwrap().y0
    };
    assert!(
        top_of_front(10) + 10 < top_of_front(1),
        "{} vs {}",
        top_of_front(10),
        top_of_front(1)
    );
}
