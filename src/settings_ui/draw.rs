//! Draws the settings screen into a `Frame`, in the grey, bevelled look of a
//! Windows 95 dialog (seed 003's Settings dialog is the reference).

use super::font::{self, ADVANCE};
use super::help::{self, Tone};
use super::layout::{
    Button, CTRL_END, CTRL_X, HELP_CHARS, HELP_LINE, LABEL_X, Layout, PANEL_W, ROW_H, SEED_BUTTON,
    VALUE_X,
};
use super::model::Model;
use super::values::{self, Widget};
use super::widgets::{
    ALERT, DARK, DIM, FACE, FIELD, HINT, SELECT, SELECT_TEXT, TEXT, bevel, blit, centred_text,
    dotted, etched, fill, outline, scroll_bar, text, tick, typed_text,
};
use super::wrap::{fit, fit_middle, help_then_message, wrap};
use crate::render::{Frame, Rect, Size};
use crate::settings::keys::{self, KEYS, Value};

/// Everything the screen shows besides the model.
pub struct Extras<'a> {
    /// The preview picture, drawn inside `layout.preview`.
    pub preview: Option<&'a Frame>,
    /// One line under the preview saying what it shows.
    pub caption: &'a str,
    /// The preferences file's path, shown over the buttons.
    pub file: &'a str,
}

/// Draws the whole screen.
pub fn draw(frame: &mut Frame, layout: &Layout, model: &Model, extras: &Extras<'_>) {
    frame.clear(FACE);
    draw_preview(frame, layout, extras);
    for (b, r) in &layout.buttons {
        let focused = model.focused_button() == Some(*b);
        draw_button(frame, layout, *r, b.caption(), focused, *b == Button::Ok);
    }
    draw_rows(frame, layout, model);
    draw_help(frame, layout, model, extras);
    if let Some(list) = &model.open_list {
        draw_list(frame, layout, &list.files, list.pick);
    }
}

/// The shown part of the settings list, its scroll bar, and a line under
/// it that parts it from the help.
fn draw_rows(frame: &mut Frame, layout: &Layout, model: &Model) {
    for (y, title) in layout.headings() {
        let x = layout.panel_x + layout.px(2);
        text(frame, layout, x, y + layout.px(4), title, SELECT);
        let w = layout.px(font::text_width(title));
        let line_y = y + layout.px(15);
        fill(frame, Rect::sized(x, line_y, w, layout.px(1)), SELECT);
    }
    for i in layout.rows_shown().filter(|i| *i < KEYS.len()) {
        draw_row(frame, layout, model, i);
    }
    if let Some(bar) = layout.list.bar() {
        scroll_bar(frame, layout, &bar);
    }
    let under = layout.help_y - layout.px(4);
    etched(frame, layout, layout.panel_x, under, layout.px(PANEL_W));
}

fn draw_button(
    frame: &mut Frame,
    layout: &Layout,
    r: Rect,
    caption: &str,
    focus: bool,
    default: bool,
) {
    fill(frame, r, FACE);
    bevel(frame, layout, r, false);
    if default {
        outline(frame, r, layout.px(1), DARK);
    }
    centred_text(frame, layout, r, caption, TEXT);
    if focus {
        let inset = layout.px(3);
        let inner = Rect {
            x0: r.x0 + inset,
            y0: r.y0 + inset,
            x1: r.x1 - inset,
            y1: r.y1 - inset,
        };
        dotted(frame, inner, layout.scale);
    }
}

fn draw_preview(frame: &mut Frame, layout: &Layout, extras: &Extras<'_>) {
    let p = layout.preview;
    let b = layout.px(2);
    let inner = Rect {
        x0: p.x0 + b,
        y0: p.y0 + b,
        x1: p.x1 - b,
        y1: p.y1 - b - layout.px(ROW_H),
    };
    fill(frame, p, FACE);
    bevel(frame, layout, p, true);
    fill(frame, inner, 0);
    if let Some(pic) = extras.preview {
        blit(frame, pic, inner.x0, inner.y0);
    }
    let y = inner.y1 + layout.px(5);
    // In a narrow window the caption stays off the panel: the hint after
    // its last wide gap goes first, then a long name loses its middle.
    let chars = ((inner.x1 - inner.x0) / layout.px(ADVANCE)).saturating_sub(2) as usize;
    let mut caption = extras.caption;
    while caption.chars().count() > chars
        && let Some(gap) = caption.rfind("   ")
    {
        caption = &caption[..gap];
    }
    let caption = fit_middle(caption, chars);
    text(frame, layout, inner.x0 + layout.px(4), y, &caption, TEXT);
}

/// The preview picture's size for a layout.
pub fn preview_size(layout: &Layout) -> Size {
    let p = layout.preview;
    let b = layout.px(2);
    let w = (p.x1 - p.x0).saturating_sub(2 * b);
    let h = (p.y1 - p.y0).saturating_sub(2 * b + layout.px(ROW_H));
    Size::new(w.max(1), h.max(1))
}

fn draw_row(frame: &mut Frame, layout: &Layout, model: &Model, i: usize) {
    let key = &KEYS[i];
    let r = layout.row(i);
    let focused = model.focused_row() == Some(i);
    let label_right = layout.panel_x + layout.px(CTRL_X - 4);
    let ty = r.y0 + layout.px(5);
    if focused {
        fill(
            frame,
            Rect::sized(
                r.x0,
                r.y0 + layout.px(1),
                label_right - r.x0,
                layout.px(ROW_H - 2),
            ),
            SELECT,
        );
    }
    let color = match (focused, values::matters(&model.settings, key)) {
        (true, _) => SELECT_TEXT,
        (false, true) => TEXT,
        (false, false) => DIM,
    };
    if model.changed(i) {
        text(frame, layout, r.x0 + layout.px(3), ty, "*", color);
    }
    let label = fit(
        &values::label(key),
        ((CTRL_X - LABEL_X - 4) / ADVANCE) as usize,
    );
    text(frame, layout, r.x0 + layout.px(LABEL_X), ty, &label, color);
    let editing = if focused {
        model.editing.as_deref()
    } else {
        None
    };
    match values::widget(key) {
        Widget::Slider => draw_slider(frame, layout, model, i, editing),
        Widget::Check => draw_check(frame, layout, model, i),
        Widget::Choice => draw_choice(frame, layout, model, i),
        Widget::Text => draw_field(frame, layout, model, i, editing, CTRL_END),
        Widget::Seed => {
            draw_field(frame, layout, model, i, editing, SEED_BUTTON.0 - 4);
            let r = layout.row(i);
            let caption = if model.settings.seed.is_some() {
                "Random"
            } else {
                "Keep"
            };
            small_button(frame, layout, layout.columns(SEED_BUTTON), r.y0, caption);
        }
    }
}

fn small_button(frame: &mut Frame, layout: &Layout, span: (u32, u32), y: u32, caption: &str) {
    let r = Rect {
        x0: span.0,
        y0: y + layout.px(2),
        x1: span.1,
        y1: y + layout.px(ROW_H - 2),
    };
    fill(frame, r, FACE);
    bevel(frame, layout, r, false);
    centred_text(frame, layout, r, caption, TEXT);
}

fn draw_slider(frame: &mut Frame, layout: &Layout, model: &Model, i: usize, editing: Option<&str>) {
    let key = &KEYS[i];
    let y = layout.row(i).y0;
    let (minus, plus) = layout.minus_plus();
    small_button(frame, layout, minus, y, "-");
    small_button(frame, layout, plus, y, "+");
    let (t0, t1) = layout.track();
    let mid = y + layout.px(ROW_H / 2);
    let groove = Rect {
        x0: t0,
        y0: mid - layout.px(2),
        x1: t1,
        y1: mid + layout.px(2),
    };
    bevel(frame, layout, groove, true);
    let v = values::number(&model.settings, key).unwrap_or(0.0);
    let f = values::fraction(key, v);
    let travel = (t1 - t0) / layout.scale - 8;
    let x = t0 + layout.px((travel as f64 * f).round() as u32);
    let thumb = Rect::sized(x, y + layout.px(2), layout.px(8), layout.px(ROW_H - 4));
    fill(frame, thumb, FACE);
    bevel(frame, layout, thumb, false);
    let vx = layout.panel_x + layout.px(VALUE_X);
    let ty = y + layout.px(5);
    match editing {
        Some(t) => typed_text(frame, layout, vx, y, layout.px(56), t),
        None => text(
            frame,
            layout,
            vx,
            ty,
            &fit(&values::display(&model.settings, key), 9),
            TEXT,
        ),
    }
}

fn draw_check(frame: &mut Frame, layout: &Layout, model: &Model, i: usize) {
    let y = layout.row(i).y0;
    let x = layout.panel_x + layout.px(CTRL_X);
    let boxr = Rect::sized(x, y + layout.px(3), layout.px(12), layout.px(12));
    fill(frame, boxr, FIELD);
    bevel(frame, layout, boxr, true);
    let on = keys::get(&model.settings, &KEYS[i]) == Value::Bool(true);
    if on {
        tick(frame, layout, x + layout.px(3), y + layout.px(6));
    }
    let t = if on { "on" } else { "off" };
    text(frame, layout, x + layout.px(18), y + layout.px(5), t, TEXT);
}

fn draw_choice(frame: &mut Frame, layout: &Layout, model: &Model, i: usize) {
    let y = layout.row(i).y0;
    let (left, right) = layout.arrows();
    small_button(frame, layout, left, y, "<");
    small_button(frame, layout, right, y, ">");
    let field = Rect {
        x0: left.1 + layout.px(2),
        y0: y + layout.px(2),
        x1: right.0 - layout.px(2),
        y1: y + layout.px(ROW_H - 2),
    };
    fill(frame, field, FIELD);
    bevel(frame, layout, field, true);
    let s = values::display(&model.settings, &KEYS[i]);
    centred_text(frame, layout, field, &s, TEXT);
}

/// A text field from the control column to `right` (logical, panel-relative).
fn draw_field(
    frame: &mut Frame,
    layout: &Layout,
    model: &Model,
    i: usize,
    editing: Option<&str>,
    right: u32,
) {
    let y = layout.row(i).y0;
    let x = layout.panel_x + layout.px(CTRL_X + 2);
    let w = layout.px(right - CTRL_X);
    match editing {
        Some(t) => typed_text(frame, layout, x, y, w, t),
        None => {
            let r = Rect::sized(x - layout.px(2), y + layout.px(2), w, layout.px(ROW_H - 4));
            fill(frame, r, FIELD);
            bevel(frame, layout, r, true);
            let chars = ((right - CTRL_X - 8) / ADVANCE) as usize;
            let s = fit(&values::display(&model.settings, &KEYS[i]), chars);
            text(frame, layout, x, y + layout.px(5), &s, TEXT);
        }
    }
}

fn draw_help(frame: &mut Frame, layout: &Layout, model: &Model, extras: &Extras<'_>) {
    let x = layout.panel_x + layout.px(2);
    let chars = HELP_CHARS;
    let mut y = layout.help_y;
    let line = layout.px(HELP_LINE);
    let mut lines: Vec<(String, u32)> = help::lines(model.focused_row().map(|i| &KEYS[i]))
        .into_iter()
        .map(|(l, tone)| (l, if tone == Tone::Text { TEXT } else { HINT }))
        .collect();
    if (0..KEYS.len()).any(|i| model.changed(i)) {
        lines.push((help::CHANGED.into(), HINT));
    }
    let alert = if model.file_error.is_some() {
        ALERT
    } else {
        TEXT
    };
    let rows = (layout.file_y.saturating_sub(y) / line) as usize;
    let (help, colours): (Vec<String>, Vec<u32>) = lines.into_iter().unzip();
    // Each help line keeps its colour through wrapping.
    let mut coloured = Vec::new();
    for (l, c) in help.iter().zip(&colours) {
        coloured.extend(wrap(l, chars).into_iter().map(|part| (part, *c)));
    }
    let (help, message) = help_then_message(&help, &model.message, chars, rows);
    let shown = coloured.into_iter().take(help.len());
    for (part, color) in shown.chain(message.into_iter().map(|m| (m, alert))) {
        text(frame, layout, x, y, &part, color);
        y += line;
    }
    // A long path keeps its file name.
    let file = format!("File: {}", fit_middle(extras.file, chars.saturating_sub(6)));
    text(frame, layout, x, layout.file_y + layout.px(2), &file, HINT);
}

/// A data set as listed: its name first, then the folder it is in.
fn list_entry(path: &std::path::Path) -> String {
    let name = path.file_name().map_or_else(
        || path.display().to_string(),
        |n| n.to_string_lossy().into_owned(),
    );
    match path.parent() {
        Some(dir) => format!("{name}   in {}", dir.display()),
        None => name,
    }
}

fn draw_list(frame: &mut Frame, layout: &Layout, list: &[std::path::PathBuf], pick: usize) {
    let shown = list.len().min(layout.list_capacity());
    if shown == 0 {
        return;
    }
    let first = layout.list_item(0);
    let last = layout.list_item(shown - 1);
    let pad = layout.px(4);
    let bg = Rect {
        x0: first.x0 - pad,
        y0: first.y0 - pad,
        x1: first.x1 + pad,
        y1: last.y1 + pad,
    };
    fill(frame, bg, FIELD);
    outline(frame, bg, layout.px(1), DARK);
    let chars = ((first.x1 - first.x0) / layout.px(ADVANCE)).saturating_sub(1) as usize;
    for (i, path) in list.iter().take(shown).enumerate() {
        let r = layout.list_item(i);
        let color = if i == pick {
            fill(frame, r, SELECT);
            SELECT_TEXT
        } else {
            TEXT
        };
        let name = fit(&list_entry(path), chars);
        text(
            frame,
            layout,
            r.x0 + layout.px(3),
            r.y0 + layout.px(5),
            &name,
            color,
        );
    }
}
