//! Speed of saving and loading data sets.

use std::path::Path;

use criterion::{Criterion, criterion_group, criterion_main};
use mountains::settings::Settings;
use mountains::terrain::Heightfield;
use mountains::terrain::heightmap::{decode, encode};

fn field(exponent: u32) -> Heightfield {
    let mut f = Heightfield::flat(exponent, 400.0);
    let n = f.size();
    for y in 0..n {
        for x in 0..n {
            let (u, v) = (x as f32 / n as f32, y as f32 / n as f32);
            f.set(
                x,
                y,
                40.0 * (u * 23.0).sin() * (v * 17.0).cos() + 9.0 * (u * v * 300.0).sin(),
            );
        }
    }
    f
}

fn foreign_8bit(side: u32) -> Vec<u8> {
    let data: Vec<u8> = (0..side * side)
        .map(|i| (((i % side) as f32 * 0.05).sin() * 100.0 + (i / side) as f32 * 0.1) as u8)
        .collect();
    let mut out = Vec::new();
    let mut enc = png::Encoder::new(&mut out, side, side);
    enc.set_color(png::ColorType::Grayscale);
    enc.set_depth(png::BitDepth::Eight);
    let mut w = enc.write_header().unwrap();
    w.write_image_data(&data).unwrap();
    w.finish().unwrap();
    out
}

fn bench(c: &mut Criterion) {
    let s = Settings::default();
    let p = Path::new("bench.png");
    for n in [8, 10] {
        let f = field(n);
        let side = f.size();
        c.bench_function(&format!("encode {side}"), |b| {
            b.iter(|| encode(&f, Some(1), &s, p).unwrap())
        });
        let bytes = encode(&f, Some(1), &s, p).unwrap();
        c.bench_function(&format!("decode own {side}"), |b| {
            b.iter(|| decode(&bytes, p).unwrap())
        });
    }
    let bytes = foreign_8bit(1000);
    c.bench_function("decode foreign 8-bit 1000 -> 1025", |b| {
        b.iter(|| decode(&bytes, p).unwrap())
    });
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(10);
    targets = bench
}
criterion_main!(benches);
