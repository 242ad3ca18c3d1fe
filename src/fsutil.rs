//! File reading that never hangs or floods, and writing that never leaves
//! a user's file half-written.

use std::fs::File;
use std::io::{self, Read, Write};
use std::path::{Path, PathBuf};

/// The eight bytes every PNG file begins with: how a file read as one
/// thing (a preferences file) is known to be an image (a data set), and
/// how a data set is known at all.
pub const PNG_SIGNATURE: [u8; 8] = [0x89, b'P', b'N', b'G', b'\r', b'\n', 0x1a, b'\n'];

/// The largest preferences file read: a real one is a few KiB; a bigger one
/// is a mistake (or `/dev/zero`), not something to read into memory.
pub const MAX_PREFERENCES_BYTES: u64 = 4 << 20;

/// Opens `path` for reading if it is a regular file (after following
/// links) of at most `cap` bytes. A FIFO would block until someone writes
/// to it, a device may never end: both get a message instead.
pub fn open_regular(path: &Path, cap: u64) -> io::Result<File> {
    let meta = std::fs::metadata(path).map_err(|e| nowhere(path, e))?;
    if !meta.is_file() {
        return Err(io::Error::new(
            io::ErrorKind::InvalidInput,
            format!("is {}, not a regular file", kind_of(&meta)),
        ));
    }
    if meta.len() > cap {
        return Err(too_big(meta.len(), cap));
    }
    File::open(path)
}

/// `e`, the error of following `path`, said as a link to nowhere when
/// `path` is a symbolic link to nothing. Not `NotFound` then: a name with
/// nothing at all is a file not made yet, which a save creates, but a
/// link is someone's, and a file written in its place would replace it.
fn nowhere(path: &Path, e: io::Error) -> io::Error {
    let is_link = std::fs::symlink_metadata(path).is_ok_and(|m| m.file_type().is_symlink());
    if e.kind() != io::ErrorKind::NotFound || !is_link {
        return e;
    }
    let to = std::fs::read_link(path).unwrap_or_default();
    io::Error::new(
        io::ErrorKind::InvalidInput,
        format!("a link to nowhere (to {})", to.display()),
    )
}

/// Whether anything is at `path`: a file, a folder, or a link, even one
/// to nowhere (which `Path::exists` follows, and calls missing: a file
/// written there as if new would replace someone's link).
pub fn taken(path: &Path) -> bool {
    std::fs::symlink_metadata(path).is_ok()
}

/// Whether `a` and `b` name one file (links and `..` resolved; both must
/// exist). Neither is opened: a FIFO's open would wait for a writer.
pub fn same_file(a: &Path, b: &Path) -> bool {
    match (a.canonicalize(), b.canonicalize()) {
        (Ok(a), Ok(b)) => a == b,
        _ => false,
    }
}

/// Whether `path` names the null device (`/dev/null`, or `NUL` on
/// Windows), the usual way to say "no file": it reads as empty, so a
/// preferences file there means the defaults, not an error.
pub fn is_null_device(path: &Path) -> bool {
    crate::platform::os::is_null_device(path)
}

/// The bytes of the regular file at `path`, at most `cap` of them (a file
/// that grows while it is read is cut off with an error, not followed).
pub fn read_regular(path: &Path, cap: u64) -> io::Result<Vec<u8>> {
    let file = open_regular(path, cap)?;
    let mut bytes = Vec::new();
    file.take(cap + 1).read_to_end(&mut bytes)?;
    if bytes.len() as u64 > cap {
        return Err(too_big(bytes.len() as u64, cap));
    }
    Ok(bytes)
}

fn too_big(len: u64, cap: u64) -> io::Error {
    io::Error::new(
        io::ErrorKind::InvalidData,
        format!(
            "is {} KiB; at most {} KiB is read",
            len.div_ceil(1024),
            cap / 1024
        ),
    )
}

/// What a non-regular file is, in words.
fn kind_of(meta: &std::fs::Metadata) -> &'static str {
    let t = meta.file_type();
    if t.is_dir() {
        return "a folder";
    }
    crate::platform::os::special_file_kind(&t).unwrap_or("not a file")
}

/// How a read that failed is said, after the file it names (the path,
/// and the flag that named it, are the caller's): one wording for every
/// file we read, data sets and preferences alike.
pub fn cannot_read(e: &io::Error) -> String {
    format!("cannot read: {e}")
}

/// How a write that failed is said, after the file it names (the path,
/// and the flag that named it, are the caller's): one wording for every
/// file we write, pictures, data sets and preferences alike.
pub fn cannot_write(e: &io::Error) -> String {
    format!("cannot write: {e}")
}

/// Writes what `write` makes to `path`, or to standard output when `path`
/// is `-` (`-o -`, for a pipe); see [`write_atomic_with`]. `write` is given
/// the destination (buffered), so a large picture never exists whole in
/// memory.
pub fn write_output_with(
    path: &Path,
    write: impl FnOnce(&mut dyn Write) -> io::Result<()>,
) -> io::Result<()> {
    if path == Path::new("-") {
        let mut out = io::BufWriter::new(io::stdout().lock());
        write(&mut out)?;
        return out.flush();
    }
    write_atomic_with(path, write)
}

/// Writes what `write` makes to `path` so a reader sees the old file or
/// the new one, never a mix: a temporary file in the same folder, flushed
/// to disk, then renamed over the target. A symbolic link is written
/// through (its target is replaced, the link stays); a device or FIFO is
/// written to directly (there is nothing to replace: `-o /dev/null` must
/// not make a file); a folder and a read-only file are refused.
pub fn write_atomic_with(
    path: &Path,
    write: impl FnOnce(&mut dyn Write) -> io::Result<()>,
) -> io::Result<()> {
    write_atomic_checked(path, write, || Ok(true)).map(|_| ())
}

/// The file a write to `path` replaces: a link's target (the link stays),
/// else `path` itself, there or not yet. A link to nowhere, or round in a
/// loop, is an error: a file renamed in its place would replace the link.
/// So is a name that ends in a separator and is no folder (`new/`).
/// Nothing is opened (a FIFO's open would wait), so a command can ask
/// before its work as well as when it writes.
pub fn write_target(path: &Path) -> io::Result<PathBuf> {
    match std::fs::canonicalize(path) {
        Ok(real) => Ok(real),
        Err(e) if path.is_symlink() => Err(nowhere(path, e)),
        Err(_) => match last_separator(path) {
            Some(separator) => Err(named_as_a_folder(separator)),
            None => Ok(path.to_path_buf()),
        },
    }
}

/// The separator `path` ends in, if it ends in one (`new/`): it names a
/// folder, never a file.
fn last_separator(path: &Path) -> Option<char> {
    let last = path.as_os_str().to_string_lossy().chars().last()?;
    std::path::is_separator(last).then_some(last)
}

/// The error of a write to a name that ends in a separator and is no
/// folder there (`-o new/`, `-o x.png/`): its temporary file was made
/// beside it and the work done, and only the last rename said "Not a
/// directory", of a folder that was never there.
fn named_as_a_folder(separator: char) -> io::Error {
    io::Error::new(
        io::ErrorKind::InvalidInput,
        format!("names a folder (it ends in {separator}), not a file"),
    )
}

/// Whether a write to `path` ([`write_atomic_with`]) can begin: its folder
/// is there and takes a new file, and `path` is no folder, no read-only
/// file and no link to nowhere. Asked before a long work (a 4K picture, a
/// large data set), so a wrong `-o` is said at once rather than after it. The write's own
/// temporary file is made and removed: the only sure test of leave to
/// write in a folder. A device or FIFO is not opened (a FIFO's open would
/// wait for a reader).
pub fn writable(path: &Path) -> io::Result<()> {
    let target = write_target(path)?;
    match std::fs::metadata(&target) {
        Ok(m) if m.is_dir() => Err(a_folder()),
        Ok(m) if !m.is_file() => Ok(()),
        Ok(m) if m.permissions().readonly() => Err(read_only()),
        _ => {
            let tmp = temporary(&target)?;
            let _pending = partial::Pending::new(&tmp);
            File::create(&tmp)?;
            std::fs::remove_file(&tmp)
        }
    }
}

/// The error of a write to a folder.
fn a_folder() -> io::Error {
    io::Error::new(io::ErrorKind::InvalidInput, "is a folder, not a file")
}

/// The error of a write to a file its owner made read-only. The rename
/// that replaces a file asks leave of its folder, not of the file, so a
/// file kept from changes (`chmod a-w`) was replaced as if it were not:
/// it is refused, as a shell's `>` or `cp` refuses it.
fn read_only() -> io::Error {
    io::Error::new(
        io::ErrorKind::PermissionDenied,
        "is read-only (its owner keeps it from changes)",
    )
}

/// The temporary file beside `path` that a write fills before renaming
/// it over `path`: hidden, and this process's own.
fn temporary(path: &Path) -> io::Result<PathBuf> {
    let dir = match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    };
    let name = path.file_name().ok_or_else(|| {
        io::Error::new(
            io::ErrorKind::InvalidInput,
            format!("{} names no file", path.display()),
        )
    })?;
    let mut tmp_name = std::ffi::OsString::from(".");
    tmp_name.push(name);
    tmp_name.push(format!(".{}.tmp", std::process::id()));
    Ok(dir.join(tmp_name))
}

/// [`write_atomic_with`], asking `still_wanted` once the new text is on
/// disk and just before it replaces the old: `Ok(false)` drops the new
/// file and leaves the old one (the result is then `Ok(false)`). A caller
/// that merged its change into the file as it was read checks here that
/// nobody replaced the file meanwhile, which shrinks the window in which a
/// concurrent change is lost from the whole write to one read.
pub fn write_atomic_checked(
    path: &Path,
    write: impl FnOnce(&mut dyn Write) -> io::Result<()>,
    still_wanted: impl FnOnce() -> io::Result<bool>,
) -> io::Result<bool> {
    let target = write_target(path)?;
    match std::fs::metadata(&target) {
        Ok(m) if m.is_dir() => Err(a_folder()),
        Ok(m) if m.is_file() && m.permissions().readonly() => Err(read_only()),
        Ok(m) if !m.is_file() => {
            if !still_wanted()? {
                return Ok(false);
            }
            let file = std::fs::OpenOptions::new().write(true).open(&target)?;
            let mut out = io::BufWriter::new(file);
            write(&mut out)?;
            out.flush().map(|()| true)
        }
        _ => replace_file(&target, write, still_wanted),
    }
}

/// The temporary-file-and-rename write of `write_atomic_with`, for a
/// regular file. The temporary file is known to [`partial`] while it
/// exists, so a signal that ends the program can remove it.
fn replace_file(
    path: &Path,
    write: impl FnOnce(&mut dyn Write) -> io::Result<()>,
    still_wanted: impl FnOnce() -> io::Result<bool>,
) -> io::Result<bool> {
    let tmp = temporary(path)?;
    let _pending = partial::Pending::new(&tmp);
    let result = (|| {
        // The file replaced keeps its owner's leave to read it: a private
        // (0600) preferences file, which may hold where its owner lives,
        // came back readable by all from the new file's defaults. The new
        // text is as private while it is written.
        let old = std::fs::metadata(path).ok().map(|m| m.permissions());
        let created = crate::platform::os::create_like(&tmp, old.as_ref())?;
        let mut out = io::BufWriter::new(created);
        write(&mut out)?;
        let file = out.into_inner().map_err(|e| e.into_error())?;
        // The umask may have narrowed the mode the file was made with.
        if let Some(old) = old {
            file.set_permissions(old)?;
        }
        file.sync_all()?;
        if !still_wanted()? {
            return Ok(false);
        }
        std::fs::rename(&tmp, path).map(|()| true)
    })();
    if !matches!(result, Ok(true)) {
        let _ = std::fs::remove_file(&tmp);
    }
    result
}

/// Temporary files of writes in progress, so that a program ended by a
/// signal leaves none behind (see `signals::end_cleanly`).
pub mod partial {
    use std::path::{Path, PathBuf};
    use std::sync::Mutex;

    static PENDING: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

    /// A temporary file being written; forgotten when dropped (renamed or
    /// removed by then).
    pub(super) struct Pending(PathBuf);

    impl Pending {
        pub(super) fn new(path: &Path) -> Self {
            lock().push(path.to_path_buf());
            Pending(path.to_path_buf())
        }
    }

    impl Drop for Pending {
        fn drop(&mut self) {
            lock().retain(|p| *p != self.0);
        }
    }

    /// Removes every temporary file still being written. Holding the lock
    /// while removing means a write cannot finish (and be forgotten) half
    /// way through; a file already renamed is simply not found.
    pub fn remove_all() {
        for path in lock().drain(..) {
            let _ = std::fs::remove_file(path);
        }
    }

    fn lock() -> std::sync::MutexGuard<'static, Vec<PathBuf>> {
        // A panic elsewhere while holding it leaves a usable list.
        PENDING.lock().unwrap_or_else(|e| e.into_inner())
    }
}
