//! "Edit file": the preferences file in the user's own editor, without
//! blocking the screen. The editor is chosen by `commands::edit_config`
//! (Windows: Notepad; elsewhere `$VISUAL`, `$EDITOR`, else xdg-open); the
//! screen notices the saved file by its modification time.

use std::path::Path;

/// Starts the editor on `path` in the background and says so. A file that
/// does not exist yet is created from the commented defaults first.
pub fn open(path: &Path) -> Result<String, String> {
    let owned = path.to_path_buf();
    std::thread::Builder::new()
        .name("editor".into())
        .spawn(move || {
            let _ = crate::commands::edit_config(Some(&owned));
        })
        .map_err(|e| format!("cannot start the editor: {e}"))?;
    Ok(format!(
        "Opened {} in your editor; saved changes show here.",
        path.display()
    ))
}
