//! The author checks of the catalogue of mistakes: every catalogued
//! mistake, made in the exercise as a learner would make it, is named as
//! itself by `check`, and correct answers written differently from the
//! reference get no `Likely mistake` line.
//!
//! They build in the author lab the other author checks use
//! (`target/learn-author-checks/`), so each check is an incremental build
//! of an exercise compiled once; the fingerprints are learnt once, in
//! `target/learn-mistakes/`, and kept there for every later run.

use std::path::{Path, PathBuf};
use std::sync::Mutex;
use std::time::Duration;

use learn::core::CORE_EXERCISES;
use learn::lab::Lab;
use learn::mistakes::{MISTAKES, Mistake, made_in, source_file};
use learn::path::{Item, find};
use learn_check::check::{Limits, Verdict, check_with};
use learn_check::core_check::check_core;

mod author;
use author::author_lab;

static LOCK: Mutex<()> = Mutex::new(());

const SHORT: Limits = Limits {
    tests: Duration::from_secs(20),
    render: Duration::from_secs(30),
};

/// The reference file of `exercise` that holds `region`, with `from`
/// written as `to` in that region (markers kept).
fn wrong_source(lab: &Lab, mistake: &Mistake) -> (PathBuf, String) {
    let file = source_file(&lab.root, mistake).expect("the mistake's file");
    let text = std::fs::read_to_string(lab.root.join(&file)).unwrap();
    let wrong = made_in(&text, mistake).unwrap_or_else(|| {
        panic!(
            "{} {}: no `{}`",
            mistake.exercise, mistake.slug, mistake.from
        )
    });
    (file, wrong)
}

/// Check the exercise `name` with its reference file `file` replaced by
/// `text` (with markers), in the author lab.
fn check_with_source(lab: &Lab, name: &str, file: &Path, text: &str) -> (Verdict, String) {
    let mut out = Vec::new();
    let verdict = match find(name).unwrap() {
        Item::Core(core) => {
            let src = lab.core_src();
            if src.exists() {
                std::fs::remove_dir_all(&src).unwrap();
            }
            let _ = std::fs::remove_file(lab.progress_path());
            for exercise in &CORE_EXERCISES {
                lab.start_core(exercise, true).unwrap();
                lab.record_core_pass(exercise.name).unwrap();
            }
            std::fs::write(src.join(file.file_name().unwrap()), text).unwrap();
            check_core(lab, core, SHORT, &mut out)
        }
        Item::Chapter(chapter) => {
            let folder = lab.folder(chapter);
            if folder.exists() {
                std::fs::remove_dir_all(&folder).unwrap();
            }
            lab.start(chapter, true).unwrap();
            let solved = learn::exercise::blank_only(text, |_| false).unwrap();
            std::fs::write(folder.join(chapter.step), solved.exercise).unwrap();
            check_with(lab, chapter, SHORT, &mut out)
        }
        Item::Shader => unreachable!("no shader mistakes are catalogued"),
    };
    (verdict, String::from_utf8_lossy(&out).into_owned())
}

#[test]
fn every_catalogued_mistake_is_named_as_itself_by_check() {
    let _turn = LOCK.lock().unwrap_or_else(|e| e.into_inner());
    let lab = author_lab();
    for mistake in &MISTAKES {
        let (file, wrong) = wrong_source(&lab, mistake);
        let (verdict, text) = check_with_source(&lab, mistake.exercise, &file, &wrong);
        assert!(
            !verdict.passed(),
            "{} {}:\n{text}",
            mistake.exercise,
            mistake.slug
        );
        let line = format!("Likely mistake: {} — {}; see ", mistake.slug, mistake.what);
        assert!(
            text.contains(&line),
            "`{}` {}: no `{line}` in\n{text}",
            mistake.exercise,
            mistake.slug
        );
        assert_eq!(text.matches("Likely mistake:").count(), 1, "{text}");
    }
}

/// Correct answers written otherwise than the reference: the exercise,
/// and in its reference file `from` written as `to`.
const CORRECT_VARIANTS: [(&str, &str, &str); 5] = [
    (
        "2",
        "hit.point + to_sun * surface.epsilon()",
        "hit.point + hit.facing_normal * surface.epsilon()",
    ),
    (
        "3",
        "let direction = reflect(ray.direction, hit.facing_normal).normalize();",
        "let n = hit.facing_normal;\n        let direction = (ray.direction - 2.0 * ray.direction.dot(n) * n).normalize();",
    ),
    (
        "4",
        "let eta = if hit.entering { 1.0 / ior } else { ior };",
        "let eta = if !hit.entering { ior } else { ior.recip() };",
    ),
    (
        "refract",
        "    if k < 0.0 {\n        return None;\n    }\n    Some(eta * i - (eta * cos_i + k.sqrt()) * n)",
        "    (k >= 0.0).then(|| eta * i - (eta * cos_i + k.sqrt()) * n)",
    ),
    (
        "stack",
        "        self.len = self.len.checked_sub(1)?;\n        Some(self.rays[self.len])",
        "        if self.len == 0 {\n            return None;\n        }\n        self.len -= 1;\n        Some(self.rays[self.len])",
    ),
];

#[test]
fn the_reference_and_a_correct_answer_written_differently_get_no_likely_mistake() {
    let _turn = LOCK.lock().unwrap_or_else(|e| e.into_inner());
    let lab = author_lab();
    for (name, from, to) in CORRECT_VARIANTS {
        let region = MISTAKES
            .iter()
            .find(|m| m.exercise == name)
            .expect("an exercise with mistakes");
        let file = source_file(&lab.root, region).unwrap();
        let reference = std::fs::read_to_string(lab.root.join(&file)).unwrap();
        assert!(reference.contains(from), "`{name}`: `{from}`");
        for text in [reference.clone(), reference.replacen(from, to, 1)] {
            let (verdict, out) = check_with_source(&lab, name, &file, &text);
            assert_eq!(verdict, Verdict::Passed, "`{name}`:\n{out}");
            assert!(!out.contains("Likely mistake"), "`{name}`:\n{out}");
        }
    }
}
