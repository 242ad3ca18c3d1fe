//! One full-screen saver per display: an idle daemon (swayidle, hypridle)
//! starts `mountains /s` again at its next idle period while the first
//! still runs. The first holds an flock on a file named after the display
//! in `$XDG_RUNTIME_DIR`; a second finds it held and ends at once. The
//! kernel drops the lock when its holder dies, however it dies, so a crash
//! leaves nothing stale; the file itself is left in place (removing it
//! would let a third copy lock a new file while the second holds the old).

use std::fs::File;
use std::path::{Path, PathBuf};

use super::backend::Backend;

/// The lock of this display, held while it lives.
#[derive(Debug)]
pub struct Claim {
    _file: File,
}

/// The lock file's name for `backend`'s display named `display`
/// (`wayland-1`, `:0`, or a path): characters other than letters, digits,
/// `.`, `-` and `_` become `_`, so any value stays one file name.
pub fn lock_name(backend: Backend, display: &str) -> String {
    let kind = match backend {
        Backend::X11 => "x11",
        Backend::Windows => "windows",
        Backend::Wayland => "wayland",
    };
    let safe: String = display
        .chars()
        .map(|c| match c {
            'a'..='z' | 'A'..='Z' | '0'..='9' | '.' | '-' | '_' => c,
            _ => '_',
        })
        .collect();
    format!("mountains-fullscreen-{kind}-{safe}.lock")
}

/// Claims the display `backend` runs on: `Ok(None)` when another
/// full-screen saver holds it. Errors say what could not be done (the
/// caller runs on without the claim).
pub fn claim(backend: Backend) -> Result<Option<Claim>, String> {
    let var = match backend {
        Backend::X11 | Backend::Windows => "DISPLAY",
        Backend::Wayland if std::env::var_os("WAYLAND_DISPLAY").is_some() => "WAYLAND_DISPLAY",
        Backend::Wayland => "WAYLAND_SOCKET",
    };
    let display = std::env::var(var).unwrap_or_default();
    let runtime = std::env::var_os("XDG_RUNTIME_DIR").map(PathBuf::from);
    let one = one_name(backend, &display, runtime.as_deref());
    claim_at(&lock_dir().join(lock_name(backend, &one)))
}

/// One name for each display, however it is written: an X screen with
/// its number, screen 0 where none is given, and `unix` as no host (`:0`,
/// `:0.0` and `unix:0` are one screen, and two savers ran on it at once),
/// a compositor by its socket's path (`wayland-1` under `runtime`,
/// `XDG_RUNTIME_DIR`, is that folder's `wayland-1`).
pub fn one_name(backend: Backend, display: &str, runtime: Option<&Path>) -> String {
    match backend {
        Backend::X11 => {
            let Some((host, rest)) = display.rsplit_once(':') else {
                return display.to_string();
            };
            let host = if host == "unix" { "" } else { host };
            match rest.contains('.') {
                true => format!("{host}:{rest}"),
                false => format!("{host}:{rest}.0"),
            }
        }
        Backend::Wayland => super::backend::wayland_socket(display, runtime)
            .map_or_else(|| display.to_string(), |p| p.display().to_string()),
        Backend::Windows => display.to_string(),
    }
}

/// `$XDG_RUNTIME_DIR` (the user's, cleared at logout), else the temporary
/// folder with the user's id in the name.
fn lock_dir() -> PathBuf {
    match std::env::var_os("XDG_RUNTIME_DIR") {
        Some(dir) if Path::new(&dir).is_absolute() => PathBuf::from(dir),
        // SAFETY: getuid cannot fail.
        _ => std::env::temp_dir().join(format!("mountains-{}", unsafe { libc::getuid() })),
    }
}

/// Takes the lock on `path` (made if missing, never truncated): `Ok(None)`
/// when another open file holds it.
pub fn claim_at(path: &Path) -> Result<Option<Claim>, String> {
    use std::os::unix::fs::{DirBuilderExt, OpenOptionsExt};
    use std::os::unix::io::AsRawFd;
    if let Some(dir) = path.parent() {
        if !dir.exists() {
            let _ = std::fs::DirBuilder::new().mode(0o700).create(dir);
        }
        this_users_alone(dir)?;
    }
    let file = std::fs::OpenOptions::new()
        .create(true)
        .truncate(false)
        .write(true)
        .mode(0o600)
        .open(path)
        .map_err(|e| format!("cannot open {}: {e}", path.display()))?;
    // SAFETY: flock on a descriptor this function owns.
    let locked = unsafe { libc::flock(file.as_raw_fd(), libc::LOCK_EX | libc::LOCK_NB) };
    if locked == 0 {
        return Ok(Some(Claim { _file: file }));
    }
    let error = std::io::Error::last_os_error();
    if error.raw_os_error() == Some(libc::EWOULDBLOCK) {
        return Ok(None);
    }
    Err(format!("cannot lock {}: {error}", path.display()))
}

/// Refuses a lock folder another user can write in (one made first in
/// the temporary folder under our name, or a world-writable
/// `$XDG_RUNTIME_DIR`): whoever held a lock file there kept every `/s` of
/// this user from starting, the screen left unprotected.
fn this_users_alone(dir: &Path) -> Result<(), String> {
    use std::os::unix::fs::MetadataExt;
    let meta =
        std::fs::symlink_metadata(dir).map_err(|e| format!("cannot use {}: {e}", dir.display()))?;
    // SAFETY: getuid cannot fail.
    let uid = unsafe { libc::getuid() };
    let shared = meta.mode() & 0o022 != 0;
    if !meta.is_dir() || meta.uid() != uid || shared {
        return Err(format!(
            "{} is not a folder of this user's alone (owner {}, mode {:o}): another could hold the lock",
            dir.display(),
            meta.uid(),
            meta.mode() & 0o7777
        ));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_keep_one_file_per_display() {
        assert_eq!(
            lock_name(Backend::Wayland, "wayland-1"),
            "mountains-fullscreen-wayland-wayland-1.lock"
        );
        assert_eq!(
            lock_name(Backend::X11, ":0.0"),
            "mountains-fullscreen-x11-_0.0.lock"
        );
        assert_eq!(
            lock_name(Backend::Wayland, "/run/user/1000/wayland-0"),
            "mountains-fullscreen-wayland-_run_user_1000_wayland-0.lock"
        );
    }

    #[test]
    fn one_display_written_two_ways_is_one_lock() {
        let x = |d| one_name(Backend::X11, d, None);
        for same in [":0.0", "unix:0", "unix:0.0", ":0"] {
            assert_eq!(x(same), ":0.0", "{same}");
        }
        assert_eq!(x("host:1"), x("host:1.0"));
        assert_ne!(x(":1"), x(":10"));
        // Another screen of the server is another display.
        assert_ne!(x(":0.1"), x(":0"));
        let run = Path::new("/run/user/1000");
        let wl = |d| one_name(Backend::Wayland, d, Some(run));
        assert_eq!(wl("wayland-1"), wl("/run/user/1000/wayland-1"));
        assert_ne!(wl("wayland-1"), wl("wayland-2"));
    }

    #[test]
    fn a_second_claim_fails_until_the_first_is_dropped() {
        let dir = std::env::temp_dir().join(format!("mountains-single-{}", std::process::id()));
        let path = dir.join(lock_name(Backend::Wayland, "wayland-9"));
        let first = claim_at(&path).unwrap();
        assert!(first.is_some());
        assert!(claim_at(&path).unwrap().is_none(), "held by the first");
        let other = dir.join(lock_name(Backend::Wayland, "wayland-8"));
        assert!(claim_at(&other).unwrap().is_some(), "another display");
        drop(first);
        assert!(claim_at(&path).unwrap().is_some(), "free again");
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    fn a_lock_folder_others_can_write_in_is_refused() {
        use std::os::unix::fs::PermissionsExt;
        let dir = std::env::temp_dir().join(format!("mountains-shared-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::set_permissions(&dir, std::fs::Permissions::from_mode(0o777)).unwrap();
        let path = dir.join(lock_name(Backend::X11, ":0"));
        let e = claim_at(&path).expect_err("another user could hold the lock");
        assert!(e.contains("not a folder of this user's alone"), "{e}");
        assert!(e.contains("mode 777"), "{e}");
        std::fs::set_permissions(&dir, std::fs::Permissions::from_mode(0o700)).unwrap();
        assert!(claim_at(&path).unwrap().is_some(), "private again");
        let _ = std::fs::remove_dir_all(&dir);
    }
}
