//! The packages a user installs: the .deb that `scripts/deb.sh` makes
//! (here from the binary cargo built for these tests, stripped on the way,
//! so no release build is needed) and the Windows zip that
//! `scripts/windows_zip.sh` makes from the cross-built exe.
//!
//! The .deb tests need dpkg-deb, dpkg-shlibdeps, strip and
//! desktop-file-validate (`apt-get install dpkg-dev desktop-file-utils`);
//! without them they fail, or skip with `MOUNTAINS_SKIP_MISSING=1` unless
//! `MOUNTAINS_REQUIRE_DPKG=1` (as CI sets it). The zip test is ignored in
//! a plain `cargo test`: it needs the cross-built exe (CI runs it with
//! `--include-ignored`, as tests/platforms/windows_resources.rs).

#[path = "../../examples/hicolor_icons/ico.rs"]
mod ico;
use crate::common::pe;
use crate::common::tools;
use crate::common::wine;

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use std::sync::OnceLock;

use mountains::platform::libcheck::{WAYLAND_LIBRARIES, X11_LIBRARIES};

const ROOT: &str = env!("CARGO_MANIFEST_DIR");
const DEB_TOOLS: &str = "apt-get install dpkg-dev desktop-file-utils";

/// Runs `program args`, panicking with its output unless it succeeds.
fn run(program: &str, args: &[&str]) -> Output {
    let out = Command::new(program)
        .args(args)
        .output()
        .unwrap_or_else(|e| panic!("{program}: {e}"));
    assert!(
        out.status.success(),
        "{program} {args:?}: {}\n{}{}",
        out.status,
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    out
}

fn stdout(program: &str, args: &[&str]) -> String {
    String::from_utf8(run(program, args).stdout).expect("UTF-8 output")
}

/// True when `tool` can be started (`--version` or `--help` need not succeed).
fn have(tool: &str) -> bool {
    Command::new(tool).arg("--version").output().is_ok()
}

/// False (the test skips) when a tool the .deb needs is missing and a skip
/// was asked for; a failure otherwise.
fn deb_tools() -> bool {
    for tool in ["dpkg-deb", "dpkg-shlibdeps", "strip", "readelf"] {
        if !have(tool) {
            tools::missing(
                &format!("{tool} is not installed"),
                DEB_TOOLS,
                "MOUNTAINS_REQUIRE_DPKG",
            );
            return false;
        }
    }
    true
}

/// A folder under target/ that the scripts write into (each package is
/// renamed into place whole, so runs at the same time do not clash).
fn output_dir(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("packages-{name}"));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// A folder under target/ for this run's files, empty at first.
fn scratch(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join(format!("packages-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// The .deb, made once for all tests from the tests' own binary.
fn deb() -> Option<&'static Path> {
    static DEB: OnceLock<PathBuf> = OnceLock::new();
    if !deb_tools() {
        return None;
    }
    let deb = DEB.get_or_init(|| {
        let out = output_dir("deb");
        let made = stdout(
            "sh",
            &[
                &format!("{ROOT}/scripts/deb.sh"),
                "--binary",
                env!("CARGO_BIN_EXE_mountains"),
                "--out",
                &out.display().to_string(),
            ],
        );
        let path = PathBuf::from(made.trim());
        let name = format!("mountains_{}_{}.deb", env!("CARGO_PKG_VERSION"), arch());
        assert_eq!(
            path,
            out.join(name),
            "the script names the package it wrote"
        );
        path
    });
    Some(deb)
}

fn arch() -> String {
    stdout("dpkg", &["--print-architecture"]).trim().to_string()
}

/// One line of `dpkg-deb -c`: mode, owner, size in bytes, and a link's target.
#[derive(Debug, PartialEq)]
struct Entry {
    mode: String,
    owner: String,
    size: u64,
    link: Option<String>,
}

/// Every entry of the package by path (without the leading `.`), folders too.
fn listing(deb: &Path) -> BTreeMap<String, Entry> {
    let listing = stdout("dpkg-deb", &["-c", &deb.display().to_string()]);
    listing
        .lines()
        .map(|line| {
            let fields: Vec<&str> = line.split_whitespace().collect();
            assert!(fields.len() >= 6, "{line}");
            let path = fields[5].trim_start_matches('.').to_string();
            let link = (fields.get(6) == Some(&"->")).then(|| fields[7].to_string());
            let entry = Entry {
                mode: fields[0].into(),
                owner: fields[1].into(),
                size: fields[2].parse().expect("a size in bytes"),
                link,
            };
            (path, entry)
        })
        .collect()
}

/// The package's files by path (without the leading `.`), folders left out.
fn contents(deb: &Path) -> BTreeMap<String, Entry> {
    let mut entries = listing(deb);
    entries.retain(|_, e| !e.mode.starts_with('d'));
    entries
}

/// What the package's entries take once installed, in KiB as
/// dpkg-gencontrol counts them: a file its size rounded up, anything else
/// (a folder, a link) 1.
fn installed_kib(deb: &Path) -> u64 {
    listing(deb)
        .values()
        .map(|e| {
            if e.mode.starts_with('-') {
                e.size.div_ceil(1024)
            } else {
                1
            }
        })
        .sum()
}

/// Whether the ELF file at `path` keeps its symbol table or debug info.
fn has_symbols(path: &Path) -> bool {
    let sections = stdout("readelf", &["-S", "-W", &path.display().to_string()]);
    [".symtab", ".debug_info", ".debug_line"]
        .iter()
        .any(|s| sections.contains(s))
}

/// Everything the package installs, and nothing else.
const FILES: [&str; 11] = [
    "/usr/bin/mountains",
    "/usr/libexec/xscreensaver/mountains",
    "/usr/share/applications/mountains-settings.desktop",
    "/usr/share/applications/mountains.desktop",
    "/usr/share/doc/mountains/copyright",
    "/usr/share/icons/hicolor/16x16/apps/mountains.png",
    "/usr/share/icons/hicolor/256x256/apps/mountains.png",
    "/usr/share/icons/hicolor/32x32/apps/mountains.png",
    "/usr/share/icons/hicolor/48x48/apps/mountains.png",
    "/usr/share/man/man6/mountains.6.gz",
    "/usr/share/xscreensaver/config/mountains.xml",
];

#[test]
fn deb_holds_the_binary_the_hack_its_settings_the_man_page_entries_and_icons() {
    let Some(deb) = deb() else { return };
    let files = contents(deb);
    let paths: Vec<&str> = files.keys().map(String::as_str).collect();
    assert_eq!(paths, FILES);
    for (path, entry) in &files {
        assert_eq!(
            entry.owner, "root/root",
            "{path}: owned by root (--root-owner-group)"
        );
        let mode = match path.as_str() {
            "/usr/bin/mountains" => "-rwxr-xr-x",
            "/usr/libexec/xscreensaver/mountains" => "lrwxrwxrwx",
            _ => "-rw-r--r--",
        };
        assert_eq!(entry.mode, mode, "{path}");
    }
    // Relative, so it points into whatever root the package is unpacked in.
    let hack = &files["/usr/libexec/xscreensaver/mountains"];
    assert_eq!(hack.link.as_deref(), Some("../../bin/mountains"));
    let listing = stdout("dpkg-deb", &["-c", &deb.display().to_string()]);
    for line in listing.lines().filter(|l| l.starts_with('d')) {
        assert!(line.starts_with("drwxr-xr-x root/root"), "{line}");
    }
}

/// The packages of a Depends line, without their versions.
fn package_names(depends: &str) -> Vec<String> {
    depends
        .split(',')
        .map(|d| d.split_whitespace().next().unwrap_or("").to_string())
        .collect()
}

#[test]
fn deb_depends_on_the_c_library_and_every_library_opened_at_run_time() {
    let Some(deb) = deb() else { return };
    let field = |name: &str| {
        stdout("dpkg-deb", &["-f", &deb.display().to_string(), name])
            .trim()
            .to_string()
    };
    assert_eq!(field("Package"), "mountains");
    assert_eq!(field("Version"), env!("CARGO_PKG_VERSION"));
    assert_eq!(field("Architecture"), arch());
    assert!(field("Maintainer").contains('<'), "a name and an address");
    let depends = field("Depends");
    let names = package_names(&depends);
    // Linked: the C library with the version its symbols need.
    assert!(
        depends.split(", ").any(|d| d.starts_with("libc6 (>= 2.")),
        "{depends}"
    );
    for (library, package) in X11_LIBRARIES.iter().chain(WAYLAND_LIBRARIES) {
        assert!(
            names.iter().any(|n| n == package),
            "{library} is opened at run time, but {package} is not in Depends: {depends}"
        );
    }
    let mut unique = names.clone();
    unique.sort();
    unique.dedup();
    assert_eq!(unique.len(), names.len(), "a package twice: {depends}");
    // What the files packaged take, not what the folder they were put
    // together in took (blocks differ from one filesystem to another).
    let size: u64 = field("Installed-Size").parse().expect("a number of KiB");
    assert_eq!(size, installed_kib(deb), "Installed-Size");
    // The binary packaged is the one given, stripped on the way: smaller
    // when the given one has symbols (a test or debug build), no larger
    // when the profile stripped it already (release).
    let given = Path::new(env!("CARGO_BIN_EXE_mountains"));
    let binary = std::fs::metadata(given).unwrap().len();
    let packaged = contents(deb)["/usr/bin/mountains"].size;
    assert!(packaged > 0, "an empty binary");
    if has_symbols(given) {
        assert!(
            packaged < binary,
            "{packaged} of {binary} bytes: not stripped?"
        );
    } else {
        assert!(packaged <= binary, "{packaged} of {binary} bytes");
    }
}

/// A scratch dpkg root whose database holds this system's entries for the
/// packages `deb` depends on (so dpkg checks them, versions too, without
/// touching the real system), removed when dropped.
struct ScratchRoot {
    dir: PathBuf,
}

impl ScratchRoot {
    fn new(deb: &Path) -> ScratchRoot {
        let dir = scratch("root");
        let admin = dir.join("var/lib/dpkg");
        for sub in ["info", "updates", "triggers"] {
            std::fs::create_dir_all(admin.join(sub)).unwrap();
        }
        let depends = stdout("dpkg-deb", &["-f", &deb.display().to_string(), "Depends"]);
        let names = package_names(depends.trim());
        let mut query = Command::new("dpkg-query");
        let status = query.arg("-s").args(&names).output().expect("dpkg-query");
        if !status.status.success() {
            panic!(
                "the package's dependencies are not all installed here ({}): install them with README's apt line",
                String::from_utf8_lossy(&status.stderr).trim()
            );
        }
        std::fs::write(admin.join("status"), &status.stdout).unwrap();
        // Their file lists, empty: the files are the system's, not this root's.
        let installed = Command::new("dpkg-query")
            .args(["-W", "-f", "${binary:Package}\n"])
            .args(&names)
            .output()
            .expect("dpkg-query");
        for name in String::from_utf8(installed.stdout).unwrap().lines() {
            std::fs::write(admin.join(format!("info/{name}.list")), "").unwrap();
        }
        ScratchRoot { dir }
    }

    /// Runs dpkg on this root (as any user: files get the caller as owner).
    fn dpkg(&self, args: &[&str]) -> Output {
        let mut command = Command::new("dpkg");
        command
            .arg(format!("--root={}", self.dir.display()))
            .arg("--log=/dev/null")
            .args(args)
            // dpkg looks for ldconfig and start-stop-daemon on PATH.
            .env(
                "PATH",
                format!(
                    "/usr/sbin:/sbin:{}",
                    std::env::var("PATH").unwrap_or_default()
                ),
            );
        if !is_root() {
            command.arg("--force-not-root");
        }
        let out = command.output().expect("dpkg");
        assert!(
            out.status.success(),
            "dpkg {args:?}: {}\n{}{}",
            out.status,
            String::from_utf8_lossy(&out.stdout),
            String::from_utf8_lossy(&out.stderr)
        );
        out
    }

    /// Every file and link under the root, outside dpkg's database.
    fn files(&self) -> Vec<String> {
        let mut found = Vec::new();
        walk(&self.dir, &self.dir, &mut found);
        found.retain(|f| !f.starts_with("/var/lib/dpkg/"));
        found.sort();
        found
    }
}

impl Drop for ScratchRoot {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.dir);
    }
}

fn walk(root: &Path, dir: &Path, found: &mut Vec<String>) {
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() && !path.is_symlink() {
            walk(root, &path, found);
        } else {
            found.push(format!("/{}", path.strip_prefix(root).unwrap().display()));
        }
    }
}

fn is_root() -> bool {
    stdout("id", &["-u"]).trim() == "0"
}

#[test]
fn deb_installs_runs_and_is_removed_without_a_trace() {
    let Some(deb) = deb() else { return };
    let root = ScratchRoot::new(deb);
    // No --force-depends: dpkg checks Depends against the copied database.
    root.dpkg(&["--install", &deb.display().to_string()]);
    assert_eq!(root.files(), FILES);
    root.dpkg(&["--verify", "mountains"]);
    // The binary runs, by its name and as xscreensaver's hack.
    for program in ["usr/bin/mountains", "usr/libexec/xscreensaver/mountains"] {
        let version = stdout(
            &root.dir.join(program).display().to_string(),
            &["--version"],
        );
        assert_eq!(
            version.trim(),
            format!("mountains {}", env!("CARGO_PKG_VERSION")),
            "{program}"
        );
    }
    assert!(
        !has_symbols(&root.dir.join("usr/bin/mountains")),
        "not stripped"
    );
    // The contrib files as they are in the sources; the man page gzipped.
    let same = |installed: &str, source: &str| {
        let a = std::fs::read(root.dir.join(installed)).unwrap();
        let b = std::fs::read(Path::new(ROOT).join(source)).unwrap();
        assert!(a == b, "{installed} differs from {source}");
    };
    same(
        "usr/share/xscreensaver/config/mountains.xml",
        "contrib/mountains.xml",
    );
    same(
        "usr/share/applications/mountains.desktop",
        "contrib/mountains.desktop",
    );
    same(
        "usr/share/icons/hicolor/48x48/apps/mountains.png",
        "assets/hicolor/48x48/apps/mountains.png",
    );
    let man = stdout(
        "gzip",
        &[
            "-dc",
            &root
                .dir
                .join("usr/share/man/man6/mountains.6.gz")
                .display()
                .to_string(),
        ],
    );
    assert_eq!(
        man,
        std::fs::read_to_string(Path::new(ROOT).join("contrib/mountains.6")).unwrap()
    );
    let copyright =
        std::fs::read_to_string(root.dir.join("usr/share/doc/mountains/copyright")).unwrap();
    assert!(
        copyright.contains("License: MIT\n Permission is hereby granted"),
        "{copyright}"
    );
    root.dpkg(&["--purge", "mountains"]);
    assert_eq!(
        root.files(),
        Vec::<String>::new(),
        "left behind after purge"
    );
}

/// The `Key=value` lines of a desktop entry's main group.
fn desktop_keys(text: &str) -> BTreeMap<String, String> {
    text.lines()
        .skip_while(|l| *l != "[Desktop Entry]")
        .skip(1)
        .take_while(|l| !l.starts_with('['))
        .filter_map(|l| l.split_once('='))
        .map(|(k, v)| (k.to_string(), v.to_string()))
        .collect()
}

#[test]
fn desktop_entries_are_valid_and_open_the_window_and_the_settings() {
    if !deb_tools() {
        return;
    }
    if !have("desktop-file-validate") {
        return tools::missing(
            "desktop-file-validate is not installed",
            DEB_TOOLS,
            "MOUNTAINS_REQUIRE_DPKG",
        );
    }
    let usage = mountains::help::USAGE;
    for (file, exec) in [
        ("contrib/mountains.desktop", "mountains --window"),
        ("contrib/mountains-settings.desktop", "mountains --settings"),
    ] {
        let path = format!("{ROOT}/{file}");
        let out = run("desktop-file-validate", &[&path]);
        assert!(
            out.stdout.is_empty() && out.stderr.is_empty(),
            "{file}: {}",
            String::from_utf8_lossy(&out.stdout)
        );
        let text = std::fs::read_to_string(&path).unwrap();
        let keys = desktop_keys(&text);
        assert_eq!(keys["Exec"], exec, "{file}");
        // Every command, the actions' too, is one --help's usage lists.
        for command in text.lines().filter_map(|l| l.strip_prefix("Exec=")) {
            let (program, flag) = command.split_once(' ').expect("a program and a flag");
            assert_eq!(program, "mountains", "{file}: the packaged binary, by name");
            let listed = usage.lines().any(|l| {
                let l = l.trim_start();
                l.starts_with("mountains ") && l.split_whitespace().any(|word| word == flag)
            });
            assert!(listed, "{file}: {command} is not in --help's usage");
        }
        // The icon the package installs, and the window's app_id / class.
        assert_eq!(keys["Icon"], "mountains", "{file}");
        assert_eq!(keys["StartupWMClass"], "mountains", "{file}");
        assert_eq!(keys["Terminal"], "false", "{file}");
    }
}

#[test]
fn hicolor_icons_are_the_pictures_of_the_windows_icon() {
    let bytes = std::fs::read(format!("{ROOT}/assets/mountains.ico")).unwrap();
    let pictures = ico::pictures(&bytes).unwrap();
    let sizes: Vec<u32> = pictures.iter().map(|p| p.size).collect();
    assert_eq!(sizes, [16, 32, 48, 256]);
    for picture in pictures {
        let size = picture.size;
        let path = format!("{ROOT}/assets/hicolor/{size}x{size}/apps/mountains.png");
        let file = std::fs::File::open(&path)
            .unwrap_or_else(|e| panic!("{path}: {e} (sh scripts/linux_icons.sh)"));
        let mut reader = png::Decoder::new(std::io::BufReader::new(file))
            .read_info()
            .unwrap();
        let mut rgba = vec![0; reader.output_buffer_size().unwrap()];
        let info = reader.next_frame(&mut rgba).unwrap();
        assert_eq!(
            (info.width, info.height, info.color_type),
            (size, size, png::ColorType::Rgba),
            "{path}"
        );
        assert!(
            rgba[..info.buffer_size()] == picture.rgba[..],
            "{path} is not the icon's {size} px picture: run sh scripts/linux_icons.sh"
        );
        // Not a blank: a mountain has many colours and opaque pixels.
        let opaque = picture.rgba.chunks(4).filter(|p| p[3] == 255).count();
        assert!(
            opaque * 2 > (size * size) as usize,
            "{path}: mostly transparent"
        );
    }
}

/// The number of COFF symbols a PE file keeps (0 once stripped).
fn coff_symbols(bytes: &[u8]) -> u32 {
    let pe = u32::from_le_bytes(bytes[0x3c..0x40].try_into().unwrap()) as usize;
    // NumberOfSymbols: the COFF header starts after "PE\0\0".
    u32::from_le_bytes(bytes[pe + 16..pe + 20].try_into().unwrap())
}

#[test]
#[ignore = "needs the cross-built exe: cargo build --release --target x86_64-pc-windows-gnu"]
fn windows_zip_holds_the_stripped_scr_a_read_me_and_the_licence() {
    let Some(exe) = wine::cross_built_exe() else {
        return;
    };
    for (tool, install) in [
        (
            "x86_64-w64-mingw32-strip",
            "apt-get install gcc-mingw-w64-x86-64",
        ),
        ("zip", "apt-get install zip"),
        ("unzip", "apt-get install unzip"),
    ] {
        if !have(tool) {
            return tools::missing(
                &format!("{tool} is not installed"),
                install,
                "MOUNTAINS_REQUIRE_WINE",
            );
        }
    }
    let out = output_dir("zip");
    let made = stdout(
        "sh",
        &[
            &format!("{ROOT}/scripts/windows_zip.sh"),
            "--exe",
            &exe.display().to_string(),
            "--out",
            &out.display().to_string(),
        ],
    );
    let zip = out.join(format!(
        "mountains-{}-windows-x86_64.zip",
        env!("CARGO_PKG_VERSION")
    ));
    assert_eq!(Path::new(made.trim()), zip);
    let zip = zip.display().to_string();
    // `unzip -Z1`: one name a line, nothing else.
    let names = stdout("unzip", &["-Z1", &zip]);
    assert_eq!(
        names.lines().collect::<Vec<_>>(),
        ["mountains.scr", "README-windows.txt", "LICENSE.txt"]
    );
    let member = |name: &str| run("unzip", &["-p", &zip, name]).stdout;

    let scr = member("mountains.scr");
    assert_eq!(coff_symbols(&scr), 0, "the .scr keeps its symbols");
    assert!(scr.len() as u64 <= std::fs::metadata(&exe).unwrap().len());
    // Stripping keeps what Windows shows: the name in the Screen Saver list.
    let pe = pe::Pe::parse(&scr).expect("a PE file");
    let block = pe.resource(pe::RT_STRING, 1).expect("string table");
    assert_eq!(pe::table_string(block[0].data, 1).unwrap(), "Mountains");

    let readme = String::from_utf8(member("README-windows.txt")).unwrap();
    assert!(
        readme.starts_with(&format!("Mountains {}:", env!("CARGO_PKG_VERSION"))),
        "{readme}"
    );
    for words in [
        "choose Install",
        "System32",
        "Settings",
        "Uninstall",
        "%APPDATA%\\mountains",
    ] {
        assert!(readme.contains(words), "README-windows.txt lacks {words:?}");
    }
    let licence = String::from_utf8(member("LICENSE.txt")).unwrap();
    assert_eq!(
        licence.replace("\r\n", "\n"),
        std::fs::read_to_string(format!("{ROOT}/LICENSE")).unwrap()
    );
    // Notepad before Windows 10 1809 shows one long line without CR.
    for text in [&readme, &licence] {
        assert_eq!(
            text.matches('\n').count(),
            text.matches("\r\n").count(),
            "Windows line ends"
        );
    }
}
