//! `cargo run -p learn -- <start|check|watch|hint|list> [N]`, from the
//! workspace's root: do each chapter's step yourself.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use clap::{Parser, Subcommand};

use learn::check::{RENDER_TIME_LIMIT, TEST_TIME_LIMIT, check};
use learn::exercise::{EXERCISES, Exercise, blank, exercise};
use learn::lab::Lab;

/// Do the lab yourself: write each chapter's step, checked by its tests
/// and against the reference image.
#[derive(Parser, Debug)]
#[command(name = "learn", version)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Lay chapter N's exercise into my-lab/chNN/ (never overwrites your files)
    Start { chapter: u8 },
    /// Build chapter N's exercise, run its tests, compare its render with the reference
    Check { chapter: u8 },
    /// Check chapter N again every time you save, until Ctrl-C
    Watch { chapter: u8 },
    /// What to do in chapter N, and how
    Hint { chapter: u8 },
    /// Every exercise and how far you are
    List,
}

/// Why the command could not run: one line, exit code 2.
fn usage(line: String) -> ExitCode {
    eprintln!("learn: error: {line}");
    ExitCode::from(2)
}

fn find(number: u8) -> Result<&'static Exercise, ExitCode> {
    exercise(number).ok_or_else(|| {
        let first = EXERCISES.first().map_or(1, |e| e.number);
        let last = EXERCISES.last().map_or(1, |e| e.number);
        usage(format!(
            "there is no exercise for chapter {number}: the exercises are chapters {first} to {last} \
             (`cargo run -p learn -- list`)"
        ))
    })
}

/// The workspace's root: the folder above `crates/learn/`, found from the
/// current folder so that the lab is the learner's checkout.
fn workspace_root() -> Result<PathBuf, ExitCode> {
    let here = std::env::current_dir().map_err(|e| usage(format!("no current folder: {e}")))?;
    here.ancestors()
        .find(|dir| dir.join("crates/learn/Cargo.toml").is_file() && dir.join("chapters").is_dir())
        .map(Path::to_owned)
        .ok_or_else(|| {
            usage("run it inside the raylab workspace: `cargo run -p learn -- list`".into())
        })
}

fn run(cli: Cli) -> Result<ExitCode, ExitCode> {
    let lab = Lab::in_workspace(&workspace_root()?);
    let stdout = std::io::stdout();
    let mut out = stdout.lock();
    match cli.command {
        Command::Start { chapter } => {
            let exercise = find(chapter)?;
            let started = lab
                .start(exercise, false)
                .map_err(|e| usage(e.to_string()))?;
            let folder = started
                .folder
                .strip_prefix(&lab.root)
                .unwrap_or(&started.folder);
            for name in &started.kept {
                let _ = writeln!(out, "kept your {}", folder.join(name).display());
            }
            if started.written.is_empty() {
                let _ = writeln!(out, "{} is already there, left as it was", folder.display());
            } else {
                let _ = writeln!(out, "wrote {} for {exercise}", folder.display());
            }
            let blanked = std::fs::read_to_string(lab.reference_source(exercise))
                .ok()
                .and_then(|s| blank(&s).ok());
            for task in blanked.iter().flat_map(|b| &b.tasks) {
                let _ = writeln!(
                    out,
                    "  write `{}` in {}/{}: {}",
                    task.name,
                    folder.display(),
                    exercise.step,
                    task.text
                );
            }
            let _ = writeln!(
                out,
                "then: cargo run -p learn -- check {chapter}   (or `watch {chapter}` to check on every save)"
            );
            Ok(ExitCode::SUCCESS)
        }
        Command::Check { chapter } | Command::Watch { chapter }
            if exercise(chapter).is_some_and(|e| !lab.folder(e).join("src/lib.rs").is_file()) =>
        {
            Err(usage(format!(
                "no exercise in my-lab/ch{chapter:02}: make it with `cargo run -p learn -- start {chapter}`"
            )))
        }
        Command::Check { chapter } => {
            let exercise = find(chapter)?;
            let verdict = check(&lab, exercise, &mut out);
            Ok(exit_for(&verdict))
        }
        Command::Watch { chapter } => {
            let exercise = find(chapter)?;
            learn::watch::watch(&lab, exercise, &mut out).map_err(|_| ExitCode::from(2))?;
            Ok(ExitCode::SUCCESS)
        }
        Command::Hint { chapter } => {
            let exercise = find(chapter)?;
            let _ = writeln!(out, "{exercise}: {}", exercise.hint);
            let _ = writeln!(
                out,
                "The check runs the chapter's tests (stopped after {} s) and renders 160×120 \
                 (stopped after {} s). The book: {}",
                TEST_TIME_LIMIT.as_secs(),
                RENDER_TIME_LIMIT.as_secs(),
                exercise.page
            );
            Ok(ExitCode::SUCCESS)
        }
        Command::List => {
            let progress = lab.progress();
            for exercise in &EXERCISES {
                let state = if progress.passed.contains(&exercise.number) {
                    "passed"
                } else if lab.folder(exercise).join("src/lib.rs").is_file() {
                    "started"
                } else {
                    "not started"
                };
                let _ = writeln!(out, "  {:<28} {state}", exercise.to_string());
            }
            let _ = writeln!(
                out,
                "{} of {} passed (kept in {}); start one with `cargo run -p learn -- start N`",
                progress.passed.len(),
                EXERCISES.len(),
                lab.progress_path()
                    .strip_prefix(&lab.root)
                    .unwrap_or(&lab.progress_path())
                    .display()
            );
            Ok(ExitCode::SUCCESS)
        }
    }
}

/// 0 for a pass, 1 for work still to do, 2 for a check that could not run.
fn exit_for(verdict: &learn::check::Verdict) -> ExitCode {
    use learn::check::Verdict;
    match verdict {
        Verdict::Passed => ExitCode::SUCCESS,
        Verdict::NoExercise | Verdict::Broken(_) => ExitCode::from(2),
        _ => ExitCode::from(1),
    }
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
    let first = EXERCISES.first().map_or(1, |e| e.number);
    let last = EXERCISES.last().map_or(1, |e| e.number);
    let tip = text.lines().map(str::trim).find(|l| l.starts_with("tip:"));
    if error.kind() == clap::error::ErrorKind::MissingRequiredArgument {
        format!("{message}: the chapter, {first} to {last}, e.g. `check {first}` (see --help)")
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
