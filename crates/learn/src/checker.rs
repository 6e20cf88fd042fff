//! `check` and `watch` are a program of their own, `learn-check` (the
//! workspace's `crates/learn-check`), which `learn` builds the first time
//! the learner asks for a check and then hands the command to.
//!
//! Why: a check needs the tracer itself. It renders the reference
//! chapters, reads and writes images and watches files, so the checker
//! links the core, chapters 1 to 6, the command line and the image
//! library, about 120 crates. `list`, `start`, `hint` and `mistakes`
//! need none of them: kept out of `learn`, it compiles in about half a
//! minute on a fresh clone and the learner sees the exercises at once, and
//! the long build comes when there is something to check, after a note
//! that says what it compiles and about how long it takes. Chapter 10's
//! shader check goes one step further the same way: the checker builds
//! the workspace's `ch10-gpu` program, and the GPU stack under it, only
//! for `check shader`.
//!
//! A package of its own rather than an optional feature of `learn`: the
//! learner's command stays `cargo run -p learn -- check NAME` (a feature
//! would have to be typed, or turned on by `learn` calling cargo again,
//! which compiles `learn` a second time with it), and the checker's code
//! is always compiled and tested (`cargo build`, `cargo test` and learn's
//! own author checks use it as a library), never a configuration nobody
//! builds. `learn` runs it in its own place (`exec` on Unix), so the
//! checker's output, its Ctrl-C (`watch`) and its exit code (0 passed, 1
//! not yet, 2 could not check) are the learner's command's.

use std::io::Write;
use std::path::PathBuf;
use std::process::{Command, ExitCode};
use std::time::Instant;

use crate::lab::Lab;
use crate::run::cargo;

/// The checker's package, and its program.
pub const PACKAGE: &str = "learn-check";

/// What `learn` says before it builds the checker for the first time.
pub const BUILD_NOTE: &str = "building the checker, once: the core, chapters 1 to 6 (they \
     draw the reference pictures), the command line and the image library, about 120 crates; \
     about a minute and a half of compiling on a quiet 2-core machine, two or three when it is \
     busy. Later checks start in a fraction of a second …";

/// Where the checker's program is once built: the lab's target folder,
/// as `cargo run` builds it.
pub fn program(lab: &Lab) -> PathBuf {
    lab.target
        .join("debug")
        .join(format!("{PACKAGE}{}", std::env::consts::EXE_SUFFIX))
}

/// Build the checker (after the first time, cargo finds it up to date in
/// a fraction of a second, or rebuilds what changed), then run
/// `learn-check COMMAND NAME` in this process's place: its output, its
/// Ctrl-C and its exit code are the learner's command's.
pub fn run(lab: &Lab, command: &str, name: &str, out: &mut dyn Write) -> Result<ExitCode, String> {
    let program = program(lab);
    let first = !program.is_file();
    let mut build = cargo();
    build
        .arg("build")
        .args(["-p", PACKAGE, "--bin", PACKAGE])
        .arg("--manifest-path")
        .arg(lab.root.join("Cargo.toml"))
        .arg("--target-dir")
        .arg(&lab.target);
    if first {
        // The first build shows cargo's own progress, which is long
        // enough to want it; later ones are silent unless they fail.
        let _ = writeln!(out, "learn: {BUILD_NOTE}");
        let _ = out.flush();
    } else {
        build.arg("--quiet");
    }
    let start = Instant::now();
    let built = build
        .status()
        .map_err(|e| format!("cannot run cargo: {e}"))?;
    if !built.success() {
        return Err(format!(
            "the checker ({PACKAGE}) does not build: cargo's messages are above"
        ));
    }
    if first {
        let seconds = start.elapsed().as_secs();
        let _ = writeln!(
            out,
            "learn: the checker is built (in {} min {:02} s); checking …",
            seconds / 60,
            seconds % 60
        );
        let _ = out.flush();
    }
    let mut checker = Command::new(&program);
    checker.args([command, name]);
    hand_over(checker, &program)
}

/// Run `command` in this process's place (Unix), or as a child whose exit
/// code is ours.
#[cfg(unix)]
fn hand_over(mut command: Command, program: &std::path::Path) -> Result<ExitCode, String> {
    use std::os::unix::process::CommandExt;
    let error = command.exec();
    Err(format!("cannot run {}: {error}", program.display()))
}

#[cfg(not(unix))]
fn hand_over(mut command: Command, program: &std::path::Path) -> Result<ExitCode, String> {
    let status = command
        .status()
        .map_err(|e| format!("cannot run {}: {e}", program.display()))?;
    Ok(status
        .code()
        .and_then(|code| u8::try_from(code).ok())
        .map_or(ExitCode::FAILURE, ExitCode::from))
}
