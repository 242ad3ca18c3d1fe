//! `generator = "brownian"`: a fractional Brownian surface whose power
//! spectrum falls as `f^-(2H+2)`, the same bits on any thread count, and
//! the same mountain at every detail.

use crate::common::terrain_setup;

use mountains::settings::{Detail, Generator, Settings};
use mountains::terrain::{generate, generate_audited, generate_into, generate_with_threads};
use terrain_setup::settings;

fn brownian(detail: u32, hurst: f32) -> Settings {
    Settings {
        hurst,
        ..settings(Generator::Brownian, detail)
    }
}

fn bits(heights: &[f32]) -> Vec<u32> {
    heights.iter().map(|h| h.to_bits()).collect()
}

/// The periodic `n x n` part of a field (its last row and column repeat
/// the first), in f64.
fn periodic_part(s: &Settings, seed: u64) -> (usize, Vec<f64>) {
    let field = generate(s, seed);
    let n = field.size() - 1;
    let mut out = Vec::with_capacity(n * n);
    for y in 0..n {
        out.extend(field.row(y)[..n].iter().map(|&h| f64::from(h)));
    }
    (n, out)
}

/// The 2D discrete Fourier transform's power `|F(kx, ky)|^2`, by two
/// passes of plain sums (slow, independent of the program's FFT).
fn power_spectrum(n: usize, data: &[f64]) -> Vec<f64> {
    let (cos, sin): (Vec<f64>, Vec<f64>) = (0..n)
        .map(|i| {
            let a = -2.0 * std::f64::consts::PI * i as f64 / n as f64;
            (a.cos(), a.sin())
        })
        .unzip();
    // Rows first: (re, im) per (y, kx).
    let mut rows = vec![(0.0, 0.0); n * n];
    for y in 0..n {
        for kx in 0..n {
            let (mut re, mut im) = (0.0, 0.0);
            for x in 0..n {
                let t = (kx * x) % n;
                re += data[y * n + x] * cos[t];
                im += data[y * n + x] * sin[t];
            }
            rows[y * n + kx] = (re, im);
        }
    }
    let mut power = vec![0.0; n * n];
    for kx in 0..n {
        for ky in 0..n {
            let (mut re, mut im) = (0.0, 0.0);
            for y in 0..n {
                let t = (ky * y) % n;
                let (a, b) = rows[y * n + kx];
                re += a * cos[t] - b * sin[t];
                im += a * sin[t] + b * cos[t];
            }
            power[ky * n + kx] = re * re + im * im;
        }
    }
    power
}

/// The slope of log(power) against log(frequency), the power averaged
/// over rings of integer radius from `lo` to `hi`, fitted by least squares.
fn radial_slope(n: usize, power: &[f64], lo: usize, hi: usize) -> f64 {
    let mut sum = vec![0.0; hi + 1];
    let mut count = vec![0usize; hi + 1];
    for ky in 0..n {
        for kx in 0..n {
            let signed = |k: usize| {
                if k > n / 2 {
                    k as f64 - n as f64
                } else {
                    k as f64
                }
            };
            let r = (signed(kx).powi(2) + signed(ky).powi(2)).sqrt().round() as usize;
            if (lo..=hi).contains(&r) {
                sum[r] += power[ky * n + kx];
                count[r] += 1;
            }
        }
    }
    let points: Vec<(f64, f64)> = (lo..=hi)
        .map(|r| ((r as f64).ln(), (sum[r] / count[r] as f64).ln()))
        .collect();
    let m = points.len() as f64;
    let (mx, my) = points
        .iter()
        .fold((0.0, 0.0), |(a, b), &(x, y)| (a + x / m, b + y / m));
    let (sxy, sxx) = points.iter().fold((0.0, 0.0), |(a, b), &(x, y)| {
        (a + (x - mx) * (y - my), b + (x - mx) * (x - mx))
    });
    sxy / sxx
}

#[test]
fn the_spectrum_falls_as_the_hurst_exponent_says() {
    for hurst in [0.2f32, 0.5, 0.8] {
        for seed in [1, 2] {
            let (n, data) = periodic_part(&brownian(8, hurst), seed);
            let slope = radial_slope(n, &power_spectrum(n, &data), 2, n / 4);
            let want = -(2.0 * f64::from(hurst) + 2.0);
            assert!(
                ((slope - want) / want).abs() < 0.1,
                "H {hurst} seed {seed}: slope {slope:.3}, want {want:.3}"
            );
        }
    }
}

/// The test above can fail: a rougher surface's slope is told apart.
#[test]
fn the_slopes_of_two_hurst_exponents_differ_by_the_law() {
    let slope = |hurst| {
        let (n, data) = periodic_part(&brownian(7, hurst), 3);
        radial_slope(n, &power_spectrum(n, &data), 2, n / 4)
    };
    let (rough, smooth) = (slope(0.1), slope(0.9));
    assert!((smooth - rough + 1.6).abs() < 0.3, "{rough} {smooth}");
}

#[test]
fn the_thread_count_changes_nothing() {
    for detail in [5, 10] {
        let s = brownian(detail, 0.6);
        let one = bits(generate_with_threads(&s, 77, 1).heights());
        for threads in [2, 3, 7] {
            let many = bits(generate_with_threads(&s, 77, threads).heights());
            assert!(one == many, "detail {detail} on {threads} threads differs");
        }
        let audit = generate_audited(&s, 77, 2);
        assert_eq!((audit.rewrites, audit.unset), (0, 0));
        assert!(one == bits(audit.field.heights()));
        let mut old = generate(&brownian(detail, 0.3), 1);
        generate_into(&s, 77, &mut old);
        assert!(one == bits(old.heights()));
    }
}

#[test]
fn seeds_make_different_mountains_and_the_same_seed_the_same() {
    let s = brownian(7, 0.8);
    assert_eq!(
        bits(generate(&s, 5).heights()),
        bits(generate(&s, 5).heights())
    );
    let (a, b) = (generate(&s, 5), generate(&s, 6));
    let same = a
        .heights()
        .iter()
        .zip(b.heights())
        .filter(|(x, y)| x == y)
        .count();
    assert!(same < a.heights().len() / 100, "{same} equal heights");
}

/// A coarser grid is the finer one's mountain without its finest
/// frequencies: at the points they share, they agree closely.
#[test]
fn a_coarser_detail_is_the_same_mountain() {
    let s = |detail| Settings {
        detail: Detail::Level(detail),
        ..brownian(10, 0.8)
    };
    let fine = generate(&s(10), 9);
    let coarse = generate(&s(7), 9);
    let shared = fine.coarsened(3);
    let (lo, hi) = fine.min_max();
    let worst = coarse
        .heights()
        .iter()
        .zip(shared.heights())
        .map(|(a, b)| (a - b).abs())
        .fold(0.0f32, f32::max);
    assert!(
        worst < 0.05 * (hi - lo),
        "worst {worst} of a relief {}",
        hi - lo
    );
}

/// The surface wraps: its last row and column are its first.
#[test]
fn the_periodic_surface_closes_its_edges() {
    let f = generate(&brownian(6, 0.5), 4);
    let last = f.size() - 1;
    for i in 0..=last {
        assert_eq!(f.get(i, 0), f.get(i, last));
        assert_eq!(f.get(0, i), f.get(last, i));
    }
    let (lo, hi) = f.min_max();
    assert!(hi - lo > 20.0, "relief {}", hi - lo);
}
