//! The layout keeps its promises: no two source files import each other,
//! directly or round a circle, no room of `render` imports a room above
//! it, and what knows one platform stays in `src/platform` (its `cfg`s
//! and its crates) (docs/architecture.md). A circle ties files that
//! should be one, or hides a piece both need; an arrow back up ties a
//! stage to one that comes later; a platform's `cfg` in a neutral file
//! spreads one platform's knowledge over the house. This finds each as
//! soon as it is written; a frame size written as two numbers again, not
//! `render::Size`, is found the same way.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// Every `.rs` file under `dir`.
fn sources(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            sources(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

/// The module path a file holds: `src/a/b.rs` and `src/a/b/mod.rs` are
/// `["a", "b"]`; `src/lib.rs` is `[]`.
fn module_of(src: &Path, file: &Path) -> Vec<String> {
    let rel = file.strip_prefix(src).unwrap().with_extension("");
    let mut parts: Vec<String> = rel
        .iter()
        .map(|p| p.to_string_lossy().into_owned())
        .collect();
    if matches!(
        parts.last().map(String::as_str),
        Some("mod" | "lib" | "main")
    ) {
        parts.pop();
    }
    parts
}

/// The code of a file without comments and string contents (a doc comment
/// that names `crate::x` is not an import).
fn code(text: &str) -> String {
    let mut out = String::new();
    for line in text.lines() {
        let line = line.split("//").next().unwrap_or("");
        let mut in_str = false;
        for c in line.chars() {
            if c == '"' {
                in_str = !in_str;
            }
            if !in_str {
                out.push(c);
            }
        }
        out.push('\n');
    }
    out
}

/// The paths a file names that start with `crate`, `super` or `self`,
/// braces expanded one level at a time (`super::{a, b::c}`).
fn paths(code: &str) -> Vec<Vec<String>> {
    let mut found = Vec::new();
    let bytes: Vec<char> = code.chars().collect();
    let mut i = 0;
    while i < bytes.len() {
        let rest: String = bytes[i..bytes.len().min(i + 6)].iter().collect();
        let starts = ["crate::", "super::", "self::"]
            .iter()
            .any(|p| rest.starts_with(&p[..p.len().min(6)]))
            && (i == 0 || !(bytes[i - 1].is_alphanumeric() || bytes[i - 1] == '_'));
        if !starts {
            i += 1;
            continue;
        }
        let mut j = i;
        let mut depth = 0;
        while j < bytes.len() {
            let c = bytes[j];
            if c == '{' {
                depth += 1;
            } else if c == '}' {
                if depth == 0 {
                    break;
                }
                depth -= 1;
            } else if depth == 0 && !(c.is_alphanumeric() || c == '_' || c == ':') {
                break;
            }
            j += 1;
        }
        let text: String = bytes[i..j].iter().collect();
        expand(&text, &mut found);
        i = j.max(i + 1);
    }
    found
}

/// `a::{b, c::d}` into `a::b` and `a::c::d`.
fn expand(text: &str, out: &mut Vec<Vec<String>>) {
    let Some(open) = text.find('{') else {
        let parts: Vec<String> = text
            .split("::")
            .filter(|p| !p.is_empty())
            .map(String::from)
            .collect();
        if !parts.is_empty() {
            out.push(parts);
        }
        return;
    };
    let head = text[..open].trim_end_matches("::");
    let inner = &text[open + 1..text.rfind('}').unwrap_or(text.len())];
    let mut depth = 0;
    let mut item = String::new();
    for c in inner.chars().chain(std::iter::once(',')) {
        match c {
            '{' => depth += 1,
            '}' => depth -= 1,
            _ => {}
        }
        if c == ',' && depth == 0 {
            let item_t = item.trim();
            if !item_t.is_empty() {
                let joined = if item_t == "self" {
                    head.to_string()
                } else {
                    format!("{head}::{item_t}")
                };
                expand(&joined, out);
            }
            item.clear();
        } else if !c.is_whitespace() {
            item.push(c);
        }
    }
}

/// The file a path names, seen from `module`: its longest prefix that is
/// a module of the crate.
fn target(
    module: &[String],
    path: &[String],
    modules: &BTreeMap<Vec<String>, PathBuf>,
) -> Option<PathBuf> {
    let mut at: Vec<String> = module.to_vec();
    let mut rest = path;
    match rest.first().map(String::as_str) {
        Some("crate") => at.clear(),
        Some("self") => {}
        Some("super") => {
            while rest.first().map(String::as_str) == Some("super") {
                at.pop();
                rest = &rest[1..];
            }
            let mut full = at.clone();
            full.extend(rest.iter().cloned());
            return longest(&full, modules);
        }
        _ => return None,
    }
    let mut full = at;
    full.extend(rest[1..].iter().cloned());
    longest(&full, modules)
}

fn longest(full: &[String], modules: &BTreeMap<Vec<String>, PathBuf>) -> Option<PathBuf> {
    (0..=full.len())
        .rev()
        .find_map(|n| modules.get(&full[..n]).cloned())
}

/// The crate's source files and what each imports.
struct Imports {
    /// The `src` folder.
    src: PathBuf,
    /// For each file, the files it imports (its own tests aside).
    edges: BTreeMap<PathBuf, BTreeSet<PathBuf>>,
    /// Every source file but main.rs, by its module path.
    modules: BTreeMap<Vec<String>, PathBuf>,
}

/// Every source file of the crate (but main.rs) by its module path, and
/// for each file the files it imports.
fn imports() -> Imports {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = Vec::new();
    sources(&src, &mut files);
    let modules: BTreeMap<Vec<String>, PathBuf> = files
        .iter()
        .filter(|f| f.file_name().is_some_and(|n| n != "main.rs"))
        .map(|f| (module_of(&src, f), f.clone()))
        .collect();
    let mut edges: BTreeMap<PathBuf, BTreeSet<PathBuf>> = BTreeMap::new();
    for (module, file) in &modules {
        let text = code(&std::fs::read_to_string(file).unwrap());
        // A file's own tests may use anything.
        let text = text.split("#[cfg(test)]").next().unwrap_or("").to_string();
        for path in paths(&text) {
            if let Some(to) = target(module, &path, &modules).filter(|to| to != file) {
                edges.entry(file.clone()).or_default().insert(to);
            }
        }
    }
    Imports {
        src,
        edges,
        modules,
    }
}

#[test]
fn no_source_file_imports_round_a_circle() {
    let Imports { src, edges, .. } = imports();
    // Depth-first search for a way back to where it started.
    let name = |p: &PathBuf| p.strip_prefix(&src).unwrap().display().to_string();
    for start in edges.keys() {
        let mut stack = vec![(start.clone(), vec![start.clone()])];
        let mut seen = BTreeSet::new();
        while let Some((at, trail)) = stack.pop() {
            for next in edges.get(&at).into_iter().flatten() {
                if next == start {
                    let circle: Vec<String> = trail.iter().map(name).collect();
                    panic!("an import circle: {} -> back", circle.join(" -> "));
                }
                if seen.insert(next.clone()) {
                    let mut t = trail.clone();
                    t.push(next.clone());
                    stack.push((next.clone(), t));
                }
            }
        }
    }
    assert!(
        edges.len() > 50,
        "only {} files import anything: the scan is broken",
        edges.len()
    );
}

/// The rooms of `render`, from the ground floor up (docs/architecture.md):
/// a file may import its own room and the rooms below it. The files at the
/// top of `render` (`mod.rs`, the painter, ...) stand above them all.
const RENDER_FLOORS: &[&str] = &[
    "base", "framing", "shade", "scene", "scan", "order", "edges",
];

/// The floor of `render` a module stands on, or `None` outside `render`.
fn floor(module: &[String]) -> Option<usize> {
    match module {
        [first, rest @ ..] if first == "render" => Some(
            rest.first()
                .and_then(|room| RENDER_FLOORS.iter().position(|r| r == room))
                .unwrap_or(RENDER_FLOORS.len()),
        ),
        _ => None,
    }
}

#[test]
fn no_room_of_render_imports_a_room_above_it() {
    let Imports {
        src,
        edges,
        modules,
    } = imports();
    let module_of_file: BTreeMap<&PathBuf, &Vec<String>> =
        modules.iter().map(|(m, f)| (f, m)).collect();
    let name = |p: &PathBuf| p.strip_prefix(&src).unwrap().display().to_string();
    let mut checked = 0;
    let mut up = Vec::new();
    for (from, tos) in &edges {
        let Some(low) = floor(module_of_file[from]) else {
            continue;
        };
        for to in tos {
            let Some(high) = floor(module_of_file[to]) else {
                continue;
            };
            checked += 1;
            if high > low {
                up.push(format!("{} -> {}", name(from), name(to)));
            }
        }
    }
    assert!(
        up.is_empty(),
        "imports from a room of render up to a room above it:\n{}",
        up.join("\n")
    );
    // Every room is there and imports or is imported: a renamed room
    // would otherwise leave its files on the top floor, unchecked.
    for room in RENDER_FLOORS {
        let key: Vec<String> = ["render", room].iter().map(|s| s.to_string()).collect();
        assert!(modules.contains_key(&key), "no room render/{room}");
    }
    assert!(
        checked > 60,
        "only {checked} imports inside render: the scan is broken"
    );
}

/// The words that make a `cfg` a platform's: the OS families, the target
/// OS, and the window systems (build.rs's aliases among them).
const PLATFORM_WORDS: &[&str] = &[
    "unix",
    "windows",
    "target_os",
    "target_vendor",
    "x11",
    "wayland",
    "_platform",
];

/// The lines of `text` with a `cfg` (attribute, `cfg!`, `cfg_attr`) that
/// names a platform.
fn platform_cfgs(text: &str) -> Vec<String> {
    text.lines()
        .map(|line| line.split("//").next().unwrap_or(""))
        .filter(|code| {
            ["cfg(", "cfg!(", "cfg_attr("]
                .iter()
                .any(|c| code.contains(c))
        })
        .filter(|code| PLATFORM_WORDS.iter().any(|w| code.contains(w)))
        .map(|code| code.trim().to_string())
        .collect()
}

/// Every file of `src`, by its path, with its platform `cfg` lines.
fn platform_cfgs_by_file() -> Vec<(String, Vec<String>)> {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = Vec::new();
    sources(&src, &mut files);
    files.sort();
    files
        .iter()
        .map(|f| {
            let name = f.strip_prefix(&src).unwrap().display().to_string();
            (name, platform_cfgs(&std::fs::read_to_string(f).unwrap()))
        })
        .collect()
}

/// The most platform `cfg`s the platform-neutral files may hold.
const NEUTRAL_PLATFORM_CFGS: usize = 5;

#[test]
fn platform_cfgs_stay_in_the_platform_rooms() {
    let by_file = platform_cfgs_by_file();
    let inside = |name: &str| name.starts_with("platform/") || name.starts_with("platform\\");
    let outside: Vec<String> = by_file
        .iter()
        .filter(|(name, _)| !inside(name))
        .flat_map(|(name, lines)| lines.iter().map(move |l| format!("src/{name}: {l}")))
        .collect();
    assert!(
        outside.len() <= NEUTRAL_PLATFORM_CFGS,
        "{} platform cfgs outside src/platform (at most {NEUTRAL_PLATFORM_CFGS}): \
         move the code into a platform room behind the facade (src/platform/mod.rs)\n{}",
        outside.len(),
        outside.join("\n")
    );
    // The rooms hold them: a scan that finds none there is broken.
    let rooms: usize = by_file
        .iter()
        .filter(|(name, _)| inside(name))
        .map(|(_, lines)| lines.len())
        .sum();
    assert!(
        rooms > 20,
        "only {rooms} platform cfgs in src/platform: the scan is broken"
    );
}

/// The crates that talk to one window system or OS.
const PLATFORM_CRATES: &[&str] = &[
    "x11rb::",
    "x11_dl::",
    "windows_sys::",
    "smithay_client_toolkit::",
    "winit::platform::",
    "libc::",
    "signal_hook::",
    "libloading::",
];

#[test]
fn only_the_platform_rooms_use_platform_crates() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let platform = src.join("platform");
    let mut files = Vec::new();
    sources(&src, &mut files);
    let (mut inside, mut outside) = (0, Vec::new());
    for file in &files {
        let text = code(&std::fs::read_to_string(file).unwrap());
        let uses = PLATFORM_CRATES.iter().filter(|c| text.contains(*c)).count();
        if file.starts_with(&platform) {
            inside += uses;
        } else if uses > 0 {
            outside.push(file.strip_prefix(&src).unwrap().display().to_string());
        }
    }
    assert!(
        outside.is_empty(),
        "files outside src/platform use a platform's crate (x11rb, windows-sys, winit::platform, libc, ...): {}",
        outside.join(", ")
    );
    assert!(
        inside > 10,
        "only {inside} uses in src/platform: the scan is broken"
    );
}

/// The code of a file with comments and strings gone and every run of
/// white space one space, so a signature rustfmt broke over lines reads
/// as one.
fn one_line(text: &str) -> String {
    code(text).split_whitespace().collect::<Vec<_>>().join(" ")
}

/// The name a type at the end of `before` belongs to: the field, binding
/// or variant before `: `, or the function before `(...) -> `; wrappers
/// (`Option<`, `Result<`, `&`) and tuple patterns (`(w, h)`) kept whole.
fn name_before(before: &str) -> &str {
    let mut s = before.trim_end();
    loop {
        let t = s.trim_end();
        let t = ["Option<", "Result<", "&", "->", ":"]
            .iter()
            .find_map(|w| t.strip_suffix(w))
            .unwrap_or(t);
        if t.len() == s.len() {
            break;
        }
        s = t.trim_end();
    }
    // A function's result: the name before its parameters; a pattern
    // (`(width, height)`): the pattern.
    if s.ends_with(')') || s.ends_with(']') {
        let (open, close) = if s.ends_with(')') {
            ('(', ')')
        } else {
            ('[', ']')
        };
        let mut depth = 0;
        for (i, c) in s.char_indices().rev() {
            depth += i32::from(c == close) - i32::from(c == open);
            if depth == 0 {
                let pattern = &s[i..];
                let head = s[..i].trim_end();
                let name_start = head
                    .rfind(|c: char| !(c.is_alphanumeric() || c == '_'))
                    .map_or(0, |j| j + 1);
                let name = &head[name_start..];
                let is_fn = head[..name_start].trim_end().ends_with("fn");
                return if is_fn { name } else { pattern };
            }
        }
    }
    let start = s
        .rfind(|c: char| !(c.is_alphanumeric() || c == '_'))
        .map_or(0, |j| j + 1);
    &s[start..]
}

/// Each place in `text` that spells a size the old ways: `width: u32,
/// height: u32` (or `w: u32, h: u32`), or a `(u32, u32)` or `[u32; 2]`
/// belonging to a name that says size, width or height (`size:
/// (u32, u32)`, `fn preview_size() -> (u32, u32)`, `(width, height):
/// (u32, u32)`, `Resized(u32, u32)`).
fn old_size_spellings(text: &str) -> Vec<String> {
    let code = one_line(text);
    let mut found = Vec::new();
    for pair in ["width: u32, height: u32", "w: u32, h: u32"] {
        for (at, _) in code.match_indices(pair) {
            let word_start =
                at == 0 || !code[..at].ends_with(|c: char| c.is_alphanumeric() || c == '_');
            if word_start {
                found.push(pair.to_string());
            }
        }
    }
    for ty in ["(u32, u32)", "[u32; 2]"] {
        for (at, _) in code.match_indices(ty) {
            let name = name_before(&code[..at]).to_lowercase();
            let sized = ["size", "width", "height"].iter().any(|w| name.contains(w))
                || name.replace(' ', "") == "(w,h)";
            if sized {
                found.push(format!("{name}: {ty}"));
            }
        }
    }
    found
}

/// Where a frame's size may still be two numbers, and why: none of them
/// is a frame's, window's or monitor's size.
const NOT_FRAME_SIZES: &[(&str, &str, usize)] = &[
    (
        "terrain/heightmap/fit.rs",
        "a heightmap image's sides, cropped to the grid (terrain stands below render)",
        1,
    ),
    (
        "terrain/heightmap/decode.rs",
        "a heightmap image's sides, checked against its bytes",
        2,
    ),
    (
        "saver/heads.rs",
        "a test's monitor rectangle on the desktop (x, y, width, height)",
        1,
    ),
    (
        "saver/span.rs",
        "a test's monitor rectangle on the desktop (x, y, width, height)",
        1,
    ),
];

#[test]
fn a_frame_size_is_a_size() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let base = src.join("render").join("base");
    let mut files = Vec::new();
    sources(&src, &mut files);
    files.sort();
    let mut wrong = Vec::new();
    let mut seen = 0;
    for file in files.iter().filter(|f| !f.starts_with(&base)) {
        let name = file.strip_prefix(&src).unwrap().display().to_string();
        let name = name.replace('\\', "/");
        let text = std::fs::read_to_string(file).unwrap();
        seen += code(&text).matches("u32").count();
        let spelt = old_size_spellings(&text);
        let allowed = NOT_FRAME_SIZES
            .iter()
            .find(|(f, ..)| *f == name)
            .map_or(0, |(.., n)| *n);
        if spelt.len() > allowed {
            wrong.push(format!(
                "src/{name} ({allowed} allowed): {}",
                spelt.join("; ")
            ));
        }
    }
    assert!(
        wrong.is_empty(),
        "a frame's size written as two numbers, not render::Size (src/render/base/size.rs):\n{}",
        wrong.join("\n")
    );
    // The scan reads the tree: one that saw no u32 is broken.
    assert!(seen > 100, "only {seen} u32s in src: the scan is broken");
}

#[test]
fn the_size_scan_knows_each_old_spelling() {
    let old = "fn f(a: u8, width: u32,\n    height: u32) {}\n\
               struct S { size: (u32, u32), monitor_size: Option<[u32; 2]> }\n\
               fn preview_size(l: &L) -> (u32, u32) { let (w, h): (u32, u32) = g(); }\n\
               enum E { Resized(u32, u32) }";
    assert_eq!(
        old_size_spellings(old).len(),
        6,
        "{:?}",
        old_size_spellings(old)
    );
    let not_sizes = "fn f(span: (u32, u32), x: u32, y: u32) -> Option<(u32, u32)> {}\n\
                     fn columns(&self, span: (u32, u32)) -> (u32, u32) {}\n\
                     let plot = |x, y| (); fn g(p: impl FnMut(u32, u32)) {} // size: (u32, u32)";
    assert_eq!(old_size_spellings(not_sizes), Vec::<String>::new());
}
