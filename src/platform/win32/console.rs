//! The console of a GUI-subsystem program started from one: `--help`,
//! `render` and errors print there.

use windows_sys::Win32::Foundation::{HANDLE, INVALID_HANDLE_VALUE};
use windows_sys::Win32::System::Console::{
    ATTACH_PARENT_PROCESS, AttachConsole, GetStdHandle, STD_ERROR_HANDLE, STD_HANDLE,
    STD_OUTPUT_HANDLE, SetStdHandle,
};

/// The handle to keep for `which`: one the parent gave us (a file, a pipe).
fn inherited(which: STD_HANDLE) -> Option<HANDLE> {
    // SAFETY: GetStdHandle only reads the process's standard handle table.
    let h = unsafe { GetStdHandle(which) };
    (!h.is_null() && h != INVALID_HANDLE_VALUE).then_some(h)
}

/// Attaches to the parent's console, keeping redirected output where it
/// is (see `log::use_parent_console`).
pub fn attach_parent() {
    let (out, err) = (inherited(STD_OUTPUT_HANDLE), inherited(STD_ERROR_HANDLE));
    if out.is_some() && err.is_some() {
        return;
    }
    // SAFETY: plain calls on the process's own console state; a failure
    // (no parent console, e.g. started by Windows) changes nothing.
    unsafe {
        if AttachConsole(ATTACH_PARENT_PROCESS) == 0 {
            return;
        }
        // Attaching points the standard handles at the console; put back
        // the redirections the parent set up (`> file`, `2> file`, pipes),
        // and open the console by name where attaching set nothing.
        for (which, kept) in [(STD_OUTPUT_HANDLE, out), (STD_ERROR_HANDLE, err)] {
            match kept.or_else(|| inherited(which)).or_else(console_output) {
                Some(h) => SetStdHandle(which, h),
                None => 0,
            };
        }
    }
}

/// A new handle on the attached console's screen buffer, kept open for
/// the life of the process. Read access too: std asks it for its mode.
fn console_output() -> Option<HANDLE> {
    use std::os::windows::io::IntoRawHandle;
    let file = std::fs::OpenOptions::new()
        .read(true)
        .write(true)
        .open("CONOUT$")
        .ok()?;
    Some(file.into_raw_handle() as HANDLE)
}
