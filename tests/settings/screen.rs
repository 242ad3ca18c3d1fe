//! The settings screen without a window: focus order, values from the key
//! table, slider steps, OK/Cancel/Defaults, mouse hit-testing at 1x and 2x,
//! and the drawn screen.

use crate::common::files;
use files::replace_keeping_mtime;
use std::path::{Path, PathBuf};

use mountains::render::Rect;
use mountains::saved;
use mountains::settings::Detail;
use mountains::settings::keys::{self, KEYS, Kind, Value};
use mountains::settings::{ColorMode, Settings, load};
use mountains::settings_ui::layout::{Button, Hit, Layout, Part, WINDOW_H, WINDOW_W};
use mountains::settings_ui::model::{Effect, Input, Model, focus_count};
use mountains::settings_ui::screen::{Next, Screen};
use mountains::settings_ui::values;

fn layout(scale: u32) -> Layout {
    Layout::new(WINDOW_W * scale, WINDOW_H * scale, scale)
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

fn focus_on(m: &mut Model, l: &Layout, name: &str) {
    while m.focused_row() != Some(row(name)) {
        m.handle(Input::Tab { back: false }, l);
    }
}

fn centre(r: Rect) -> (f64, f64) {
    (f64::from(r.x0 + r.x1) / 2.0, f64::from(r.y0 + r.y1) / 2.0)
}

#[test]
fn tab_visits_every_row_in_key_order_then_every_button_and_wraps() {
    let l = layout(1);
    let mut m = model();
    assert_eq!(m.focused_row(), Some(0));
    let mut seen_rows = vec![0];
    let mut seen_buttons = Vec::new();
    for _ in 1..focus_count() {
        m.handle(Input::Tab { back: false }, &l);
        match (m.focused_row(), m.focused_button()) {
            (Some(r), None) => seen_rows.push(r),
            (None, Some(b)) => seen_buttons.push(b),
            other => panic!("focus on both or neither: {other:?}"),
        }
    }
    assert_eq!(seen_rows, (0..KEYS.len()).collect::<Vec<_>>());
    assert_eq!(seen_buttons, Button::ALL.to_vec());
    m.handle(Input::Tab { back: false }, &l);
    assert_eq!(m.focused_row(), Some(0), "Tab wraps to the first row");
    m.handle(Input::Tab { back: true }, &l);
    assert_eq!(
        m.focused_button(),
        Some(Button::Cancel),
        "Shift+Tab goes back"
    );
    m.handle(Input::Up, &l);
    assert_eq!(m.focused_button(), Some(Button::Ok));
    m.handle(Input::Left, &l);
    assert_eq!(
        m.focused_button(),
        Some(Button::EditFile),
        "arrows move between buttons"
    );
}

#[test]
fn home_and_end_reach_exactly_the_key_tables_range() {
    let l = layout(1);
    let mut m = model();
    for (i, key) in KEYS.iter().enumerate() {
        let (min, max) = match key.kind {
            Kind::Int { min, max } => (min as f64, max as f64),
            Kind::Float { min, max } => (min, max),
            _ => continue,
        };
        m.focus = i;
        m.handle(Input::End, &l);
        assert_eq!(
            values::number(&m.settings, key),
            Some(max as f32 as f64),
            "{}",
            key.name
        );
        m.handle(Input::Right, &l);
        m.handle(Input::PageUp, &l);
        assert_eq!(
            values::number(&m.settings, key),
            Some(max as f32 as f64),
            "{} stays at max",
            key.name
        );
        m.handle(Input::Home, &l);
        assert_eq!(
            values::number(&m.settings, key),
            Some(min as f32 as f64),
            "{}",
            key.name
        );
        m.handle(Input::Left, &l);
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
    let l = layout(1);
    let mut m = model();
    focus_on(&mut m, &l, "cragginess");
    m.handle(Input::Right, &l);
    assert_eq!(m.settings.cragginess, 65);
    m.handle(Input::PageUp, &l);
    assert_eq!(m.settings.cragginess, 78, "a big step is a tenth of 1-128");
    focus_on(&mut m, &l, "sea_level");
    m.handle(Input::Right, &l);
    assert_eq!(m.settings.sea_level, 0.02);
    for _ in 0..4 {
        m.handle(Input::Right, &l);
    }
    assert_eq!(
        value(&m, "sea_level"),
        // A key's value reads as its f32's shortest decimal: a drifted
        // 0.100000024 would read as that.
        Value::Float(0.1),
        "no binary drift"
    );
    focus_on(&mut m, &l, "pause_seconds");
    m.handle(Input::Left, &l);
    assert_eq!(
        m.settings.pause_seconds, 8.0,
        "fine steps at small values of a wide range"
    );
    m.handle(Input::End, &l);
    m.handle(Input::Left, &l);
    assert_eq!(
        m.settings.pause_seconds, 3580.0,
        "coarse steps at large values"
    );
}

#[test]
fn choices_cycle_and_wrap_and_checks_toggle() {
    let l = layout(1);
    let mut m = model();
    focus_on(&mut m, &l, "color");
    m.handle(Input::Left, &l);
    assert_eq!(
        m.settings.color,
        ColorMode::Ridges,
        "left from the first wraps to the last"
    );
    m.handle(Input::Right, &l);
    m.handle(Input::Space, &l);
    assert_eq!(m.settings.color, ColorMode::Gray);
    focus_on(&mut m, &l, "rotation");
    m.handle(Input::Right, &l);
    assert_eq!(m.settings.rotation, 90);
    focus_on(&mut m, &l, "shadows");
    assert_eq!(m.handle(Input::Space, &l), Effect::Repaint);
    assert!(!m.settings.shadows);
    m.handle(Input::Right, &l);
    assert!(m.settings.shadows, "right means on");
}

#[test]
fn only_drawing_keys_repaint_the_current_mountain() {
    let l = layout(1);
    let mut m = model();
    focus_on(&mut m, &l, "color");
    assert_eq!(m.handle(Input::Right, &l), Effect::Repaint);
    focus_on(&mut m, &l, "relative_depth");
    assert_eq!(m.handle(Input::Space, &l), Effect::Repaint);
    focus_on(&mut m, &l, "sun");
    assert_eq!(m.handle(Input::Right, &l), Effect::Repaint);
    focus_on(&mut m, &l, "low_detail");
    assert_eq!(m.handle(Input::Space, &l), Effect::Regenerate);
    focus_on(&mut m, &l, "cragginess");
    assert_eq!(m.handle(Input::Right, &l), Effect::Redraw);
    assert!(m.message.contains("next mountain"), "{}", m.message);
    assert_eq!(m.handle(Input::Char('n'), &l), Effect::NewMountain);
    // The slide show's pacing changes nothing drawn: no "next mountain"
    // (it said so for every key it did not repaint).
    focus_on(&mut m, &l, "pause_seconds");
    assert_eq!(m.handle(Input::Right, &l), Effect::Redraw);
    assert_eq!(m.message, "");
    // The numeric detail remakes the preview as Low Detail does (it waited
    // for the next mountain although Low Detail halves it).
    focus_on(&mut m, &l, "detail");
    assert_eq!(m.handle(Input::Right, &l), Effect::Regenerate);
}

#[test]
fn typed_values_go_through_the_key_table() {
    let l = layout(1);
    let mut m = model();
    focus_on(&mut m, &l, "cragginess");
    for c in "200".chars() {
        m.handle(Input::Char(c), &l);
    }
    assert_eq!(m.editing.as_deref(), Some("200"));
    assert_eq!(
        m.handle(Input::Enter, &l),
        Effect::Redraw,
        "Enter ends typing, not the dialog"
    );
    assert_eq!(
        m.settings.cragginess, 64,
        "an illegal value changes nothing"
    );
    assert!(m.message.contains("1 to 128"), "{}", m.message);
    for c in "100".chars() {
        m.handle(Input::Char(c), &l);
    }
    m.handle(Input::Tab { back: false }, &l);
    assert_eq!(
        m.settings.cragginess, 100,
        "leaving the row applies what was typed"
    );
    focus_on(&mut m, &l, "seed");
    for c in "1234".chars() {
        m.handle(Input::Char(c), &l);
    }
    m.handle(Input::Enter, &l);
    assert_eq!(m.settings.seed, Some(1234));
    m.handle(Input::Right, &l);
    assert_eq!(
        m.settings.seed, None,
        "arrows switch the seed back to random"
    );
    focus_on(&mut m, &l, "draw_seconds");
    m.handle(Input::Backspace, &l);
    m.handle(Input::Char('5'), &l);
    assert_eq!(
        m.editing.as_deref(),
        Some("8.5"),
        "backspace edits the shown value"
    );
    assert_eq!(
        m.handle(Input::Escape, &l),
        Effect::Redraw,
        "Esc cancels typing only"
    );
    assert_eq!(m.settings.draw_seconds, 8.0);
}

#[test]
fn ok_cancel_and_defaults() {
    let l = layout(1);
    let start = Settings {
        cragginess: 7,
        color: ColorMode::Sonar,
        ..Settings::default()
    };
    let mut m = Model::new(start.clone(), &[]);
    assert_eq!(
        m.handle(Input::Enter, &l),
        Effect::Save,
        "Enter on a row is OK"
    );
    assert_eq!(m.handle(Input::Escape, &l), Effect::Close);
    assert_eq!(m.settings, start, "neither changes the values");
    assert_eq!(m.activate(Button::Defaults), Effect::Regenerate);
    assert_eq!(m.settings, Settings::default());
    assert_eq!(m.original, start, "defaults are on the screen only");
    assert!(m.changed(row("cragginess")) && !m.changed(row("detail")));
    assert_eq!(m.activate(Button::Cancel), Effect::Close);
}

#[test]
fn a_file_that_does_not_parse_cannot_be_saved_and_offers_edit_file() {
    let l = layout(1);
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
    assert_eq!(m.handle(Input::Enter, &l), Effect::EditFile);
    assert_eq!(m.activate(Button::Ok), Effect::Redraw, "OK does not save");
    assert_eq!(m.handle(Input::Enter, &l), Effect::Redraw, "nor does Enter");
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
    // Rows do not overlap and sit below one another.
    for i in 1..KEYS.len() {
        assert!(one.row(i).y0 >= one.row(i - 1).y1);
    }
}

#[test]
fn mouse_clicks_drags_and_wheel_change_values() {
    for scale in [1, 2] {
        let l = layout(scale);
        let mut m = model();
        let y = f64::from(l.row(row("cragginess")).y0 + l.px(9));
        let ((m0, m1), (p0, p1)) = l.minus_plus();
        m.handle(Input::Press(f64::from(p0 + p1) / 2.0, y), &l);
        m.handle(Input::Release(f64::from(p0 + p1) / 2.0, y), &l);
        assert_eq!(m.settings.cragginess, 65, "plus at {scale}x");
        m.handle(Input::Press(f64::from(m0 + m1) / 2.0, y), &l);
        assert_eq!(m.settings.cragginess, 64, "minus at {scale}x");
        let (t0, t1) = l.track();
        m.handle(Input::Press(f64::from(t0 + t1) / 2.0, y), &l);
        assert_eq!(m.settings.cragginess, 65, "middle of 1-128 at {scale}x");
        m.handle(Input::Move(f64::from(t1) + 500.0, y + 300.0), &l);
        assert_eq!(
            m.settings.cragginess, 128,
            "dragging past the end at {scale}x"
        );
        m.handle(Input::Release(f64::from(t1) + 500.0, y + 300.0), &l);
        m.handle(Input::Move(f64::from(t0), y), &l);
        assert_eq!(m.settings.cragginess, 128, "no drag after release");
        let dy = f64::from(l.row(row("detail")).y0 + l.px(9));
        m.handle(Input::Wheel(f64::from(t0), dy, 1), &l);
        // The key's least level: 3 (seed 000's Iterations menu).
        assert_eq!(
            m.settings.detail,
            Detail::Level(3),
            "wheel up from auto at {scale}x"
        );
        assert_eq!(m.focused_row(), Some(row("detail")));
        let cy = f64::from(l.row(row("shadows")).y0 + l.px(9));
        m.handle(Input::Press(f64::from(m0) + 2.0, cy), &l);
        assert!(!m.settings.shadows, "check box at {scale}x");
        let (ok_x, ok_y) = centre(l.button(Button::Ok));
        assert_eq!(m.handle(Input::Press(ok_x, ok_y), &l), Effect::Redraw);
        assert_eq!(m.handle(Input::Release(ok_x, ok_y), &l), Effect::Save);
        let (cx, cy) = centre(l.button(Button::Cancel));
        m.handle(Input::Press(cx, cy), &l);
        assert_eq!(
            m.handle(Input::Release(ok_x, ok_y), &l),
            Effect::Redraw,
            "releasing away from the pressed button does nothing"
        );
    }
}

#[test]
fn the_open_list_is_driven_by_keys_and_clicks() {
    let l = layout(1);
    let mut m = model();
    let files = vec![PathBuf::from("/d/a.png"), PathBuf::from("/d/b.png")];
    m.show_list(files.clone(), "/d");
    m.handle(Input::Down, &l);
    assert_eq!(
        m.handle(Input::Enter, &l),
        Effect::OpenDataSet(files[1].clone())
    );
    assert!(m.open_list.is_none());
    m.show_list(files.clone(), "/d");
    let (x, y) = centre(l.list_item(0));
    assert_eq!(
        m.handle(Input::Press(x, y), &l),
        Effect::OpenDataSet(files[0].clone())
    );
    m.show_list(files, "/d");
    assert_eq!(
        m.handle(Input::Escape, &l),
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
    let size = (WINDOW_W * scale, WINDOW_H * scale);
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
        let l = layout(scale);
        let mut m = model();
        m.preview_seed = Some(99);
        let (b0, b1) = l.columns(SEED_BUTTON);
        let y = f64::from(l.row(row("seed")).y0 + l.px(9));
        let x = f64::from(b0 + b1) / 2.0;
        m.handle(Input::Press(x, y), &l);
        assert_eq!(m.settings.seed, Some(99), "Keep at {scale}x");
        m.handle(Input::Press(x, y), &l);
        assert_eq!(m.settings.seed, None, "Random at {scale}x");
        let (f0, _) = l.columns((130, 131));
        m.handle(Input::Press(f64::from(f0), y), &l);
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
        saved::list_pngs(&folders),
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
    assert_eq!(whole_scale(2.0, Some((3840, 2160))), 2);
    assert_eq!(whole_scale(1.5, Some((2880, 1800))), 2);
    assert_eq!(
        whole_scale(1.5, Some((1920, 1080))),
        1,
        "1240 rows would not fit"
    );
    assert_eq!(whole_scale(f64::NAN, None), 1);
    assert_eq!(whole_scale(100.0, Some((1024, 768))), 1);
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
        sc.resize(w, h, s);
        sc.input(Input::Tab { back: false });
        while sc.step_preview() {}
        let f = sc.draw();
        assert_eq!((f.width(), f.height()), (w, h));
    }
    // A larger window gives the extra room to the preview; the panel and
    // the buttons stay at the right and the bottom.
    let l = Layout::new(1400, 900, 1);
    assert_eq!(l.panel_x, 1400 - 8 - 372);
    assert_eq!(l.button(Button::Ok).y1, 900 - 8);
    assert!(l.preview.x1 > Layout::new(960, 620, 1).preview.x1);
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
