//! The fill rule and lines of `render::raster`.

use mountains::render::raster::{Clip, Fixed2, SUBPIXEL, draw_line, fill_triangle, to_fixed};
use rand::{Rng, SeedableRng};
use rand_pcg::Pcg32;

const W: usize = 96;
const H: usize = 80;

/// A grid of `n` x `n` cells over the rectangle (`x0`, `y0`)-(`x1`, `y1`)
/// (pixels), interior points moved by up to `jitter` of a cell, and how
/// many times its triangles cover each pixel.
fn coverage(n: usize, rect: [f32; 4], jitter: f32, seed: u64, flip: bool) -> Vec<u8> {
    let mut rng = Pcg32::seed_from_u64(seed);
    let [x0, y0, x1, y1] = rect;
    let (cw, ch) = ((x1 - x0) / n as f32, (y1 - y0) / n as f32);
    let mut pts = vec![[0i64; 2]; (n + 1) * (n + 1)];
    for j in 0..=n {
        for i in 0..=n {
            let inner = i > 0 && j > 0 && i < n && j < n;
            let (dx, dy) = if inner && jitter > 0.0 {
                (
                    rng.random_range(-jitter..jitter),
                    rng.random_range(-jitter..jitter),
                )
            } else {
                (0.0, 0.0)
            };
            let p = to_fixed(x0 + (i as f32 + dx) * cw, y0 + (j as f32 + dy) * ch);
            pts[j * (n + 1) + i] = p;
        }
    }
    let mut count = vec![0u8; W * H];
    let clip = Clip::frame(W as u32, H as u32);
    let at = |i: usize, j: usize| pts[j * (n + 1) + i];
    for j in 0..n {
        for i in 0..n {
            let (a, b, c, d) = (at(i, j), at(i + 1, j), at(i, j + 1), at(i + 1, j + 1));
            let tris: [[Fixed2; 3]; 2] = if flip ^ ((i + j) % 2 == 0) {
                [[a, b, c], [b, d, c]]
            } else {
                [[a, b, d], [a, d, c]]
            };
            for t in tris {
                fill_triangle(t, &clip, |y, xa, xb| {
                    for x in xa..xb {
                        count[y as usize * W + x as usize] += 1;
                    }
                });
            }
        }
    }
    count
}

/// Every pixel whose centre is strictly inside `rect` is covered exactly
/// once; pixels on or outside its border at most once.
fn assert_tiles(count: &[u8], rect: [f32; 4], what: &str) {
    let [x0, y0, x1, y1] = rect;
    for y in 0..H {
        for x in 0..W {
            let (cx, cy) = (x as f32 + 0.5, y as f32 + 0.5);
            let c = count[y * W + x];
            let inside = cx > x0 && cx < x1 && cy > y0 && cy < y1;
            if inside {
                assert_eq!(c, 1, "{what}: pixel ({x}, {y}) covered {c} times");
            } else {
                let far = cx < x0 - 0.01 || cx > x1 + 0.01 || cy < y0 - 0.01 || cy > y1 + 0.01;
                assert!(
                    c <= if far { 0 } else { 1 },
                    "{what}: pixel ({x}, {y}) covered {c} times outside"
                );
            }
        }
    }
}

#[test]
fn jittered_meshes_cover_every_pixel_once() {
    let rect = [3.3, 2.7, 90.6, 77.2];
    for seed in 0..40 {
        for n in [3, 8, 30, 120] {
            let flip = seed % 2 == 1;
            let count = coverage(n, rect, 0.15, seed, flip);
            assert_tiles(&count, rect, &format!("seed {seed}, {n} cells"));
        }
    }
}

#[test]
fn meshes_on_exact_pixel_centres_and_corners_cover_once() {
    // Vertices exactly on pixel centres or pixel corners: every tie is decided
    // by the top-left rule.
    for rect in [
        [0.5, 0.5, 80.5, 64.5],
        [0.0, 0.0, 96.0, 80.0],
        [2.0, 1.5, 50.0, 41.5],
    ] {
        for n in [1, 4, 16] {
            for flip in [false, true] {
                let count = coverage(n, rect, 0.0, 0, flip);
                // Pixels centred exactly on the border belong to the top and
                // left edges only.
                for y in 0..H {
                    for x in 0..W {
                        let (cx, cy) = (x as f32 + 0.5, y as f32 + 0.5);
                        let inside = cx >= rect[0] && cx < rect[2] && cy >= rect[1] && cy < rect[3];
                        let expect = u8::from(inside);
                        assert_eq!(
                            count[y * W + x],
                            expect,
                            "rect {rect:?}, {n} cells, pixel ({x}, {y})"
                        );
                    }
                }
            }
        }
    }
}

#[test]
fn degenerate_and_far_triangles_cover_nothing_and_never_panic() {
    let clip = Clip::frame(10, 10);
    let mut hits = 0;
    let flat = [to_fixed(1.0, 1.0), to_fixed(5.0, 5.0), to_fixed(9.0, 9.0)];
    fill_triangle(flat, &clip, |_, a, b| hits += b - a);
    assert_eq!(hits, 0, "a zero-area triangle covered pixels");
    let far = [
        to_fixed(-1e30, 0.0),
        to_fixed(f32::NAN, 1e30),
        to_fixed(f32::INFINITY, -5.0),
    ];
    let big = [[i64::MIN / 4, 0], [i64::MAX / 4, 0], [0, i64::MAX / 4]];
    for tri in [far, big] {
        let mut hits = 0;
        fill_triangle(tri, &clip, |_, a, b| hits += b - a);
        assert!(hits <= 100, "a triangle covered more than the clip");
    }
}

#[test]
fn clip_limits_spans_to_its_rows_and_columns() {
    let clip = Clip {
        x0: 2,
        x1: 7,
        y0: 3,
        y1: 5,
    };
    let tri = [
        to_fixed(-10.0, -10.0),
        to_fixed(40.0, -10.0),
        to_fixed(-10.0, 40.0),
    ];
    let mut rows = Vec::new();
    fill_triangle(tri, &clip, |y, a, b| rows.push((y, a, b)));
    assert_eq!(rows, vec![(3, 2, 7), (4, 2, 7)]);
}

#[test]
fn lines_are_thin_connected_and_the_same_both_ways() {
    let clip = Clip::frame(64, 64);
    let mut rng = Pcg32::seed_from_u64(7);
    for _ in 0..500 {
        let mut p = || -> Fixed2 {
            [
                rng.random_range(0..64 * SUBPIXEL),
                rng.random_range(0..64 * SUBPIXEL),
            ]
        };
        let (a, b) = (p(), p());
        let mut fwd = Vec::new();
        let mut back = Vec::new();
        draw_line(a, b, &clip, |x, y| fwd.push((x, y)));
        draw_line(b, a, &clip, |x, y| back.push((x, y)));
        fwd.sort_unstable();
        back.sort_unstable();
        assert_eq!(fwd, back, "line {a:?}-{b:?} differs by direction");
        let (ax, ay) = ((a[0] / SUBPIXEL) as u32, (a[1] / SUBPIXEL) as u32);
        let (bx, by) = ((b[0] / SUBPIXEL) as u32, (b[1] / SUBPIXEL) as u32);
        let long = ax.abs_diff(bx).max(ay.abs_diff(by)) as usize + 1;
        assert_eq!(
            fwd.len(),
            long,
            "line {a:?}-{b:?}: one pixel per step of its long axis"
        );
        assert!(
            fwd.contains(&(ax, ay)) && fwd.contains(&(bx, by)),
            "ends missing"
        );
    }
}

#[test]
fn line_ends_are_the_lines_own_pixels_next_to_the_end() {
    use mountains::render::raster::draw_line_end;
    let clip = Clip::frame(64, 64);
    let mut rng = Pcg32::seed_from_u64(11);
    for _ in 0..500 {
        let mut p = || -> Fixed2 {
            [
                rng.random_range(0..64 * SUBPIXEL),
                rng.random_range(0..64 * SUBPIXEL),
            ]
        };
        let (a, b) = (p(), p());
        let mut whole = Vec::new();
        draw_line(a, b, &clip, |x, y| whole.push((x, y)));
        let mut end = Vec::new();
        draw_line_end(a, b, &clip, |x, y| end.push((x, y)));
        let (bx, by) = ((b[0] / SUBPIXEL) as u32, (b[1] / SUBPIXEL) as u32);
        let near: Vec<_> = whole
            .iter()
            .copied()
            .filter(|&(x, y)| x.abs_diff(bx) <= 1 && y.abs_diff(by) <= 1)
            .collect();
        end.sort_unstable();
        let mut near = near;
        near.sort_unstable();
        assert_eq!(
            end, near,
            "line {a:?}-{b:?}: end pixels differ from the line's"
        );
    }
}

/// Whether the centre of pixel (`x`, `y`) is covered by triangle `v` under
/// the top-left rule, worked out from scratch: the reference every fill
/// path (narrow scans, wide scans, walked edges) must agree with.
fn covers(v: [Fixed2; 3], x: i64, y: i64) -> bool {
    let (px, py) = (x * SUBPIXEL + SUBPIXEL / 2, y * SUBPIXEL + SUBPIXEL / 2);
    let [a, mut b, mut c] = v;
    let area = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    if area == 0 {
        return false;
    }
    if area > 0 {
        std::mem::swap(&mut b, &mut c);
    }
    [(a, b), (b, c), (c, a)].iter().all(|&(p, q)| {
        let (dx, dy) = (q[0] - p[0], q[1] - p[1]);
        let e = (px - p[0]) * dy - (py - p[1]) * dx;
        let top_left = dy > 0 || (dy == 0 && dx < 0);
        if top_left { e >= 0 } else { e > 0 }
    })
}

/// Random triangles of every box shape the filler tells apart (a few
/// columns, up to eight columns and four rows, larger), slivers a row
/// high among them: the spans cover exactly the pixels whose centres the
/// reference finds inside.
#[test]
fn spans_cover_exactly_the_centres_inside() {
    let mut rng = Pcg32::seed_from_u64(11);
    let clip = Clip::frame(W as u32, H as u32);
    for i in 0..5_000 {
        let (w, h) = match i % 4 {
            0 => (4.0, 4.0),
            1 => (9.0, 1.5),
            2 => (9.0, 5.0),
            _ => (30.0, 30.0),
        };
        // Some cross the frame's edges, where the clip cuts their boxes.
        let (ox, oy) = (rng.random_range(-10.0..90.0), rng.random_range(-10.0..75.0));
        let mut corner = || to_fixed(ox + rng.random_range(0.0..w), oy + rng.random_range(0.0..h));
        let v = [corner(), corner(), corner()];
        let mut got = vec![false; W * H];
        fill_triangle(v, &clip, |y, xa, xb| {
            for x in xa..xb {
                assert!(!got[y as usize * W + x as usize], "{v:?}: a pixel twice");
                got[y as usize * W + x as usize] = true;
            }
        });
        for y in 0..H {
            for x in 0..W {
                assert_eq!(
                    got[y * W + x],
                    covers(v, x as i64, y as i64),
                    "{v:?}: pixel ({x}, {y})"
                );
            }
        }
    }
}
