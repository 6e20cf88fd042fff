//! The stages of a core exercise's check in order, without matching a
//! failure with the catalogue of mistakes: [`crate::core_check`] adds that,
//! and the catalogue checks its own mistakes through these.

use std::io::Write;

use learn::core::CoreExercise;
use learn::core_lab::{package_name, program_name};
use learn::lab::{Lab, LabError};
use learn::limits::{HEIGHT, WIDTH};
use learn::run::shown;

use crate::build::{Builds, cargo_build, noted_build};
use crate::picture::{Picture, render_and_compare};
use crate::test_run::run_tests;
use crate::verdict::Verdict;
use learn::limits::Limits;

/// [`check_core`](crate::core_check::check_core) without matching a
/// failure with the catalogue.
pub(crate) fn check_core_quietly(
    lab: &Lab,
    exercise: &CoreExercise,
    limits: Limits,
    out: &mut dyn Write,
) -> Verdict {
    check_core_steps(lab, exercise, limits, out)
}

/// The stages in order: the regions, the core's tests of them, the
/// picture, and a pass recorded.
pub(crate) fn check_core_steps(
    lab: &Lab,
    exercise: &CoreExercise,
    limits: Limits,
    out: &mut dyn Write,
) -> Verdict {
    let here = std::env::current_dir().unwrap_or_default();
    let src = shown(&lab.core_src(), &here);
    if !lab.core_started(exercise) {
        let _ = writeln!(
            out,
            "learn: error: no exercise `{name}` in {src}: make it with `cargo run -p learn -- start {name}`",
            name = exercise.name
        );
        return Verdict::NoExercise;
    }
    let files: Vec<String> = exercise
        .files
        .iter()
        .map(|f| format!("{src}/{f}"))
        .collect();
    let _ = writeln!(
        out,
        "core exercise `{}` ({}), {}:",
        exercise.name,
        exercise.title,
        files.join(" and ")
    );
    let progress = lab.progress();
    if let Err(error) = lab.assemble_core(exercise, &progress.core) {
        return match error {
            LabError::Manifest { path, what } if path.starts_with(lab.core_src()) => {
                let _ = writeln!(out, "  ✗ {}: {what}", shown(&path, &here));
                Verdict::Markers(what)
            }
            error => Verdict::Broken(error.to_string()),
        };
    }
    let build = lab.core_build();
    let manifest = build.join("Cargo.toml");
    let (Some(program), Some(package)) = (
        program_name(exercise.chapter),
        package_name(exercise.chapter),
    ) else {
        return Verdict::Broken(format!("no chapter {} to render", exercise.chapter));
    };
    // Compiler messages name the copy the build compiles; show the
    // learner's file instead (the same lines where the whole file is theirs).
    let shown_as = [(
        "raylab/src/".to_owned(),
        format!("{}/", shown(&lab.core_src(), &here)),
    )];
    // The tests first: when they fail, nothing else needs building, and
    // a failing check after an edit recompiles the core alone. The first
    // time, on top of the libraries the checker's build compiled, this
    // compiles the core twice (the library and its tests) and about ten
    // libraries again: `-p raylab` chooses their features for the core
    // alone, not as the command line does. Building the chapter here too
    // would share them, but would recompile the command line and the
    // chapter before every failing check's tests, seconds each time.
    let note = "compiling the core with your code for its tests, the first time: about half \
                a minute; later checks recompile only what you change …";
    let built = match noted_build(lab, "core-tests", note, out, |out| {
        cargo_build(
            &manifest,
            &lab.target,
            &["-p", "raylab", "--lib", "--tests"],
            &shown_as,
            Builds::Lab,
            out,
        )
    }) {
        Ok(built) => built,
        Err(verdict) => return verdict,
    };
    let Some(tests) = built.tests else {
        return Verdict::Broken("the build made no test harness for the core".into());
    };
    let _ = writeln!(out, "  ✓ it compiles");
    if let Err(verdict) = run_tests(
        &tests,
        &build,
        &build.join("raylab/src"),
        exercise.tests,
        limits.tests,
        out,
    ) {
        return verdict;
    }
    let note = format!(
        "compiling the command line and chapter {} on your core, the first time: seconds …",
        exercise.chapter
    );
    let built = match noted_build(lab, &program, &note, out, |out| {
        cargo_build(
            &manifest,
            &lab.target,
            &["-p", package, "--bin", &program],
            &shown_as,
            Builds::Lab,
            out,
        )
    }) {
        Ok(built) => built,
        Err(verdict) => return verdict,
    };
    let Some(program) = built.program else {
        return Verdict::Broken(format!("the build made no {program}"));
    };
    let picture = Picture {
        number: exercise.chapter,
        package,
        dir: lab.core_check_dir(exercise),
        ..Picture::default()
    };
    let verdict = render_and_compare(&picture, &program, &here, limits.render, out);
    if verdict.passed() {
        let _ = writeln!(
            out,
            "  ✓ chapter {}'s render ({WIDTH}×{HEIGHT}) with your core matches the reference within the lab model's tolerance\n\
             Done: `{}` passes. The reference is in src/ ({}), and the book's {}.",
            exercise.chapter,
            exercise.name,
            exercise.files.join(", "),
            exercise.page(),
        );
        if let Err(error) = lab.record_core_pass(exercise.name) {
            let _ = writeln!(out, "learn: could not record the pass: {error}");
        }
        let _ = writeln!(
            out,
            "{}",
            learn::path::next_line(exercise.name, &lab.progress())
        );
    }
    verdict
}
