//! `learn check shader`: does the learner's shader compile, and does it
//! render chapters 2, 3 and 4 as those chapters do?
//!
//! Everything here runs the workspace's own `ch10-gpu` program, built the
//! first time the learner checks the shader: the GPU stack (wgpu, naga)
//! is that program's, never `learn`'s, so that `learn` and every other
//! exercise build without it. The program asks naga (the WGSL compiler
//! inside wgpu) to parse and validate the file before it looks for a GPU,
//! so a mistake is one line with its line and column, on any machine.
//! Then it renders the shader, `--shader` the learner's file, once per
//! [`STAGES`], each in a process of its own under the render's time limit
//! (a shader that never ends is stopped, as a chapter's step is).
//!
//! The reference is each chapter's own render on the CPU, the images the
//! chapters' checks compare with: the shader is meant to be the chapters'
//! tracer, and chapter 10's tests hold the reference shader to those very
//! images within the lab model's tolerance, which covers the GPU's arithmetic.
//! Rendering the reference shader instead would need the GPU twice and
//! would only ever judge the learner against a copy of the same code.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::time::Instant;

use learn::lab::Lab;
use learn::limits::{HEIGHT, WIDTH};
use learn::run::{panic_message, run_with_limit, shown};
use learn::shader::{CHAPTER, NAME, PACKAGE, PAGE, STAGES, Stage};

use crate::build::{Builds, cargo_build, took};
use crate::picture::{Picture, render_and_compare, size_flags};
use crate::verdict::Verdict;
use learn::limits::Limits;

/// The words of chapter 10's error when it finds no GPU adapter.
const NO_ADAPTER: &str = "no GPU adapter found";

/// Check the learner's shader, writing what it finds to `out` as it goes.
pub fn check_shader(lab: &Lab, limits: Limits, out: &mut dyn Write) -> Verdict {
    let verdict = check_steps(lab, limits, out);
    if let Verdict::Broken(why) = &verdict {
        let _ = writeln!(out, "learn: error: {why}");
    }
    verdict
}

fn check_steps(lab: &Lab, limits: Limits, out: &mut dyn Write) -> Verdict {
    let here = std::env::current_dir().unwrap_or_default();
    let file = lab.shader_file();
    let name = shown(&file, &here);
    if !file.is_file() {
        let _ = writeln!(
            out,
            "learn: error: no exercise in {name}: make it with `cargo run -p learn -- start {NAME}`"
        );
        return Verdict::NoExercise;
    }
    let _ = writeln!(out, "chapter {CHAPTER}'s shader, {name}:");

    let program = match build_program(lab, out) {
        Ok(program) => program,
        Err(verdict) => return verdict,
    };
    if let Err(verdict) = validate(lab, &program, &here, limits, out) {
        return verdict;
    }
    let _ = writeln!(out, "  ✓ it compiles (naga parses and validates it)");
    for stage in &STAGES {
        let verdict = render_stage(lab, stage, &program, &here, limits, out);
        if !verdict.passed() {
            return verdict;
        }
        let _ = writeln!(
            out,
            "  ✓ {}, the render ({}×{}) matches chapter {}'s within the lab model's tolerance: {} is \
             right",
            stage.label(),
            WIDTH,
            HEIGHT,
            stage.chapter,
            stage.task
        );
    }
    let _ = writeln!(
        out,
        "Done: the shader passes. The reference is {} (and the book's {}).",
        shown(&lab.shader_reference(), &here),
        shown(&lab.root.join(PAGE), &here),
    );
    if let Err(error) = lab.record_pass(CHAPTER) {
        let _ = writeln!(out, "learn: could not record the pass: {error}");
    }
    let _ = writeln!(out, "{}", learn::path::next_line(NAME, &lab.progress()));
    Verdict::Passed
}

/// The workspace's `ch10-gpu`, built into the lab's target folder: the
/// first check compiles it, and the GPU stack under it; later ones find it
/// up to date.
///
/// It is chosen by `--bin` alone, not `-p`: cargo then turns on the
/// libraries' features as a build of the whole workspace does, and uses
/// what `cargo build` or `cargo test` compiled (after `cargo test`, only
/// `tempfile`, whose features the tests' own dependencies change, and the
/// few crates above it are compiled again). `-p ch10-gpu` would choose
/// features for ch10-gpu's tree alone, and compile the GPU stack again.
fn build_program(lab: &Lab, out: &mut dyn Write) -> Result<PathBuf, Verdict> {
    let binary = format!("{PACKAGE}{}", std::env::consts::EXE_SUFFIX);
    let first = !lab.target.join("debug").join(&binary).exists();
    if first {
        let _ = writeln!(out, "  {}", GPU_BUILD_NOTE);
        let _ = out.flush();
    }
    let start = Instant::now();
    let built = cargo_build(
        &lab.root.join("Cargo.toml"),
        &lab.target,
        &["--bin", PACKAGE],
        &[],
        Builds::Workspace,
        out,
    )
    .map_err(|verdict| match verdict {
        // The program is the workspace's, not the learner's.
        Verdict::DoesNotCompile => Verdict::Broken(format!(
            "the workspace's {PACKAGE} does not build (see above)"
        )),
        other => other,
    })?;
    if first {
        took(start, out);
    }
    built
        .program
        .ok_or_else(|| Verdict::Broken(format!("the build made no {PACKAGE}")))
}

/// What the first shader check says before it builds the program.
pub const GPU_BUILD_NOTE: &str = "building ch10-gpu, the program that compiles and runs your \
     shader, with the GPU stack under it (wgpu, naga, ash and the crates below them) for the \
     first time: several minutes on a 2-core machine; later checks only run it …";

/// Ask the program whether the shader compiles: it parses and validates
/// the file before it looks for a GPU, and says where a mistake is as
/// `FILE:LINE:COLUMN: what`. A one-pixel render, so that a shader that
/// compiles costs next to nothing more; a machine with no GPU adapter is
/// left to the first stage to report.
fn validate(
    lab: &Lab,
    program: &Path,
    here: &Path,
    limits: Limits,
    out: &mut dyn Write,
) -> Result<(), Verdict> {
    let file = lab.shader_file();
    let mut command = std::process::Command::new(program);
    command
        .arg(format!("--shader={}", file.display()))
        .arg(format!("--like={}", STAGES[0].package))
        .args(["--width=1", "--height=1", "--quiet", "--no-diagrams"])
        .arg(format!(
            "--out={}",
            lab.shader_check_dir().join("compile").display()
        ))
        .env("RUST_BACKTRACE", "0");
    let output = run_with_limit(command, limits.render)
        .map_err(|e| Verdict::Broken(format!("cannot run {}: {e}", program.display())))?;
    if output.success() || output.timed_out() {
        return Ok(());
    }
    let why = panic_message(&output.stderr)
        .unwrap_or_else(|| output.stderr.lines().last().unwrap_or("").to_owned());
    let why = why
        .split_once(": error: ")
        .map_or(why.as_str(), |(_, rest)| rest);
    let at_file = format!("{}:", file.display());
    if let Some(rest) = why.strip_prefix(&at_file) {
        let _ = writeln!(
            out,
            "  ✗ it does not compile: {}:{rest}",
            shown(&file, here)
        );
        return Err(Verdict::DoesNotCompile);
    }
    if why.starts_with("cannot read shader") {
        let _ = writeln!(out, "  ✗ {why}");
        return Err(Verdict::DoesNotCompile);
    }
    Ok(())
}

/// Render the shader like one chapter and compare it with that chapter.
fn render_stage(
    lab: &Lab,
    stage: &Stage,
    program: &Path,
    here: &Path,
    limits: Limits,
    out: &mut dyn Write,
) -> Verdict {
    let like = format!("--like={}", stage.package);
    let shader = format!("--shader={}", lab.shader_file().display());
    let flags = [like.as_str(), shader.as_str()];
    let [width, height] = size_flags();
    let dir = lab.shader_check_dir();
    let scene = stage.scene.map(|file| lab.root.join(file));
    let scene_flag = scene
        .as_ref()
        .map(|file| format!(" --scene={}", shown(file, here)))
        .unwrap_or_default();
    let again = format!(
        "cargo run -p {PACKAGE} -- --shader={} {like}{scene_flag} {width} {height} --out={}",
        shown(&lab.shader_file(), here),
        shown(&dir.join("yours"), here),
    );
    let picture = Picture {
        number: stage.chapter,
        package: stage.package,
        flags: &flags,
        dir,
        headline: Some(format!(
            "{}, the render differs from chapter {}'s, which adds {}: {} (`{}`) is not right \
             yet",
            stage.label(),
            stage.chapter,
            stage.shows,
            stage.task,
            stage.region
        )),
        again: Some(again),
        unavailable: Some(NO_ADAPTER),
        scene,
    };
    render_and_compare(&picture, program, here, limits.render, out)
}
