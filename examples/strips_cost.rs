//! What the saver's way of drawing a slide costs against `render`'s, on one
//! core: the saver steps a `Painter` strip by strip from the back (a few
//! strips a tick, each nearer strip drawn over the farther ones: every
//! face's pixels are worked out, also those that a nearer face covers
//! later); `render_full` draws the same picture from the front in bands,
//! leaving out the cells and pixels already covered. Both draw the seed's
//! mountain made for the frame (`detail = "auto"`), with the default
//! preferences (or `--set`'s); the least time of the rounds is kept, and the two
//! pictures are compared.
//!
//! taskset -c 0 cargo run --release --example strips_cost -- [--size WxH] [--seeds A-B] [--rounds N] [--set KEY=VALUE]...
//!
//! Run it on one core (`taskset -c 0`): `render_full` uses every core, and
//! the saver's drawing one, so only then are the two times the two
//! drawings' CPU.

#[path = "shared/flags.rs"]
mod flags;

use std::sync::Arc;
use std::time::{Duration, Instant};

use mountains::render::{Frame, Painter, Size, detail, render_full};
use mountains::settings::Settings;
use mountains::terrain::generate;

/// Strips the saver draws between two looks at its signals (as
/// `saver::show` does): the step size of the strips' drawing here.
const STRIPS_A_STEP: usize = 4;

fn main() {
    let (mut size, mut seeds, mut rounds) = ((1920, 1080), vec![1, 5, 8, 42], 3);
    let mut prefs = Settings::default();
    let args: Vec<String> = std::env::args().skip(1).collect();
    for pair in args.chunks(2) {
        match (pair[0].as_str(), pair.get(1)) {
            ("--size", Some(v)) => size = flags::size(v),
            ("--seeds", Some(v)) => seeds = flags::seeds(v),
            ("--rounds", Some(v)) => rounds = v.parse().expect("--rounds N"),
            ("--set", Some(v)) => flags::set(&mut prefs, v),
            _ => panic!("usage: --size WxH --seeds A-B --rounds N [--set KEY=VALUE]..."),
        }
    }
    let (w, h) = size;
    println!("{w}x{h}, least of {rounds} rounds: render_full, strips from the back (ratio)");
    for seed in seeds {
        let settings = detail::for_frame(&prefs, Size::new(w, h));
        let field = Arc::new(generate(&settings, seed));
        let (mut full, mut strips) = (Duration::MAX, Duration::MAX);
        let mut same = true;
        for _ in 0..rounds {
            let mut a = Frame::new(w, h).expect("frame");
            let t = Instant::now();
            render_full(&field, &settings, &mut a);
            full = full.min(t.elapsed());
            let mut b = Frame::new(w, h).expect("frame");
            let t = Instant::now();
            let mut painter = Painter::new(Arc::clone(&field), &settings, a.size());
            while !painter.is_done() {
                painter.step(&mut b, STRIPS_A_STEP);
            }
            strips = strips.min(t.elapsed());
            same &= a.pixels() == b.pixels();
        }
        let ms = |d: Duration| d.as_secs_f64() * 1e3;
        println!(
            "seed {seed:3}: {:6.1} ms, {:6.1} ms ({:.2}){}",
            ms(full),
            ms(strips),
            ms(strips) / ms(full),
            if same { "" } else { "  THE PICTURES DIFFER" }
        );
    }
}
