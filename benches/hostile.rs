//! How long the hostile corpus takes (tests/common/hostile.rs): the whole of
//! each half, and the slowest single case, so a spoilt file that makes the
//! decoder or the preferences check slow shows here (the tests bound memory
//! and messages, not time).

use std::path::Path;
use std::time::{Duration, Instant};

use criterion::{Criterion, criterion_group, criterion_main};
use mountains::settings::{Settings, load};
use mountains::terrain::heightmap::decode;

#[path = "../tests/common/heightmaps.rs"]
mod heightmaps;
#[path = "../tests/common/hostile.rs"]
mod hostile;

fn decode_case(png: &[u8]) {
    let _ = std::hint::black_box(decode(png, Path::new("spoilt.png")));
}

fn check_case(text: &str) {
    let mut settings = Settings::default();
    std::hint::black_box(load::apply_toml(&mut settings, text, "spoilt.toml"));
}

/// The slowest case of `cases` (best of five runs each), and its index.
fn slowest<T>(cases: &[T], run: impl Fn(&T)) -> (usize, Duration) {
    let best = |case: &T| {
        (0..5)
            .map(|_| {
                let start = Instant::now();
                run(case);
                start.elapsed()
            })
            .min()
            .unwrap()
    };
    cases
        .iter()
        .map(best)
        .enumerate()
        .max_by_key(|&(_, t)| t)
        .unwrap()
}

fn bench_corpus(c: &mut Criterion) {
    let data_sets = hostile::data_sets();
    let files = hostile::preference_files();
    let (i, t) = slowest(&data_sets, |png| decode_case(png));
    eprintln!("slowest spoilt data set: case {i}, {t:?}");
    let (i, t) = slowest(&files, |text| check_case(text));
    eprintln!("slowest spoilt preferences file: case {i}, {t:?}");
    c.bench_function("hostile_data_sets_1000", |b| {
        b.iter(|| data_sets.iter().for_each(|png| decode_case(png)))
    });
    c.bench_function("hostile_preferences_1000", |b| {
        b.iter(|| files.iter().for_each(|text| check_case(text)))
    });
}

/// A preferences file of 100,000 keys none of which is known, each with
/// a nearest-name search for its message (issue 22: it took 6.0 s).
fn bench_unknown_keys(c: &mut Criterion) {
    let text: String = (0..100_000).map(|i| format!("key_{i:06} = 1\n")).collect();
    c.bench_function("unknown_keys_100000", |b| b.iter(|| check_case(&text)));
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(10);
    targets = bench_corpus, bench_unknown_keys
}
criterion_main!(benches);
