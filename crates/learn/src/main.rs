//! `cargo run -p learn -- <start|check|watch|hint|list> [NAME]`, from the
//! workspace's root: write the core and each chapter's step yourself.

use std::io::Write;
use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Parser, Subcommand};

use learn::exercise::blank;
use learn::lab::{Lab, workspace_root};
use learn::limits::{HEIGHT, RENDER_TIME_LIMIT, TEST_TIME_LIMIT, WIDTH};
use learn::path::{self, Item};
use learn::shader;

/// Do the lab yourself: write the tracer's core and each chapter's step,
/// each checked by its tests and against the reference image.
#[derive(Parser, Debug)]
#[command(name = "learn", version)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Lay an exercise out in my-lab/ (never overwrites your files): a core
    /// exercise by name (`sphere`), a chapter's step by number (`2`), or
    /// chapter 10's shader (`shader`)
    Start { exercise: String },
    /// Build an exercise, run its tests, compare its render with the reference
    Check { exercise: String },
    /// Check an exercise again every time you save, until Ctrl-C
    Watch { exercise: String },
    /// A hint, one level at a time: 1 a nudge (what to think about), 2 the
    /// rule (what the code must do), 3 the recipe (how). Without LEVEL, the
    /// level after the last one you asked for
    Hint {
        exercise: String,
        #[arg(value_parser = clap::value_parser!(u8).range(1..=3))]
        level: Option<u8>,
    },
    /// Every exercise, in order, and how far you are
    List,
    /// The known mistakes of an exercise: what each is, what it does to the
    /// picture, where the book explains it, and (once a check has learnt
    /// it) which tests it fails. A failed check names the one it matches
    Mistakes { exercise: String },
}

/// Why the command could not run: one line, exit code 2.
fn usage(line: String) -> ExitCode {
    eprintln!("learn: error: {line}");
    ExitCode::from(2)
}

fn find(name: &str) -> Result<Item, ExitCode> {
    path::find(name).ok_or_else(|| {
        usage(format!(
            "there is no exercise `{name}`: the exercises are {} (`cargo run -p learn -- list`)",
            path::names()
        ))
    })
}

/// The workspace's root, found from the current folder so that the lab is
/// the learner's checkout.
fn root() -> Result<PathBuf, ExitCode> {
    let here = std::env::current_dir().map_err(|e| usage(format!("no current folder: {e}")))?;
    workspace_root(&here).ok_or_else(|| {
        usage("run it inside the raylab workspace: `cargo run -p learn -- list`".into())
    })
}

fn run(cli: Cli) -> Result<ExitCode, ExitCode> {
    let lab = Lab::in_workspace(&root()?);
    let stdout = std::io::stdout();
    let mut out = stdout.lock();
    match cli.command {
        Command::Start { exercise } => {
            let item = find(&exercise)?;
            start(&lab, item, &mut out)?;
            Ok(ExitCode::SUCCESS)
        }
        Command::Check { exercise } | Command::Watch { exercise }
            if path::find(&exercise).is_some_and(|item| !item.started(&lab)) =>
        {
            Err(usage(format!(
                "no exercise `{exercise}` in my-lab/: make it with `cargo run -p learn -- start {exercise}`"
            )))
        }
        // The checker is a program of its own, built on first use.
        Command::Check { exercise } => {
            let item = find(&exercise)?;
            learn::checker::run(&lab, "check", &item.name(), &mut out).map_err(usage)
        }
        Command::Watch { exercise } => {
            let item = find(&exercise)?;
            learn::checker::run(&lab, "watch", &item.name(), &mut out).map_err(usage)
        }
        Command::Hint { exercise, level } => {
            let item = find(&exercise)?;
            let name = item.name();
            let last = lab.progress().hints.get(&name).copied().unwrap_or(0);
            let level = level.unwrap_or((last + 1).min(3));
            const LEVELS: [&str; 3] = ["a nudge", "the rule", "the recipe"];
            let text = item.hints()[usize::from(level - 1)];
            let _ = writeln!(
                out,
                "{}, hint {level} of 3 ({}): {text}",
                item.title(),
                LEVELS[usize::from(level - 1)]
            );
            if let Err(error) = lab.record_hint(&name, level.max(last)) {
                let _ = writeln!(out, "learn: could not record the hint: {error}");
            }
            let page = item.page();
            if level < 3 {
                let _ = writeln!(
                    out,
                    "More: `cargo run -p learn -- hint {name}` gives {} (hint {}); the book: {page}",
                    LEVELS[usize::from(level)],
                    level + 1
                );
            } else if item == Item::Shader {
                let _ = writeln!(
                    out,
                    "The check asks naga whether the shader compiles, then renders it {WIDTH}×{HEIGHT} \
                     like chapters 2, 3 and 4 (each stopped after {} s; it needs a GPU adapter, \
                     lavapipe will do) and compares each with the chapter's own render. The \
                     book: {page}",
                    RENDER_TIME_LIMIT.as_secs(),
                );
            } else {
                let _ = writeln!(
                    out,
                    "The check runs the exercise's tests (stopped after {} s) and renders \
                     {WIDTH}×{HEIGHT} (stopped after {} s). The book: {page}",
                    TEST_TIME_LIMIT.as_secs(),
                    RENDER_TIME_LIMIT.as_secs(),
                );
            }
            Ok(ExitCode::SUCCESS)
        }
        Command::Mistakes { exercise } => {
            let item = find(&exercise)?;
            let name = item.name();
            let mistakes: Vec<_> = learn::mistakes::of(&name).collect();
            if mistakes.is_empty() {
                let _ = writeln!(out, "No mistakes of `{name}` are catalogued yet.");
                return Ok(ExitCode::SUCCESS);
            }
            let cache = learn::mistakes::mistake_lab(&lab).dir.join("fingerprints");
            // The tests by their titles, as the reference's sources give them.
            let src = match item {
                Item::Chapter(chapter) => lab.root.join(chapter.dir).join("src"),
                _ => lab.root.join("src"),
            };
            let titles = learn::run::test_titles(&src);
            let title = |name: &str| {
                learn::run::title_of(&titles, name).unwrap_or_else(|| learn::run::sentence(name))
            };
            let _ = writeln!(out, "The known mistakes of `{name}`, {}:", item.title());
            for m in mistakes {
                let _ = writeln!(out, "  {} — {}", m.slug, m.what);
                let _ = writeln!(out, "      the picture: {}", m.picture);
                let _ = writeln!(out, "      the book: {}", m.section);
                let print: Option<learn::mistakes::Fingerprint> =
                    std::fs::read_to_string(cache.join(format!("{}-{}.toml", m.exercise, m.slug)))
                        .ok()
                        .and_then(|text| toml::from_str(&text).ok());
                if let Some(print) = print {
                    let seen = if !print.failing.is_empty() {
                        let tests: Vec<String> = print.failing.iter().map(|t| title(t)).collect();
                        format!("fails {}", tests.join("; "))
                    } else if print.image.is_some() {
                        "passes the tests; its picture differs".to_owned()
                    } else {
                        print.verdict.clone()
                    };
                    let _ = writeln!(out, "      the check: {seen}");
                }
            }
            let _ = writeln!(
                out,
                "A failed `check {name}` names the one whose failing tests (or, where the tests \
                 pass, whose picture) match yours: `Likely mistake: SLUG`."
            );
            Ok(ExitCode::SUCCESS)
        }
        Command::List => {
            let progress = lab.progress();
            let _ = writeln!(
                out,
                "From the empty skeleton (start at `ray`) or from the lab's own start, the ray \
                 caster given (start at `1`):"
            );
            let mut passed = 0;
            let width = path::items()
                .map(|i| i.title().chars().count())
                .max()
                .unwrap_or(0);
            for item in path::items() {
                let state = if item.passed(&progress) {
                    passed += 1;
                    "passed"
                } else if item.started(&lab) {
                    "started"
                } else {
                    "not started"
                };
                let _ = writeln!(
                    out,
                    "  {:<8} {:<width$}  {state}",
                    item.name(),
                    item.title()
                );
            }
            let _ = writeln!(
                out,
                "{passed} of {} passed (kept in {}); start one with `cargo run -p learn -- start NAME`",
                path::PATH.len(),
                lab.progress_path()
                    .strip_prefix(&lab.root)
                    .unwrap_or(&lab.progress_path())
                    .display()
            );
            Ok(ExitCode::SUCCESS)
        }
    }
}

/// `learn start`: lay the exercise out and say what to write where.
fn start(lab: &Lab, item: Item, out: &mut dyn Write) -> Result<(), ExitCode> {
    let name = item.name();
    // A last word after the tasks, where the exercise needs one.
    let (started, tasks, note) = match item {
        Item::Core(core) => {
            let started = lab
                .start_core(core, false)
                .map_err(|e| usage(e.to_string()))?;
            let mut tasks = Vec::new();
            for file in core.files {
                let source = std::fs::read_to_string(lab.root.join("src").join(file)).ok();
                let blanked = source.and_then(|s| blank(&s).ok());
                for task in blanked.into_iter().flat_map(|b| b.tasks) {
                    if core.regions.contains(&task.name.as_str()) {
                        tasks.push((task, (*file).to_owned()));
                    }
                }
            }
            let note = "between its marker lines, which the check needs: it uses the reference \
                        for every region you have not passed yet";
            (started, tasks, Some(note.to_owned()))
        }
        Item::Chapter(chapter) => {
            let started = lab
                .start(chapter, false)
                .map_err(|e| usage(e.to_string()))?;
            let blanked = std::fs::read_to_string(lab.reference_source(chapter))
                .ok()
                .and_then(|s| blank(&s).ok());
            let tasks = blanked
                .into_iter()
                .flat_map(|b| b.tasks)
                .filter(|task| chapter.regions.contains(&task.name.as_str()))
                .map(|task| (task, chapter.step.to_owned()))
                .collect();
            (started, tasks, None)
        }
        Item::Shader => {
            let started = lab.start_shader(false).map_err(|e| usage(e.to_string()))?;
            let mut tasks: Vec<_> = lab
                .shader_text(false)
                .map(|(_, tasks)| tasks)
                .unwrap_or_default()
                .into_iter()
                .map(|task| (task, shader::FILE.to_owned()))
                .collect();
            // In the order the check judges them, not the file's.
            tasks.sort_by_key(|(task, _)| {
                shader::STAGES
                    .iter()
                    .position(|stage| stage.region == task.name)
            });
            let file = lab.shader_file();
            let note = format!(
                "as handed out it compiles and renders, with no shadows and no mirror or glass: \
                 watch yours live with `cargo run -p {} -- --watch --shader {} --like \
                 ch04-refraction`",
                shader::PACKAGE,
                file.strip_prefix(&lab.root).unwrap_or(&file).display()
            );
            (started, tasks, Some(note))
        }
    };
    let folder = started
        .folder
        .strip_prefix(&lab.root)
        .unwrap_or(&started.folder);
    for file in &started.kept {
        let _ = writeln!(out, "kept your {}", folder.join(file).display());
    }
    if started.written.is_empty() {
        let _ = writeln!(out, "`{name}` is already there, left as it was");
    } else {
        for file in &started.written {
            let _ = writeln!(out, "wrote {}", folder.join(file).display());
        }
    }
    for (task, file) in tasks {
        let _ = writeln!(
            out,
            "  write `{}` in {}: {}",
            task.name,
            folder.join(file).display(),
            task.text
        );
    }
    if let Some(note) = note {
        let _ = writeln!(out, "  ({note})");
    }
    let _ = writeln!(
        out,
        "then: cargo run -p learn -- check {name}   (or `watch {name}` to check on every save)"
    );
    Ok(())
}

/// A clap error as one line: its message with the lines clap puts under it
/// (the missing argument's name), and what a chapter may be.
fn usage_line(error: &clap::Error) -> String {
    let text = error.render().to_string();
    let message: Vec<&str> = text
        .lines()
        .map(str::trim)
        .take_while(|l| !l.is_empty())
        .collect();
    let message = message.join(" ");
    let message = message.trim_start_matches("error: ");
    let tip = text.lines().map(str::trim).find(|l| l.starts_with("tip:"));
    if error.kind() == clap::error::ErrorKind::MissingRequiredArgument {
        format!(
            "{message}: the exercise, one of {}, e.g. `check ray` (see --help)",
            path::names()
        )
    } else if let Some(tip) = tip {
        format!("{message} ({tip})")
    } else {
        format!("{message} (see --help)")
    }
}

fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e)
            if matches!(
                e.kind(),
                clap::error::ErrorKind::DisplayHelp | clap::error::ErrorKind::DisplayVersion
            ) =>
        {
            let _ = e.print();
            return ExitCode::SUCCESS;
        }
        Err(e) => return usage(usage_line(&e)),
    };
    run(cli).unwrap_or_else(|code| code)
}
