use mountains::settings_ui::{model::Input, screen::Screen};
fn main() {
    let scale: u32 = std::env::args().nth(1).unwrap().parse().unwrap();
    let out = std::env::args().nth(2).unwrap();
    let mut s = Screen::new(
        mountains::settings::Settings::default(),
        &[],
        "/tmp/x/mountains.toml".into(),
        (960 * scale, 620 * scale),
        scale,
    );
    for _ in 0..3 {
        s.input(Input::Down);
    }
    s.input(Input::Right);
    while s.step_preview() {}
    let f = s.draw().clone();
    mountains::snapshot::write_png(std::path::Path::new(&out), &f).unwrap();
}
