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

/// The settings window's sizes in the README are the layout's own.
#[test]
fn the_settings_window_sizes_are_the_layouts() {
    use mountains::settings_ui::layout::{MIN_H, MIN_W, WINDOW_H, WINDOW_W};
    let text = readme().split_whitespace().collect::<Vec<_>>().join(" ");
    let said =
        format!("opens at {WINDOW_W}x{WINDOW_H} and may be made as small as {MIN_W}x{MIN_H}");
    assert!(text.contains(&said), "README should say: {said}");
}
