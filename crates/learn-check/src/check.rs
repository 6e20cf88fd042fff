//! `learn check N`: does the learner's step compile, pass the chapter's
//! tests, and render the reference image? The chapter's own step and its
//! named exercises (`cosine`, `nee`); the core's are [`crate::core_check`],
//! the shader's [`crate::shader_check`]. Each is the same four stages, one
//! module each: [`crate::build`], [`crate::test_run`], [`crate::picture`]
//! and, when the picture differs, [`crate::picture::report`]; a failure is matched
//! with the catalogue of mistakes by [`crate::diagnose`]. The stages in
//! order are [`crate::chapter_stages`]'s: the catalogue's own mistakes
//! are checked through them, without a diagnosis.

use std::io::Write;

use learn::exercise::Exercise;
use learn::lab::Lab;
pub use learn::limits::Limits;

pub use crate::chapter_stages::check_picture_with;
use crate::chapter_stages::check_steps;
use crate::diagnose::after_failure;
pub use crate::verdict::Verdict;

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
