//! Where everything sits on the settings screen, and what a pointer is over.
//!
//! Positions are planned in logical pixels and multiplied by a whole scale
//! (1 at 100%, 2 at 200%), so the font stays crisp and hit-testing matches
//! drawing exactly at every scale.

use super::font::ADVANCE;
use super::help;
use super::list_view::{BarPart, Line, ListView};
use super::values::{self, Widget};
use crate::render::{Rect, Size};
use crate::settings::keys::{self, KEYS, Key};

/// Logical size the window asks for.
pub const WINDOW_W: u32 = 960;
/// Logical height the window asks for.
pub const WINDOW_H: u32 = 620;
/// The narrowest the window may be made, logical pixels: the panel, the
/// margins, and a preview as wide as the buttons above it.
pub const MIN_W: u32 = 640;
/// The lowest the window may be made, logical pixels: the list then shows
/// eight lines and scrolls, and the help below it is whole.
pub const MIN_H: u32 = WINDOW_H / 2;

const MARGIN: u32 = 8;
/// Width of the settings panel, logical pixels.
pub const PANEL_W: u32 = 372;
/// Height of one settings row, logical pixels.
pub const ROW_H: u32 = 17;
const BUTTON_H: u32 = 22;
const BUTTON_W: u32 = 84;
const TOOL_W: u32 = 64;
/// The scroll bar, at the panel's right.
const SCROLL_W: u32 = 14;
/// A row: the panel less the scroll bar's column.
const ROW_W: u32 = PANEL_W - SCROLL_W;
/// One line of help.
pub const HELP_LINE: u32 = 12;
/// Characters in a line of help: the panel's width.
pub const HELP_CHARS: usize = (PANEL_W / ADVANCE) as usize;
const HELP_GAP: u32 = 6;
/// The file line over the buttons.
const FILE_H: u32 = 14;

/// Control columns inside a row, logical pixels from the panel's left.
pub const LABEL_X: u32 = 12;
/// Where a row's control starts.
pub const CTRL_X: u32 = 128;
/// Where a row's control ends, clear of the scroll bar.
pub const CTRL_END: u32 = ROW_W - 4;
const MINUS: (u32, u32) = (128, 142);
const TRACK: (u32, u32) = (148, 274);
const PLUS: (u32, u32) = (280, 294);
/// Where a slider's value text starts.
pub const VALUE_X: u32 = 300;
const LEFT_ARROW: (u32, u32) = MINUS;
const RIGHT_ARROW: (u32, u32) = (CTRL_END - 14, CTRL_END);
/// The seed row's "Random" / "Keep" button.
pub const SEED_BUTTON: (u32, u32) = (CTRL_END - 66, CTRL_END);

/// The buttons, in focus order after the rows.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Button {
    /// A new preview mountain.
    New,
    /// Open a saved data set (a PNG or raw heightmap).
    Open,
    /// Save the preview mountain as a data set.
    SaveData,
    /// Put every value back to its default (on screen only).
    Defaults,
    /// Open the preferences file in the user's editor.
    EditFile,
    /// Save and close.
    Ok,
    /// Close without saving.
    Cancel,
}

impl Button {
    /// Every button, in focus order.
    pub const ALL: [Button; 7] = [
        Button::New,
        Button::Open,
        Button::SaveData,
        Button::Defaults,
        Button::EditFile,
        Button::Ok,
        Button::Cancel,
    ];

    /// The caption.
    pub fn caption(self) -> &'static str {
        match self {
            Button::New => "New",
            Button::Open => "Open...",
            Button::SaveData => "Save",
            Button::Defaults => "Defaults",
            Button::EditFile => "Edit file",
            Button::Ok => "OK",
            Button::Cancel => "Cancel",
        }
    }
}

/// Section headings, placed before the row of the named key.
pub const SECTIONS: &[(&str, &str)] = &[
    (keys::SEED.name, "The mountain"),
    (keys::LOOK.name, "The look"),
    (keys::AUTO_REDRAW.name, "The slide show"),
];

/// Which part of a row a point is on.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Part {
    /// The label or empty space.
    Label,
    /// The slider's minus box, or a choice's left arrow.
    Minus,
    /// The slider's plus box.
    Plus,
    /// The slider track, at this fraction of its length.
    Track(f64),
    /// A choice's right arrow, or the seed's Random/Keep button.
    Next,
    /// The control itself (check box, choice text, text field).
    Control,
}

/// What a point on the screen is over.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Hit {
    /// A settings row (index into `KEYS`) and the part of it.
    Row(usize, Part),
    /// A part of the settings list's scroll bar.
    Bar(BarPart),
    /// A button.
    Button(Button),
    /// Entry `i` of the open-a-data-set list.
    ListItem(usize),
    /// The preview picture.
    Preview,
}

/// The planned screen for one window size and scale.
#[derive(Debug, Clone, PartialEq)]
pub struct Layout {
    /// Whole pixels per logical pixel (1 or more).
    pub scale: u32,
    /// Frame size in pixels.
    pub size: Size,
    /// Left edge of the settings panel, pixels.
    pub panel_x: u32,
    /// The settings list (headings and rows) and the window it is seen
    /// through: what is shown, and where it is scrolled to.
    pub list: ListView,
    /// Where the focused key's help text starts, pixels.
    pub help_y: u32,
    /// Top of the line naming the preferences file, pixels: the help ends
    /// above it.
    pub file_y: u32,
    /// Each button and its rectangle.
    pub buttons: Vec<(Button, Rect)>,
    /// The preview picture.
    pub preview: Rect,
    /// The row whose control is the seed's field and button.
    seed_row: Option<usize>,
}

/// The whole scale for a window's scale factor (1.25 -> 1, 1.5 and 2 -> 2),
/// lowered until the window fits on a monitor of `monitor` size (a
/// 1920x1080 screen at 150% gets 1, not a window taller than the screen).
pub fn whole_scale(scale_factor: f64, monitor: Option<Size>) -> u32 {
    let mut s = if scale_factor.is_finite() {
        scale_factor.round().clamp(1.0, 8.0) as u32
    } else {
        1
    };
    if let Some(Size {
        width: mw,
        height: mh,
    }) = monitor
    {
        while s > 1 && (WINDOW_W * s > mw || (WINDOW_H + BARS_H) * s > mh) {
            s -= 1;
        }
    }
    s
}

/// Room left on a monitor for a title bar and a task bar, logical pixels.
const BARS_H: u32 = 60;

/// The window's size in physical pixels at `scale`: the size it asks for,
/// each side held to a monitor of `monitor` size (less [`BARS_H`] down),
/// but never under the least it may be made. On a 1024x600 netbook's
/// screen the 620-pixel window had its OK and Cancel below the screen.
pub fn window_size(scale: u32, monitor: Option<Size>) -> Size {
    let (w, h) = (WINDOW_W * scale, WINDOW_H * scale);
    let (w, h) = match monitor {
        Some(m) => (
            w.min(m.width),
            h.min(m.height.saturating_sub(BARS_H * scale)),
        ),
        None => (w, h),
    };
    Size::new(w.max(MIN_W * scale), h.max(MIN_H * scale))
}

/// The lines of the settings list for `keys`: each key's row, a section's
/// heading before the row that starts it.
fn lines_of(keys: &[Key]) -> Vec<Line> {
    let mut lines = Vec::with_capacity(keys.len() + SECTIONS.len());
    for (i, key) in keys.iter().enumerate() {
        if let Some((_, title)) = SECTIONS.iter().find(|(k, _)| *k == key.name) {
            lines.push(Line::Heading(title));
        }
        lines.push(Line::Row(i));
    }
    lines
}

impl Layout {
    /// Plans a frame of `size` at whole `scale`, scrolled to the
    /// top. A frame smaller than the window may be made keeps the smallest
    /// layout, clipped.
    pub fn new(size: Size, scale: u32) -> Layout {
        Layout::with_keys(size, scale, KEYS)
    }

    /// `new` for a list of `keys` other than the key table's (tests plan
    /// the keys still to come). The list shows as many whole lines as fit
    /// above the longest help, and scrolls when they are not all shown;
    /// extra height goes to the preview, extra width too.
    pub fn with_keys(size: Size, scale: u32, keys: &[Key]) -> Layout {
        let s = scale.max(1);
        let w_log = (size.width / s).max(MIN_W);
        let h_log = (size.height / s).max(MIN_H);
        let panel = w_log - MARGIN - PANEL_W;
        let by = h_log - MARGIN - BUTTON_H;
        let file_y = by - FILE_H;
        let lines = lines_of(keys);
        let help_h = help::most_rows(keys, HELP_CHARS) as u32 * HELP_LINE;
        let room = file_y.saturating_sub(MARGIN + HELP_GAP + help_h);
        let shown = (room / ROW_H).clamp(1, lines.len().max(1) as u32);
        let help_y = MARGIN + shown * ROW_H + HELP_GAP;
        let mut buttons = Vec::new();
        for (i, b) in [Button::New, Button::Open, Button::SaveData]
            .iter()
            .enumerate()
        {
            let r = Rect::sized(MARGIN + i as u32 * (TOOL_W + 6), MARGIN, TOOL_W, BUTTON_H);
            buttons.push((*b, r));
        }
        let bottom = [
            Button::Defaults,
            Button::EditFile,
            Button::Ok,
            Button::Cancel,
        ];
        for (i, b) in bottom.iter().enumerate() {
            let x = panel + PANEL_W - (4 - i as u32) * (BUTTON_W + 6) + 6;
            buttons.push((*b, Rect::sized(x, by, BUTTON_W, BUTTON_H)));
        }
        let top = MARGIN + BUTTON_H + 6;
        let preview = Rect::sized(MARGIN, top, panel - 2 * MARGIN, h_log - top - MARGIN);
        let scaled = |r: Rect| Rect {
            x0: r.x0 * s,
            y0: r.y0 * s,
            x1: r.x1 * s,
            y1: r.y1 * s,
        };
        let area = Rect::sized(panel, MARGIN, PANEL_W, shown * ROW_H);
        Layout {
            scale: s,
            size,
            panel_x: panel * s,
            list: ListView::new(lines, area, ROW_H, SCROLL_W, s),
            help_y: help_y * s,
            file_y: file_y * s,
            buttons: buttons.into_iter().map(|(b, r)| (b, scaled(r))).collect(),
            preview: scaled(preview),
            seed_row: keys.iter().position(|k| values::widget(k) == Widget::Seed),
        }
    }

    /// Scrolls the list as little as shows row `i` whole.
    pub fn reveal_row(&mut self, i: usize) {
        if let Some(line) = self.list.line_of_row(i) {
            self.list.reveal(line);
        }
    }

    /// Whether row `i` is shown (not scrolled out of the list's window).
    pub fn row_shown(&self, i: usize) -> bool {
        self.list
            .line_of_row(i)
            .is_some_and(|l| self.list.top(l).is_some())
    }

    /// A logical length in pixels.
    pub fn px(&self, logical: u32) -> u32 {
        logical * self.scale
    }

    /// The rectangle of button `b`.
    pub fn button(&self, b: Button) -> Rect {
        self.buttons
            .iter()
            .find(|(x, _)| *x == b)
            .map_or(Rect::default(), |(_, r)| *r)
    }

    /// The rectangle of row `i` (across the panel up to the scroll bar)
    /// where it is shown; an empty one while it is scrolled out of sight.
    pub fn row(&self, i: usize) -> Rect {
        let top = self.list.line_of_row(i).and_then(|l| self.list.top(l));
        let Some(y0) = top else {
            return Rect::default();
        };
        Rect {
            x0: self.panel_x,
            y0,
            x1: self.panel_x + self.px(ROW_W),
            y1: y0 + self.px(ROW_H),
        }
    }

    /// The shown section headings: top, pixels, and title.
    pub fn headings(&self) -> impl Iterator<Item = (u32, &'static str)> + '_ {
        self.list.visible().filter_map(|(y, line)| match line {
            Line::Heading(title) => Some((y, title)),
            Line::Row(_) => None,
        })
    }

    /// The shown rows (indices into `KEYS`), top to bottom.
    pub fn rows_shown(&self) -> impl Iterator<Item = usize> + '_ {
        self.list.visible().filter_map(|(_, line)| match line {
            Line::Row(i) => Some(i),
            Line::Heading(_) => None,
        })
    }

    /// A span of a row's columns (logical, from the panel's left) in pixels.
    pub fn columns(&self, span: (u32, u32)) -> (u32, u32) {
        (
            self.panel_x + self.px(span.0),
            self.panel_x + self.px(span.1),
        )
    }

    /// The slider track's left and right ends, pixels.
    pub fn track(&self) -> (u32, u32) {
        self.columns(TRACK)
    }

    /// The slider's minus and plus boxes, pixels.
    pub fn minus_plus(&self) -> ((u32, u32), (u32, u32)) {
        (self.columns(MINUS), self.columns(PLUS))
    }

    /// A choice's arrow boxes, pixels.
    pub fn arrows(&self) -> ((u32, u32), (u32, u32)) {
        (self.columns(LEFT_ARROW), self.columns(RIGHT_ARROW))
    }

    /// Rectangle of entry `i` of a list of `n` shown over the preview.
    pub fn list_item(&self, i: usize) -> Rect {
        let p = self.preview;
        let y0 = p.y0 + self.px(8) + i as u32 * self.px(ROW_H);
        Rect {
            x0: p.x0 + self.px(8),
            y0,
            x1: p.x1.saturating_sub(self.px(8)),
            y1: y0 + self.px(ROW_H),
        }
    }

    /// How many list entries fit over the preview.
    pub fn list_capacity(&self) -> usize {
        let h = self
            .preview
            .y1
            .saturating_sub(self.preview.y0 + self.px(16));
        (h / self.px(ROW_H)).max(1) as usize
    }

    /// What the point `(x, y)` (pixels) is over; `list_len` entries of the
    /// open list are shown when it is open.
    pub fn hit(&self, x: f64, y: f64, list_len: Option<usize>) -> Option<Hit> {
        if !(x.is_finite() && y.is_finite()) || x < 0.0 || y < 0.0 {
            return None;
        }
        let (xi, yi) = (x as u32, y as u32);
        let inside = |r: &Rect| xi >= r.x0 && xi < r.x1 && yi >= r.y0 && yi < r.y1;
        if let Some(n) = list_len {
            let shown = n.min(self.list_capacity());
            if let Some(i) = (0..shown).find(|i| inside(&self.list_item(*i))) {
                return Some(Hit::ListItem(i));
            }
        }
        if let Some((b, _)) = self.buttons.iter().find(|(_, r)| inside(r)) {
            return Some(Hit::Button(*b));
        }
        if let Some(part) = self.list.bar_part(xi, yi) {
            return Some(Hit::Bar(part));
        }
        if let Some(i) = self.rows_shown().find(|i| inside(&self.row(*i))) {
            return Some(Hit::Row(i, self.part(i, x)));
        }
        inside(&self.preview).then_some(Hit::Preview)
    }

    /// Whether the point `(x, y)` (pixels) is over the settings list or
    /// its scroll bar: where the wheel scrolls the list.
    pub fn over_list(&self, x: f64, y: f64) -> bool {
        x.is_finite()
            && y.is_finite()
            && x >= 0.0
            && y >= 0.0
            && self.list.contains(x as u32, y as u32)
    }

    /// The part of row `i` at pixel column `x`.
    fn part(&self, i: usize, x: f64) -> Part {
        let within = |span: (u32, u32)| {
            let (a, b) = self.columns(span);
            x >= a as f64 && x < b as f64
        };
        let seed = self.seed_row == Some(i);
        if seed && within(SEED_BUTTON) {
            Part::Next
        } else if seed && within((CTRL_X, SEED_BUTTON.0)) {
            Part::Control
        } else if within(MINUS) {
            Part::Minus
        } else if within(RIGHT_ARROW) {
            Part::Next
        } else if within(PLUS) {
            Part::Plus
        } else if within(TRACK) {
            Part::Track(self.track_fraction(x))
        } else if x < self.columns((CTRL_X, CTRL_X)).0 as f64 {
            Part::Label
        } else {
            Part::Control
        }
    }

    /// A slider fraction for a pointer at column `x`, clamped to the track
    /// (used while dragging, when the pointer may leave it).
    /// The thumb is 8 logical pixels wide, so its centre travels from 4 in
    /// from the left end to 4 in from the right.
    pub fn track_fraction(&self, x: f64) -> f64 {
        let (t0, t1) = self.track();
        let half = self.px(4) as f64;
        let travel = (t1 - t0) as f64 - 2.0 * half;
        ((x - t0 as f64 - half) / travel).clamp(0.0, 1.0)
    }
}
