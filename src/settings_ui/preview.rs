//! The live preview: one mountain, drawn a few strips per frame into its own
//! picture, remade or repainted as the settings change. No window here.

use std::path::{Path, PathBuf};
use std::sync::Arc;

use crate::mountain::Mountain;
use crate::render::{Frame, Painter, Size};
use crate::settings::{Detail, Settings};
use crate::terrain::Heightfield;
use crate::terrain::heightmap::GeneratorParams;

/// The preview never generates more than 2^9+1 points a side: the picture is
/// a few hundred pixels wide, so more detail would only cost time.
pub const MAX_PREVIEW_DETAIL: u32 = 9;

/// Strips drawn per frame are the total divided by this: about a third of a
/// second per mountain at 60 frames a second.
const FRAMES_PER_MOUNTAIN: usize = 20;

/// What the preview shows and how far it has drawn it.
pub struct Preview {
    field: Option<Arc<Heightfield>>,
    /// The seed of the mountain shown, when it was generated or its file says.
    pub seed: Option<u64>,
    /// The data set file shown, when it came from one.
    pub file: Option<PathBuf>,
    /// What that file recorded (see `Mountain::recorded`).
    recorded: Option<GeneratorParams>,
    painter: Option<Painter>,
    picture: Option<Frame>,
}

impl Default for Preview {
    fn default() -> Self {
        Self::new()
    }
}

impl Preview {
    /// An empty preview.
    pub fn new() -> Preview {
        Preview {
            field: None,
            seed: None,
            file: None,
            recorded: None,
            painter: None,
            picture: None,
        }
    }

    /// The settings the preview generates with: the screen's, with the
    /// detail fitted to the preview's size and capped.
    fn preview_settings(settings: &Settings, size: Size) -> Settings {
        let mut s = crate::render::detail::for_frame(settings, size);
        if let Detail::Level(n) = s.detail {
            s.detail = Detail::Level(n.min(MAX_PREVIEW_DETAIL));
        }
        s
    }

    /// A new mountain from `seed` under `settings`.
    pub fn generate(&mut self, settings: &Settings, seed: u64, size: Size) {
        let made = Mountain::from_seed(&Self::preview_settings(settings, size), seed);
        self.field = Some(made.field);
        self.seed = made.seed;
        self.file = None;
        self.recorded = None;
        self.repaint(settings, size);
    }

    /// The same mountain made again (same seed) under new settings; a data
    /// set from a file is only repainted.
    pub fn regenerate(&mut self, settings: &Settings, size: Size) {
        match (self.seed, &self.file) {
            (Some(seed), None) => self.generate(settings, seed, size),
            _ => self.repaint(settings, size),
        }
    }

    /// Shows a data set from disk.
    pub fn open(&mut self, path: &Path, settings: &Settings, size: Size) -> Result<(), String> {
        let (opened, _notes) = Mountain::open(path)?;
        self.field = Some(opened.field);
        self.seed = opened.seed;
        self.file = Some(path.to_path_buf());
        self.recorded = opened.recorded;
        self.repaint(settings, size);
        Ok(())
    }

    /// Starts drawing the current mountain again, from the back.
    pub fn repaint(&mut self, settings: &Settings, size: Size) {
        let drawn = self.drawn_with(settings);
        self.painter = self
            .field
            .as_ref()
            .map(|f| Painter::at_hour(f.clone(), &drawn, size, crate::solar::now_for(&drawn)));
        self.picture = Frame::new(size.width, size.height);
    }

    /// The settings the mountain shown is drawn with under the screen's
    /// `settings`: for a data set, with the keys its file recorded (see
    /// `Mountain::drawn_with`).
    pub fn drawn_with(&self, settings: &Settings) -> Settings {
        Mountain::drawn_under(self.recorded.as_ref(), settings)
    }

    /// What a data set of the mountain shown records under `settings`
    /// (see `Mountain::saved_with`).
    pub fn saved_with(&self, field: &Heightfield, settings: &Settings) -> Settings {
        let opened = self.file.is_some().then_some(self.recorded.as_ref());
        Mountain::saved_under(opened, field, settings)
    }

    /// Draws the next few strips; true while more remain.
    pub fn step(&mut self) -> bool {
        let (Some(p), Some(pic)) = (self.painter.as_mut(), self.picture.as_mut()) else {
            return false;
        };
        let budget = (p.strips_total() / FRAMES_PER_MOUNTAIN).max(1);
        p.step(pic, budget);
        !p.is_done()
    }

    /// The picture so far.
    pub fn picture(&self) -> Option<&Frame> {
        self.picture.as_ref()
    }

    /// The heights shown, for saving as a data set.
    pub fn field(&self) -> Option<&Heightfield> {
        self.field.as_deref()
    }

    /// One line saying what the preview shows.
    pub fn caption(&self) -> String {
        match (&self.file, self.seed) {
            (Some(f), _) => {
                let name = f.file_name().map_or_else(
                    || f.display().to_string(),
                    |n| n.to_string_lossy().into_owned(),
                );
                format!("Data set {name}")
            }
            (None, Some(s)) => format!("Seed {s}   N: new mountain"),
            (None, None) => "No mountain yet".into(),
        }
    }
}
