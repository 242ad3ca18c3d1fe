//! The live preview: one mountain, drawn a few strips per frame into its own
//! picture, remade or repainted as the settings change. No window here.

use std::path::{Path, PathBuf};

use crate::mountain::Mountain;
use crate::render::{Frame, Painter, Size};
use crate::settings::{Detail, Settings};
use crate::terrain::Heightfield;

/// The preview never generates more than 2^9+1 points a side: the picture is
/// a few hundred pixels wide, so more detail would only cost time.
pub const MAX_PREVIEW_DETAIL: u32 = 9;

/// Strips drawn per frame are the total divided by this: about a third of a
/// second per mountain at 60 frames a second.
const FRAMES_PER_MOUNTAIN: usize = 20;

/// What the preview shows and how far it has drawn it.
pub struct Preview {
    /// The mountain shown, generated here or read from a data set.
    mountain: Option<Mountain>,
    /// The data set file shown, when it came from one.
    pub file: Option<PathBuf>,
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
            mountain: None,
            file: None,
            painter: None,
            picture: None,
        }
    }

    /// The seed of the mountain shown, when it was generated or its file
    /// says.
    pub fn seed(&self) -> Option<u64> {
        self.mountain.as_ref().and_then(|m| m.seed)
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
        self.mountain = Some(made);
        self.file = None;
        self.repaint(settings, size);
    }

    /// The same mountain made again (same seed) under new settings; a data
    /// set from a file is only repainted.
    pub fn regenerate(&mut self, settings: &Settings, size: Size) {
        match (self.seed(), &self.file) {
            (Some(seed), None) => self.generate(settings, seed, size),
            _ => self.repaint(settings, size),
        }
    }

    /// Shows a data set from disk.
    pub fn open(&mut self, path: &Path, settings: &Settings, size: Size) -> Result<(), String> {
        let (opened, _notes) = Mountain::open(path)?;
        self.mountain = Some(opened);
        self.file = Some(path.to_path_buf());
        self.repaint(settings, size);
        Ok(())
    }

    /// Starts drawing the current mountain again, from the back.
    pub fn repaint(&mut self, settings: &Settings, size: Size) {
        self.painter = self.mountain.as_ref().map(|m| {
            let drawn = m.drawn_with(settings);
            Painter::at_hour(m.field.clone(), &drawn, size, crate::solar::now_for(&drawn))
        });
        self.picture = Frame::new(size.width, size.height);
    }

    /// What a data set of the mountain shown records under the screen's
    /// `settings` (see `Mountain::saved_with`), and its heights; `None`
    /// before there is a mountain.
    pub fn to_save(&self, settings: &Settings) -> Option<(&Heightfield, Settings)> {
        let m = self.mountain.as_ref()?;
        Some((&m.field, m.saved_with(settings)))
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

    /// One line saying what the preview shows.
    pub fn caption(&self) -> String {
        match (&self.file, self.seed()) {
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
