//! The settings screen without its window: the model, the preview, the
//! frame, and what each effect does on disk. The window layer feeds it
//! inputs and presents its frame.

use std::path::{Path, PathBuf};

use super::draw::{self, Extras};
use super::layout::Layout;
use super::model::{Effect, Input, Model};
use super::preview::Preview;
use crate::render::{Frame, Size};
use crate::settings::{Settings, load, paths, save};

/// What the window should do after an input.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Next {
    /// Keep the window open.
    Stay,
    /// Close the window: saved, or cancelled.
    Close,
}

/// The whole screen's state.
pub struct Screen {
    /// The settings being edited and the focus.
    pub model: Model,
    layout: Layout,
    frame: Frame,
    preview: Preview,
    config: PathBuf,
    /// The file's bytes when last read (`None`: absent or unreadable).
    config_seen: Option<Vec<u8>>,
    data_dir: Option<PathBuf>,
    editing: super::editor::Editing,
}

/// The file's content, compared rather than its modification time, which
/// a copy made with `cp -p` or `rsync -t` keeps although the text changed.
fn contents(path: &Path) -> Option<Vec<u8>> {
    crate::fsutil::read_regular(path, crate::fsutil::MAX_PREFERENCES_BYTES).ok()
}

impl Screen {
    /// A screen for `settings` read from `config` (with its `problems`),
    /// drawn into a frame of `size` at whole `scale`.
    pub fn new(
        settings: Settings,
        problems: &[load::Problem],
        config: PathBuf,
        size: Size,
        scale: u32,
    ) -> Screen {
        let model = Model::new(settings, problems);
        Screen::of_model(model, config, size, scale)
    }

    /// A screen for the file's `settings` showing `shown` (`--set` on top of
    /// them) as changed here: see [`Model::with_unsaved`].
    pub fn with_unsaved(
        settings: Settings,
        shown: Settings,
        problems: &[load::Problem],
        config: PathBuf,
        size: Size,
        scale: u32,
    ) -> Screen {
        let model = Model::with_unsaved(settings, shown, problems);
        Screen::of_model(model, config, size, scale)
    }

    fn of_model(model: Model, config: PathBuf, size: Size, scale: u32) -> Screen {
        let layout = Layout::new(size, scale);
        let frame = Frame::new(size.width.max(1), size.height.max(1)).unwrap_or_else(tiny_frame);
        let mut screen = Screen {
            model,
            layout,
            frame,
            preview: Preview::new(),
            config_seen: contents(&config),
            config,
            data_dir: paths::data_dir(),
            editing: Default::default(),
        };
        screen.new_mountain();
        screen
    }

    /// Where saved data sets go and Open looks first (tests point it elsewhere).
    pub fn set_data_dir(&mut self, dir: Option<PathBuf>) {
        self.data_dir = dir;
    }

    /// The layout in use.
    pub fn layout(&self) -> &Layout {
        &self.layout
    }

    /// Follows a new window size or scale: the list keeps its place as far
    /// as it can, and the focused row stays in sight.
    pub fn resize(&mut self, size: Size, scale: u32) {
        let Some(frame) = Frame::new(size.width, size.height) else {
            return;
        };
        self.frame = frame;
        let first = self.layout.list.first();
        self.layout = Layout::new(size, scale);
        self.layout.list.scroll_to(first);
        if let Some(i) = self.model.focused_row() {
            self.layout.reveal_row(i);
        }
        self.preview
            .repaint(&self.model.settings, self.preview_size());
    }

    fn preview_size(&self) -> Size {
        draw::preview_size(&self.layout)
    }

    fn new_mountain(&mut self) {
        let seed = self.model.settings.next_seed();
        self.preview
            .generate(&self.model.settings, seed, self.preview_size());
        self.model.preview_seed = self.preview.seed();
    }

    /// Handles one input and carries out what it asks for.
    pub fn input(&mut self, input: Input) -> Next {
        let effect = self.model.handle(input, &mut self.layout);
        self.apply(effect)
    }

    /// Carries out an effect.
    pub fn apply(&mut self, effect: Effect) -> Next {
        let size = self.preview_size();
        let settings = &self.model.settings;
        match effect {
            Effect::Redraw => {}
            Effect::Repaint => self.preview.repaint(settings, size),
            Effect::Regenerate => self.preview.regenerate(settings, size),
            Effect::NewMountain => self.new_mountain(),
            Effect::ListDataSets => self.list_data_sets(),
            Effect::OpenDataSet(path) => self.open_data_set(&path),
            Effect::SaveDataSet => self.save_data_set(),
            Effect::EditFile => self.edit_file(),
            Effect::Save => return self.save(),
            Effect::Close => return Next::Close,
        }
        Next::Stay
    }

    /// Writes only the keys changed on the screen, into the file as it is
    /// now: another program's change to any other key since the screen
    /// read the file survives, even one it has not noticed yet.
    fn save(&mut self) -> Next {
        let changed = self.model.changed_keys();
        match save::save_changes(&self.config, &self.model.settings, &changed) {
            Ok(()) => Next::Close,
            Err(e) => {
                self.model.message = format!("{e}. {}", e.advice());
                Next::Stay
            }
        }
    }

    fn list_data_sets(&mut self) {
        let dirs = crate::saved::folders(
            self.data_dir.as_deref(),
            self.model.settings.heightmaps_dir.as_deref(),
        );
        let names: Vec<String> = dirs.iter().map(|d| d.display().to_string()).collect();
        let searched = if names.is_empty() {
            "no folder (no data directory, heightmaps_dir empty)".to_string()
        } else {
            names.join(" and ")
        };
        self.model
            .show_list(crate::saved::list_data_sets(&dirs), &searched);
    }

    fn open_data_set(&mut self, path: &Path) {
        let size = self.preview_size();
        match self.preview.open(path, &self.model.settings, size) {
            Ok(()) => {
                self.model.preview_seed = self.preview.seed();
                self.model.message = format!("Opened {}.", path.display());
            }
            Err(e) => self.model.message = format!("Cannot open: {e}"),
        }
    }

    fn save_data_set(&mut self) {
        let to_save = self.preview.to_save(&self.model.settings);
        let (Some((field, saved)), Some(dir)) = (to_save, self.data_dir.as_deref()) else {
            self.model.message = "Nothing to save, or no data directory.".into();
            return;
        };
        self.model.message =
            match crate::saved::save_data_set(dir, field, self.preview.seed(), &saved) {
                Ok(path) => format!("Saved {}.", path.display()),
                Err(e) => format!("Cannot save the data set: {e}"),
            };
    }

    fn edit_file(&mut self) {
        match super::editor::open(&self.config, &self.editing) {
            Ok(what) => self.model.message = what,
            Err(e) => self.model.message = e,
        }
    }

    /// Reloads the preferences file if it changed on disk (edited with Edit
    /// file, or by hand), keeping the values changed on the screen, and
    /// says so if the editor failed. Returns true when either happened.
    pub fn poll_file(&mut self) -> bool {
        if let Some(failure) = self.editing.take_failure() {
            self.model.message = failure;
            return true;
        }
        let now = contents(&self.config);
        if now == self.config_seen {
            return false;
        }
        self.config_seen = now;
        let mut fresh = Settings::default();
        // A link to nowhere is read, and says so (`exists` follows it).
        let problems = if crate::fsutil::taken(&self.config) {
            load::apply_file(&mut fresh, &self.config)
        } else {
            Vec::new()
        };
        self.model.merge_from_file(fresh, &problems);
        true
    }

    /// Draws the next strips of the preview; true while more remain.
    pub fn step_preview(&mut self) -> bool {
        self.preview.step()
    }

    /// Draws the screen and returns the frame to present.
    pub fn draw(&mut self) -> &Frame {
        let caption = self.preview.caption();
        let file = self.config.display().to_string();
        let extras = Extras {
            preview: self.preview.picture(),
            caption: &caption,
            file: &file,
        };
        draw::draw(&mut self.frame, &self.layout, &self.model, &extras);
        &self.frame
    }
}

fn tiny_frame() -> Frame {
    Frame::new(1, 1).unwrap_or_else(|| unreachable!("a 1x1 frame is always allowed"))
}
