//! The settings screen without a window: focus order, values from the key
//! table, slider steps, OK/Cancel/Defaults, mouse hit-testing at 1x and 2x,
//! and the drawn screen.

use crate::common::files;
use files::replace_keeping_mtime;
use std::path::{Path, PathBuf};

use mountains::render::Rect;
use mountains::render::Size;
use mountains::saved;
use mountains::settings::Detail;
use mountains::settings::keys::{self, KEYS, Key, Kind, Value};
use mountains::settings::{ColorMode, Settings, load};
use mountains::settings_ui::font::ADVANCE;
use mountains::settings_ui::layout::{
    Button, HELP_LINE, Hit, Layout, MIN_H, MIN_W, PANEL_W, Part, WINDOW_H, WINDOW_W,
};
use mountains::settings_ui::list_view::BarPart;
use mountains::settings_ui::model::{Effect, Input, Model, focus_count};
use mountains::settings_ui::screen::{Next, Screen};
use mountains::settings_ui::values;

fn layout(scale: u32) -> Layout {
    Layout::new(Size::new(WINDOW_W * scale, WINDOW_H * scale), scale)
}

/// The values these tests start from, spelt out so that a change of a
/// default (the owners of the generators may tune them) does not break them.
fn start() -> Settings {
    Settings {
        seed: None,
        cragginess: 64,
        detail: Detail::Auto,
        sea_level: 0.0,
        color: ColorMode::Natural,
        relative_depth: true,
        low_detail: false,
        shadows: true,
        rotation: 0,
        draw_seconds: 8.0,
        pause_seconds: 10.0,
        ..Settings::default()
    }
}

fn model() -> Model {
    Model::new(start(), &[])
}

fn row(name: &str) -> usize {
    KEYS.iter().position(|k| k.name == name).unwrap()
}

fn value(m: &Model, name: &str) -> Value {
    keys::get(&m.settings, keys::find(name).unwrap())
}

fn focus_on(m: &mut Model, l: &mut Layout, name: &str) {
    while m.focused_row() != Some(row(name)) {
        m.handle(Input::Tab { back: false }, l);
    }
}

fn centre(r: Rect) -> (f64, f64) {
    (f64::from(r.x0 + r.x1) / 2.0, f64::from(r.y0 + r.y1) / 2.0)
}

#[test]
fn tab_visits_every_row_in_key_order_then_every_button_and_wraps() {
    let mut l = layout(1);
    let mut m = model();
    assert_eq!(m.focused_row(), Some(0));
    let mut seen_rows = vec![0];
    let mut seen_buttons = Vec::new();
    for _ in 1..focus_count() {
        m.handle(Input::Tab { back: false }, &mut l);
        match (m.focused_row(), m.focused_button()) {
            (Some(r), None) => seen_rows.push(r),
            (None, Some(b)) => seen_buttons.push(b),
            other => panic!("focus on both or neither: {other:?}"),
        }
    }
    assert_eq!(seen_rows, (0..KEYS.len()).collect::<Vec<_>>());
    assert_eq!(seen_buttons, Button::ALL.to_vec());
    m.handle(Input::Tab { back: false }, &mut l);
    assert_eq!(m.focused_row(), Some(0), "Tab wraps to the first row");
    m.handle(Input::Tab { back: true }, &mut l);
    assert_eq!(
        m.focused_button(),
        Some(Button::Cancel),
        "Shift+Tab goes back"
    );
    m.handle(Input::Up, &mut l);
    assert_eq!(m.focused_button(), Some(Button::Ok));
    m.handle(Input::Left, &mut l);
    assert_eq!(
        m.focused_button(),
        Some(Button::EditFile),
        "arrows move between buttons"
    );
}

#[test]
fn home_and_end_reach_exactly_the_key_tables_range() {
    let mut l = layout(1);
    let mut m = model();
    for (i, key) in KEYS.iter().enumerate() {
        let (min, max) = match key.kind {
            Kind::Int { min, max } => (min as f64, max as f64),
            Kind::Float { min, max } => (min, max),
            _ => continue,
        };
        m.focus = i;
        m.handle(Input::End, &mut l);
        assert_eq!(
            values::number(&m.settings, key),
            Some(max as f32 as f64),
            "{}",
            key.name
        );
        m.handle(Input::Right, &mut l);
        m.handle(Input::PageUp, &mut l);
        assert_eq!(
            values::number(&m.settings, key),
            Some(max as f32 as f64),
            "{} stays at max",
            key.name
        );
        m.handle(Input::Home, &mut l);
        assert_eq!(
            values::number(&m.settings, key),
            Some(min as f32 as f64),
            "{}",
            key.name
        );
        m.handle(Input::Left, &mut l);
        assert_eq!(
            values::number(&m.settings, key),
            Some(min as f32 as f64),
            "{} stays at min",
            key.name
        );
    }
}

#[test]
fn slider_steps_suit_each_range() {
    let mut l = layout(1);
    let mut m = model();
    focus_on(&mut m, &mut l, "cragginess");
    m.handle(Input::Right, &mut l);
    assert_eq!(m.settings.cragginess, 65);
    m.handle(Input::PageUp, &mut l);
    assert_eq!(m.settings.cragginess, 78, "a big step is a tenth of 1-128");
    focus_on(&mut m, &mut l, "sea_level");
    m.handle(Input::Right, &mut l);
    assert_eq!(m.settings.sea_level, 0.02);
    for _ in 0..4 {
        m.handle(Input::Right, &mut l);
    }
    assert_eq!(
        value(&m, "sea_level"),
        // A key's value reads as its f32's shortest decimal: a drifted
        // 0.100000024 would read as that.
        Value::Float(0.1),
        "no binary drift"
    );
    focus_on(&mut m, &mut l, "pause_seconds");
    m.handle(Input::Left, &mut l);
    assert_eq!(
        m.settings.pause_seconds, 8.0,
        "fine steps at small values of a wide range"
    );
    m.handle(Input::End, &mut l);
    m.handle(Input::Left, &mut l);
    assert_eq!(
        m.settings.pause_seconds, 3580.0,
        "coarse steps at large values"
    );
}

#[test]
fn choices_cycle_and_wrap_and_checks_toggle() {
    let mut l = layout(1);
    let mut m = model();
    focus_on(&mut m, &mut l, "color");
    m.handle(Input::Left, &mut l);
    assert_eq!(
        m.settings.color,
        ColorMode::Ridges,
        "left from the first wraps to the last"
    );
    m.handle(Input::Right, &mut l);
    m.handle(Input::Space, &mut l);
    assert_eq!(m.settings.color, ColorMode::Gray);
    focus_on(&mut m, &mut l, "rotation");
    m.handle(Input::Right, &mut l);
    assert_eq!(m.settings.rotation, 90);
    focus_on(&mut m, &mut l, "shadows");
    assert_eq!(m.handle(Input::Space, &mut l), Effect::Repaint);
    assert!(!m.settings.shadows);
    m.handle(Input::Right, &mut l);
    assert!(m.settings.shadows, "right means on");
}

#[test]
fn only_drawing_keys_repaint_the_current_mountain() {
    let mut l = layout(1);
    let mut m = model();
    focus_on(&mut m, &mut l, "color");
    assert_eq!(m.handle(Input::Right, &mut l), Effect::Repaint);
    focus_on(&mut m, &mut l, "relative_depth");
    assert_eq!(m.handle(Input::Space, &mut l), Effect::Repaint);
    focus_on(&mut m, &mut l, "sun");
    assert_eq!(m.handle(Input::Right, &mut l), Effect::Repaint);
    focus_on(&mut m, &mut l, "low_detail");
    assert_eq!(m.handle(Input::Space, &mut l), Effect::Regenerate);
    focus_on(&mut m, &mut l, "cragginess");
    assert_eq!(m.handle(Input::Right, &mut l), Effect::Redraw);
    assert!(m.message.contains("next mountain"), "{}", m.message);
    assert_eq!(m.handle(Input::Char('n'), &mut l), Effect::NewMountain);
    // The slide show's pacing changes nothing drawn: no "next mountain"
    // (it said so for every key it did not repaint).
    focus_on(&mut m, &mut l, "pause_seconds");
    assert_eq!(m.handle(Input::Right, &mut l), Effect::Redraw);
    assert_eq!(m.message, "");
    // The numeric detail remakes the preview as Low Detail does (it waited
    // for the next mountain although Low Detail halves it).
    focus_on(&mut m, &mut l, "detail");
    assert_eq!(m.handle(Input::Right, &mut l), Effect::Regenerate);
}

#[test]
fn typed_values_go_through_the_key_table() {
    let mut l = layout(1);
    let mut m = model();
    focus_on(&mut m, &mut l, "cragginess");
    for c in "200".chars() {
        m.handle(Input::Char(c), &mut l);
    }
    assert_eq!(m.editing.as_deref(), Some("200"));
    assert_eq!(
        m.handle(Input::Enter, &mut l),
        Effect::Redraw,
        "Enter ends typing, not the dialog"
    );
    assert_eq!(
        m.settings.cragginess, 64,
        "an illegal value changes nothing"
    );
    assert!(m.message.contains("1 to 128"), "{}", m.message);
    for c in "100".chars() {
        m.handle(Input::Char(c), &mut l);
    }
    m.handle(Input::Tab { back: false }, &mut l);
    assert_eq!(
        m.settings.cragginess, 100,
        "leaving the row applies what was typed"
    );
    focus_on(&mut m, &mut l, "seed");
    for c in "1234".chars() {
        m.handle(Input::Char(c), &mut l);
    }
    m.handle(Input::Enter, &mut l);
    assert_eq!(m.settings.seed, Some(1234));
    m.handle(Input::Right, &mut l);
    assert_eq!(
        m.settings.seed, None,
        "arrows switch the seed back to random"
    );
    focus_on(&mut m, &mut l, "draw_seconds");
    m.handle(Input::Backspace, &mut l);
    m.handle(Input::Char('5'), &mut l);
    assert_eq!(
        m.editing.as_deref(),
        Some("8.5"),
        "backspace edits the shown value"
    );
    assert_eq!(
        m.handle(Input::Escape, &mut l),
        Effect::Redraw,
        "Esc cancels typing only"
    );
    assert_eq!(m.settings.draw_seconds, 8.0);
}

#[test]
fn ok_cancel_and_defaults() {
    let mut l = layout(1);
    let start = Settings {
        cragginess: 7,
        color: ColorMode::Sonar,
        ..Settings::default()
    };
    let mut m = Model::new(start.clone(), &[]);
    assert_eq!(
        m.handle(Input::Enter, &mut l),
        Effect::Save,
        "Enter on a row is OK"
    );
    assert_eq!(m.handle(Input::Escape, &mut l), Effect::Close);
    assert_eq!(m.settings, start, "neither changes the values");
    assert_eq!(m.activate(Button::Defaults), Effect::Regenerate);
    assert_eq!(m.settings, Settings::default());
    assert_eq!(m.original, start, "defaults are on the screen only");
    assert!(m.changed(row("cragginess")) && !m.changed(row("detail")));
    assert_eq!(m.activate(Button::Cancel), Effect::Close);
}

#[test]
fn a_file_that_does_not_parse_cannot_be_saved_and_offers_edit_file() {
    let mut l = layout(1);
    let mut s = Settings::default();
    let problems = load::apply_toml(&mut s, "color = = 3\n", "/home/u/mountains.toml");
    let mut m = Model::new(s, &problems);
    assert_eq!(m.focused_button(), Some(Button::EditFile));
    assert!(
        m.message.contains("/home/u/mountains.toml:1:"),
        "{}",
        m.message
    );
    assert!(m.message.contains("Edit file"), "{}", m.message);
    assert_eq!(m.handle(Input::Enter, &mut l), Effect::EditFile);
    assert_eq!(m.activate(Button::Ok), Effect::Redraw, "OK does not save");
    assert_eq!(
        m.handle(Input::Enter, &mut l),
        Effect::Redraw,
        "nor does Enter"
    );
    // Syntax errors that name their key stop the reading too.
    for text in [
        "seed = 1\nseed = 2\n",
        "cragginess =\n",
        "seed = 18446744073709551615\n",
    ] {
        let mut s = Settings::default();
        let problems = load::apply_toml(&mut s, text, "/home/u/mountains.toml");
        let mut m = Model::new(s, &problems);
        assert_eq!(m.focused_button(), Some(Button::EditFile), "{text}");
        assert!(
            m.message.contains("OK cannot save"),
            "{text}: {}",
            m.message
        );
        assert_eq!(m.activate(Button::Ok), Effect::Redraw, "{text}");
    }
}

#[test]
fn hit_testing_agrees_at_100_and_200_percent() {
    let one = layout(1);
    let two = layout(2);
    let probes = [
        (Hit::Button(Button::Ok), centre(one.button(Button::Ok))),
        (Hit::Button(Button::New), centre(one.button(Button::New))),
        (Hit::Row(row("cragginess"), Part::Label), {
            let r = one.row(row("cragginess"));
            (f64::from(r.x0 + 20), f64::from(r.y0 + 9))
        }),
        (Hit::Row(row("detail"), Part::Plus), {
            let ((_, _), (p0, p1)) = one.minus_plus();
            (
                f64::from(p0 + p1) / 2.0,
                f64::from(one.row(row("detail")).y0 + 9),
            )
        }),
        (Hit::Preview, centre(one.preview)),
    ];
    for (expected, (x, y)) in probes {
        assert_eq!(one.hit(x, y, None), Some(expected), "1x at {x},{y}");
        assert_eq!(
            two.hit(2.0 * x, 2.0 * y, None),
            Some(expected),
            "2x at {x},{y}"
        );
        assert_eq!(two.hit(2.0 * x + 1.0, 2.0 * y + 1.0, None), Some(expected));
    }
    assert_eq!(one.hit(-1.0, 5.0, None), None);
    assert_eq!(one.hit(f64::NAN, 5.0, None), None);
    // Rows do not overlap and sit below one another, wherever the list
    // is scrolled to.
    let mut one = one;
    for i in 1..KEYS.len() {
        one.reveal_row(i);
        assert!(
            one.row_shown(i - 1) && one.row_shown(i),
            "rows {i} and before"
        );
        assert!(one.row(i).y0 >= one.row(i - 1).y1);
    }
}

#[test]
fn mouse_clicks_drags_and_wheel_change_values() {
    for scale in [1, 2] {
        let mut l = layout(scale);
        let mut m = model();
        let y = f64::from(l.row(row("cragginess")).y0 + l.px(9));
        let ((m0, m1), (p0, p1)) = l.minus_plus();
        m.handle(Input::Press(f64::from(p0 + p1) / 2.0, y), &mut l);
        m.handle(Input::Release(f64::from(p0 + p1) / 2.0, y), &mut l);
        assert_eq!(m.settings.cragginess, 65, "plus at {scale}x");
        m.handle(Input::Press(f64::from(m0 + m1) / 2.0, y), &mut l);
        assert_eq!(m.settings.cragginess, 64, "minus at {scale}x");
        let (t0, t1) = l.track();
        m.handle(Input::Press(f64::from(t0 + t1) / 2.0, y), &mut l);
        assert_eq!(m.settings.cragginess, 65, "middle of 1-128 at {scale}x");
        m.handle(Input::Move(f64::from(t1) + 500.0, y + 300.0), &mut l);
        assert_eq!(
            m.settings.cragginess, 128,
            "dragging past the end at {scale}x"
        );
        m.handle(Input::Release(f64::from(t1) + 500.0, y + 300.0), &mut l);
        m.handle(Input::Move(f64::from(t0), y), &mut l);
        assert_eq!(m.settings.cragginess, 128, "no drag after release");
        let dy = f64::from(l.row(row("detail")).y0 + l.px(9));
        // The wheel over a row without the focus scrolls the list (at its
        // top here: nothing moves) and changes nothing.
        m.handle(Input::Wheel(f64::from(t0), dy, 1), &mut l);
        assert_eq!(
            m.settings.detail,
            Detail::Auto,
            "wheel over detail at {scale}x"
        );
        assert_eq!(m.focused_row(), Some(row("cragginess")));
        assert_eq!(l.list.first(), 0);
        // Clicked (on its label, which changes nothing), the row takes the wheel.
        let label_x = f64::from(l.row(row("detail")).x0 + l.px(20));
        m.handle(Input::Press(label_x, dy), &mut l);
        m.handle(Input::Release(label_x, dy), &mut l);
        assert_eq!(m.settings.detail, Detail::Auto);
        m.handle(Input::Wheel(f64::from(t0), dy, 1), &mut l);
        // The key's least level: 3 (seed 000's Iterations menu).
        assert_eq!(
            m.settings.detail,
            Detail::Level(3),
            "wheel up from auto at {scale}x"
        );
        assert_eq!(m.focused_row(), Some(row("detail")));
        let cy = f64::from(l.row(row("shadows")).y0 + l.px(9));
        m.handle(Input::Press(f64::from(m0) + 2.0, cy), &mut l);
        assert!(!m.settings.shadows, "check box at {scale}x");
        let (ok_x, ok_y) = centre(l.button(Button::Ok));
        assert_eq!(m.handle(Input::Press(ok_x, ok_y), &mut l), Effect::Redraw);
        assert_eq!(m.handle(Input::Release(ok_x, ok_y), &mut l), Effect::Save);
        let (cx, cy) = centre(l.button(Button::Cancel));
        m.handle(Input::Press(cx, cy), &mut l);
        assert_eq!(
            m.handle(Input::Release(ok_x, ok_y), &mut l),
            Effect::Redraw,
            "releasing away from the pressed button does nothing"
        );
    }
}

#[test]
fn the_open_list_is_driven_by_keys_and_clicks() {
    let mut l = layout(1);
    let mut m = model();
    let files = vec![PathBuf::from("/d/a.png"), PathBuf::from("/d/b.png")];
    m.show_list(files.clone(), "/d");
    m.handle(Input::Down, &mut l);
    assert_eq!(
        m.handle(Input::Enter, &mut l),
        Effect::OpenDataSet(files[1].clone())
    );
    assert!(m.open_list.is_none());
    m.show_list(files.clone(), "/d");
    let (x, y) = centre(l.list_item(0));
    assert_eq!(
        m.handle(Input::Press(x, y), &mut l),
        Effect::OpenDataSet(files[0].clone())
    );
    m.show_list(files, "/d");
    assert_eq!(
        m.handle(Input::Escape, &mut l),
        Effect::Redraw,
        "Esc closes the list only"
    );
    assert!(m.open_list.is_none());
    m.show_list(Vec::new(), "/d");
    assert!(m.message.contains("/d"), "{}", m.message);
}

fn scratch(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("ui-{name}"));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn screen(file: &Path, scale: u32) -> Screen {
    let mut s = start();
    let problems = if file.exists() {
        load::apply_file(&mut s, file)
    } else {
        Vec::new()
    };
    let size = Size::new(WINDOW_W * scale, WINDOW_H * scale);
    let mut sc = Screen::new(s, &problems, file.to_path_buf(), size, scale);
    sc.set_data_dir(Some(file.with_file_name("data")));
    sc
}

#[test]
fn ok_writes_the_file_and_cancel_writes_nothing() {
    let dir = scratch("okcancel");
    let file = dir.join("mountains.toml");
    let text = "# mine\ncragginess = 40 # sharp\nzzz = 1\n";
    std::fs::write(&file, text).unwrap();
    let mut sc = screen(&file, 1);
    for input in [Input::Down, Input::Down, Input::Right, Input::Escape] {
        sc.input(input);
    }
    assert_eq!(std::fs::read_to_string(&file).unwrap(), text);
    let mut sc = screen(&file, 1);
    for input in [Input::Down, Input::Down, Input::Right] {
        assert_eq!(sc.input(input), Next::Stay);
    }
    assert_eq!(sc.input(Input::Enter), Next::Close);
    assert_eq!(
        std::fs::read_to_string(&file).unwrap(),
        "# mine\ncragginess = 41 # sharp\nzzz = 1\n"
    );
}

#[test]
fn ok_on_a_broken_file_keeps_the_window_open_and_the_file() {
    let dir = scratch("broken");
    let file = dir.join("mountains.toml");
    std::fs::write(&file, "cragginess = [\n").unwrap();
    let mut sc = screen(&file, 1);
    sc.model.activate(Button::Ok);
    assert_eq!(sc.apply(Effect::Save), Next::Stay);
    assert_eq!(std::fs::read_to_string(&file).unwrap(), "cragginess = [\n");
    assert!(
        sc.model.message.contains("not saved"),
        "{}",
        sc.model.message
    );
}

/// OK on a preferences file that is a link to nowhere keeps the window
/// open and the link a link, and says why: no file of the defaults is put
/// in the link's place.
#[cfg(unix)]
#[test]
fn ok_on_a_link_to_nowhere_keeps_the_window_open_and_the_link() {
    let dir = scratch("nowhere");
    let file = dir.join("mountains.toml");
    std::os::unix::fs::symlink(dir.join("gone.toml"), &file).unwrap();
    let mut sc = screen(&file, 1);
    for input in [Input::Down, Input::Down, Input::Right] {
        sc.input(input);
    }
    assert_eq!(sc.input(Input::Enter), Next::Stay);
    assert!(std::fs::symlink_metadata(&file).unwrap().is_symlink());
    assert!(!dir.join("gone.toml").exists());
    assert!(
        sc.model.message.contains("a link to nowhere"),
        "{}",
        sc.model.message
    );
}

#[test]
fn the_200_percent_screen_is_the_100_percent_screen_doubled() {
    let dir = scratch("scale");
    let file = dir.join("mountains.toml");
    // The same seed, so both previews caption the same mountain.
    std::fs::write(&file, "seed = 7\n").unwrap();
    let mut one = screen(&file, 1);
    let mut two = screen(&file, 2);
    for sc in [&mut one, &mut two] {
        sc.input(Input::Down);
        sc.input(Input::Down);
        sc.input(Input::Right);
    }
    let preview = one.layout().preview;
    let a = one.draw().clone();
    let b = two.draw().clone();
    assert_eq!((b.width(), b.height()), (2 * a.width(), 2 * a.height()));
    let mut checked = 0;
    for y in 0..b.height() {
        for x in 0..b.width() {
            let (x1, y1) = (x / 2, y / 2);
            let in_preview =
                x1 >= preview.x0 && x1 < preview.x1 && y1 >= preview.y0 && y1 < preview.y1;
            if in_preview {
                continue;
            }
            let pa = a.pixels()[(y1 * a.width() + x1) as usize];
            let pb = b.pixels()[(y * b.width() + x) as usize];
            assert_eq!(pa, pb, "pixel {x},{y} at 2x differs from {x1},{y1} at 1x");
            checked += 1;
        }
    }
    assert!(checked > 1_000_000);
    // Text is there: the focused row's label is drawn in white on navy.
    let r = one.layout().row(row("cragginess"));
    let label: Vec<u32> = (r.y0..r.y1)
        .flat_map(|y| (r.x0..r.x0 + 100).map(move |x| (x, y)))
        .map(|(x, y)| a.pixels()[(y * a.width() + x) as usize])
        .collect();
    assert!(label.contains(&0xFFFFFF) && label.contains(&0x000080));
}

#[test]
fn the_seed_button_keeps_the_preview_mountain_or_goes_back_to_random() {
    use mountains::settings_ui::layout::SEED_BUTTON;
    for scale in [1, 2] {
        let mut l = layout(scale);
        let mut m = model();
        m.preview_seed = Some(99);
        let (b0, b1) = l.columns(SEED_BUTTON);
        let y = f64::from(l.row(row("seed")).y0 + l.px(9));
        let x = f64::from(b0 + b1) / 2.0;
        m.handle(Input::Press(x, y), &mut l);
        assert_eq!(m.settings.seed, Some(99), "Keep at {scale}x");
        m.handle(Input::Press(x, y), &mut l);
        assert_eq!(m.settings.seed, None, "Random at {scale}x");
        let (f0, _) = l.columns((130, 131));
        m.handle(Input::Press(f64::from(f0), y), &mut l);
        assert_eq!(
            m.editing.as_deref(),
            Some("random"),
            "the field takes typing"
        );
        assert_eq!(m.settings.seed, None);
    }
}

#[test]
fn data_sets_are_listed_from_both_folders_and_saved_under_readable_names() {
    let dir = scratch("datasets");
    let (data, maps) = (dir.join("data"), dir.join("maps"));
    for d in [&data, &maps] {
        std::fs::create_dir_all(d).unwrap();
    }
    for f in ["b.png", "a.PNG", "notes.txt"] {
        std::fs::write(data.join(f), b"x").unwrap();
    }
    std::fs::write(maps.join("world.png"), b"x").unwrap();
    std::fs::create_dir_all(maps.join("folder.png")).unwrap();
    let maps_str = maps.to_str().unwrap();
    let folders = saved::folders(Some(&data), Some(maps_str));
    assert_eq!(
        saved::list_data_sets(&folders),
        vec![
            data.join("a.PNG"),
            data.join("b.png"),
            maps.join("world.png")
        ]
    );
    assert_eq!(saved::folders(Some(&data), Some("")), vec![data.clone()]);
    // Save names data sets by date, time and seed, and never replaces a file.
    let first = saved::new_path(&data, ".png", Some(1234)).unwrap();
    let name = first.file_name().unwrap().to_str().unwrap().to_string();
    assert!(
        name.starts_with("mountain-20") && name.ends_with("-seed-1234.png"),
        "{name}"
    );
    std::fs::write(&first, b"taken").unwrap();
    let stem = name.trim_end_matches(".png");
    assert_eq!(
        saved::free_path(&data, stem, ".png").unwrap(),
        data.join(format!("{stem}-2.png")),
        "an existing file is never replaced"
    );
}

#[test]
fn open_lists_the_data_directory_on_the_screen() {
    let dir = scratch("open");
    let file = dir.join("mountains.toml");
    std::fs::create_dir_all(dir.join("data")).unwrap();
    std::fs::write(dir.join("data").join("m.png"), b"not really a png").unwrap();
    let mut sc = screen(&file, 1);
    sc.model.activate(Button::Open);
    assert_eq!(sc.apply(Effect::ListDataSets), Next::Stay);
    assert_eq!(
        sc.model.open_list.as_ref().map(|l| l.files.clone()),
        Some(vec![dir.join("data").join("m.png")])
    );
    assert_eq!(sc.input(Input::Enter), Next::Stay);
    assert!(sc.model.message.contains("m.png"), "{}", sc.model.message);
    assert!(!file.exists(), "nothing is written before OK");
}

#[test]
fn the_scale_is_whole_and_the_window_fits_the_monitor() {
    use mountains::settings_ui::layout::whole_scale;
    assert_eq!(whole_scale(1.0, None), 1);
    assert_eq!(whole_scale(1.25, None), 1);
    assert_eq!(whole_scale(2.0, Some(Size::new(3840, 2160))), 2);
    assert_eq!(whole_scale(1.5, Some(Size::new(2880, 1800))), 2);
    assert_eq!(
        whole_scale(1.5, Some(Size::new(1920, 1080))),
        1,
        "1240 rows would not fit"
    );
    assert_eq!(whole_scale(f64::NAN, None), 1);
    assert_eq!(whole_scale(100.0, Some(Size::new(1024, 768))), 1);
}

/// On a screen lower than the window (a 1024x600 netbook, an 800x600
/// display) the window opened 960x620, its OK and Cancel below the screen;
/// it is now held to the screen, never under the least it may be made.
#[test]
fn the_window_is_held_to_a_small_screen() {
    use mountains::settings_ui::layout::{MIN_H, MIN_W, WINDOW_H, WINDOW_W, window_size};
    let asked = Size::new(WINDOW_W, WINDOW_H);
    assert_eq!(window_size(1, None), asked);
    assert_eq!(window_size(1, Some(Size::new(1920, 1080))), asked);
    assert_eq!(
        window_size(2, Some(Size::new(3840, 2160))),
        Size::new(1920, 1240)
    );
    assert_eq!(
        window_size(1, Some(Size::new(1024, 600))),
        Size::new(960, 540)
    );
    assert_eq!(
        window_size(1, Some(Size::new(800, 600))),
        Size::new(800, 540)
    );
    assert_eq!(
        window_size(1, Some(Size::new(320, 240))),
        Size::new(MIN_W, MIN_H),
        "no smaller than the layout allows"
    );
}

#[test]
fn a_file_edited_elsewhere_is_taken_in_keeping_the_screens_edits() {
    let dir = scratch("reload");
    let file = dir.join("mountains.toml");
    std::fs::write(&file, "cragginess = 40\n").unwrap();
    let mut sc = screen(&file, 1);
    assert!(!sc.poll_file(), "nothing changed yet");
    sc.model.focus = row("color");
    sc.input(Input::Right);
    assert_eq!(sc.model.settings.color, ColorMode::Gray);
    // Another program (the editor) rewrites the file, with a new mtime.
    std::fs::write(&file, "cragginess = 50\ncolor = \"sonar\"\nheight = 2\n").unwrap();
    let later = std::time::SystemTime::now() + std::time::Duration::from_secs(2);
    std::fs::File::options()
        .write(true)
        .open(&file)
        .unwrap()
        .set_modified(later)
        .unwrap();
    assert!(sc.poll_file());
    let s = &sc.model.settings;
    assert_eq!((s.cragginess, s.height), (50, 2), "the file's new values");
    assert_eq!(s.color, ColorMode::Gray, "the screen's own edit stays");
    assert_eq!(sc.model.original.color, ColorMode::Sonar);
}

#[test]
fn any_window_size_lays_out_and_draws_without_panicking() {
    let dir = scratch("sizes");
    let file = dir.join("mountains.toml");
    let mut sc = screen(&file, 1);
    for (w, h, s) in [
        (1, 1, 1),
        (50, 30, 1),
        (959, 619, 2),
        (1400, 900, 1),
        (3000, 2000, 3),
    ] {
        sc.resize(Size::new(w, h), s);
        sc.input(Input::Tab { back: false });
        while sc.step_preview() {}
        let f = sc.draw();
        assert_eq!((f.width(), f.height()), (w, h));
    }
    // A larger window gives the extra room to the preview; the panel and
    // the buttons stay at the right and the bottom.
    let l = Layout::new(Size::new(1400, 900), 1);
    assert_eq!(l.panel_x, 1400 - 8 - 372);
    assert_eq!(l.button(Button::Ok).y1, 900 - 8);
    assert!(l.preview.x1 > Layout::new(Size::new(960, 620), 1).preview.x1);
}

/// Edit file runs `$EDITOR` as the shell reads it, so an editor with
/// arguments works (`code --wait` failed: it was run as one program name),
/// the file's path is passed whole however it is spelt, and a missing
/// editor is a failure status the screen can report.
#[cfg(unix)]
#[test]
fn the_editor_command_takes_arguments_and_any_path() {
    use mountains::settings_ui::editor;
    let dir = std::env::temp_dir().join(format!("mountains-editor-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let script = dir.join("fake editor.sh");
    let said = dir.join("args");
    std::fs::write(
        &script,
        format!("printf '%s\\n' \"$@\" > '{}'\n", said.display()),
    )
    .unwrap();
    let prefs = dir.join("my 'prefs' $HOME \"file\".toml");
    let line = format!("sh '{}' --wait -n", script.display());
    let status = editor::command(Some(&line), &prefs).status().unwrap();
    assert!(status.success());
    let args = std::fs::read_to_string(&said).unwrap();
    assert_eq!(args, format!("--wait\n-n\n{}\n", prefs.display()));

    // The shell's "not found" is captured: expected, and the test's own.
    let missing = editor::command(Some("no-such-editor-4711 --wait"), &prefs)
        .output()
        .unwrap();
    assert_eq!(missing.status.code(), Some(127));
    let said = String::from_utf8_lossy(&missing.stderr);
    assert!(said.contains("no-such-editor-4711"), "{said}");
    assert_eq!(editor::command(None, &prefs).get_program(), "xdg-open");
    assert_eq!(
        editor::command(Some("  "), &prefs).get_program(),
        "xdg-open"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn ok_keeps_a_change_made_on_disk_that_the_screen_has_not_seen() {
    let dir = scratch("unseen");
    let file = dir.join("mountains.toml");
    std::fs::write(&file, "# mine\ncragginess = 40 # sharp\n").unwrap();
    let mut sc = screen(&file, 1);
    sc.model.focus = row("cragginess");
    sc.input(Input::Right);
    // Renamed in between the screen's last look and OK: no poll sees it.
    replace_keeping_mtime(
        &file,
        "# mine\ncragginess = 40 # sharp\ncolor = \"sonar\"\n",
    );
    assert_eq!(sc.input(Input::Enter), Next::Close, "Enter on a row is OK");
    assert_eq!(
        std::fs::read_to_string(&file).unwrap(),
        "# mine\ncragginess = 41 # sharp\ncolor = \"sonar\"\n"
    );
}

#[test]
fn a_file_replaced_with_its_old_mtime_is_still_taken_in() {
    let dir = scratch("samemtime");
    let file = dir.join("mountains.toml");
    std::fs::write(&file, "cragginess = 40\n").unwrap();
    let mut sc = screen(&file, 1);
    replace_keeping_mtime(&file, "cragginess = 40\ncolor = \"sonar\"\n");
    assert!(sc.poll_file(), "the content changed, the mtime did not");
    assert_eq!(sc.model.settings.color, ColorMode::Sonar);
    assert!(!sc.poll_file(), "nothing new since");
}

#[test]
fn two_screens_saving_one_after_the_other_keep_both_changes() {
    let dir = scratch("twoscreens");
    let file = dir.join("mountains.toml");
    std::fs::write(&file, "cragginess = 40\nheight = 2\n").unwrap();
    let mut first = screen(&file, 1);
    let mut second = screen(&file, 1);
    first.model.focus = row("cragginess");
    first.input(Input::Right);
    second.model.focus = row("color");
    second.input(Input::Right);
    assert_eq!(first.apply(Effect::Save), Next::Close);
    assert_eq!(second.apply(Effect::Save), Next::Close);
    let mut s = Settings::default();
    assert!(load::apply_file(&mut s, &file).is_empty());
    assert_eq!((s.cragginess, s.height), (41, 2));
    assert_eq!(s.color, second.model.settings.color);
    assert_ne!(
        s.color,
        Settings::default().color,
        "the second screen's edit"
    );
}

/// The size the window opens at and the smallest it may be made.
const SIZES: [(u32, u32); 2] = [(WINDOW_W, WINDOW_H), (MIN_W, MIN_H)];

/// How many lines of `width` characters `s` takes, broken at spaces.
fn wrapped_lines(s: &str, width: usize) -> usize {
    let mut lines = 0;
    let mut used = 0;
    for word in s.split_whitespace() {
        let n = word.chars().count().min(width);
        if used > 0 && used + 1 + n <= width {
            used += 1 + n;
        } else {
            lines += 1;
            used = n;
        }
    }
    lines
}

/// The lines of help a focused key's row brings: what it does, what it
/// allows, and, when it takes typing, how to type.
fn help_lines(key: &Key) -> usize {
    let width = (PANEL_W / ADVANCE) as usize;
    let allowed = format!("Allowed: {}", key.kind.allowed());
    wrapped_lines(key.doc, width)
        + wrapped_lines(&allowed, width)
        + usize::from(values::accepts_typing(key))
}

/// Checks that row `i` of `l` is shown whole inside the list's window,
/// above the help, and is what a click on it hits.
fn assert_row_shown_whole(l: &Layout, i: usize, what: &str) {
    assert!(l.row_shown(i), "{what}: row {i} is shown");
    let (r, area) = (l.row(i), l.list.area());
    assert!(
        r.y0 >= area.y0 && r.y1 <= area.y1 && r.x1 <= area.x1,
        "{what}: row {i} {r:?} inside the list {area:?}"
    );
    assert!(r.y1 < l.help_y, "{what}: row {i} above the help");
    let (x, y) = (f64::from(r.x0 + l.px(20)), f64::from(r.y0 + l.px(9)));
    assert_eq!(l.hit(x, y, None), Some(Hit::Row(i, Part::Label)), "{what}");
}

/// Issue 36: at 960x620 the file line was drawn over the last row and the
/// focused key's help had no room. At the default size and the smallest,
/// at 100% and 200%, the list, the help, the file line and the buttons
/// follow one another inside the window; Tab reaches every row, each is
/// scrolled into sight whole, and the help has room for its key's lines,
/// the changed line and a two-line message.
#[test]
fn every_row_and_its_whole_help_fit_at_the_default_and_the_smallest_size() {
    for (w, h) in SIZES {
        for scale in [1, 2] {
            let what = format!("{w}x{h} at {scale}x");
            let mut l = Layout::new(Size::new(w * scale, h * scale), scale);
            let area = l.list.area();
            assert!(area.y1 < l.help_y && l.help_y < l.file_y, "{what}");
            let ok = l.button(Button::Ok);
            assert!(l.file_y + l.px(2 + 7) <= ok.y0, "{what}: file line over OK");
            assert!(ok.y1 <= h * scale && l.button(Button::Cancel).x1 <= w * scale);
            assert!(area.x1 <= w * scale, "{what}: the panel in the window");
            assert!(l.button(Button::SaveData).x1 <= l.preview.x1, "{what}");
            assert!(
                l.preview.x1 <= l.panel_x,
                "{what}: the preview left of the panel"
            );
            assert!(l.list.last_first() > 0, "{what}: the list scrolls here");
            let help_rows = ((l.file_y - l.help_y) / l.px(HELP_LINE)) as usize;
            let mut m = model();
            for (i, key) in KEYS.iter().enumerate() {
                assert_eq!(m.focused_row(), Some(i));
                assert_row_shown_whole(&l, i, &what);
                assert!(
                    help_rows >= help_lines(key) + 1 + 2,
                    "{what}: {} needs {} lines of help, has {help_rows}",
                    key.name,
                    help_lines(key)
                );
                m.handle(Input::Tab { back: false }, &mut l);
            }
            assert_eq!(l.list.first(), l.list.last_first(), "{what}: at the end");
            for _ in Button::ALL {
                m.handle(Input::Tab { back: false }, &mut l);
            }
            assert_eq!(m.focused_row(), Some(0));
            assert_eq!(
                l.list.first(),
                0,
                "{what}: back at the top, heading and all"
            );
        }
    }
    // A window tall enough shows every row and no scroll bar.
    let tall = Layout::new(Size::new(WINDOW_W, 900), 1);
    assert!(tall.list.bar().is_none());
    for i in 0..KEYS.len() {
        assert_row_shown_whole(&tall, i, "960x900");
    }
}

/// The keys still to come (world, latitude, longitude, on_battery), planned
/// as copies of keys of their kinds: the list grows by four lines and
/// scrolls to show each; the help keeps its room.
#[test]
fn four_more_keys_still_fit_by_scrolling() {
    let mut keys: Vec<Key> = KEYS.to_vec();
    for (name, like) in [
        ("world", "look"),
        ("latitude", "sea_level"),
        ("longitude", "sea_level"),
        ("on_battery", "shadows"),
    ] {
        let mut key = KEYS[row(like)];
        key.name = name;
        keys.push(key);
    }
    for (w, h) in SIZES {
        for scale in [1, 2] {
            let what = format!("{w}x{h} at {scale}x with {} keys", keys.len());
            let base = Layout::new(Size::new(w * scale, h * scale), scale);
            let mut l = Layout::with_keys(Size::new(w * scale, h * scale), scale, &keys);
            assert_eq!(l.list.lines().len(), base.list.lines().len() + 4);
            assert_eq!(l.list.last_first(), base.list.last_first() + 4, "{what}");
            assert_eq!((l.help_y, l.file_y), (base.help_y, base.file_y), "{what}");
            for i in (0..keys.len()).chain((0..keys.len()).rev()) {
                l.reveal_row(i);
                assert_row_shown_whole(&l, i, &what);
            }
        }
    }
}

/// The wheel over the list scrolls it three lines a notch and changes no
/// value; the scroll bar's arrows move a line, its track a page, its thumb
/// drags; a key brings the focused row back into sight.
#[test]
fn the_wheel_the_scroll_bar_and_the_keys_move_the_list() {
    for scale in [1, 2] {
        let mut l = layout(scale);
        let mut m = model();
        let last = KEYS.len() - 1;
        let label = |l: &Layout, i: usize| {
            let r = l.row(i);
            (f64::from(r.x0 + l.px(20)), f64::from(r.y0 + l.px(9)))
        };
        let (x, y) = label(&l, row("detail"));
        let (_, (p0, _)) = l.minus_plus();
        m.handle(Input::Wheel(f64::from(p0), y, -1), &mut l);
        assert_eq!(l.list.first(), 3, "a notch toward the user at {scale}x");
        m.handle(Input::Wheel(x, y, -100), &mut l);
        assert_eq!(
            l.list.first(),
            l.list.last_first(),
            "no further than the end"
        );
        assert!(l.row_shown(last));
        m.handle(Input::Wheel(x, y, 100), &mut l);
        assert_eq!(l.list.first(), 0);
        assert_eq!(m.settings, start(), "scrolling changed nothing");
        let (px, py) = centre(l.preview);
        m.handle(Input::Wheel(px, py, -1), &mut l);
        assert_eq!(l.list.first(), 0, "the wheel over the preview");

        let bar = l.list.bar().expect("a scroll bar at 960x620");
        let hit = |l: &Layout, r: Rect| l.hit(centre(r).0, centre(r).1, None);
        assert_eq!(hit(&l, bar.down), Some(Hit::Bar(BarPart::Down)));
        m.handle(Input::Press(centre(bar.down).0, centre(bar.down).1), &mut l);
        assert_eq!(l.list.first(), 1, "the down arrow at {scale}x");
        m.handle(Input::Press(centre(bar.up).0, centre(bar.up).1), &mut l);
        assert_eq!(l.list.first(), 0, "the up arrow");
        let below = f64::from(bar.down.y0 - 2);
        m.handle(Input::Press(centre(bar.track).0, below), &mut l);
        assert_eq!(
            l.list.first(),
            (l.list.shown() - 1).min(l.list.last_first())
        );
        m.handle(Input::Wheel(x, y, 100), &mut l);

        let thumb = l.list.bar().unwrap().thumb;
        let (tx, ty) = centre(thumb);
        m.handle(Input::Press(tx, ty), &mut l);
        // The thumb travels the track less its own length.
        let travel = f64::from((bar.track.y1 - bar.track.y0) - (thumb.y1 - thumb.y0));
        m.handle(Input::Move(tx, ty + 2.0 * travel), &mut l);
        assert_eq!(
            l.list.first(),
            l.list.last_first(),
            "the thumb dragged down"
        );
        m.handle(Input::Move(tx, ty + travel / 2.0), &mut l);
        let half = l.list.first();
        assert_eq!(
            half,
            l.list.last_first().div_ceil(2),
            "half way at {scale}x"
        );
        m.handle(Input::Release(tx, ty + travel / 2.0), &mut l);
        m.handle(Input::Move(tx, ty), &mut l);
        assert_eq!(l.list.first(), half, "no drag after release");
        assert_eq!(m.settings, start(), "nothing changed");

        // Focus on the first row, scrolled out of sight: a key shows it.
        m.handle(Input::Wheel(x, y, -100), &mut l);
        assert!(!l.row_shown(0));
        m.handle(Input::Down, &mut l);
        assert_row_shown_whole(&l, 1, "after Down");
        m.handle(Input::Up, &mut l);
        assert_eq!(l.list.first(), 0, "the first row brings its heading");
        m.handle(Input::Up, &mut l);
        assert_eq!(m.focused_button(), Some(Button::Cancel));
        for _ in Button::ALL {
            m.handle(Input::Up, &mut l);
        }
        assert_eq!(m.focused_row(), Some(last));
        assert_row_shown_whole(&l, last, "Up from the buttons");
    }
}

/// Sees the focused row's highlight, its help lines and the file line in
/// a drawn frame; counts the help's lines by their ink.
fn assert_drawn(frame: &mountains::render::Frame, l: &Layout, i: usize, what: &str) {
    let px = |x: u32, y: u32| frame.pixels()[(y * frame.width() + x) as usize];
    let r = l.row(i);
    assert_eq!(
        px(r.x0 + l.px(2), r.y0 + l.px(2)),
        0x000080,
        "{what}: highlight"
    );
    let ink = |y0: u32, y1: u32| {
        (y0..y1).any(|y| {
            (l.panel_x..l.panel_x + l.px(PANEL_W)).any(|x| matches!(px(x, y), 0x000000 | 0x404040))
        })
    };
    let line = l.px(HELP_LINE);
    let drawn: Vec<bool> = (0..(l.file_y - l.help_y) / line)
        .map(|n| ink(l.help_y + n * line, l.help_y + n * line + line))
        .collect();
    let want = help_lines(&KEYS[i]);
    let inked = drawn.iter().filter(|d| **d).count();
    assert!(
        drawn[..want].iter().all(|d| *d) && inked == want,
        "{what}: {} has {want} lines of help, drawn {drawn:?}",
        KEYS[i].name
    );
    assert!(ink(l.file_y, l.file_y + l.px(10)), "{what}: the file line");
    // Between the list and the help: only the face and the line parting them.
    let under = l.list.area().y1..l.help_y - l.px(4);
    for y in under {
        for x in l.panel_x..l.panel_x + l.px(PANEL_W) {
            assert_eq!(
                px(x, y),
                0xC0C0C0,
                "{what}: drawn under the list at {x},{y}"
            );
        }
    }
}

/// The drawn screen at 960x620 and at the smallest size, 100% and 200%:
/// each focused row is drawn where the layout says, its whole help below
/// the list and the file line under it; after a resize the focused row
/// stays in sight. Writes `target/tmp/settings-ui-<w>x<h>-<key>.png`.
#[test]
fn the_drawn_screen_shows_each_focused_row_and_its_whole_help() {
    let dir = scratch("fit");
    let file = dir.join("mountains.toml");
    let out = Path::new(env!("CARGO_TARGET_TMPDIR"));
    let mut sc = screen(&file, 1);
    for scale in [1, 2] {
        for (w, h) in SIZES {
            let what = format!("{w}x{h} at {scale}x");
            sc.resize(Size::new(w * scale, h * scale), scale);
            while sc.step_preview() {}
            while sc.model.focused_row() != Some(0) {
                sc.input(Input::Tab { back: false });
            }
            for (i, key) in KEYS.iter().enumerate() {
                let frame = sc.draw().clone();
                assert_drawn(&frame, sc.layout(), i, &what);
                let shot = matches!(key.name, "look" | "heightmaps_dir");
                if scale == 1 && shot {
                    let name = format!("settings-ui-{w}x{h}-{}.png", key.name);
                    mountains::snapshot::write_png(&out.join(name), &frame).unwrap();
                }
                sc.input(Input::Tab { back: false });
            }
        }
    }
    // The last row focused at the default size stays in sight when the
    // window is made as small as it may be.
    sc.resize(Size::new(WINDOW_W, WINDOW_H), 1);
    sc.input(Input::Tab { back: true });
    while sc.model.focused_row().is_none() {
        sc.input(Input::Tab { back: true });
    }
    sc.resize(Size::new(MIN_W, MIN_H), 1);
    assert_row_shown_whole(sc.layout(), KEYS.len() - 1, "resized");
}
