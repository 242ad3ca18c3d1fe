//! The settings screen as data: what has focus, what each input does, what
//! the window layer must do next. No window, no clock, no files: tested as is.

use std::path::PathBuf;

pub use super::input::Input;
use super::layout::{Button, Hit, Layout, Part};
use super::list_view::BarPart;
use super::open_list::{OpenList, Outcome};
use super::values::{self, Widget};
use crate::settings::keys::{self, Change, KEYS, Key, Value};
use crate::settings::{Settings, load};

/// What the window layer must do after an input.
#[derive(Debug, Clone, PartialEq)]
pub enum Effect {
    /// Nothing beyond redrawing the screen.
    Redraw,
    /// Draw the current preview mountain again with the new settings.
    Repaint,
    /// Make the current mountain again (same seed) with the new settings.
    Regenerate,
    /// Make a new preview mountain.
    NewMountain,
    /// Show the list of data sets to open (the window lists the files).
    ListDataSets,
    /// Load this data set into the preview.
    OpenDataSet(PathBuf),
    /// Save the preview mountain as a data set.
    SaveDataSet,
    /// Open the preferences file in the user's editor.
    EditFile,
    /// Write the settings to the file, then close.
    Save,
    /// Close without writing anything.
    Close,
}

/// The settings screen's state.
#[derive(Debug, Clone)]
pub struct Model {
    /// The values on the screen.
    pub settings: Settings,
    /// The values the file held when the screen opened (or last reloaded).
    pub original: Settings,
    /// Index into the focus order: rows (like `KEYS`), then `Button::ALL`.
    pub focus: usize,
    /// Text being typed into the focused row, not yet applied.
    pub editing: Option<String>,
    /// The line under the rows: what happened, or what is wrong.
    pub message: String,
    /// Set when the preferences file cannot be read, is not text or does
    /// not parse: OK cannot save.
    pub file_error: Option<String>,
    /// The Open list, while it is shown.
    pub open_list: Option<OpenList>,
    /// The seed of the preview mountain, when it has one.
    pub preview_seed: Option<u64>,
    /// What the held mouse button is dragging.
    drag: Option<Drag>,
    /// The button under a press, activated on release over it.
    pressed: Option<Button>,
}

/// What a held mouse button is dragging.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Drag {
    /// The slider of row `i`.
    Slider(usize),
    /// The scroll bar's thumb, grabbed at pixel row `y` while line `first`
    /// was the list's top.
    Thumb { y: f64, first: usize },
}

/// Lines the list scrolls for one notch of the wheel.
const WHEEL_LINES: i64 = 3;

/// How many places the focus can be: every row, then every button.
pub fn focus_count() -> usize {
    KEYS.len() + Button::ALL.len()
}

impl Model {
    /// A screen showing `settings`, read from a file that had `problems`.
    pub fn new(settings: Settings, problems: &[load::Problem]) -> Model {
        let mut m = Model {
            original: settings.clone(),
            settings,
            focus: 0,
            editing: None,
            message: String::new(),
            file_error: None,
            open_list: None,
            preview_seed: None,
            drag: None,
            pressed: None,
        };
        m.reload(m.settings.clone(), problems);
        m
    }

    /// A screen of the file's `settings` showing `shown` over them: a key
    /// they differ in counts as changed here (`--settings --set`), so OK
    /// saves it and Cancel forgets it, as a key changed on the screen.
    pub fn with_unsaved(settings: Settings, shown: Settings, problems: &[load::Problem]) -> Model {
        let mut m = Model::new(settings, problems);
        m.settings = shown;
        m
    }

    /// Shows freshly read settings (after the file was edited elsewhere).
    pub fn reload(&mut self, settings: Settings, problems: &[load::Problem]) {
        self.original = settings.clone();
        self.settings = settings;
        self.editing = None;
        // Nothing in such a file was used (a syntax error, even one naming
        // its key, stops the reading), and no save can merge into it.
        let broken = problems.iter().find(|p| p.drops_the_file());
        self.file_error = broken.map(|p| format!("{p}. Fix it with Edit file; OK cannot save."));
        self.message = match (&self.file_error, problems.first()) {
            (Some(e), _) => e.clone(),
            (None, Some(p)) => format!("{}{}", describe(p), more(problems.len())),
            (None, None) => String::new(),
        };
        if self.file_error.is_some() {
            self.focus = KEYS.len() + button_index(Button::EditFile);
        }
    }

    /// Takes in a file that changed on disk: keys changed on the screen keep
    /// the screen's value, every other key takes the file's new value.
    pub fn merge_from_file(&mut self, fresh: Settings, problems: &[load::Problem]) {
        let mut merged = fresh.clone();
        for (i, key) in KEYS.iter().enumerate() {
            if self.changed(i) {
                keys::copy(key, &self.settings, &mut merged);
            }
        }
        let focus = self.focus;
        self.reload(fresh, problems);
        self.settings = merged;
        if self.file_error.is_none() {
            self.focus = focus;
            if problems.is_empty() {
                self.message = "The file changed on disk; its new values are shown.".into();
            }
        }
    }

    /// The focused row, if the focus is on a row.
    pub fn focused_row(&self) -> Option<usize> {
        (self.focus < KEYS.len()).then_some(self.focus)
    }

    /// The focused button, if the focus is on a button.
    pub fn focused_button(&self) -> Option<Button> {
        self.focus
            .checked_sub(KEYS.len())
            .and_then(|i| Button::ALL.get(i).copied())
    }

    /// True when row `i` differs from the file.
    pub fn changed(&self, i: usize) -> bool {
        KEYS.get(i)
            .is_some_and(|k| keys::get(&self.settings, k) != keys::get(&self.original, k))
    }

    /// The keys whose value on the screen differs from the file's: what OK
    /// writes (every other key keeps what the file says when OK is pressed).
    pub fn changed_keys(&self) -> Vec<&'static Key> {
        (0..KEYS.len())
            .filter(|&i| self.changed(i))
            .map(|i| &KEYS[i])
            .collect()
    }

    /// Handles one input against the current layout, scrolling its list
    /// as the input asks; after a key the focused row is scrolled into view.
    pub fn handle(&mut self, input: Input, layout: &mut Layout) -> Effect {
        let key = input.is_key();
        let effect = self.handle_input(input, layout);
        if key && let Some(i) = self.focused_row() {
            layout.reveal_row(i);
        }
        effect
    }

    fn handle_input(&mut self, input: Input, layout: &mut Layout) -> Effect {
        if self.open_list.is_some()
            && let Some(effect) = self.handle_list(&input, layout)
        {
            return effect;
        }
        match input {
            Input::Tab { back } => self.move_focus(if back { -1 } else { 1 }),
            Input::Up => self.move_focus(-1),
            Input::Down => self.move_focus(1),
            Input::Left => self.arrow(-1),
            Input::Right => self.arrow(1),
            Input::PageUp => self.nudge(1, true),
            Input::PageDown => self.nudge(-1, true),
            Input::Home => self.extreme(false),
            Input::End => self.extreme(true),
            Input::Enter => self.enter(),
            Input::Space => self.space(),
            Input::Escape => self.escape(),
            Input::Backspace => self.backspace(),
            Input::Char(c) => self.typed(c),
            Input::Press(x, y) => self.press(layout, x, y),
            Input::Move(x, y) => self.drag_to(layout, x, y),
            Input::Release(x, y) => self.release(layout, x, y),
            Input::Wheel(x, y, lines) => self.wheel(layout, x, y, lines),
        }
    }

    fn move_focus(&mut self, delta: i32) -> Effect {
        let commit = self.commit_text();
        let n = focus_count() as i32;
        self.focus = (self.focus as i32 + delta).rem_euclid(n) as usize;
        commit
    }

    fn arrow(&mut self, delta: i32) -> Effect {
        if let Some(b) = self.focused_button() {
            let i = button_index(b) as i32 + delta;
            let n = Button::ALL.len() as i32;
            self.focus = KEYS.len() + i.rem_euclid(n) as usize;
            return Effect::Redraw;
        }
        if self.editing.is_some() {
            return Effect::Redraw;
        }
        let Some(i) = self.focused_row() else {
            return Effect::Redraw;
        };
        let key = &KEYS[i];
        match values::widget(key) {
            Widget::Slider => self.nudge(delta, false),
            Widget::Check => self.set(i, Value::Bool(delta > 0)),
            Widget::Choice => self.cycle(i, delta),
            Widget::Seed => self.toggle_seed(i),
            Widget::Text => Effect::Redraw,
        }
    }

    /// Moves the focused slider by `steps` (small or big steps).
    fn nudge(&mut self, steps: i32, big: bool) -> Effect {
        let Some(i) = self.focused_row() else {
            return Effect::Redraw;
        };
        self.step_row(i, steps, big)
    }

    fn step_row(&mut self, i: usize, steps: i32, big: bool) -> Effect {
        let key = &KEYS[i];
        match values::widget(key) {
            Widget::Slider => {
                let Some(v) = values::number(&self.settings, key) else {
                    return Effect::Redraw;
                };
                match values::stepped(key, v, steps, big) {
                    Some(nv) => self.set(i, values::number_value(key, nv)),
                    None => Effect::Redraw,
                }
            }
            Widget::Choice => self.cycle(i, steps.signum()),
            _ => Effect::Redraw,
        }
    }

    fn extreme(&mut self, top: bool) -> Effect {
        let Some(i) = self.focused_row() else {
            return Effect::Redraw;
        };
        match values::range(&KEYS[i]) {
            Some((min, max)) if self.editing.is_none() => {
                let v = if top { max } else { min };
                self.set(i, values::number_value(&KEYS[i], v))
            }
            _ => Effect::Redraw,
        }
    }

    fn cycle(&mut self, i: usize, delta: i32) -> Effect {
        match values::next_choice(&self.settings, &KEYS[i], delta) {
            Some(v) => self.set(i, v),
            None => Effect::Redraw,
        }
    }

    /// Seed: "random" <-> the preview mountain's seed (so a mountain you
    /// like can be kept).
    fn toggle_seed(&mut self, i: usize) -> Effect {
        let value = match (self.settings.seed, self.preview_seed) {
            (None, Some(s)) => Value::Str(s.to_string()),
            (None, None) => Value::Int(1),
            (Some(_), _) => Value::Str("random".into()),
        };
        self.set(i, value)
    }

    fn enter(&mut self) -> Effect {
        if self.editing.is_some() {
            return self.commit_text();
        }
        match self.focused_button() {
            Some(b) => self.activate(b),
            None => self.activate(Button::Ok),
        }
    }

    fn space(&mut self) -> Effect {
        if self.editing.is_some() {
            return self.typed(' ');
        }
        if let Some(b) = self.focused_button() {
            return self.activate(b);
        }
        let Some(i) = self.focused_row() else {
            return Effect::Redraw;
        };
        match values::widget(&KEYS[i]) {
            Widget::Check => self.toggle(i),
            Widget::Choice => self.cycle(i, 1),
            Widget::Seed => self.toggle_seed(i),
            _ => Effect::Redraw,
        }
    }

    fn escape(&mut self) -> Effect {
        if self.editing.take().is_some() {
            self.message = "Typing cancelled.".into();
            return Effect::Redraw;
        }
        self.activate(Button::Cancel)
    }

    fn backspace(&mut self) -> Effect {
        let Some(i) = self.focused_row() else {
            return Effect::Redraw;
        };
        if !values::accepts_typing(&KEYS[i]) {
            return Effect::Redraw;
        }
        let mut text = self
            .editing
            .take()
            .unwrap_or_else(|| self.edit_start_text(i));
        text.pop();
        self.editing = Some(text);
        Effect::Redraw
    }

    fn edit_start_text(&self, i: usize) -> String {
        match keys::get(&self.settings, &KEYS[i]) {
            Value::Str(s) => s,
            Value::Float(x) => values::format_float(x),
            v => v.to_string(),
        }
    }

    fn typed(&mut self, c: char) -> Effect {
        let row = self.focused_row().map(|i| (i, &KEYS[i]));
        let typing = row.filter(|(_, k)| values::accepts_typing(k) && takes_char(k, c));
        match typing {
            Some(_) if c.is_control() => Effect::Redraw,
            Some(_) => {
                let text = self.editing.get_or_insert_with(String::new);
                if text.chars().count() < 1024 {
                    text.push(c);
                }
                Effect::Redraw
            }
            None if c.eq_ignore_ascii_case(&'n') && self.editing.is_none() => {
                self.activate(Button::New)
            }
            None => Effect::Redraw,
        }
    }

    /// Applies typed text through the key table; a refused value changes
    /// nothing and the message says what is allowed.
    fn commit_text(&mut self) -> Effect {
        let (Some(text), Some(i)) = (self.editing.take(), self.focused_row()) else {
            return Effect::Redraw;
        };
        let key = &KEYS[i];
        let mut candidate = self.settings.clone();
        let result = match key.kind {
            keys::Kind::Path => keys::apply(&mut candidate, key, &Value::Str(text.clone())),
            _ => load::apply_set(&mut candidate, key.name, text.trim()).map_err(|p| p.message),
        };
        match result {
            Ok(()) => {
                let value = keys::get(&candidate, key);
                self.set(i, value)
            }
            Err(e) => {
                self.message = format!("{}: {e}; not changed.", values::label(key));
                Effect::Redraw
            }
        }
    }

    fn toggle(&mut self, i: usize) -> Effect {
        match keys::get(&self.settings, &KEYS[i]) {
            Value::Bool(b) => self.set(i, Value::Bool(!b)),
            _ => Effect::Redraw,
        }
    }

    /// Sets row `i` through `keys::apply` and says what the change does.
    pub fn set(&mut self, i: usize, value: Value) -> Effect {
        let key = &KEYS[i];
        let before = keys::get(&self.settings, key);
        if let Err(e) = keys::apply(&mut self.settings, key, &value) {
            self.message = format!("{}: {e}", values::label(key));
            return Effect::Redraw;
        }
        if keys::get(&self.settings, key) == before {
            return Effect::Redraw;
        }
        self.effect_of_change(key)
    }

    /// What the preview does after `key` changed, as the key table says.
    fn effect_of_change(&mut self, key: &Key) -> Effect {
        self.message = String::new();
        match key.change {
            Change::Repaint => Effect::Repaint,
            Change::Remake => Effect::Regenerate,
            Change::Next => {
                self.message = format!(
                    "{} applies to the next mountain: press N or New to see it.",
                    values::label(key)
                );
                Effect::Redraw
            }
            Change::Nothing => Effect::Redraw,
        }
    }

    /// What a button does.
    pub fn activate(&mut self, b: Button) -> Effect {
        self.focus_button(b);
        match b {
            Button::New => Effect::NewMountain,
            Button::Open => Effect::ListDataSets,
            Button::SaveData => Effect::SaveDataSet,
            Button::Defaults => {
                self.editing = None;
                self.settings = Settings::default();
                self.message = "Defaults restored on the screen; OK saves them.".into();
                Effect::Regenerate
            }
            Button::EditFile => Effect::EditFile,
            Button::Ok => {
                if let Some(e) = &self.file_error {
                    self.message = e.clone();
                    Effect::Redraw
                } else {
                    Effect::Save
                }
            }
            Button::Cancel => Effect::Close,
        }
    }

    fn focus_button(&mut self, b: Button) {
        if self.focused_button() != Some(b) {
            self.editing = None;
        }
        self.focus = KEYS.len() + button_index(b);
    }

    fn focus_row(&mut self, i: usize) -> Effect {
        if self.focus != i {
            let commit = self.commit_text();
            self.focus = i;
            return commit;
        }
        Effect::Redraw
    }

    fn press(&mut self, layout: &mut Layout, x: f64, y: f64) -> Effect {
        match layout.hit(x, y, None) {
            Some(Hit::Bar(part)) => {
                self.press_bar(layout, part, y);
                Effect::Redraw
            }
            Some(Hit::Button(b)) => {
                self.pressed = Some(b);
                Effect::Redraw
            }
            Some(Hit::Row(i, part)) => {
                let commit = self.focus_row(i);
                let effect = self.press_row(i, part);
                if effect == Effect::Redraw {
                    commit
                } else {
                    effect
                }
            }
            _ => Effect::Redraw,
        }
    }

    fn press_row(&mut self, i: usize, part: Part) -> Effect {
        let key = &KEYS[i];
        match (values::widget(key), part) {
            (Widget::Slider, Part::Minus) => self.step_row(i, -1, false),
            (Widget::Slider, Part::Plus) => self.step_row(i, 1, false),
            (Widget::Slider, Part::Track(f)) => {
                self.drag = Some(Drag::Slider(i));
                self.set_fraction(i, f)
            }
            (Widget::Choice, Part::Minus) => self.cycle(i, -1),
            (Widget::Choice, Part::Label) => Effect::Redraw,
            (Widget::Choice, _) => self.cycle(i, 1),
            (Widget::Check, _) => self.toggle(i),
            (Widget::Seed, Part::Next) => self.toggle_seed(i),
            (Widget::Seed | Widget::Text, Part::Label) => Effect::Redraw,
            (Widget::Seed | Widget::Text, _) => {
                if self.editing.is_none() {
                    self.editing = Some(self.edit_start_text(i));
                }
                Effect::Redraw
            }
            _ => Effect::Redraw,
        }
    }

    fn set_fraction(&mut self, i: usize, f: f64) -> Effect {
        match values::at_fraction(&KEYS[i], f) {
            Some(v) => self.set(i, values::number_value(&KEYS[i], v)),
            None => Effect::Redraw,
        }
    }

    /// The scroll bar: the arrows move a line, the track a page (the lines
    /// shown but one, so the line at the edge stays in sight), the thumb is
    /// grabbed.
    fn press_bar(&mut self, layout: &mut Layout, part: BarPart, y: f64) {
        let list = &mut layout.list;
        let page = list.shown().saturating_sub(1).max(1) as i64;
        match part {
            BarPart::Up => list.scroll_by(-1),
            BarPart::Down => list.scroll_by(1),
            BarPart::PageUp => list.scroll_by(-page),
            BarPart::PageDown => list.scroll_by(page),
            BarPart::Thumb => {
                let first = list.first();
                self.drag = Some(Drag::Thumb { y, first });
            }
        }
    }

    fn drag_to(&mut self, layout: &mut Layout, x: f64, y: f64) -> Effect {
        match self.drag {
            Some(Drag::Slider(i)) => self.set_fraction(i, layout.track_fraction(x)),
            Some(Drag::Thumb { y: y0, first }) => {
                let to = layout.list.dragged(first, y - y0);
                layout.list.scroll_to(to);
                Effect::Redraw
            }
            None => Effect::Redraw,
        }
    }

    fn release(&mut self, layout: &Layout, x: f64, y: f64) -> Effect {
        self.drag = None;
        let pressed = self.pressed.take();
        match (pressed, layout.hit(x, y, None)) {
            (Some(b), Some(Hit::Button(h))) if b == h => self.activate(b),
            _ => Effect::Redraw,
        }
    }

    /// The wheel scrolls the list; over the focused row's slider or choice
    /// it steps that value instead, so scrolling past a control never
    /// changes it by chance.
    fn wheel(&mut self, layout: &mut Layout, x: f64, y: f64, lines: i32) -> Effect {
        if lines == 0 {
            return Effect::Redraw;
        }
        match layout.hit(x, y, None) {
            Some(Hit::Row(i, part))
                if self.focused_row() == Some(i)
                    && part != Part::Label
                    && matches!(values::widget(&KEYS[i]), Widget::Slider | Widget::Choice) =>
            {
                self.step_row(i, lines.signum(), false)
            }
            _ if layout.over_list(x, y) => {
                layout.list.scroll_by(-i64::from(lines) * WHEEL_LINES);
                Effect::Redraw
            }
            _ => Effect::Redraw,
        }
    }

    /// Shows the data sets Open can load (the window found them on disk).
    pub fn show_list(&mut self, files: Vec<PathBuf>, searched: &str) {
        if files.is_empty() {
            self.message = format!(
                "No data sets ({}) in {searched}.",
                crate::terrain::heightmap::data_set_extensions()
            );
            self.open_list = None;
        } else {
            self.message = "Choose a data set: arrows and Enter, or click; Esc closes.".into();
            self.open_list = Some(OpenList::new(files));
        }
    }

    /// Input while the open list is shown; `None` lets it through.
    fn handle_list(&mut self, input: &Input, layout: &Layout) -> Option<Effect> {
        let list = self.open_list.as_mut()?;
        let outcome = list.handle(input, layout);
        if !matches!(outcome, Outcome::Stays | Outcome::Passes) {
            self.open_list = None;
        }
        match outcome {
            Outcome::Stays => Some(Effect::Redraw),
            Outcome::Closed => {
                self.message.clear();
                Some(Effect::Redraw)
            }
            Outcome::Picked(path) => {
                self.message.clear();
                Some(Effect::OpenDataSet(path))
            }
            Outcome::ClosedPassing | Outcome::Passes => None,
        }
    }
}

/// A problem in the file, without the path (the screen shows it already),
/// and what the screen does about it.
fn describe(p: &load::Problem) -> String {
    let at = p
        .position
        .map_or(String::new(), |(l, _)| format!("Line {l}: "));
    let key = p.key.as_ref().map_or(String::new(), |k| format!("`{k}`: "));
    let what = if keys::find(p.key.as_deref().unwrap_or("")).is_some() {
        "the default is shown; OK writes it"
    } else {
        "OK leaves it in the file as it is"
    };
    format!("{at}{key}{} ({what})", p.message)
}

fn more(n: usize) -> String {
    match n {
        0 | 1 => String::new(),
        2 => "; 1 more problem".into(),
        n => format!("; {} more problems", n - 1),
    }
}

fn button_index(b: Button) -> usize {
    Button::ALL.iter().position(|x| *x == b).unwrap_or(0)
}

/// Whether a typed character belongs in the key's text: numbers take digits
/// and number signs (so N still makes a new mountain), paths take anything.
fn takes_char(key: &Key, c: char) -> bool {
    match key.kind {
        keys::Kind::Path => !c.is_control(),
        keys::Kind::Seed => c.is_ascii_digit(),
        _ => c.is_ascii_digit() || matches!(c, '.' | '-' | '+'),
    }
}
