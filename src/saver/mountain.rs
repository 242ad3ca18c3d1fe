//! A mountain of the slide show: heights, and the seed that made them.

use std::sync::Arc;

use crate::settings::Settings;
use crate::terrain::heightmap::DataSet;
use crate::terrain::{self, Heightfield};

/// A mountain ready to draw and the seed that made it (none for a foreign heightmap).
#[derive(Debug, Clone)]
pub struct Mountain {
    /// The heights.
    pub field: Arc<Heightfield>,
    /// The seed that generated them, when known.
    pub seed: Option<u64>,
    /// Made here from `seed` (not read from a file), so it can be made
    /// again, e.g. at another detail.
    pub generated: bool,
}

impl Mountain {
    /// A data set read from a file: shown as it is, never made again.
    pub fn loaded(data: DataSet) -> Self {
        Mountain {
            field: Arc::new(data.field),
            seed: data.seed,
            generated: false,
        }
    }

    /// Generates a mountain from `settings`, with its seed or a fresh random one.
    pub fn generate(settings: &Settings) -> Self {
        let seed = settings.next_seed();
        Mountain {
            field: Arc::new(terrain::generate(settings, seed)),
            seed: Some(seed),
            generated: true,
        }
    }
}
