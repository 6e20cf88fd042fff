//! The stages of a chapter's check in order (build, tests, picture), and
//! the pass recorded, without matching a failure with the catalogue of
//! mistakes: [`crate::check`] adds that, and the catalogue checks its own
//! mistakes through these.

use std::io::Write;

use learn::exercise::Exercise;
use learn::lab::Lab;
use learn::limits::{HEIGHT, Limits, WIDTH};
use learn::run::shown;

use crate::build::build;
use crate::picture::{Picture, render_and_compare, render_and_judge};
use crate::test_run::run_tests;
use crate::verdict::Verdict;

/// [`check_with`](crate::check::check_with) without matching a failure
/// with the catalogue of mistakes: how the catalogue's own mistakes are
/// checked.
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

/// The stages in order: build, the tests (`with_tests`), the picture,
/// and a pass recorded.
pub(crate) fn check_steps(
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
