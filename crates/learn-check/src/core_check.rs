//! `learn check ray` (and every core exercise): the learner's regions of
//! the core, judged by the core's own unit tests of them, then by a chapter
//! rendered with the learner's core against the reference. The build
//! workspace it compiles in is assembled by [`learn::core_lab`].

use std::io::Write;

use learn::core::CoreExercise;
use learn::lab::Lab;
use learn::limits::Limits;

use crate::core_stages::check_core_steps;
use crate::diagnose::after_failure;
use crate::verdict::Verdict;

/// Check one core exercise: its regions, with the learner's core.
pub fn check_core(
    lab: &Lab,
    exercise: &CoreExercise,
    limits: Limits,
    out: &mut dyn Write,
) -> Verdict {
    let verdict = check_core_steps(lab, exercise, limits, out);
    if let Verdict::Broken(why) = &verdict {
        let _ = writeln!(out, "learn: error: {why}");
    }
    after_failure(
        lab,
        exercise.name,
        &verdict,
        &lab.core_check_dir(exercise),
        out,
    );
    verdict
}
