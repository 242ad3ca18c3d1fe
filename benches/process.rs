//! Speed of a whole `mountains render --size 1920x1080` process, as a user
//! runs it: start, generate, draw, encode and write the PNG, exit.
//!
//! `cargo bench --bench process -- --warm-up-time 1 --measurement-time 6`

use std::process::Command;

use criterion::{Criterion, criterion_group, criterion_main};

fn run(args: &[&str]) {
    let status = Command::new(env!("CARGO_BIN_EXE_mountains"))
        .args(args)
        .stdout(std::process::Stdio::null())
        .status()
        .expect("start mountains");
    assert!(status.success(), "mountains {args:?}: {status}");
}

fn bench(c: &mut Criterion) {
    let dir = std::env::temp_dir().join(format!("mountains-bench-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let out = dir.join("frame.png");
    let out = out.to_str().expect("utf-8 temp path");
    // An empty preferences file: the defaults, whatever the user's file says.
    let config = dir.join("empty.toml");
    std::fs::write(&config, "").expect("write empty config");
    let config = config.to_str().expect("utf-8 temp path");
    let base = [
        "render",
        "--config",
        config,
        "--size",
        "1920x1080",
        "--set",
        "seed=42",
    ];
    let cases: [(&str, &[&str]); 2] = [
        ("render_1080p_default", &[]),
        ("render_1080p_detail_10", &["--set", "detail=10"]),
    ];
    for (name, extra) in cases {
        let args: Vec<&str> = base
            .iter()
            .chain(extra)
            .chain(&["-o", out])
            .copied()
            .collect();
        c.bench_function(name, |b| b.iter(|| run(&args)));
    }
    let _ = std::fs::remove_dir_all(&dir);
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(20);
    targets = bench
}
criterion_main!(benches);
