//! Speed of the colour work: cast shadows on a 1025x1025 field (1080p) and a
//! 2049x2049 one (4K: swept on every second point), the per-face
//! palette lookup, dithering and a full Ridges picture at 1080p.

use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use glam::Vec3;
use mountains::render::Size;
use mountains::render::palette::Palette;
use mountains::render::ridges::Ridges;
use mountains::render::{Frame, dither, shadow};
use mountains::settings::Settings;
use mountains::terrain::Heightfield;

/// A bumpy 2^n + 1 field with some sea, value-stable.
fn field(exponent: u32) -> Heightfield {
    let n = (1usize << exponent) + 1;
    let mut f = Heightfield::flat(exponent, 400.0);
    for y in 0..n {
        for x in 0..n {
            let (u, v) = (x as f32 / n as f32 * 40.0, y as f32 / n as f32 * 40.0);
            let h =
                40.0 * (u * 0.3).sin() * (v * 0.2).cos() + 12.0 * (u * 1.3 + v * 0.9).sin() + 10.0;
            f.set(x, y, h);
        }
    }
    f
}

fn shadows(c: &mut Criterion) {
    let f = field(10);
    let light = Palette::new(&Settings::default(), &f).light();
    c.bench_function("shadow::cast 1025x1025 default light", |b| {
        b.iter(|| shadow::cast(black_box(&f), black_box(light)))
    });
    let side = Vec3::new(-0.8, 0.3, 0.5).normalize();
    c.bench_function("shadow::cast 1025x1025 side light", |b| {
        b.iter(|| shadow::cast(black_box(&f), black_box(side)))
    });
    let f = field(11);
    c.bench_function("shadow::cast 2049x2049 default light", |b| {
        b.iter(|| shadow::cast(black_box(&f), black_box(light)))
    });
}

fn palette(c: &mut Criterion) {
    let f = field(8);
    let p = Palette::new(&Settings::default(), &f);
    let faces: Vec<(f32, Vec3, f32)> = (0..4096)
        .map(|i| {
            let t = i as f32;
            let n = Vec3::new((t * 0.37).sin() * 0.5, (t * 0.11).cos() * 0.5, 1.0).normalize();
            ((t * 0.618).fract() * 60.0, n, (t * 0.3).sin().abs())
        })
        .collect();
    c.bench_function("Palette::land x4096", |b| {
        b.iter(|| {
            let mut acc = 0u32;
            for &(h, n, lit) in &faces {
                acc ^= p.land(black_box(h), black_box(n), black_box(lit));
            }
            acc
        })
    });
    c.bench_function("Palette::water x4096", |b| {
        b.iter(|| {
            let mut acc = 0u32;
            for &(h, _, _) in &faces {
                acc ^= p.water(black_box(h));
            }
            acc
        })
    });
    c.bench_function("Palette::new 257x257", |b| {
        b.iter(|| Palette::new(black_box(&Settings::default()), black_box(&f)))
    });
}

fn dithering(c: &mut Criterion) {
    c.bench_function("dither level+is_on x4096", |b| {
        b.iter(|| {
            let mut on = 0u32;
            for i in 0..4096u32 {
                let l = dither::level(black_box((i * 0x010101) & 0xff_ffff));
                on += dither::is_on(l, i, i >> 6) as u32;
            }
            on
        })
    });
}

fn ridges(c: &mut Criterion) {
    let f = field(8);
    let s = Settings::default();
    let mut frame = Frame::new(1920, 1080).unwrap();
    c.bench_function("Ridges 1920x1080 all strips", |b| {
        b.iter(|| {
            let r = Ridges::new(&f, &s, Size::new(1920, 1080));
            for i in 0..r.strips_total() {
                r.draw_strip(&mut frame, i);
            }
        })
    });
}

criterion_group!(benches, shadows, palette, dithering, ridges);
criterion_main!(benches);
