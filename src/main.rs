//! `mountains`: argv -> mode -> run.

// A Windows GUI program: a .scr started by Windows (/s, /p, /c) must not open
// a console window. Command-line use still prints: see `log::use_parent_console`.
#![cfg_attr(windows, windows_subsystem = "windows")]
// Printing goes through `console`: `println!` and `eprintln!` panic on a
// closed pipe.
#![warn(clippy::print_stdout, clippy::print_stderr)]

use std::process::ExitCode;

use mountains::cli::{self, Mode};
use mountains::commands::{self, EXIT_USAGE};
use mountains::settings::{load, paths};
use mountains::{console, help, log, platform, saver};

fn main() -> ExitCode {
    saver::mark_start();
    console::quiet_failed_messages();
    log::use_parent_console();
    let args: Vec<_> = std::env::args_os().skip(1).collect();
    let inv = match cli::parse(&args) {
        Ok(inv) => inv,
        Err(e) => {
            // Arguments Windows sent and we did not understand are invisible
            // without a console: keep them in the log as well.
            if platform::os::NO_CONSOLE {
                gui_log();
            }
            // The message names what was wrong; the usage after it would
            // push it off a small terminal.
            log::error(&e.to_string());
            console::err(cli::SEE_HELP);
            return ExitCode::from(EXIT_USAGE);
        }
    };
    match &inv.mode {
        Mode::Help => return printed(console::out(&help::text())),
        Mode::XscreensaverXml => {
            return printed(console::out(&mountains::contrib::xscreensaver::xml()));
        }
        Mode::ManPage => return printed(console::out(&mountains::contrib::man_page::man_page())),
        Mode::Version => {
            let version = format!("mountains {}", env!("CARGO_PKG_VERSION"));
            return printed(console::outln(&version));
        }
        Mode::CheckConfig(path) => {
            return commands::check_config(path.as_deref(), &inv);
        }
        Mode::ChangePassword => {
            return printed(console::outln(
                "mountains: no password needed; Windows handles locking.",
            ));
        }
        _ => {}
    }
    if let Some(display) = &inv.xss.display {
        // SAFETY: no other thread has started yet (the saver, the settings
        // screen and the generators all start below), so nothing can read
        // the environment while it changes.
        unsafe { std::env::set_var("DISPLAY", display) };
    }
    // Once, for every mode: the slide shows' pacing reads them, and what is
    // said of the X display (the settings screen's too) names `-display`.
    mountains::saver::set_options(&inv.xss);
    if matches!(inv.mode, Mode::Render { .. } | Mode::Heightmap { .. }) {
        mountains::memory::one_pool();
        if let Err(e) = mountains::platform::signals::end_cleanly() {
            console::err(&format!("warning: cannot watch for SIGTERM: {e}"));
        }
    } else {
        // The saver and the settings screen make and free fields and frames
        // for as long as they run.
        mountains::memory::give_back_big_blocks();
    }
    let unreadable = match inv.mode {
        Mode::Render { .. } | Mode::Heightmap { .. } => load::Unreadable::Refuse,
        Mode::Settings { .. } => load::Unreadable::NewIfMissing,
        _ => load::Unreadable::Defaults,
    };
    let loaded = match load::resolve(inv.config.as_deref(), &inv.key_values(), unreadable) {
        Ok(l) => l,
        Err(p) => {
            console::error(&p.to_string());
            // A preferences file that cannot be read fails the work, as a
            // data set or an output that cannot be does; a bad `--set` is
            // a mistake in what was typed.
            return match p.is_unreadable() {
                true => ExitCode::FAILURE,
                false => ExitCode::from(EXIT_USAGE),
            };
        }
    };
    let open = inv.open.as_deref();
    match &inv.mode {
        Mode::Render { size, output } => {
            let warnings = one_shot_warnings(&loaded, &inv);
            commands::render(&loaded.settings, open, *size, output, &warnings)
        }
        Mode::Heightmap { output } => {
            let warnings = one_shot_warnings(&loaded, &inv);
            commands::heightmap(&loaded.settings, open, output, &warnings)
        }
        Mode::Settings { parent } => {
            gui_log();
            // The saver's own choice and check: without it winit's error
            // names a file in its source instead of what to do.
            let backend = match platform::choose_backend(inv.xss.display.is_some()) {
                Ok(backend) => backend,
                Err(e) => {
                    log::error(&e.to_string());
                    return ExitCode::FAILURE;
                }
            };
            platform::report_when_the_server_goes();
            mountains::settings_ui::run(inv.config.as_deref(), &loaded, *parent, backend)
        }
        mode => run_saver(mode, loaded, open),
    }
}

/// Success once the text is out (or its reader has left: see `console`).
fn printed(result: std::io::Result<()>) -> ExitCode {
    console::status(result, ExitCode::SUCCESS)
}

/// One rule for a preferences file in every mode: a bad or unknown key is
/// a warning naming file:line:key, and the key keeps its default (a file
/// that cannot be read, is not text or is not TOML: all of them, and the
/// warning says so). Only `--set` and flags, typed for this one run, are
/// errors.
fn problem_warnings(loaded: &load::Loaded) -> Vec<String> {
    let what = |p: &load::Problem| {
        if p.is_unreadable() {
            "using the defaults"
        } else if p.drops_the_file() {
            "nothing in the file was used: using the defaults"
        } else if p.is_unknown_key() {
            "ignored"
        } else {
            "using the default"
        }
    };
    load::report_with(&loaded.problems, |p| format!("warning: {p}; {}", what(p)))
}

/// What the one-shot commands warn of on stderr (each problem of the
/// preferences file, each key `--open` leaves without effect) before their
/// work, and only if they do it.
fn one_shot_warnings(loaded: &load::Loaded, inv: &cli::Invocation) -> Vec<String> {
    let problems = problem_warnings(loaded).into_iter();
    let problems = problems.map(|line| format!("mountains: {line}"));
    problems
        .chain(commands::heights_only_warnings(inv))
        .collect()
}

/// The screensaver modes keep going on a broken or unreadable file: each
/// problem is logged (a .scr has no console) and its key keeps the default.
fn run_saver(mode: &Mode, loaded: load::Loaded, open: Option<&std::path::Path>) -> ExitCode {
    gui_log();
    for line in problem_warnings(&loaded) {
        log::warn(&line);
    }
    let opened = open.and_then(|path| match mountains::mountain::Mountain::open(path) {
        Ok((mountain, notes)) => {
            for note in &notes {
                log::warn(&format!("{}: {note}", path.display()));
            }
            Some(mountain)
        }
        Err(e) => {
            // Said as the preferences' problems are (`warning:`), and by its
            // flag as `render --open` names it: it was the file alone.
            log::warn(&format!(
                "warning: --open {e}; showing generated mountains instead"
            ));
            None
        }
    });
    platform::report_when_the_server_goes();
    match saver::run(mode, loaded.settings, opened) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            log::error(&e.to_string());
            ExitCode::FAILURE
        }
    }
}

/// The window modes have no console to print to (a .scr, xscreensaver):
/// their messages also go to `mountains.log` in the data directory.
fn gui_log() {
    log::set_file(paths::data_dir().map(|d| d.join("mountains.log")));
}
