//! "Edit file": the preferences file in the user's own editor, without
//! blocking the screen. The screen notices the saved file by its
//! modification time, and hears of an editor that could not run.

use std::path::Path;
use std::process::{Child, Command};
use std::sync::{Arc, Mutex};

use crate::settings::load;

/// The command that opens `path` in the editor `editor` names (a command
/// line such as `code --wait` or `emacsclient -c`, read by the shell as git
/// reads `$EDITOR`); with none, the desktop's choice (`xdg-open`). Windows:
/// Notepad.
pub fn command(editor: Option<&str>, path: &Path) -> Command {
    if let Some(fixed) = crate::platform::os::FIXED_EDITOR {
        let mut c = Command::new(fixed);
        c.arg(path);
        return c;
    }
    match editor.map(str::trim).filter(|e| !e.is_empty()) {
        Some(editor) => {
            let mut c = Command::new("sh");
            // The path is passed as "$1", never spliced into the command
            // line: spaces and quotes in it are safe.
            c.arg("-c")
                .arg(format!("{editor} \"$1\""))
                .arg("sh")
                .arg(path);
            c
        }
        None => {
            let mut c = Command::new("xdg-open");
            c.arg(path);
            c
        }
    }
}

/// The editor the user chose: `$VISUAL`, else `$EDITOR`. One set but
/// empty (`VISUAL= mountains --settings`) counts as unset, as [`command`]
/// counts it: an empty `$VISUAL` hid `$EDITOR`, and xdg-open ran.
fn chosen_editor() -> Option<String> {
    let set = |name| std::env::var(name).ok().filter(|v| !v.trim().is_empty());
    set("VISUAL").or_else(|| set("EDITOR"))
}

/// An editor started by Edit file; what became of it, once it has ended
/// badly, for the screen to say.
#[derive(Clone, Default)]
pub struct Editing {
    failure: Arc<Mutex<Option<String>>>,
}

impl Editing {
    /// A failure not yet shown, taken (each is said once).
    pub fn take_failure(&self) -> Option<String> {
        self.failure.lock().ok()?.take()
    }
}

/// Starts the editor on `path` (creating the file from the commented
/// defaults first if it does not exist) and says so. A program that cannot
/// start is an error now; one that ends with a failure status is reported
/// through `editing`.
pub fn open(path: &Path, editing: &Editing) -> Result<String, String> {
    create_default(path)?;
    let editor = chosen_editor();
    let name = editor.clone().unwrap_or_else(|| "xdg-open".into());
    let child = command(editor.as_deref(), path)
        .spawn()
        .map_err(|e| format!("Cannot start the editor `{name}`: {e}"))?;
    watch(child, name, editing.clone());
    Ok(format!(
        "Opened {} in your editor; saved changes show here.",
        path.display()
    ))
}

/// The commented defaults, written where the preferences file belongs if
/// no file is there: asked again just before the new file is renamed into
/// place, so a file another program made meanwhile is kept (it was
/// replaced whenever it came after the first look). A link to nowhere is
/// refused by the write.
fn create_default(path: &Path) -> Result<(), String> {
    let nothing_there = || !path.exists();
    if !nothing_there() {
        return Ok(());
    }
    if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir)
            .map_err(|e| format!("Cannot create {}: {e}", dir.display()))?;
    }
    let defaults = |w: &mut dyn std::io::Write| w.write_all(load::DEFAULT_TOML.as_bytes());
    crate::fsutil::write_atomic_checked(path, defaults, || Ok(nothing_there()))
        .map(|_| ())
        .map_err(|e| format!("Cannot create {}: {e}", path.display()))
}

/// Waits for the editor on a thread of its own; a failure status (127:
/// the shell found no such program) is left in `editing`.
fn watch(mut child: Child, name: String, editing: Editing) {
    let _ = std::thread::Builder::new()
        .name("editor".into())
        .spawn(move || {
            let said = match child.wait() {
                Ok(status) if status.success() => return,
                Ok(status) if status.code() == Some(127) => {
                    format!("The editor `{name}` was not found ({status}); set $VISUAL or $EDITOR.")
                }
                Ok(status) => format!("The editor `{name}` ended with {status}."),
                Err(e) => format!("The editor `{name}`: {e}"),
            };
            if let Ok(mut slot) = editing.failure.lock() {
                *slot = Some(said);
            }
        });
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The defaults are written where no file is, and never over one that
    /// is there, however late it came.
    #[test]
    fn the_defaults_never_replace_a_file_that_is_there() {
        let dir = std::env::temp_dir().join(format!("mountains-editor-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        let path = dir.join("new/mountains.toml");
        create_default(&path).expect("made");
        assert_eq!(std::fs::read_to_string(&path).unwrap(), load::DEFAULT_TOML);
        std::fs::write(&path, "seed = 7\n").unwrap();
        create_default(&path).expect("kept");
        assert_eq!(std::fs::read_to_string(&path).unwrap(), "seed = 7\n");
        let _ = std::fs::remove_dir_all(&dir);
    }
}
