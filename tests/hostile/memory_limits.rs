//! Under a memory limit (`prlimit --as`, what `ulimit -v` sets), `render`
//! and `heightmap` either finish or say there is not enough memory and
//! exit 1, leaving no file: never an abort (SIGABRT) half way through.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("mountains-memory-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// Runs the binary with at most `mib` MiB of address space.
fn run_limited(mib: u64, args: &[&str], home: &Path) -> Output {
    Command::new("prlimit")
        .arg(format!("--as={}", mib << 20))
        .arg(env!("CARGO_BIN_EXE_mountains"))
        .args(args)
        .env("HOME", home)
        .env("XDG_CONFIG_HOME", home.join("config"))
        .env("XDG_DATA_HOME", home.join("data"))
        .output()
        .expect("prlimit (util-linux)")
}

/// Runs `args` (writing `out`) under each limit in `limits`: every run
/// ends in the file and exit 0, or in a message with `says` and exit 1 and
/// no file. The limits must cross the line: both endings are seen.
fn sweep(name: &str, args: &[&str], out: &Path, limits: impl Iterator<Item = u64>, says: &str) {
    let home = scratch(name);
    let (mut made, mut refused) = (0, 0);
    for mib in limits {
        let _ = std::fs::remove_file(out);
        let got = run_limited(mib, args, &home);
        let err = String::from_utf8_lossy(&got.stderr);
        match got.status.code() {
            Some(0) => {
                assert!(std::fs::metadata(out).unwrap().len() > 0, "{args:?}");
                made += 1;
            }
            Some(1) => {
                assert!(err.contains(says), "{args:?} under {mib} MiB: {err}");
                assert_eq!(err.lines().count(), 1, "{err}");
                assert!(!out.exists(), "{args:?} under {mib} MiB left a file");
                refused += 1;
            }
            _ => panic!("{args:?} under {mib} MiB: {}: {err}", got.status),
        }
    }
    assert!(
        made > 0 && refused > 0,
        "{args:?}: {made} made, {refused} refused"
    );
}

/// A frame inside the allowed size that the memory limit cannot hold is a
/// message and exit 1, not an abort (it was SIGABRT under a 1 GiB limit).
#[test]
fn a_frame_too_big_for_the_memory_limit_is_a_message() {
    let dir = scratch("frame");
    let out = dir.join("big.png");
    let got = run_limited(
        1024,
        &[
            "render",
            "--size",
            "16384x16384",
            "-o",
            out.to_str().unwrap(),
        ],
        &dir,
    );
    let err = String::from_utf8_lossy(&got.stderr);
    assert_eq!(got.status.code(), Some(1), "{err}");
    assert!(
        err.contains("--size 16384x16384: not enough memory for the frame (1024 MiB)"),
        "{err}"
    );
    assert!(!out.exists());
}

/// Room for the frame but not for the terrain and drawing beside it: a
/// message before the work starts (it aborted in a later allocation when
/// the frame just fitted, e.g. 16384x16384 under 2 GiB, 1920x1080 under 160
/// MiB).
#[test]
fn render_under_every_limit_ends_in_a_picture_or_a_message() {
    let dir = scratch("render");
    for (size, name, limits) in [
        ("1920x1080", "r.png", (30..=300).step_by(6)),
        ("4096x4096", "r.jpg", (100..=420).step_by(20)),
    ] {
        let out = dir.join(name);
        let args = [
            "render",
            "--seed",
            "2",
            "--size",
            size,
            "-o",
            out.to_str().unwrap(),
        ];
        sweep(size, &args, &out, limits, "not enough memory");
    }
}

/// `heightmap` at the finest grid (4097x4097 points) the same way.
#[test]
fn heightmap_under_every_limit_ends_in_a_file_or_a_message() {
    let dir = scratch("heightmap");
    let out = dir.join("h.png");
    let args = [
        "heightmap",
        "--seed",
        "2",
        "--set",
        "detail=12",
        "-o",
        out.to_str().unwrap(),
    ];
    let says = "not enough memory to make the data set";
    sweep("heightmap", &args, &out, (60..=460).step_by(25), says);
}
