//! Pictures of each seed program's look made from its own document's
//! rules, by a small painter of their own (not the project's renderer),
//! over the height field the look generates: docs/classics.md shows each
//! beside `mountains render --set look=...`.
//!
//! cargo run --release --example listing_pictures -- -o DIR [--seed N]
//!
//! Writes DIR/fractal-mountain-climbing.png and mountain-terrain.png
//! (640x480), fl3.png (1280x960) and essay.png (640x384: the essay's
//! 1000x600 canvas).

mod canvas;
mod essay;
mod fl3;
mod fmc;
mod mt;

use std::path::PathBuf;

use canvas::Canvas;
use mountains::render::turn;
use mountains::settings::Settings;
use mountains::settings::load::apply_set;
use mountains::terrain::{self, Heightfield};

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let (mut out, mut seed) = (None, 7u64);
    for pair in args.chunks(2) {
        match (pair[0].as_str(), pair.get(1)) {
            ("-o", Some(dir)) => out = Some(PathBuf::from(dir)),
            ("--seed", Some(n)) => seed = n.parse().expect("--seed: a whole number"),
            _ => {
                eprintln!("usage: listing_pictures -o DIR [--seed N]");
                std::process::exit(2);
            }
        }
    }
    let Some(out) = out else {
        eprintln!("usage: listing_pictures -o DIR [--seed N]");
        std::process::exit(2);
    };
    std::fs::create_dir_all(&out).expect("making the output folder");
    let save = |name: &str, canvas: Canvas| {
        let path = out.join(format!("{name}.png"));
        canvas
            .save(&path)
            .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        println!("{}", path.display());
    };

    let (s, field) = look("fractal-mountain-climbing", seed);
    let mut c = Canvas::new(640, 480, 0);
    fmc::draw(&field, s.height, &mut c);
    save("fractal-mountain-climbing", c);

    let (s, field) = look("mountain-terrain", seed);
    let mut c = Canvas::new(640, 480, 0);
    mt::draw(&field, 0x00ff_ffff, s.relative_depth, &mut c);
    save("mountain-terrain", c);

    // Eight plys at the article's "say, a 1280 by 1024 screen" (4:3 here):
    // at 640x480 its pen's lines would cover most of the fills.
    let (_, field) = look("fl3", seed);
    let mut c = Canvas::new(1280, 960, 0);
    fl3::draw(&field, &mut c);
    save("fl3", c);

    let (_, field) = look("essay", seed);
    // Our turn moves the back edge to the left; the essay's theta the
    // other way, from its first view (PI/4: the square edge-on).
    let turned = f64::from(turn::essay_degrees(field.identity()));
    let mut c = Canvas::new(640, 384, 0x00ff_ffff);
    essay::draw(&field, (45.0 - turned).to_radians(), &mut c);
    save("essay", c);
}

/// The default settings under `look`, and the field it makes of `seed`.
fn look(name: &str, seed: u64) -> (Settings, Heightfield) {
    let mut s = Settings::default();
    apply_set(&mut s, "look", name).expect("a look");
    apply_set(&mut s, "seed", &seed.to_string()).expect("a seed");
    let field = terrain::generate(&s, seed);
    (s, field)
}
