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
