//! Names the platforms for `cfg` (`x11_platform`, `wayland_platform`,
//! `windows_platform`), and puts the Windows resources into the exe:
//! version information, the name the Screen Saver Settings list shows
//! (string 1) and the icon. The resources are made for Windows only, so a
//! Linux build needs no resource compiler.

/// What Windows shows for the saver: string 1 of a `.scr` is its name in
/// the Screen Saver Settings list (without it, the file name shows).
const SAVER_NAME: &str = "Mountains";
/// Explorer's "File description" and Task Manager's process name.
const FILE_DESCRIPTION: &str = "Mountains screensaver";
/// Made by scripts/windows_icon.sh from one of the program's mountains.
const ICON: &str = "assets/mountains.ico";
/// English (United States): the language of the strings below.
const LANGUAGE: u16 = 0x0409;

fn main() {
    platform_aliases();
    println!("cargo:rerun-if-changed=build.rs");
    println!("cargo:rerun-if-changed={ICON}");
    // winresource runs these if set, else mingw's for the target.
    println!("cargo:rerun-if-env-changed=WINDRES");
    println!("cargo:rerun-if-env-changed=AR");
    if std::env::var("CARGO_CFG_TARGET_OS").as_deref() == Ok("windows") {
        windows_resources();
    }
}

/// A `cfg` says which window system code is for, not which OS family
/// happens to carry it: `cfg(x11_platform)`, not `cfg(unix)`. The desktop
/// Unixes run X11 and Wayland (one binary, both loaded at run time);
/// wlr-layer-shell (`--layer`) and the per-display claim need Linux.
fn platform_aliases() {
    cfg_aliases::cfg_aliases! {
        x11_platform: { all(unix, not(target_vendor = "apple"), not(target_os = "android")) },
        wayland_platform: { all(unix, not(target_vendor = "apple"), not(target_os = "android")) },
        layer_shell_platform: { target_os = "linux" },
        windows_platform: { windows },
    }
}

fn windows_resources() {
    let mut res = winresource::WindowsResource::new();
    res.set_language(LANGUAGE)
        .set_icon(ICON)
        .set("FileDescription", FILE_DESCRIPTION)
        .set("ProductName", SAVER_NAME)
        .set("InternalName", "mountains")
        .set("OriginalFilename", "mountains.scr")
        .append_rc_content(&string_table());
    // Only the program: tests and benches linked for Windows need no icon.
    if let Err(e) = res.compile_for("mountains") {
        let hint = if e.kind() == std::io::ErrorKind::NotFound {
            "\nmingw's resource compiler or archiver is missing: cross-building from Linux \
             needs x86_64-w64-mingw32-windres and -ar (apt-get install gcc-mingw-w64-x86-64), \
             or name them in WINDRES and AR"
        } else {
            ""
        };
        panic!("cannot compile the Windows resources (version, name, {ICON}): {e}{hint}");
    }
}

/// The string table: id 1 is the saver's name (IDS_DESCRIPTION).
fn string_table() -> String {
    format!("STRINGTABLE\n{{\n  1, \"{SAVER_NAME}\"\n}}\n")
}
