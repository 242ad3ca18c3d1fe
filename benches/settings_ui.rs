//! The settings screen: one full redraw at 100% and 200%, and saving.

use criterion::{Criterion, criterion_group, criterion_main};
use mountains::render::Size;
use mountains::settings::Settings;
use mountains::settings::load::DEFAULT_TOML;
use mountains::settings::save::merge;
use mountains::settings_ui::layout::{WINDOW_H, WINDOW_W};
use mountains::settings_ui::model::Input;
use mountains::settings_ui::screen::Screen;

fn redraw(c: &mut Criterion) {
    for scale in [1, 2] {
        let size = Size::new(WINDOW_W * scale, WINDOW_H * scale);
        let file = std::env::temp_dir().join("mountains-bench-none.toml");
        let mut screen = Screen::new(Settings::default(), &[], file, size, scale);
        while screen.step_preview() {}
        c.bench_function(&format!("settings_ui draw {scale}x"), |b| {
            b.iter(|| {
                screen.input(Input::Down);
                screen.draw().pixels()[0]
            })
        });
    }
}

fn save(c: &mut Criterion) {
    let s = Settings {
        cragginess: 12,
        ..Settings::default()
    };
    c.bench_function("settings save merge default.toml", |b| {
        b.iter(|| merge(DEFAULT_TOML, &s).map(|t| t.len()))
    });
}

criterion_group!(benches, redraw, save);
criterion_main!(benches);
