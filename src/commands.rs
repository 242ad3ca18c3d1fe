//! The one-shot commands: render a picture, save a data set, check a file.

use std::path::Path;
use std::process::ExitCode;

use crate::cli::output::{self, Format};
use crate::cli::{Invocation, Set};
use crate::console;
use crate::mountain::Mountain;
use crate::render::{Frame, Size, render_full_at};
use crate::settings::{Settings, load, paths};
use crate::terrain::heightmap;

/// Exit code for a mistake in what the user typed: a flag, a value, flags
/// that conflict, said before any work. A file that cannot be read or
/// written, a data set that is broken, too little memory: 1.
pub const EXIT_USAGE: u8 = 2;

/// The mountain to show: a data set from `--open` (its notes said on
/// stderr), else a generated one.
pub fn mountain(settings: &Settings, open: Option<&Path>) -> Result<Mountain, String> {
    // Only a data set can fail, and its message starts with its file.
    let (mountain, notes) =
        Mountain::open_or_generate(settings, open).map_err(|e| format!("--open {e}"))?;
    if let Some(path) = open {
        for note in &notes {
            console::err(&format!("mountains: {}: {note}", path.display()));
        }
    }
    Ok(mountain)
}

/// The warnings of each `--set` (or key flag) in `inv` that its `--open`
/// leaves without effect in `render` and `heightmap`: one that only shapes
/// the heights a generator makes ([`crate::mountain::HEIGHTS_ONLY`]), where
/// the heights are the data set's. Each is named as it was typed (`-seed
/// 9` is no `--set seed=9` to the one who typed it). A preferences file's
/// keys are no mistake of this run, and are not named.
pub fn heights_only_warnings(inv: &Invocation) -> Vec<String> {
    let Some(path) = &inv.open else {
        return Vec::new();
    };
    let heights_only = |key: &str| crate::mountain::HEIGHTS_ONLY.iter().any(|k| k.name == key);
    let warning = |set: &Set| {
        format!(
            "mountains: warning: {}: no effect with --open {}: \
             the data set's heights are used as they are",
            set.typed,
            path.display()
        )
    };
    inv.sets
        .iter()
        .filter(|set| heights_only(&set.key))
        .map(warning)
        .collect()
}

/// Says `warnings` (whole lines) on stderr: once nothing is left to
/// refuse, so a refused command says only why (a warning, then a refusal
/// of the same command, told of work it never did).
fn say_warnings(warnings: &[String]) {
    for line in warnings {
        console::err(line);
    }
}

/// `mountains render`: one complete mountain to a PNG. `warnings` (about
/// the preferences and the flags) are said once the picture is sure to be
/// drawn: after every refusal, and after `--open`'s data set is read.
pub fn render(
    settings: &Settings,
    open: Option<&Path>,
    size: Size,
    output: &Path,
    warnings: &[String],
) -> ExitCode {
    if let Some(code) = refuse_the_output(open, output, "picture") {
        return code;
    }
    // A size past the frame's bound was refused as the arguments were
    // read (`cli::parse_size`): only the memory can be wanting here.
    let Some(mut frame) = Frame::new(size.width, size.height) else {
        return fail(&format!(
            "--size {size}: not enough memory for the frame ({} MiB)",
            (size.pixels() * 4) >> 20
        ));
    };
    let settings = &crate::render::detail::for_frame(settings, size);
    if let Err(mib) = crate::memory::room_to_work(work_exponent(settings, open)) {
        return fail(&format!(
            "--size {size}: not enough memory to draw it: about {mib} MiB more \
             than the frame's {} MiB is needed",
            frame.pixels().len() >> 18
        ));
    }
    let shown = match mountain(settings, open) {
        Ok(m) => m,
        Err(e) => return fail(&e),
    };
    say_warnings(warnings);
    let drawn = shown.drawn_with(settings);
    render_full_at(
        &shown.field,
        &drawn,
        &mut frame,
        crate::solar::now_for(&drawn),
    );
    let seed = shown.seed;
    let format = output::format_of(output, output::PICTURES, "a picture").unwrap_or(Format::Png);
    if let Err(e) = crate::snapshot::write_picture(output, &frame, format) {
        return fail(&e);
    }
    console::status(print_seed(seed, output), ExitCode::SUCCESS)
}

/// The grid exponent a command will work on: a data set's size is known
/// only once it is read, so the largest is assumed for one.
fn work_exponent(settings: &Settings, open: Option<&Path>) -> u32 {
    match open {
        Some(_) => crate::terrain::heightfield::MAX_EXPONENT,
        None => settings.grid_exponent(),
    }
}

/// `mountains heightmap`: generate a data set and save it as a 16-bit PNG,
/// or as raw 16-bit samples (`.r16`, `.raw`), whose height range it prints.
/// `warnings` are said as [`render`] says them.
pub fn heightmap(
    settings: &Settings,
    open: Option<&Path>,
    output: &Path,
    warnings: &[String],
) -> ExitCode {
    if let Some(code) = refuse_the_output(open, output, "data set") {
        return code;
    }
    if let Err(mib) = crate::memory::room_to_work(work_exponent(settings, open)) {
        return fail(&format!(
            "not enough memory to make the data set: about {mib} MiB is needed"
        ));
    }
    let shown = match mountain(settings, open) {
        Ok(m) => m,
        Err(e) => return fail(&e),
    };
    say_warnings(warnings);
    // A data set saved again keeps the keys its file recorded.
    let settings = &shown.saved_with(settings);
    let (field, seed) = (shown.field, shown.seed);
    let format = output::format_of(output, output::DATA_SETS, "a data set").unwrap_or(Format::Png);
    if format == Format::Raw16 {
        let (bytes, q) = heightmap::raw16(&field);
        if let Err(e) = crate::fsutil::write_output_with(output, |w| w.write_all(&bytes)) {
            return fail(&cannot_write(output, &e));
        }
        let n = field.size();
        let top = heightmap::quantise::MAX_SAMPLE;
        let range = format!(
            "{n}x{n} 16-bit little-endian samples; 0 is height {}, {top} is {}",
            q.height(0),
            q.height(top)
        );
        if let Err(e) = say(output, &range) {
            return console::status(Err(e), ExitCode::SUCCESS);
        }
    } else if let Err(e) = heightmap::save(output, &field, seed, settings) {
        // Its message starts with the file.
        return fail(&format!("-o {e}"));
    }
    console::status(print_seed(seed, output), ExitCode::SUCCESS)
}

/// Why `output`, where `made` (a picture, a data set) would be written,
/// is refused before any work, if it is: a terminal, the `--open` data set
/// itself, or a file the write would refuse.
fn refuse_the_output(open: Option<&Path>, output: &Path, made: &str) -> Option<ExitCode> {
    refuse_a_terminal(output)
        .or_else(|| refuse_the_data_set(open, output, made))
        .or_else(|| refuse_an_unwritable_output(output))
}

/// `-o -` on a terminal would fill it with binary (as `--open -` from a
/// terminal would wait for ever, which is refused too).
fn refuse_a_terminal(output: &Path) -> Option<ExitCode> {
    use std::io::IsTerminal;
    (output == Path::new("-") && std::io::stdout().is_terminal()).then(|| {
        console::error("-o -: standard output is a terminal; redirect it (-o - > file) or pipe it");
        ExitCode::from(EXIT_USAGE)
    })
}

/// `render --open X -o X` would put the picture in place of the data set
/// it was drawn from, which no one asks for on purpose; `heightmap --open
/// X -o X` a terrain tool's file in place of our fitted copy of it (cropped
/// to a square, resampled). `made` names what `-o` writes. The two paths are
/// compared resolved (on Unix without opening either: a FIFO's open would
/// wait); `-` is a pipe, never the file of that name.
fn refuse_the_data_set(open: Option<&Path>, output: &Path, made: &str) -> Option<ExitCode> {
    let dash = Path::new("-");
    let open = open.filter(|&p| p != dash && output != dash)?;
    crate::fsutil::same_file(open, output).then(|| {
        console::error(&format!(
            "-o {}: is the data set --open reads; give the {made} another name",
            output.display()
        ));
        ExitCode::from(EXIT_USAGE)
    })
}

/// An `-o` the write would refuse (a link to nowhere, a folder, a folder
/// that is not there or takes no file: [`crate::fsutil::writable`]) was
/// refused once the work was done, minutes of it for a large picture: it
/// is asked before any, and said as the write says it (exit 1). `-` is
/// standard output, no file.
fn refuse_an_unwritable_output(output: &Path) -> Option<ExitCode> {
    if output == Path::new("-") {
        return None;
    }
    let e = crate::fsutil::writable(output).err()?;
    Some(fail(&cannot_write(output, &e)))
}

/// How a file `-o` names that cannot be written is said: the flag, the
/// file, and [`crate::fsutil::cannot_write`]'s words.
fn cannot_write(output: &Path, e: &std::io::Error) -> String {
    let why = crate::fsutil::cannot_write(e);
    format!("-o {}: {why}", output.display())
}

/// Says which seed made the file.
fn print_seed(seed: Option<u64>, output: &Path) -> std::io::Result<()> {
    let line = match seed {
        Some(s) => format!("seed {s} -> {}", output.display()),
        None => format!("-> {}", output.display()),
    };
    say(output, &line)
}

/// A line about `output` for the user: on stdout, or on stderr when the
/// file itself went to standard output (`-o -`).
fn say(output: &Path, line: &str) -> std::io::Result<()> {
    if output == Path::new("-") {
        console::err(line);
        Ok(())
    } else {
        console::outln(line)
    }
}

fn fail(message: &str) -> ExitCode {
    console::error(message);
    ExitCode::FAILURE
}

/// `--check-config [FILE]`: checks FILE, else `--config`'s, else the usual
/// preferences file, and every `--set`. Exit 0 when all is good, also when
/// there is no preferences file at the usual place (the defaults are in
/// use, which is no mistake) and for the null device (`/dev/null`: no
/// preferences); 1 for any problem in the file, or a named file missing;
/// 2 for a bad `--set` or key flag (`-color pink`, or `-seed` without its
/// value: typed for the run, as in every mode), whatever the file: then
/// a good file is said to be fine, but not "ok" alone.
pub fn check_config(path: Option<&Path>, inv: &Invocation) -> ExitCode {
    let (config, sets) = (inv.config.as_deref(), &inv.sets);
    // Said first: typed for this run, they are what to mend now, and a
    // file's flood of problems ends in "... and N more".
    let mistyped = report_mistakes(inv);
    let checked = check_file(path, config, mistyped.as_deref());
    if mistyped.is_some() {
        return ExitCode::from(EXIT_USAGE);
    }
    let printed = match checked {
        Ok(printed) => printed,
        Err(code) => return code,
    };
    warn_of_missing_folders_typed(sets);
    let printed = match sets.is_empty() {
        true => printed,
        false => printed.and_then(|()| console::outln(&format!("{}: ok", sets_named(sets)))),
    };
    console::status(printed, ExitCode::SUCCESS)
}

/// How `--check-config`'s verdict names the sets it checked: `--set`
/// when every one was typed so, else each as typed (`-color sonar`: a
/// "--set: ok" named a flag no one typed).
fn sets_named(sets: &[Set]) -> String {
    if sets.iter().all(Set::by_set) {
        return "--set".to_string();
    }
    let typed: Vec<&str> = sets.iter().map(|set| set.typed.as_str()).collect();
    typed.join(" ")
}

/// Says each mistake typed for the run in the order it was typed, named
/// as it was typed (a `--set` or key flag whose key or value is bad, a
/// `--set` that gives no key=value, a key's flag or `--set` left without
/// its value), then where to read the rest, as every mode says a mistake
/// typed; returns how the verdict names the first, if any.
fn report_mistakes(inv: &Invocation) -> Option<String> {
    let mistakes = mistakes_typed(inv);
    let first = mistakes.first()?.named.clone();
    for line in load::report_with(&mistakes, |m| console::error_line(&m.said)) {
        console::err(&line);
    }
    console::err(crate::cli::SEE_HELP);
    Some(first)
}

/// One mistake typed for the run, as `--check-config` says it.
struct Typed {
    /// Where it was typed among the arguments.
    at: usize,
    /// Its message.
    said: String,
    /// How the verdict names it (`-color pink is not`).
    named: String,
}

/// Every mistake typed for the run, in the order typed: each kind was
/// said in a heap of its own (a `--set nokey` typed first was said after
/// a `-color pink` typed later), which read as if the user had typed them
/// the other way round.
fn mistakes_typed(inv: &Invocation) -> Vec<Typed> {
    // The sets typed by `--set` are named as one, as `sets_named` names them.
    let a_set = || "a --set is not".to_string();
    let bad = bad_sets(&inv.sets).into_iter().map(|(set, problem)| Typed {
        at: set.at,
        said: problem.to_string(),
        named: match set.by_set() {
            true => a_set(),
            false => format!("{} is not", set.typed),
        },
    });
    let malformed = inv.malformed.iter().map(|m| Typed {
        at: m.at,
        said: m.refusal.to_string(),
        named: a_set(),
    });
    let unfinished = inv.unfinished.iter().map(|m| Typed {
        at: m.at,
        said: m.refusal.to_string(),
        named: format!("{} needs a value", m.typed),
    });
    let mut all: Vec<Typed> = bad.chain(malformed).chain(unfinished).collect();
    all.sort_by_key(|m| m.at);
    all
}

/// Each `--set` or key flag whose key or value is bad, with its problem
/// named as it was typed. A value's range and type do not depend on the
/// other keys, so each is checked against the defaults.
fn bad_sets(sets: &[Set]) -> Vec<(&Set, load::Problem)> {
    sets.iter()
        .filter_map(|set| {
            let checked = load::apply_set(&mut Settings::default(), &set.key, &set.value);
            checked.err().map(|p| (set, set.named_as_typed(p)))
        })
        .collect()
}

/// The file part of [`check_config`]: its problems said, and `Err` with
/// the exit code when there are any (or the file cannot be checked);
/// `Ok` with what printing its verdict gave. `mistyped`: how the first
/// mistake typed with it is named (`-color pink is not`), which the
/// verdict of a good file must not hide.
fn check_file(
    path: Option<&Path>,
    config: Option<&Path>,
    mistyped: Option<&str>,
) -> Result<std::io::Result<()>, ExitCode> {
    let named = path.or(config).map(Path::to_path_buf);
    let Some(file) = named.clone().or_else(paths::config_file) else {
        return Err(fail(
            "--check-config: no preferences file given and no home directory to look in",
        ));
    };
    // A link that leads nowhere (or round in a loop) is there, and reading
    // it says what is wrong with it; only a name with nothing at all is missing.
    let present = crate::fsutil::taken(&file);
    if crate::fsutil::is_null_device(&file) {
        return Ok(console::outln(&format!(
            "mountains: {}: no preferences; the defaults are in use",
            file.display()
        )));
    }
    if !present {
        if named.is_none() {
            return Ok(console::outln(&format!(
                "mountains: no preferences file at {}; the defaults are in use",
                file.display()
            )));
        }
        let flag = flag_naming(path);
        return Err(fail(&format!("{flag} {}: no such file", file.display())));
    }
    let mut settings = Settings::default();
    let mut problems = load::apply_file(&mut settings, &file);
    if named.is_some() {
        name_by_flag(&mut problems, flag_naming(path));
    }
    for line in load::report_with(&problems, |p| console::error_line(&p.to_string())) {
        console::err(&line);
    }
    if !problems.is_empty() {
        return Err(ExitCode::FAILURE);
    }
    warn_of_a_missing_folder(&settings, &file);
    Ok(console::outln(&verdict(&file, mistyped)))
}

/// The flag that named the file `--check-config` checks, when one did:
/// its own file `path`, else `--config`'s.
fn flag_naming(path: Option<&Path>) -> &'static str {
    match path {
        Some(_) => "--check-config",
        None => "--config",
    }
}

/// A file that cannot be read is refused naming the flag that named it
/// first (`--check-config DIR: cannot read: ...`), as `--config` and
/// `--open` refuse theirs; a problem inside the file keeps its place
/// (file:line:column) alone.
fn name_by_flag(problems: &mut [load::Problem], flag: &str) {
    for problem in problems.iter_mut().filter(|p| p.is_unreadable()) {
        problem.source = format!("{flag} {}", problem.source);
    }
}

/// What `--check-config` says of a file without problems. A bare "ok"
/// beside a refused `--set` (exit 2) read as if all were well: the
/// mistake is named after it, as [`report_mistakes`] names it.
fn verdict(file: &Path, mistyped: Option<&str>) -> String {
    match mistyped {
        None => format!("{}: ok", file.display()),
        Some(mistake) => format!("{}: the file is ok; {mistake}", file.display()),
    }
}

/// Warns when `heightmaps_dir` in `file` names no folder: the value is
/// well formed, but the slide show would show none of its heightmaps, and
/// only say so in its log. Named as a problem in the file is, by file,
/// line and key; a file where the folder should be is said to be one.
fn warn_of_a_missing_folder(settings: &Settings, file: &Path) {
    let dir = settings.heightmaps_dir.as_deref();
    let Some(missing) = no_folder(dir) else {
        return;
    };
    let key = "heightmaps_dir";
    let at = load::value_position(file, key).map_or(String::new(), |(l, c)| format!(":{l}:{c}"));
    console::err(&format!(
        "mountains: warning: {}{at}: key `{key}`: {:?}: {missing}; \
         every slide is generated",
        file.display(),
        dir.unwrap_or_default(),
    ));
}

/// Warns of each `heightmaps_dir` typed for the run (`--heightmaps-dir
/// DIR`, `--set heightmaps_dir=DIR`) that names no folder, named as typed,
/// as the file's is warned of: "--set: ok" was all that was said.
fn warn_of_missing_folders_typed(sets: &[Set]) {
    for set in sets.iter().filter(|set| set.key == "heightmaps_dir") {
        if let Some(missing) = no_folder(Some(&set.value)) {
            console::err(&format!(
                "mountains: warning: {}: {missing}; every slide is generated",
                set.typed
            ));
        }
    }
}

/// How a `heightmaps_dir` of `dir` that names no folder is said (`no such
/// folder (/home/me/maps)`, or a file in its place `not a folder`), if it
/// names none.
fn no_folder(dir: Option<&str>) -> Option<String> {
    let folder = paths::heightmaps_folder(dir).filter(|f| !f.is_dir())?;
    let what = match folder.exists() {
        true => "not a folder",
        false => "no such folder",
    };
    Some(format!("{what} ({})", folder.display()))
}
