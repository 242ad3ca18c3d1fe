//! How much the place changes from slide to slide (the worlds): over a run
//! of seeds with the default preferences (or `--set KEY=VALUE`s), how many
//! slides are mostly green below the horizon, how many have water across
//! the bottom third, how many have snow in the lower two thirds, how alike
//! each slide is to its nearest other, and how often the lakes show.
//!
//! cargo run --release --example worlds_survey -- --size 320x180 --seeds 1-120 [--set world=alpine]
//!
//! The classifier (each slide at `--size`, its class picture beside it):
//! - *below the horizon* is the land the class picture marks (not the sky,
//!   not the water); a pixel is *green* when its CIE Lab hue angle lies
//!   between 95 and 200 degrees with a chroma of at least 8 (grass, forest,
//!   jungle; not olive rock or sand); a slide is *mostly green* when over
//!   half its land pixels are;
//! - *water* is a pixel the class picture marks as water whose colour is
//!   not ice or salt (L* under 75) nor sand (b* under 12); a slide has
//!   *water across the bottom third* when over half of the bottom third's
//!   pixels are water;
//! - *snow* is a land pixel with L* of at least 72 and chroma under 14; a
//!   slide has *snow in the lower two thirds* when at least 2% of those
//!   rows' pixels are;
//! - *alike*: each slide box-averaged to a 16x9 thumbnail, each cell in
//!   Lab; two slides are the mean CIE76 dE of their 144 cells apart;
//! - *night*: the slide's light is the night's;
//! - *lakes seen*: at least 0.1% of the frame is water with `lakes = true`
//!   and not with `lakes = false` (the basins' water alone);
//! - *block*: the sky shows along the bottom row: the whole grid is in
//!   view, a block in the sky, instead of the vista's land to the frame's
//!   edges;
//! - *wall*: under a fifth of the top row is sky: the land rises out of
//!   the top of the frame, and the slide is mostly one near face.
//!
//! Each slide's line and each `nearest to` line name the slide's world and
//! time of day, so the near pairs say which worlds and hours sit close.

#[path = "shared/flags.rs"]
mod flags;

use mountains::quality::facets::{delta_e, lab};
use mountains::quality::image::channels;
use mountains::render::Size;
use mountains::render::classes::{Class, render_classes};
use mountains::render::light::Lighting;
use mountains::render::palette::Palette;
use mountains::render::{Frame, detail, render_full};
use mountains::settings::{Settings, worlds};
use mountains::terrain;

/// What one slide is.
struct Slide {
    seed: u64,
    world: String,
    /// The time of day ([`time_of_day`]).
    time: String,
    night: bool,
    green: bool,
    water: bool,
    snow: bool,
    lakes: f64,
    block: bool,
    wall: bool,
    thumb: Vec<[f32; 3]>,
}

fn main() {
    let (mut size, mut seeds) = ((320, 180), (1..=120).collect::<Vec<u64>>());
    let mut prefs = Settings::default();
    let args: Vec<String> = std::env::args().skip(1).collect();
    for pair in args.chunks(2) {
        match (pair[0].as_str(), pair.get(1)) {
            ("--size", Some(v)) => size = flags::size(v),
            ("--seeds", Some(v)) => seeds = flags::seeds(v),
            ("--set", Some(v)) => flags::set(&mut prefs, v),
            _ => panic!("usage: --size WxH --seeds A-B [--set KEY=VALUE]..."),
        }
    }
    let slides: Vec<Slide> = seeds
        .iter()
        .map(|&seed| {
            let s = slide(&prefs, seed, size);
            println!(
                "seed {seed:3} {:9} {:14} night {} green {} water {} snow {} lakes {:.2}%{}",
                s.world,
                s.time,
                s.night as u8,
                s.green as u8,
                s.water as u8,
                s.snow as u8,
                100.0 * s.lakes,
                if s.block {
                    " BLOCK"
                } else if s.wall {
                    " WALL"
                } else {
                    ""
                }
            );
            s
        })
        .collect();
    report(&slides);
}

/// The figures over all `slides`.
fn report(slides: &[Slide]) {
    let n = slides.len();
    let share = |f: &dyn Fn(&Slide) -> bool| {
        100.0 * slides.iter().filter(|s| f(s)).count() as f64 / n as f64
    };
    let mut nearest = Vec::with_capacity(n);
    let mut pairs = Vec::new();
    for (i, a) in slides.iter().enumerate() {
        let (mut best, mut whose) = (f32::INFINITY, 0);
        for (j, b) in slides.iter().enumerate() {
            if i == j {
                continue;
            }
            let d = apart(&a.thumb, &b.thumb);
            if d < best {
                (best, whose) = (d, j);
            }
            if j > i {
                pairs.push(d);
            }
        }
        let b = &slides[whose];
        println!(
            "nearest to seed {:3} ({} {}): seed {:3} ({} {}), dE {best:.1}",
            a.seed, a.world, a.time, b.seed, b.world, b.time
        );
        nearest.push(best);
    }
    pairs.sort_by(f32::total_cmp);
    let median = pairs.get(pairs.len() / 2).copied().unwrap_or(0.0);
    let mean_nearest = nearest.iter().sum::<f32>() / n.max(1) as f32;
    println!("slides: {n}");
    println!(
        "mostly green below the horizon: {:.0}%",
        share(&|s| s.green)
    );
    println!("water across the bottom third: {:.0}%", share(&|s| s.water));
    println!("snow in the lower two thirds: {:.0}%", share(&|s| s.snow));
    println!("night slides: {:.1}%", share(&|s| s.night));
    println!("the grid seen whole, a block: {:.1}%", share(&|s| s.block));
    println!(
        "the land out of the top, a wall: {:.1}%",
        share(&|s| s.wall)
    );
    println!("nearest other slide, mean dE: {mean_nearest:.1}");
    println!("all pairs, median dE: {median:.1}");
    let mut worlds: Vec<&str> = slides.iter().map(|s| s.world.as_str()).collect();
    worlds.sort();
    worlds.dedup();
    for w in worlds {
        let of: Vec<&Slide> = slides.iter().filter(|s| s.world == w).collect();
        let lakes = of.iter().filter(|s| s.lakes >= 0.001).count();
        println!(
            "world {w}: {} slides, lakes seen on {lakes} ({:.0}%)",
            of.len(),
            100.0 * lakes as f64 / of.len() as f64
        );
    }
}

/// Mean CIE76 dE between two thumbnails.
fn apart(a: &[[f32; 3]], b: &[[f32; 3]]) -> f32 {
    a.iter().zip(b).map(|(&x, &y)| delta_e(x, y)).sum::<f32>() / a.len() as f32
}

/// Draws and classifies the slide of `seed`.
fn slide(prefs: &Settings, seed: u64, (w, h): (u32, u32)) -> Slide {
    let chosen = Settings {
        seed: Some(seed),
        ..prefs.clone()
    };
    let settings = detail::for_frame(&chosen, Size::new(w, h));
    let world = worlds::chosen(&settings, Some(seed)).name().to_string();
    let field = terrain::generate(&settings, seed);
    let mut frame = Frame::new(w, h).expect("frame");
    render_full(&field, &settings, &mut frame);
    let classes = classes_of(&field, &settings, (w, h));
    let dry = Settings {
        lakes: false,
        ..worlds::drawn(&settings, Some(seed))
    };
    let dry_field = terrain::generate(&dry, seed);
    let dry_classes = classes_of(&dry_field, &dry, (w, h));
    let labs: Vec<[f32; 3]> = frame.pixels().iter().map(|&p| lab(channels(p))).collect();
    let (w, h) = (w as usize, h as usize);
    let (mut ground, mut green, mut bottom, mut water, mut lower, mut snow) = (0, 0, 0, 0, 0, 0);
    let mut lakes = 0usize;
    for (i, (&c, l)) in classes.iter().zip(&labs).enumerate() {
        let y = i / w;
        let chroma = l[1].hypot(l[2]);
        let hue = l[2].atan2(l[1]).to_degrees();
        if c == Class::Land {
            ground += 1;
            green += usize::from((95.0..=200.0).contains(&hue) && chroma >= 8.0);
        }
        let wet = c == Class::Water && l[0] < 75.0 && l[2] < 12.0;
        if y >= h * 2 / 3 {
            bottom += 1;
            water += usize::from(wet);
        }
        if y >= h / 3 {
            lower += 1;
            snow += usize::from(c == Class::Land && l[0] >= 72.0 && chroma < 14.0);
        }
        lakes += usize::from(c == Class::Water && dry_classes[i] != Class::Water);
    }
    let light = Palette::lighting_for(&worlds::drawn(&settings, Some(seed)), &field);
    Slide {
        seed,
        world,
        time: time_of_day(&light),
        night: light.night > 0.0,
        green: 2 * green > ground,
        water: 2 * water > bottom,
        snow: snow * 50 >= lower,
        lakes: lakes as f64 / (w * h) as f64,
        block: classes[(h - 1) * w..].contains(&Class::Sky),
        wall: 5 * classes[..w].iter().filter(|&&c| c == Class::Sky).count() < w,
        thumb: thumbnail(&labs, w, h),
    }
}

/// The slide's time of day: "night" under a full night's look, "dusk"
/// and how far into it in twilight, else the sun's height and its
/// bearing (degrees round from the viewer's left, 90 ahead), each in
/// degrees.
fn time_of_day(light: &Lighting) -> String {
    let sun = light.sun;
    let up = sun.z.clamp(-1.0, 1.0).asin().to_degrees();
    let round = sun.y.atan2(-sun.x).to_degrees();
    match light.night {
        n if n >= 1.0 => format!("night {round:3.0}"),
        n if n > 0.0 => format!("dusk {n:.2} {round:3.0}"),
        _ => format!("sun {up:2.0} {round:3.0}"),
    }
}

/// The class of every pixel of the slide.
fn classes_of(field: &terrain::Heightfield, s: &Settings, (w, h): (u32, u32)) -> Vec<Class> {
    let mut frame = Frame::new(w, h).expect("frame");
    render_classes(field, s, &mut frame).expect("classes");
    frame.pixels().iter().map(|&p| Class::of(p)).collect()
}

/// The frame box-averaged to 16x9 cells, each in Lab (averaged in Lab).
fn thumbnail(labs: &[[f32; 3]], w: usize, h: usize) -> Vec<[f32; 3]> {
    let (cw, ch) = (16, 9);
    let mut out = Vec::with_capacity(cw * ch);
    for cy in 0..ch {
        for cx in 0..cw {
            let (x0, x1) = (cx * w / cw, (cx + 1) * w / cw);
            let (y0, y1) = (cy * h / ch, (cy + 1) * h / ch);
            let mut sum = [0.0f32; 3];
            for y in y0..y1 {
                for x in x0..x1 {
                    let l = labs[y * w + x];
                    (0..3).for_each(|k| sum[k] += l[k]);
                }
            }
            let n = ((x1 - x0) * (y1 - y0)).max(1) as f32;
            out.push(sum.map(|v| v / n));
        }
    }
    out
}
