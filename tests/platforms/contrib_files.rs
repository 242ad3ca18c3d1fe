//! contrib/mountains.xml and contrib/mountains.6: generated from the key table,
//! valid against xscreensaver's own schema, and every widget's command line
//! reads back as the value the widget shows.

use crate::common::tools;

use std::ffi::OsString;
use std::path::Path;
use std::process::Command;

use mountains::cli::{self, Mode};
use mountains::contrib;
use mountains::settings::keys::{self, Value};
use mountains::settings::load;

const XML: &str = "contrib/mountains.xml";

#[test]
fn the_committed_files_are_what_the_program_prints() {
    let xml = std::fs::read_to_string(XML).expect("read contrib/mountains.xml");
    assert!(
        xml == contrib::xscreensaver::xml(),
        "contrib/mountains.xml is stale: run sh scripts/contrib_files.sh"
    );
    let man = std::fs::read_to_string("contrib/mountains.6").expect("read contrib/mountains.6");
    assert!(
        man == contrib::man_page::man_page(),
        "contrib/mountains.6 is stale: run sh scripts/contrib_files.sh"
    );
}

#[test]
fn the_man_page_names_every_key_flag() {
    let man = contrib::man_page::man_page();
    for key in keys::KEYS {
        let flag = format!("\\-{}", key.name.replace('_', "\\-"));
        assert!(man.contains(&flag), "man page lacks {flag}");
    }
}

/// The names of the modes, subcommands and flags on a line of `--help`'s
/// usage (after `mountains`) or a man page's `.B` line, without dashes:
/// `/c[:HWND] | --settings` is `c` and `settings`, `render -o` is `render`
/// and `o`.
fn names(line: &str) -> Vec<String> {
    let tokens: Vec<&str> = line
        .split(|c: char| c.is_whitespace() || ",|[]".contains(c))
        .filter(|t| !t.is_empty())
        .collect();
    let word = tokens
        .first()
        .filter(|t| t.chars().all(|c| c.is_ascii_lowercase()))
        .map(|t| t.to_string());
    let flags = tokens
        .iter()
        .filter(|t| t.starts_with(['-', '/']) && t.len() > 1)
        .map(|t| {
            t.trim_start_matches(['-', '/'])
                .split(':')
                .next()
                .unwrap_or(t)
                .to_string()
        });
    word.into_iter().chain(flags).collect()
}

/// The man page describes every mode and subcommand of `--help`'s usage
/// and its options: it said nothing of `/s`, `/p`, `heightmap`, `--config`,
/// `--set` or `--open` (named in its synopsis alone), nor of `--help`.
#[test]
fn the_man_page_describes_every_mode_and_option_of_the_usage() {
    let man = contrib::man_page::man_page().replace("\\-", "-");
    let described: std::collections::BTreeSet<String> = man
        .lines()
        .skip_while(|l| *l != ".SH MODES")
        .take_while(|l| *l != ".SH PREFERENCE KEYS")
        .filter_map(|l| l.strip_prefix(".B "))
        .flat_map(names)
        .collect();
    let usage = mountains::help::USAGE.lines().map(str::trim_start);
    let modes = usage.clone().filter_map(|l| l.strip_prefix("mountains "));
    let modes = modes.map(|l| l.split("   ").next().unwrap_or(l));
    let options = usage.filter(|l| l.starts_with("--"));
    let wanted: Vec<String> = modes.chain(options).flat_map(names).collect();
    assert!(wanted.len() > 15, "{wanted:?}");
    let missing: Vec<_> = wanted.iter().filter(|n| !described.contains(*n)).collect();
    assert!(missing.is_empty(), "the man page describes no {missing:?}");
}

/// xmllint's output; without xmllint the test fails (or skips if asked to:
/// see common/tools.rs).
fn xmllint(args: &[&str]) -> Option<std::process::Output> {
    match Command::new("xmllint").args(args).output() {
        Ok(out) => Some(out),
        Err(e) => {
            let what = format!("xmllint cannot run ({e})");
            tools::missing(
                &what,
                "apt-get install libxml2-utils",
                "MOUNTAINS_REQUIRE_XMLLINT",
            );
            None
        }
    }
}

#[test]
fn the_xml_is_valid_against_xscreensavers_dtd_and_schema() {
    for check in [
        [
            "--noout",
            "--dtdvalid",
            "tests/data/xscreensaver/xss.dtd",
            XML,
        ],
        [
            "--noout",
            "--schema",
            "tests/data/xscreensaver/xss.xsd",
            XML,
        ],
    ] {
        let Some(out) = xmllint(&check) else { return };
        assert!(
            out.status.success(),
            "xmllint {check:?}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
    }
}

/// The values of attribute `xpath` (e.g. `//number/@arg`), in document order.
fn attributes(xpath: &str) -> Option<Vec<String>> {
    let out = xmllint(&["--xpath", xpath, XML])?;
    let text = String::from_utf8_lossy(&out.stdout).into_owned();
    Some(
        text.split('"')
            .skip(1)
            .step_by(2)
            .map(str::to_string)
            .collect(),
    )
}

/// The settings a command line from the dialog gives (under `-root`, with
/// an empty preferences file, as xscreensaver splits it: on spaces).
fn settings_of(command: &str) -> mountains::settings::Settings {
    let args: Vec<OsString> = std::iter::once("-root")
        .chain(command.split_whitespace())
        .map(OsString::from)
        .collect();
    let inv = cli::parse(&args).unwrap_or_else(|e| panic!("{command}: {e}"));
    assert_eq!(inv.mode, Mode::XRoot, "{command}");
    let empty = std::env::temp_dir().join(format!("mountains-contrib-{}.toml", std::process::id()));
    std::fs::write(&empty, "").expect("write empty config");
    let loaded =
        load::resolve(Some(&empty), &inv.key_values(), load::Unreadable::Refuse).expect("resolve");
    assert!(
        loaded.problems.is_empty(),
        "{command}: {:?}",
        loaded.problems
    );
    loaded.settings
}

/// The value a key has in `settings`, as the dialog would write it.
fn shown(settings: &mountains::settings::Settings, flag: &str) -> String {
    let name = flag
        .trim_start_matches('-')
        .trim_start_matches("no-")
        .replace('-', "_");
    let key = keys::find(&name).unwrap_or_else(|| panic!("{flag} names no key"));
    match keys::get(settings, key) {
        Value::Str(s) => s,
        Value::Float(f) => format!("{f}"),
        v => v.to_string(),
    }
}

#[test]
fn every_widget_value_reads_back_from_its_command_line() {
    let Some(sliders) = attributes("//number/@arg") else {
        return;
    };
    let lows = attributes("//number/@low").unwrap_or_default();
    let highs = attributes("//number/@high").unwrap_or_default();
    let defaults = attributes("//number/@default").unwrap_or_default();
    assert!(!sliders.is_empty() && sliders.len() == lows.len());
    for (i, arg) in sliders.iter().enumerate() {
        for v in [&lows[i], &highs[i], &defaults[i]] {
            let command = arg.replacen('%', v, 1);
            let flag = arg.split_whitespace().next().unwrap_or_default();
            let got: f64 = shown(&settings_of(&command), flag)
                .parse()
                .expect("a number");
            let want: f64 = v.parse().expect("a number");
            assert!((got - want).abs() < 1e-6, "{command}: reads back as {got}");
        }
    }
    for command in attributes("//option/@arg-set").unwrap_or_default() {
        let (flag, value) = command.split_once(' ').expect("-flag value");
        assert_eq!(shown(&settings_of(&command), flag), value, "{command}");
    }
    for (xpath, want) in [
        ("//boolean/@arg-set", "true"),
        ("//boolean/@arg-unset", "false"),
    ] {
        for command in attributes(xpath).unwrap_or_default() {
            assert_eq!(shown(&settings_of(&command), &command), want, "{command}");
        }
    }
}

/// xscreensaver puts a command line back into the dialog by the first word of
/// each widget's argument: two widgets sharing one would swap values.
#[test]
fn every_widget_has_a_first_word_of_its_own() {
    let xml = contrib::xscreensaver::xml();
    let mut owner: std::collections::HashMap<String, String> = Default::default();
    let mut widget = String::new();
    for line in xml.lines().map(str::trim) {
        if let Some(rest) = [
            "<select id=\"",
            "<number id=\"",
            "<boolean id=\"",
            "<string id=\"",
        ]
        .iter()
        .find_map(|p| line.strip_prefix(p))
        {
            widget = rest.split('"').next().unwrap_or_default().to_string();
        }
        for attr in ["arg=\"", "arg-set=\"", "arg-unset=\""] {
            let Some((_, rest)) = line.split_once(&format!(" {attr}")) else {
                continue;
            };
            let word = rest
                .split(['"', ' '])
                .next()
                .unwrap_or_default()
                .to_string();
            if let Some(before) = owner.insert(word.clone(), widget.clone()) {
                assert_eq!(before, widget, "{word} is the first word of two widgets");
            }
            assert!(
                !rest.split('"').next().unwrap_or_default().contains('='),
                "{line}"
            );
        }
    }
    assert!(owner.len() > 15, "too few widgets found: {owner:?}");
}

#[test]
fn the_dialogs_preview_command_runs_in_the_window() {
    for args in [
        ["-root", "-window-id", "0x1234"],
        ["-window-id", "0x1234", "-root"],
    ] {
        let args: Vec<OsString> = args.iter().map(OsString::from).collect();
        assert_eq!(
            cli::parse(&args).map(|i| i.mode),
            Ok(Mode::XWindowId(0x1234))
        );
    }
    assert!(Path::new(XML).exists());
}
