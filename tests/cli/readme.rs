//! What the README promises a newcomer on a fresh Debian or Ubuntu machine.

fn readme() -> String {
    std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/README.md")).expect("README.md")
}

/// Every apt line refreshes the package lists first (a fresh machine has
/// none) and says how to run it as root, where there is no sudo.
#[test]
fn apt_lines_update_first_and_work_as_root_too() {
    let text = readme();
    let apt: Vec<&str> = text
        .lines()
        .filter(|l| l.contains("apt-get install"))
        .collect();
    assert!(apt.len() >= 2, "{apt:?}");
    for line in apt.iter().filter(|l| l.trim_start().starts_with("sudo")) {
        assert!(line.contains("apt-get update &&"), "{line}");
    }
    assert!(text.contains("as root, leave out `sudo`"));
}

#[test]
fn the_licence_cargo_toml_names_is_there() {
    let manifest = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/Cargo.toml"))
        .expect("Cargo.toml");
    assert!(manifest.contains("license = \"MIT\""));
    let licence =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/LICENSE")).expect("LICENSE");
    assert!(licence.starts_with("MIT License"));
    assert!(readme().contains("cargo install --path . --locked"));
}

/// The flags and words of lines of commands: each token starting with `-`
/// or `/` (cut at `[` or `:`, so `/c[:HWND]` is `/c`), and the word after
/// `mountains` (a subcommand).
fn command_names<'a>(lines: impl Iterator<Item = &'a str>) -> std::collections::BTreeSet<String> {
    lines.flat_map(line_names).collect()
}

fn line_names(text: &str) -> Vec<String> {
    let tokens: Vec<&str> = text
        .split(|c: char| c.is_whitespace() || "`,|".contains(c))
        .map(|t| t.trim_start_matches('['))
        .filter(|t| !t.is_empty())
        .collect();
    let flags = tokens
        .iter()
        .filter(|t| t.starts_with(['-', '/']))
        .map(|t| t.split(['[', ':', ']']).next().unwrap_or(t).to_string());
    let words = tokens
        .windows(2)
        .filter(|w| w[0] == "mountains" && w[1].chars().all(|c| c.is_ascii_lowercase()))
        .map(|w| w[1].to_string());
    flags.chain(words).collect()
}

/// README's table of commands names every mode, subcommand and flag that
/// `--help`'s usage lists, and no other: the two cannot drift apart (it
/// lacked `--window`, `--xscreensaver-xml` and `--man-page`).
#[test]
fn the_table_of_commands_is_the_usage() {
    let text = readme();
    let table = text
        .lines()
        .filter(|l| l.starts_with("| `mountains"))
        .filter_map(|l| l.split(" | ").next());
    // A usage line is the command, then three spaces and what it does.
    let usage = mountains::help::USAGE
        .lines()
        .filter(|l| l.trim_start().starts_with("mountains "))
        .map(|l| l.split("   ").next().unwrap_or(l));
    let (in_table, in_usage) = (command_names(table), command_names(usage));
    assert!(in_usage.len() > 10, "{in_usage:?}");
    let missing: Vec<_> = in_usage.difference(&in_table).collect();
    let extra: Vec<_> = in_table.difference(&in_usage).collect();
    assert!(
        missing.is_empty() && extra.is_empty(),
        "README's table lacks {missing:?}; --help's usage lacks {extra:?}"
    );
}

fn file(path: &str) -> String {
    let full = format!("{}/{path}", env!("CARGO_MANIFEST_DIR"));
    std::fs::read_to_string(&full).unwrap_or_else(|e| panic!("{full}: {e}"))
}

/// The lines of the README's code blocks (indented four spaces), trimmed.
fn code_lines(text: &str) -> impl Iterator<Item = &str> {
    text.lines()
        .filter_map(|l| l.strip_prefix("    "))
        .map(str::trim)
}

/// The first screen (40 lines) holds the apt line, the one command that runs
/// the screensaver, the one that renders without installing, the one that
/// runs the tests and what they cost; the whole README stays short (issue 35).
#[test]
fn the_first_screen_has_the_apt_line_and_the_commands() {
    let text = readme();
    let first: String = text.lines().take(40).collect::<Vec<_>>().join("\n");
    let code: Vec<&str> = code_lines(&first).collect();
    for command in [
        "cargo run --release",
        "cargo test",
        "cargo run --release -- render -o out.png",
    ] {
        assert!(
            code.contains(&command),
            "the first 40 lines lack `{command}`: {code:?}"
        );
    }
    let apt: Vec<&&str> = code
        .iter()
        .filter(|l| l.contains("apt-get install"))
        .collect();
    assert!(
        apt.len() >= 2,
        "the first 40 lines lack the apt lines: {code:?}"
    );
    let lines: Vec<&str> = first.lines().collect();
    let marker = lines
        .iter()
        .position(|l| l.trim() == "<!-- test-cost -->")
        .expect("the first 40 lines lack the test cost's marker, <!-- test-cost -->");
    let cost = lines.get(marker + 1).copied().unwrap_or_default();
    assert!(
        cost.contains("cargo test") && cost.contains("minutes") && cost.contains("GB"),
        "the line after <!-- test-cost --> does not say what `cargo test` costs: {cost:?}"
    );
    let count = text.lines().count();
    assert!(count <= 250, "README.md has {count} lines, more than 250");
}

/// CI runs the README's test command, as .ci/run says it does.
#[test]
fn ci_runs_the_readmes_test_command() {
    let text = readme();
    let command = code_lines(&text)
        .find(|l| l.starts_with("cargo test"))
        .expect("README shows no test command");
    assert_eq!(command, "cargo test");
    let ci = file(".ci/run");
    assert!(
        ci.lines().any(|l| l.trim() == command),
        ".ci/run does not run the README's `{command}`"
    );
}

/// The README's way to render without installing works as written: its
/// arguments, given to the binary, write a PNG.
#[test]
fn the_readmes_render_command_writes_a_png() {
    let text = readme();
    let line = code_lines(&text)
        .find(|l| l.starts_with("cargo run --release -- render"))
        .expect("README shows no `cargo run --release -- render`");
    let args: Vec<&str> = line["cargo run --release -- ".len()..]
        .split_whitespace()
        .collect();
    let out = args
        .iter()
        .position(|a| *a == "-o")
        .and_then(|i| args.get(i + 1))
        .expect("the render command names no -o file");
    let dir = std::env::temp_dir().join(format!("mountains-readme-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let o = std::process::Command::new(env!("CARGO_BIN_EXE_mountains"))
        .args(&args)
        .current_dir(&dir)
        .env("HOME", &dir)
        .env("XDG_CONFIG_HOME", dir.join("config"))
        .env("XDG_DATA_HOME", dir.join("data"))
        .output()
        .expect("run mountains");
    let written = std::fs::read(dir.join(out));
    let _ = std::fs::remove_dir_all(&dir);
    assert!(
        o.status.success(),
        "`{line}`: {}",
        String::from_utf8_lossy(&o.stderr)
    );
    assert!(
        written.is_ok_and(|b| b.starts_with(b"\x89PNG\r\n\x1a\n")),
        "`{line}` wrote no PNG"
    );
}

/// The Markdown pages a newcomer reads, from the repository's top.
fn pages() -> Vec<String> {
    let mut pages: Vec<String> = ["README.md", "BENCHMARKS.md", "contrib/README.md"]
        .map(String::from)
        .to_vec();
    let docs = std::fs::read_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/docs")).expect("docs/");
    for entry in docs {
        let name = entry.unwrap().file_name().to_string_lossy().into_owned();
        if name.ends_with(".md") {
            pages.push(format!("docs/{name}"));
        }
    }
    pages.sort();
    pages
}

/// A table that says `mountains render ...` is for someone who installed
/// the binary: its page also says how to run it from the source folder.
#[test]
fn a_table_of_mountains_commands_says_how_to_run_them_without_installing() {
    for page in pages() {
        let text = file(&page);
        let table = text
            .lines()
            .any(|l| l.starts_with('|') && l.contains("`mountains render"));
        assert!(
            !table || text.contains("cargo run --release -- render"),
            "{page}: a table says `mountains render` but not `cargo run --release -- render`"
        );
    }
}

/// The anchor GitHub gives a heading: lower case, spaces as dashes, other
/// punctuation dropped; a repeated heading's gets -1, -2, ...
fn anchors(text: &str) -> Vec<String> {
    let mut seen: Vec<String> = Vec::new();
    let mut fenced = false;
    for line in text.lines() {
        if line.starts_with("```") {
            fenced = !fenced;
        }
        if fenced || !line.starts_with('#') {
            continue;
        }
        let slug: String = line
            .trim_start_matches('#')
            .trim()
            .to_lowercase()
            .chars()
            .filter(|c| c.is_alphanumeric() || matches!(c, '-' | '_' | ' '))
            .map(|c| if c == ' ' { '-' } else { c })
            .collect();
        let repeats = seen.iter().filter(|s| **s == slug).count();
        seen.push(slug.clone());
        if repeats > 0 {
            seen.push(format!("{slug}-{repeats}"));
        }
    }
    seen
}

/// Every relative link of every page leads to a file that exists, and to a
/// heading of it when it names one (pages and sections were moved into
/// docs/ and docs/benchmarks-history.md).
#[test]
fn relative_links_lead_to_files_and_headings() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut broken = Vec::new();
    for page in pages() {
        let text = file(&page);
        let dir = root.join(&page).parent().unwrap().to_path_buf();
        for target in text.split("](").skip(1).filter_map(|s| s.split(')').next()) {
            if target.contains("://") || target.starts_with("mailto:") {
                continue;
            }
            let (path, anchor) = target.split_once('#').unwrap_or((target, ""));
            let linked = if path.is_empty() {
                root.join(&page)
            } else {
                dir.join(path)
            };
            if !linked.exists() {
                broken.push(format!("{page}: {target} (no such file)"));
            } else if !anchor.is_empty() {
                let heads = anchors(&std::fs::read_to_string(&linked).unwrap_or_default());
                if !heads.iter().any(|h| h == anchor) {
                    broken.push(format!("{page}: {target} (no such heading)"));
                }
            }
        }
    }
    assert!(broken.is_empty(), "broken links: {broken:#?}");
}

/// The compositors a text names for `--layer`: the list after
/// "wlr-layer-shell" that ends at "; not GNOME".
fn layer_compositors(text: &str) -> Vec<Vec<String>> {
    let flat = text.split_whitespace().collect::<Vec<_>>().join(" ");
    flat.split("wlr-layer-shell")
        .skip(1)
        .filter_map(|after| after.split_once("; not GNOME").map(|(list, _)| list))
        .filter_map(|list| list.rsplit(['(', ':']).next())
        .map(|list| list.split(", ").map(|c| c.trim().to_string()).collect())
        .collect()
}

/// README, contrib/README.md and docs/install.md name the compositors
/// `--layer` works on as `--help` does (it lacked labwc, they KDE Plasma),
/// and as the refusal of a compositor without the protocol does.
#[test]
fn the_layer_compositors_are_the_ones_help_names() {
    let help = std::process::Command::new(env!("CARGO_BIN_EXE_mountains"))
        .arg("--help")
        .output()
        .expect("run mountains --help");
    assert!(help.status.success());
    let help = layer_compositors(&String::from_utf8_lossy(&help.stdout));
    assert_eq!(help.len(), 1, "--help's --layer list: {help:?}");
    let named = &help[0];
    assert!(
        named.len() >= 4 && named.contains(&"labwc".to_string()),
        "{named:?}"
    );
    #[cfg(target_os = "linux")]
    {
        let refusal = mountains::platform::wayland::layer::check_globals(&["wl_compositor"])
            .expect_err("no layer shell is refused")
            .to_string();
        assert_eq!(&layer_compositors(&refusal), &help, "{refusal}");
    }
    for page in ["README.md", "contrib/README.md", "docs/install.md"] {
        let lists = layer_compositors(&file(page));
        assert!(!lists.is_empty(), "{page} names no compositor for --layer");
        for list in lists {
            assert_eq!(&list, named, "{page} and --help name different compositors");
        }
    }
}

/// The README's first apt line installs every library the binary opens at
/// run time (the table its friendly check names them from).
#[test]
fn the_apt_line_installs_every_library_the_binary_opens() {
    use mountains::platform::libcheck::{WAYLAND_LIBRARIES, X11_LIBRARIES};
    let text = readme();
    let apt = code_lines(&text)
        .find(|l| l.contains("apt-get install"))
        .expect("an apt line");
    let packages: Vec<&str> = apt.split_whitespace().collect();
    for (library, package) in X11_LIBRARIES.iter().chain(WAYLAND_LIBRARIES) {
        assert!(
            packages.contains(package),
            "{apt} lacks {package} ({library})"
        );
    }
}

/// Each test file holding ignored tests is named in the README, which says
/// what kind they are and how CI runs them (it named only the Wine tests).
#[test]
fn the_readme_names_every_file_of_ignored_tests() {
    fn walk(dir: &std::path::Path, found: &mut Vec<std::path::PathBuf>) {
        for entry in std::fs::read_dir(dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                walk(&path, found);
            } else if path.extension().is_some_and(|e| e == "rs") {
                found.push(path);
            }
        }
    }
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut files = Vec::new();
    walk(&root.join("tests"), &mut files);
    let text = readme();
    let mut ignoring = 0;
    for path in files {
        let source = std::fs::read_to_string(&path).unwrap();
        if !source
            .lines()
            .any(|l| l.trim_start().starts_with("#[ignore"))
        {
            continue;
        }
        ignoring += 1;
        let name = path.strip_prefix(root).unwrap().display().to_string();
        assert!(
            text.contains(&format!("`{name}`")),
            "README does not name {name}"
        );
    }
    assert!(ignoring >= 1, "no ignored tests found under tests/");
}

/// Sizes written in prose go stale (README said 4.8 MB for 5.2, issue 36):
/// the README and the install page give none; BENCHMARKS.md holds them,
/// each with its date and command.
#[test]
fn the_install_pages_give_no_sizes_in_prose() {
    for page in ["README.md", "docs/install.md"] {
        let text = file(page);
        let words: Vec<&str> = text.split_whitespace().collect();
        for pair in words.windows(2) {
            let number = pair[0].trim_start_matches(['(', '`']);
            let unit = pair[1].trim_end_matches([',', '.', ')', ';', ':']);
            let is_number =
                !number.is_empty() && number.chars().all(|c| c.is_ascii_digit() || c == '.');
            assert!(
                !(is_number && matches!(unit, "MB" | "MiB" | "KB" | "KiB" | "kB")),
                "{page} gives a size in prose: {} {}",
                pair[0],
                pair[1]
            );
        }
    }
}

/// The settings window's sizes in its documentation are the layout's own.
#[test]
fn the_settings_window_sizes_are_the_layouts() {
    use mountains::settings_ui::layout::{MIN_H, MIN_W, WINDOW_H, WINDOW_W};
    let page = concat!(env!("CARGO_MANIFEST_DIR"), "/docs/keys.md");
    let text = std::fs::read_to_string(page).expect("docs/keys.md");
    let text = text.split_whitespace().collect::<Vec<_>>().join(" ");
    let said =
        format!("opens at {WINDOW_W}x{WINDOW_H} and may be made as small as {MIN_W}x{MIN_H}");
    assert!(text.contains(&said), "docs/keys.md should say: {said}");
}
