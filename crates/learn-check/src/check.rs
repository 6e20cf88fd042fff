//! `learn check N`: does the learner's step compile, pass the chapter's
//! tests, and render the reference image? The chapter's own step and its
//! named exercises (`cosine`, `nee`); the core's are [`crate::core_check`],
//! the shader's [`crate::shader_check`]. Each is the same four stages, one
//! module each: [`crate::build`], [`crate::test_run`], [`crate::picture`]
//! and, when the picture differs, [`crate::report`]; a failure is matched
//! with the catalogue of mistakes by [`crate::diagnose`].

use std::io::Write;

use learn::exercise::Exercise;
use learn::lab::Lab;
pub use learn::limits::Limits;
use learn::limits::{HEIGHT, WIDTH};
use learn::run::shown;

use crate::build::build;
use crate::compare::Comparison;
use crate::diagnose::after_failure;
use crate::noisy::NoiseAgreement;
use crate::picture::{Picture, render_and_compare, render_and_judge};
use crate::test_run::run_tests;

/// Where the check stopped.
#[derive(Clone, Debug, PartialEq)]
pub enum Verdict {
    /// It compiles, its tests pass and its render matches: done.
    Passed,
    NoExercise,
    DoesNotCompile,
    TestsFail {
        failed: usize,
        of: usize,
        /// The failing tests, by their function names (`tests::…`): what
        /// the catalogue of mistakes matches.
        failing: Vec<String>,
        /// Their messages, in the same order.
        messages: Vec<String>,
    },
    TestsTimedOut,
    RenderPanicked(String),
    RenderTimedOut,
    NonFinite(usize),
    Differs(Comparison),
    /// Chapter 6: the render is further from the reference than the two
    /// renders' noise allows.
    NoisyDiffers(NoiseAgreement),
    /// The learner's file lost the marker lines the check needs.
    Markers(String),
    /// Something outside the learner's code went wrong (cargo missing …).
    Broken(String),
}

impl Verdict {
    pub fn passed(&self) -> bool {
        *self == Verdict::Passed
    }
}

/// Check one exercise, writing what it finds to `out` as it goes.
pub fn check(lab: &Lab, exercise: &Exercise, out: &mut dyn Write) -> Verdict {
    check_with(lab, exercise, Limits::DEFAULT, out)
}

/// [`check`] with other time limits (the author checks use short ones).
pub fn check_with(lab: &Lab, exercise: &Exercise, limits: Limits, out: &mut dyn Write) -> Verdict {
    let verdict = check_steps(lab, exercise, limits, true, out);
    if let Verdict::Broken(why) = &verdict {
        let _ = writeln!(out, "learn: error: {why}");
    }
    after_failure(
        lab,
        &exercise.name(),
        &verdict,
        &lab.folder(exercise).join("check"),
        out,
    );
    verdict
}

/// [`check_with`] without matching a failure with the catalogue of
/// mistakes: how the catalogue's own mistakes are checked.
pub(crate) fn check_quietly(
    lab: &Lab,
    exercise: &Exercise,
    limits: Limits,
    out: &mut dyn Write,
) -> Verdict {
    check_steps(lab, exercise, limits, true, out)
}

/// The check without the exercise's tests: build, render, compare. For
/// the author checks, which show that the picture alone catches a wrong
/// answer the tests catch first. A pass is not recorded.
pub fn check_picture_with(
    lab: &Lab,
    exercise: &Exercise,
    limits: Limits,
    out: &mut dyn Write,
) -> Verdict {
    check_steps(lab, exercise, limits, false, out)
}

fn check_steps(
    lab: &Lab,
    exercise: &Exercise,
    limits: Limits,
    with_tests: bool,
    out: &mut dyn Write,
) -> Verdict {
    let folder = lab.folder(exercise);
    let here = std::env::current_dir().unwrap_or_default();
    let name = shown(&folder, &here);
    if !folder.join("Cargo.toml").is_file() || !folder.join("src/lib.rs").is_file() {
        let _ = writeln!(
            out,
            "learn: error: no exercise in {name}: make it with `cargo run -p learn -- start {}`",
            exercise.name()
        );
        return Verdict::NoExercise;
    }
    let _ = writeln!(out, "{exercise}, {name}/{}:", exercise.step);

    let built = match build(lab, exercise, out) {
        Ok(built) => built,
        Err(verdict) => return verdict,
    };
    let (Some(program), Some(tests)) = (built.program, built.tests) else {
        let _ = writeln!(
            out,
            "  ✗ the build made no program or no tests: is src/main.rs still there?"
        );
        return Verdict::DoesNotCompile;
    };
    let _ = writeln!(out, "  ✓ it compiles");

    if with_tests
        && let Err(verdict) =
            run_tests(&tests, &folder, &folder.join("src"), &[], limits.tests, out)
    {
        return verdict;
    }

    let picture = Picture {
        number: exercise.number,
        package: exercise.package,
        flags: exercise.flags,
        dir: folder.join("check"),
        ..Picture::default()
    };
    let verdict = if exercise.judged_statistically() {
        render_and_judge(&picture, &program, &here, limits.render, out)
    } else {
        render_and_compare(&picture, &program, &here, limits.render, out)
    };
    if verdict.passed() && with_tests {
        if !exercise.judged_statistically() {
            let _ = writeln!(
                out,
                "  ✓ its render ({WIDTH}×{HEIGHT}) matches the reference within the lab model's tolerance"
            );
        }
        let _ = writeln!(
            out,
            "Done: {exercise} passes. The reference solution is {} (and the book's {}).",
            shown(&lab.reference_source(exercise), &here),
            shown(&lab.root.join(exercise.page), &here),
        );
        if let Err(error) = lab.record_exercise_pass(exercise) {
            let _ = writeln!(out, "learn: could not record the pass: {error}");
        }
        let _ = writeln!(
            out,
            "{}",
            learn::path::next_line(&exercise.name(), &lab.progress())
        );
    }
    verdict
}
