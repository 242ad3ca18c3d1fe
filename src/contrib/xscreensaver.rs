//! xscreensaver's settings description of the hack: one widget per key that
//! makes sense under xscreensaver, each writing that key's own flag.
//!
//! xscreensaver turns widgets into a command line and, when the dialog opens
//! again, maps the command line back to widgets by the first word of each
//! widget's argument: so every widget has its own flag (`-cragginess %`), no
//! argument holds `=`, and `%` is a word of its own (xscreensaver's schema,
//! `xss.xsd`, checks both).

use std::fmt::Write;

use super::{default_text, label};
use crate::cli::key_flags::flag_name;
use crate::settings::keys::{AMOUNT_MENU, KEYS, Key, Kind, MONITORS, SEED};

/// Keys with no widget: the seed is drawn afresh for every mountain under
/// xscreensaver, and xscreensaver itself chooses the monitors.
const NO_WIDGET: &[&str] = &[SEED.name, MONITORS.name];

/// Menus side by side per row, and check boxes: the dialog must fit a
/// 720-pixel screen (two menus a row made it 753 pixels tall).
const MENUS_PER_ROW: usize = 3;
const BOXES_PER_ROW: usize = 4;
/// Columns of sliders.
const SLIDER_COLUMNS: usize = 2;

/// The whole `mountains.xml`.
pub fn xml() -> String {
    let keys: Vec<&Key> = KEYS
        .iter()
        .filter(|k| !NO_WIDGET.contains(&k.name))
        .collect();
    let is = |f: fn(&Kind) -> bool| {
        keys.iter()
            .copied()
            .filter(|k| f(&k.kind))
            .collect::<Vec<_>>()
    };
    let selects = is(|k| {
        matches!(
            k,
            Kind::Choice(_) | Kind::IntOrAuto { .. } | Kind::QuarterTurn | Kind::AmountOrVaried
        )
    });
    let numbers = is(|k| matches!(k, Kind::Int { .. } | Kind::Float { .. }));
    let booleans = is(|k| matches!(k, Kind::Bool));
    let strings = is(|k| matches!(k, Kind::Path));
    let mut x = String::from(HEAD);
    rows(&mut x, &selects, MENUS_PER_ROW, select);
    columns(&mut x, &numbers);
    rows(&mut x, &booleans, BOXES_PER_ROW, boolean);
    for k in strings {
        x.push_str(&string(k));
    }
    x.push_str(TAIL);
    x
}

const HEAD: &str = r#"<?xml version="1.0" encoding="ISO-8859-1"?>

<!-- xscreensaver's settings for mountains, generated from its key table
     (mountains -xscreensaver-xml); see contrib/README.md to install it. -->

<screensaver name="mountains" _label="Mountains">

  <command arg="-root"/>

"#;

const TAIL: &str = r#"
  <_description>
Fractal mountains drawn strip by strip, like a slide show, after Mountain
Terrain 3.0 and xmountains. The rest: ~/.config/mountains/mountains.toml.

Written by the mountains authors; 2026.
  </_description>
</screensaver>
"#;

/// Widgets `per_row` to a row.
fn rows(x: &mut String, keys: &[&Key], per_row: usize, widget: fn(&Key) -> String) {
    for row in keys.chunks(per_row) {
        x.push_str("  <hgroup>\n");
        for k in row {
            x.push_str(&widget(k));
        }
        x.push_str("  </hgroup>\n\n");
    }
}

/// Sliders in `SLIDER_COLUMNS` columns.
fn columns(x: &mut String, keys: &[&Key]) {
    x.push_str("  <hgroup>\n");
    for column in keys.chunks(keys.len().div_ceil(SLIDER_COLUMNS).max(1)) {
        x.push_str("  <vgroup>\n");
        for k in column {
            x.push_str(&number(k));
        }
        x.push_str("  </vgroup>\n");
    }
    x.push_str("  </hgroup>\n\n");
}

/// A pop-up menu; the default option adds nothing to the command line.
fn select(k: &Key) -> String {
    let values: Vec<String> = match k.kind {
        Kind::Choice(names) => names.iter().map(|s| s.to_string()).collect(),
        Kind::IntOrAuto { min, max } => std::iter::once("auto".to_string())
            .chain((min..=max).map(|n| n.to_string()))
            .collect(),
        Kind::QuarterTurn => ["0", "90", "180", "270"].map(String::from).to_vec(),
        Kind::AmountOrVaried => std::iter::once("varied".to_string())
            .chain(AMOUNT_MENU.iter().map(|a| a.to_string()))
            .collect(),
        _ => Vec::new(),
    };
    let default = default_text(k);
    let mut s = format!("    <select id=\"{}\">\n", k.name);
    for v in values {
        let shown = format!("{}: {v}", label(k));
        let id = format!("{}-{}", k.name, v);
        if v == default {
            let _ = writeln!(s, "      <option id=\"{id}\" _label=\"{shown}\"/>");
        } else {
            let arg = format!("-{} {v}", flag_name(k));
            let _ = writeln!(
                s,
                "      <option id=\"{id}\" _label=\"{shown}\" arg-set=\"{arg}\"/>"
            );
        }
    }
    s.push_str("    </select>\n");
    s
}

/// A slider over the key's whole range.
fn number(k: &Key) -> String {
    let (low, high) = match k.kind {
        Kind::Int { min, max } => (min.to_string(), max.to_string()),
        // A decimal point tells xscreensaver the range is not whole numbers.
        Kind::Float { min, max } => (decimal(min), decimal(max)),
        _ => return String::new(),
    };
    let default = default_text(k);
    format!(
        "    <number id=\"{id}\" type=\"slider\" arg=\"-{flag} %\"\n            \
         _label=\"{label}\" _low-label=\"{low}\" _high-label=\"{high}\"\n            \
         low=\"{low}\" high=\"{high}\" default=\"{default}\"/>\n",
        id = k.name,
        flag = flag_name(k),
        label = label(k),
    )
}

/// A number written with a decimal point.
fn decimal(v: f64) -> String {
    if v.fract() == 0.0 {
        format!("{v:.1}")
    } else {
        v.to_string()
    }
}

/// A check box: only the non-default state adds a flag.
fn boolean(k: &Key) -> String {
    let arg = if default_text(k) == "true" {
        format!("arg-unset=\"-no-{}\"", flag_name(k))
    } else {
        format!("arg-set=\"-{}\"", flag_name(k))
    };
    format!(
        "    <boolean id=\"{}\" _label=\"{}\" {arg}/>\n",
        k.name,
        label(k)
    )
}

/// A text field.
fn string(k: &Key) -> String {
    format!(
        "  <string id=\"{}\" _label=\"{}\" arg=\"-{} %\"/>\n",
        k.name,
        label(k),
        flag_name(k)
    )
}
