//! The operating system under the window systems: what differs between
//! the Unixes and Windows for files, memory, the clock, the console and a
//! program's defaults. Signals have their own file (`signals`).

use std::ffi::{OsStr, OsString};
use std::fs::{File, FileType};
use std::path::Path;

/// Windows starts the program without a console (it is built for the GUI
/// subsystem, so a `.scr` opens no console window): what it prints may be
/// seen nowhere, and errors also go to the log.
pub const NO_CONSOLE: bool = cfg!(windows);

/// The mode when no mode argument is given: on Windows the settings (what
/// Configure sends), elsewhere a normal window.
pub const SETTINGS_WITHOUT_A_MODE: bool = cfg!(windows);

/// The editor that opens the preferences file whatever `$EDITOR` says:
/// Notepad on Windows; elsewhere none (the user's, else the desktop's).
pub const FIXED_EDITOR: Option<&str> = if cfg!(windows) {
    Some("notepad.exe")
} else {
    None
};

/// Attaches to the console of the parent process, if any (Windows; see
/// `log::use_parent_console`). Nothing elsewhere.
pub fn use_parent_console() {
    #[cfg(windows)]
    super::win32::console::attach_parent();
}

/// `arg` split at its first `=`: the text before it, if that part is
/// valid text, and what follows as it was typed. A file's name need not
/// be text (any bytes on the Unixes, unpaired UTF-16 on Windows), so
/// `--config=NAME` keeps its name as `--config NAME` does.
pub fn split_at_equals(arg: &OsStr) -> Option<(String, OsString)> {
    #[cfg(unix)]
    {
        use std::os::unix::ffi::OsStrExt;
        let bytes = arg.as_bytes();
        let i = bytes.iter().position(|&b| b == b'=')?;
        let before = std::str::from_utf8(&bytes[..i]).ok()?;
        Some((
            before.to_string(),
            OsStr::from_bytes(&bytes[i + 1..]).into(),
        ))
    }
    #[cfg(windows)]
    {
        use std::os::windows::ffi::{OsStrExt, OsStringExt};
        let wide: Vec<u16> = arg.encode_wide().collect();
        let i = wide.iter().position(|&w| w == u16::from(b'='))?;
        let before = String::from_utf16(&wide[..i]).ok()?;
        Some((before, OsString::from_wide(&wide[i + 1..])))
    }
    #[cfg(not(any(unix, windows)))]
    {
        let _ = arg;
        None
    }
}

/// Whether `path` names the null device (`/dev/null`, or `NUL` on
/// Windows).
pub fn is_null_device(path: &Path) -> bool {
    #[cfg(unix)]
    {
        std::fs::canonicalize(path).is_ok_and(|real| real == Path::new("/dev/null"))
    }
    #[cfg(not(unix))]
    {
        path.file_stem()
            .and_then(|s| s.to_str())
            .is_some_and(|s| s.eq_ignore_ascii_case("nul"))
    }
}

/// What a special file of type `t` is, in words, where the system has
/// such files (FIFOs, devices, sockets on the Unixes).
pub fn special_file_kind(t: &FileType) -> Option<&'static str> {
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        if t.is_fifo() {
            return Some("a FIFO (named pipe)");
        }
        if t.is_char_device() || t.is_block_device() {
            return Some("a device");
        }
        if t.is_socket() {
            return Some("a socket");
        }
    }
    let _ = t;
    None
}

/// Creates (or empties) the file at `path` for writing, readable from
/// the start by no more than `like` (the file it is to replace) is, where
/// files have such permissions (the Unixes): a temporary file made with
/// the umask's defaults could be opened by anyone until it was narrowed,
/// and read on through that open file. Without `like`, the defaults.
pub fn create_like(path: &Path, like: Option<&std::fs::Permissions>) -> std::io::Result<File> {
    let mut options = std::fs::OpenOptions::new();
    options.write(true).create(true).truncate(true);
    #[cfg(unix)]
    if let Some(like) = like {
        use std::os::unix::fs::{OpenOptionsExt, PermissionsExt};
        options.mode(like.mode() & 0o777);
    }
    #[cfg(not(unix))]
    let _ = like;
    options.open(path)
}

/// glibc: every thread allocates from one pool (see
/// `memory::one_pool`). Nothing elsewhere.
pub fn allocate_from_one_pool() {
    #[cfg(all(target_os = "linux", target_env = "gnu"))]
    // SAFETY: mallopt only sets a tuning value of the allocator; called
    // before any other thread starts.
    unsafe {
        libc::mallopt(libc::M_ARENA_MAX, 1);
    }
}

/// glibc: blocks of `bytes` and over are mapped, and given back when
/// freed, whatever was freed before (see `memory::give_back_big_blocks`).
/// Nothing elsewhere.
pub fn map_blocks_from(bytes: i32) {
    #[cfg(all(target_os = "linux", target_env = "gnu"))]
    // SAFETY: mallopt only sets a tuning value of the allocator; called
    // before any other thread starts.
    unsafe {
        libc::mallopt(libc::M_MMAP_THRESHOLD, bytes);
    }
    let _ = bytes;
}

/// glibc: gives the system back every whole free page the allocator's
/// pools hold (see `memory::give_back_free_pages`). Nothing elsewhere.
pub fn trim_pools() {
    #[cfg(all(target_os = "linux", target_env = "gnu"))]
    // SAFETY: malloc_trim only returns free pages to the system; it takes
    // the pools' own locks and is safe to call from any thread.
    unsafe {
        libc::malloc_trim(0);
    }
}

/// Asks Linux to back the untouched allocation of `bytes` at `start` with
/// huge pages (see `terrain::heightfield`). Nothing elsewhere.
pub fn advise_huge_pages(start: *mut u8, bytes: usize) {
    #[cfg(target_os = "linux")]
    {
        const PAGE: usize = 4096;
        let addr = start as usize;
        let aligned = addr.next_multiple_of(PAGE);
        let len = (addr + bytes).saturating_sub(aligned) / PAGE * PAGE;
        if len > 0 {
            // SAFETY: the range lies inside an allocation this function's
            // caller owns and has not touched yet; MADV_HUGEPAGE changes only
            // how the kernel backs it, never its contents or validity.
            unsafe {
                libc::madvise(aligned as *mut libc::c_void, len, libc::MADV_HUGEPAGE);
            }
        }
    }
    let _ = (start, bytes);
}

/// The local offset from UTC at `secs`, in seconds (summer time included).
#[cfg(target_os = "linux")]
pub fn utc_offset(secs: u64) -> i64 {
    let t = secs as libc::time_t;
    // SAFETY: `localtime_r` only writes the `tm` we own and reads `t`; it is
    // the thread-safe variant (no shared static result).
    unsafe {
        let mut tm: libc::tm = std::mem::zeroed();
        if libc::localtime_r(&t, &mut tm).is_null() {
            return 0;
        }
        tm.tm_gmtoff
    }
}

/// The local offset from UTC now, in seconds (summer time included).
#[cfg(windows)]
pub use super::win32::clock::utc_offset;

/// Elsewhere: UTC, which `clock::local` then says (+00:00).
#[cfg(not(any(target_os = "linux", windows)))]
pub fn utc_offset(_secs: u64) -> i64 {
    0
}
