//! The window layer: the only module that knows about winit, softbuffer and X11.

use std::fmt;

use crate::cli::Mode;
use crate::settings::Settings;
use crate::terrain::heightmap::DataSet;

/// Why a window mode could not run.
#[derive(Debug)]
pub struct SaverError(pub String);

impl fmt::Display for SaverError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for SaverError {}

/// Runs a window mode until it ends. `open` is a data set to show instead of generating.
///
/// STUB: the window layer is being written.
pub fn run(mode: &Mode, _settings: Settings, _open: Option<DataSet>) -> Result<(), SaverError> {
    Err(SaverError(format!("{mode:?} is not written yet")))
}
