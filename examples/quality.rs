//! How a frame looks at 1:1 against the same scene drawn k times larger and
//! averaged down (issue 18): PSNR, SSIM, the error along the skyline and the
//! coast, visible facet edges, pixels far off.
//!
//! cargo run --release --example quality -- --size 1920x1080 \
//!     --seeds 1,2,3,5,8,13,21,42 [--set key=value ...] [--k 4] [--dump DIR]
//!
//! `--dump DIR` writes each seed's frame, reference and difference (eight
//! times enlarged) there as PNGs.
//!
//! The reference (LOOKS.md, "At 1:1"): the grid is fixed to what
//! `detail = "auto"` picks at the base size, unless `--set` says otherwise;
//! and the relief below the grid (`fine_relief`) stops at the base frame's
//! pixel (`render_full_finer`); everything else is the seed's own scene
//! (its light and sea are the same at every size). The vista puts its near edge a fixed number of pixels below the
//! bottom at every size, so the reference is drawn kW x Hk and its rows from
//! `crop` on are used, Hk and crop chosen so that the back and near edges
//! land where a k-times-finer sampling of the base camera puts them (worked
//! out from `View::fitted`, so it follows the vista's own constants). The
//! registration is then checked twice: by projecting grid points through
//! both views, and by a brute-force search for the shift of the reference's
//! boxes (in 1/k pixel steps) that best matches the frame's luma.

use std::time::Instant;

use mountains::quality::facets::{self, Facets};
use mountains::quality::image::Image;
use mountains::quality::metrics::{psnr, psnr_of_mse, share_off_by, squared_error, ssim};
use mountains::quality::registration::best_shift;
use mountains::render::Size;
use mountains::render::classes::{Class, render_classes};
use mountains::render::view::{self, View};
use mountains::render::{Frame, detail, render_full, render_full_finer};
use mountains::settings::{Detail, Settings, load};
use mountains::terrain::{self, Heightfield};

/// What the command line asks for.
struct Args {
    width: u32,
    height: u32,
    seeds: Vec<u64>,
    k: u32,
    settings: Settings,
    /// Where to write each seed's frame, reference and difference, if asked.
    dump: Option<std::path::PathBuf>,
}

/// One seed's figures.
#[derive(Default, Clone, Copy)]
struct Figures {
    psnr: f64,
    ssim: f64,
    edge_psnr: f64,
    edge_px: f64,
    edge_error: f64,
    sky: f64,
    water: f64,
    land: f64,
    off8: f64,
    facets: Facets,
    ref_pairs: f64,
    shift: (f64, f64),
    geometry_px: f64,
    seconds: [f64; 3],
}

fn main() {
    let args = match parse(std::env::args().skip(1).collect()) {
        Ok(a) => a,
        Err(e) => {
            eprintln!("quality: {e}");
            eprintln!("usage: quality --size WxH --seeds 1,2,3 [--set key=value ...] [--k 4]");
            std::process::exit(2);
        }
    };
    let (w, h, k) = (args.width, args.height, args.k);
    println!(
        "{w}x{h}, reference {k}x larger; grid exponent {}, sun {:?}",
        args.settings.grid_exponent(),
        args.settings.sun
    );
    println!(
        "{:>5} {:>7} {:>7} {:>8} {:>6} {:>6} {:>6} {:>6} {:>6} {:>6} {:>6} {:>6} {:>6} {:>6} {:>13} {:>6}  seconds: frame, reference, measuring",
        "seed",
        "PSNR",
        "SSIM",
        "edgePSNR",
        "edge%",
        "err%",
        "sky",
        "water",
        "land",
        "off8%",
        "facet%",
        "step%",
        "pair%",
        "refpr%",
        "shift dx,dy",
        "geom",
    );
    let mut all = Vec::new();
    for &seed in &args.seeds {
        let f = measure(&args, seed);
        print_row(&seed.to_string(), &f);
        all.push(f);
    }
    let n = all.len().max(1) as f64;
    let mean = |g: &dyn Fn(&Figures) -> f64| all.iter().map(g).sum::<f64>() / n;
    let m = Figures {
        psnr: mean(&|f| f.psnr),
        ssim: mean(&|f| f.ssim),
        edge_psnr: mean(&|f| f.edge_psnr),
        edge_px: mean(&|f| f.edge_px),
        edge_error: mean(&|f| f.edge_error),
        sky: mean(&|f| f.sky),
        water: mean(&|f| f.water),
        land: mean(&|f| f.land),
        off8: mean(&|f| f.off8),
        facets: Facets {
            land: 0,
            edge_share: mean(&|f| f.facets.edge_share),
            step_share: mean(&|f| f.facets.step_share),
            flat_share: mean(&|f| f.facets.flat_share),
            pair_share: mean(&|f| f.facets.pair_share),
        },
        ref_pairs: mean(&|f| f.ref_pairs),
        shift: (mean(&|f| f.shift.0.abs()), mean(&|f| f.shift.1.abs())),
        geometry_px: mean(&|f| f.geometry_px),
        seconds: [0, 1, 2].map(|i| mean(&|f| f.seconds[i])),
    };
    print_row("mean", &m);
    println!(
        "PSNR in dB over R, G, B against the exact (unrounded) box average; SSIM on BT.601 \
         luma, 11x11 Gaussian window (sigma 1.5), full resolution. edge: pixels next to a \
         sky/water/land boundary, dilated by 1 px (edge% of the frame, err% of the squared \
         error); sky/water/land: PSNR \
         of each class away from it. facet%: land pixels on a visible facet edge; step%: land \
         pixels with a land neighbour over dE 2.3; pair%: neighbouring land pairs over \
         dE 2.3 (refpr%: the same in the reference). shift: best shift of the reference \
         in pixels (mean of |dx|, |dy| in the mean row); geom: largest projection mismatch, px."
    );
}

fn print_row(name: &str, f: &Figures) {
    let pc = |v: f64| format!("{:.2}", 100.0 * v);
    println!(
        "{:>5} {:>7.2} {:>7.4} {:>8.2} {:>6} {:>6} {:>6.1} {:>6.1} {:>6.2} {:>6} {:>6} {:>6} {:>6} {:>6} {:>13} {:>6.3}  {:.2}, {:.2}, {:.2}",
        name,
        f.psnr,
        f.ssim,
        f.edge_psnr,
        pc(f.edge_px),
        pc(f.edge_error),
        f.sky,
        f.water,
        f.land,
        pc(f.off8),
        pc(f.facets.edge_share),
        pc(f.facets.step_share),
        pc(f.facets.pair_share),
        pc(f.ref_pairs),
        format!("{:+.3},{:+.3}", f.shift.0, f.shift.1),
        f.geometry_px,
        f.seconds[0],
        f.seconds[1],
        f.seconds[2],
    );
}

/// Draws `seed` at the base size and k times larger, and measures.
fn measure(args: &Args, seed: u64) -> Figures {
    let (w, h, k) = (args.width, args.height, args.k);
    let settings = &args.settings;
    let field = terrain::generate(settings, seed);
    let t0 = Instant::now();
    let mut frame = Frame::new(w, h).expect("room for the frame");
    render_full(&field, settings, &mut frame);
    let t1 = Instant::now();
    let (hk, crop, geometry_px) = fair_reference(&field, settings, w, h, k);
    eprintln!(
        "seed {seed}: reference {}x{hk}, its rows from {crop} on",
        k * w
    );
    let mut big = Frame::new(k * w, hk).expect("room for the reference");
    render_full_finer(&field, settings, &mut big, k);
    let t2 = Instant::now();
    let (wu, hu, ku) = (w as usize, h as usize, k as usize);
    let reference = Image::box_down(&big, ku, (0, i64::from(crop)), wu, hu);
    let picture = Image::of(&frame);
    let mut class_frame = Frame::new(w, h).expect("room for the classes");
    let classes: Vec<Class> = match render_classes(&field, settings, &mut class_frame) {
        Some(()) => class_frame.pixels().iter().map(|&p| Class::of(p)).collect(),
        None => vec![Class::Land; wu * hu],
    };
    let edge = boundary(&classes, wu, hu);
    let region_psnr = |keep: &dyn Fn(usize) -> bool| {
        let (sum, n) = squared_error(&picture, &reference, keep);
        psnr_of_mse(sum / n as f64)
    };
    let class_psnr = |c: Class| region_psnr(&|i| !edge[i] && classes[i] == c);
    let land: Vec<bool> = classes.iter().map(|&c| c == Class::Land).collect();
    let rounded: Vec<u32> = (reference.rgb.iter())
        .map(|c| {
            let v = c.map(|v| (v + 0.5) as u32);
            v[0] << 16 | v[1] << 8 | v[2]
        })
        .collect();
    if let Some(dir) = &args.dump {
        dump(dir, seed, &frame, &reference);
    }
    let shift = best_shift(&picture, &big, ku, (0, i64::from(crop)), i64::from(k));
    let figures = Figures {
        psnr: psnr(&picture, &reference),
        ssim: ssim(&picture.luma(), &reference.luma(), wu),
        edge_psnr: region_psnr(&|i| edge[i]),
        edge_px: edge.iter().filter(|&&e| e).count() as f64 / edge.len() as f64,
        edge_error: squared_error(&picture, &reference, |i| edge[i]).0
            / squared_error(&picture, &reference, |_| true).0,
        sky: class_psnr(Class::Sky),
        water: class_psnr(Class::Water),
        land: class_psnr(Class::Land),
        off8: share_off_by(&picture, &reference, 8.0),
        facets: facets::measure(frame.pixels(), &land, wu),
        ref_pairs: facets::measure(&rounded, &land, wu).pair_share,
        shift: (shift.dx, shift.dy),
        geometry_px,
        seconds: [0.0; 3],
    };
    let t3 = Instant::now();
    Figures {
        seconds: [t1 - t0, t2 - t1, t3 - t2].map(|d| d.as_secs_f64()),
        ..figures
    }
}

/// Writes `frame`, `reference` (rounded) and their difference (eight
/// times enlarged) as PNGs into `dir`, named by `seed`.
fn dump(dir: &std::path::Path, seed: u64, frame: &Frame, reference: &Image) {
    let pack = |c: [f32; 3]| {
        let v = c.map(|v| (v + 0.5).clamp(0.0, 255.0) as u32);
        v[0] << 16 | v[1] << 8 | v[2]
    };
    let mut refr = Frame::new(frame.width(), frame.height()).expect("room");
    let mut diff = refr.clone();
    for (i, (&p, r)) in frame.pixels().iter().zip(&reference.rgb).enumerate() {
        refr.pixels_mut()[i] = pack(*r);
        let own = mountains::quality::image::channels(p);
        diff.pixels_mut()[i] = pack([0, 1, 2].map(|k| (own[k] - r[k]).abs() * 8.0));
    }
    for (name, f) in [("frame", frame), ("reference", &refr), ("diff", &diff)] {
        let path = dir.join(format!("{seed}-{name}.png"));
        if let Err(e) = mountains::snapshot::write_png(&path, f) {
            eprintln!("quality: {e}");
        }
    }
}

/// The reference's height and the rows to drop from its top so that it is
/// the base view sampled `k` times finer, and the largest mismatch left
/// (base pixels) over grid points projected through both views.
fn fair_reference(
    field: &Heightfield,
    settings: &Settings,
    w: u32,
    h: u32,
    k: u32,
) -> (u32, i32, f64) {
    let tops: Vec<f32> = (0..field.size())
        .map(|y| {
            let row = field.row(y).iter().filter(|v| v.is_finite());
            row.fold(0.0f32, |m, &v| m.max(v))
        })
        .collect();
    let floor = view::near_floor(field);
    let view = |w: u32, h: u32| {
        View::fitted(
            settings.view,
            field.size(),
            field.extent(),
            (&tops, floor),
            Size::new(w, h),
        )
    };
    let steps = (field.size() - 1) as f32;
    let edges = |v: &View| {
        let back = v.project(0.5 * steps, 0.0, 0.0).y;
        (back, v.project(0.5 * steps, steps, 0.0).y - back)
    };
    let base = view(w, h);
    let (back, span) = edges(&base);
    let kf = k as f32;
    let hk = (k * h).saturating_sub(16 * k).max(1)..=k * h + 16 * k;
    let hk = hk
        .min_by(|&a, &b| {
            let miss = |hk: u32| (edges(&view(k * w, hk)).1 - kf * span).abs();
            miss(a).total_cmp(&miss(b))
        })
        .unwrap_or(k * h);
    let big = view(k * w, hk);
    let crop = (edges(&big).0 - kf * back).round();
    let mut worst = 0.0f32;
    for gy in (0..=8).map(|i| steps * i as f32 / 8.0) {
        let top = tops[(gy as usize).min(tops.len() - 1)];
        for gx in (0..=8).map(|i| steps * i as f32 / 8.0) {
            for z in [0.0, top] {
                let fine = big.project(gx, gy, z) - glam::Vec2::new(0.0, crop);
                let d = (fine / kf - base.project(gx, gy, z)).abs().max_element();
                worst = worst.max(d);
            }
        }
    }
    (hk, crop as i32, f64::from(worst))
}

/// Pixels near a boundary between classes: the boundary drawn as the
/// pixels whose right or lower neighbour is of another class (one pixel per
/// crossing), dilated by one pixel (a band 3 pixels wide).
fn boundary(classes: &[Class], w: usize, h: usize) -> Vec<bool> {
    let mut core = vec![false; w * h];
    for y in 0..h {
        for x in 0..w {
            let i = y * w + x;
            core[i] = (x + 1 < w && classes[i] != classes[i + 1])
                || (y + 1 < h && classes[i] != classes[i + w]);
        }
    }
    let mut out = vec![false; w * h];
    for y in 0..h {
        for x in 0..w {
            if core[y * w + x] {
                for yy in y.saturating_sub(1)..(y + 2).min(h) {
                    for xx in x.saturating_sub(1)..(x + 2).min(w) {
                        out[yy * w + xx] = true;
                    }
                }
            }
        }
    }
    out
}

fn parse(argv: Vec<String>) -> Result<Args, String> {
    let mut settings = Settings::default();
    let mut dump = None;
    let (mut size, mut seeds, mut k) = ((1920, 1080), vec![1, 2, 3, 5, 8, 13, 21, 42], 4);
    let mut it = argv.into_iter();
    while let Some(flag) = it.next() {
        let mut value = || it.next().ok_or(format!("{flag} needs a value"));
        match flag.as_str() {
            "--size" => {
                let v = value()?;
                let (a, b) = v.split_once('x').ok_or(format!("--size {v}: want WxH"))?;
                let num = |s: &str| s.parse::<u32>().ok().filter(|&n| n > 0);
                size = num(a).zip(num(b)).ok_or(format!("--size {v}: want WxH"))?;
            }
            "--seeds" => {
                let v = value()?;
                seeds = (v.split(','))
                    .map(|s| {
                        s.trim()
                            .parse()
                            .map_err(|_| format!("--seeds {v}: not a seed: {s}"))
                    })
                    .collect::<Result<_, _>>()?;
            }
            "--k" => {
                let v = value()?;
                k = v
                    .parse()
                    .ok()
                    .filter(|&n| (1..=8).contains(&n))
                    .ok_or(format!("--k {v}: want 1 to 8"))?;
            }
            "--dump" => dump = Some(std::path::PathBuf::from(value()?)),
            "--set" => {
                let v = value()?;
                let (key, raw) = v
                    .split_once('=')
                    .ok_or(format!("--set {v}: want key=value"))?;
                load::apply_set(&mut settings, key.trim(), raw).map_err(|p| p.to_string())?;
            }
            other => return Err(format!("unknown flag {other}")),
        }
    }
    if settings.detail == Detail::Auto {
        settings.detail = Detail::Level(detail::auto_level(&settings, Size::new(size.0, size.1)));
    }
    Ok(Args {
        width: size.0,
        height: size.1,
        seeds,
        k,
        settings,
        dump,
    })
}
