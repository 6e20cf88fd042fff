//! The author checks: every exercise as it is handed out fails its check
//! (at its tests, not with a compile error of ours), every chapter's own
//! solution passes it, and the check says one clear thing about each kind
//! of broken step.
//!
//! Every check here builds into the target folder the learner's exercises
//! use, the workspace's own `target/`: the libraries `cargo test` has just
//! compiled are used as they are, and the core is compiled for the
//! exercises once (on a fresh clone, by the first of these tests). The
//! checks also share one lab folder, `target/learn-author-checks/`: an
//! exercise is compiled from scratch once, as its stub, and every later
//! check of it (the solution, each broken variant) is an incremental build
//! of the same crate, a few seconds instead of half a minute. Sharing the
//! folder and the program names, the checks take turns (`LOCK`).
use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::Mutex;
use std::time::Duration;

use learn::exercise::{EXERCISES, Exercise, exercise};
use learn::lab::Lab;
use learn_check::check::{Limits, Verdict, check_with};

mod author;
use author::{author_lab, root};

static LOCK: Mutex<()> = Mutex::new(());

/// A lab in a fresh temporary folder, building into the shared target:
/// for the tests that lay exercises out but never build them.
fn temp_lab() -> (tempfile::TempDir, Lab) {
    let dir = tempfile::tempdir().unwrap();
    let root = root();
    let lab = Lab {
        dir: dir.path().to_owned(),
        ..Lab::in_workspace(&root)
    };
    (dir, lab)
}

/// The one lab every check here builds in (see the top of this file).
/// Lay `exercise` into the author lab afresh, as handed out or solved:
/// whatever an earlier check left in its folder goes first.
fn lay(lab: &Lab, exercise: &Exercise, solved: bool) {
    let folder = lab.folder(exercise);
    if folder.exists() {
        std::fs::remove_dir_all(&folder).unwrap();
    }
    lab.start(exercise, solved).unwrap();
}

/// Short limits: a step that loops is stopped in seconds, not half a minute.
const SHORT: Limits = Limits {
    tests: Duration::from_secs(5),
    render: Duration::from_secs(10),
};

fn check_quietly(lab: &Lab, exercise: &Exercise) -> (Verdict, String) {
    let mut out = Vec::new();
    let verdict = check_with(lab, exercise, SHORT, &mut out);
    (verdict, String::from_utf8_lossy(&out).into_owned())
}

/// Chapter `n`'s solution with `from` replaced by `to` in its step.
fn solution_with(lab: &Lab, n: u8, from: &str, to: &str) -> &'static Exercise {
    let exercise = exercise(n).unwrap();
    lay(lab, exercise, true);
    let lib = lab.folder(exercise).join("src/lib.rs");
    let text = std::fs::read_to_string(&lib).unwrap();
    assert!(
        text.contains(from),
        "the solution of chapter {n} has `{from}`"
    );
    std::fs::write(&lib, text.replacen(from, to, 1)).unwrap();
    exercise
}

#[test]
fn every_exercise_fails_its_check_at_its_tests_and_every_solution_passes() {
    let _turn = LOCK.lock().unwrap_or_else(|e| e.into_inner());
    let lab = author_lab();
    // Passes recorded by an earlier run must not count for this one.
    let _ = std::fs::remove_file(lab.progress_path());
    for exercise in &EXERCISES {
        lay(&lab, exercise, false);
        let (verdict, text) = check_quietly(&lab, exercise);
        assert!(
            matches!(verdict, Verdict::TestsFail { failed, .. } if failed > 0),
            "{exercise}'s exercise must compile and fail its tests, not {verdict:?}:\n{text}"
        );
        assert!(text.contains("✓ it compiles"), "{text}");
        assert!(text.contains("not yet implemented"), "{text}");

        lay(&lab, exercise, true);
        let (verdict, text) = check_quietly(&lab, exercise);
        assert_eq!(verdict, Verdict::Passed, "{exercise}'s solution:\n{text}");
        assert!(text.contains("The reference solution is"), "{text}");
        assert!(!text.contains("Likely mistake"), "{text}");
    }
    let progress = lab.progress();
    assert_eq!(
        progress.passed.len() + progress.named.len(),
        EXERCISES.len(),
        "every pass is recorded"
    );
}

#[test]
fn a_shadow_ray_started_on_the_surface_passes_the_tests_but_not_the_image() {
    let _turn = LOCK.lock().unwrap_or_else(|e| e.into_inner());
    let lab = author_lab();
    let exercise = solution_with(
        &lab,
        2,
        "hit.point + to_sun * surface.epsilon()",
        "hit.point",
    );
    // The tests ask where the feeler goes and what it hits, and pass; the
    // acne shows in the image, and the image is what fails.
    let (verdict, text) = check_quietly(&lab, exercise);
    assert!(
        matches!(verdict, Verdict::Differs(c) if c.within_3 < 0.95),
        "{verdict:?}:\n{text}"
    );
    assert!(
        text.contains("✓ the plane does not shadow itself"),
        "{text}"
    );
}

#[test]
fn a_wrong_image_names_its_worst_pixel_and_writes_three_images() {
    let _turn = LOCK.lock().unwrap_or_else(|e| e.into_inner());
    let lab = author_lab();
    // Chapter 3's tests look at the reflected ray's direction and weight,
    // not where it starts: a mirror ray started on the mirror passes them,
    // and the image shows it.
    let exercise = solution_with(
        &lab,
        3,
        "let origin = hit.point + direction * surface.epsilon();",
        "let origin = hit.point;",
    );
    let (verdict, text) = check_quietly(&lab, exercise);
    assert!(
        matches!(verdict, Verdict::Differs(_)),
        "{verdict:?}:\n{text}"
    );
    assert!(text.contains("worst pixel ("), "{text}");
    assert!(text.contains("--probe="), "{text}");
    for name in ["learner.png", "reference.png", "difference.png"] {
        assert!(
            lab.folder(exercise).join("check").join(name).is_file(),
            "{name}"
        );
    }
}

#[test]
fn a_render_that_makes_nan_is_one_clear_line() {
    let _turn = LOCK.lock().unwrap_or_else(|e| e.into_inner());
    let lab = author_lab();
    // The tests look at the feeler rays, not at the factor returned.
    let exercise = solution_with(
        &lab,
        2,
        "    } else {\n        SUN_LIT",
        "    } else {\n        f32::NAN",
    );
    let (verdict, text) = check_quietly(&lab, exercise);
    assert!(
        matches!(verdict, Verdict::NonFinite(n) if n > 0),
        "{verdict:?}:\n{text}"
    );
    assert!(text.contains("NaN or infinite pixels"), "{text}");
}

#[test]
fn a_step_that_never_ends_is_stopped_at_the_time_limit() {
    let _turn = LOCK.lock().unwrap_or_else(|e| e.into_inner());
    let lab = author_lab();
    let exercise = solution_with(
        &lab,
        1,
        "let cos = hit",
        "loop { std::hint::spin_loop() }\n    #[allow(unreachable_code)]\n    let cos = hit",
    );
    let (verdict, text) = check_quietly(&lab, exercise);
    assert_eq!(verdict, Verdict::TestsTimedOut, "{text}");
    assert!(text.contains("did not finish in 5 s"), "{text}");
}

#[test]
fn an_exercise_that_does_not_compile_shows_the_compiler_and_keeps_the_file() {
    let _turn = LOCK.lock().unwrap_or_else(|e| e.into_inner());
    let lab = author_lab();
    let exercise = solution_with(&lab, 2, "SUN_IN_SHADOW\n", "SUN_IN_SHADOW +\n");
    let lib = lab.folder(exercise).join("src/lib.rs");
    let before = std::fs::read_to_string(&lib).unwrap();
    let (verdict, text) = check_quietly(&lab, exercise);
    assert_eq!(verdict, Verdict::DoesNotCompile, "{text}");
    assert!(
        text.contains("error"),
        "the compiler's message is shown: {text}"
    );
    assert!(text.contains("✗ it does not compile"), "{text}");
    assert_eq!(std::fs::read_to_string(&lib).unwrap(), before);
}

#[test]
fn a_check_never_runs_the_build_of_another_lab() {
    let _turn = LOCK.lock().unwrap_or_else(|e| e.into_inner());
    // A second lab on the same target folder, as the learner's my-lab/ is
    // beside the author lab, with its own version (never the learner's own
    // 0.1.0, so that this test never touches a learner's build either).
    let (_dir, theirs) = temp_lab();
    let theirs = Lab {
        version: "0.1.0-second-lab".to_owned(),
        ..theirs
    };
    let exercise = exercise(1).unwrap();
    theirs.start(exercise, false).unwrap();
    // The author lab builds the solution after the second lab's files were
    // written: the second lab's stub is older than the newest build.
    let ours = author_lab();
    lay(&ours, exercise, true);
    assert_eq!(check_quietly(&ours, exercise).0, Verdict::Passed);
    let (verdict, text) = check_quietly(&theirs, exercise);
    assert!(
        matches!(verdict, Verdict::TestsFail { failed, .. } if failed > 0),
        "the second lab must check its own stub, not the author lab's solution: {verdict:?}\n{text}"
    );
}

#[test]
fn start_never_overwrites_a_learners_file() {
    let (_dir, lab) = temp_lab();
    let exercise = exercise(2).unwrap();
    let first = lab.start(exercise, false).unwrap();
    assert_eq!(first.kept, Vec::<PathBuf>::new());
    let lib = lab.folder(exercise).join("src/lib.rs");
    std::fs::write(&lib, "// my own work\n").unwrap();
    std::fs::remove_file(lab.folder(exercise).join("src/main.rs")).unwrap();
    let again = lab.start(exercise, false).unwrap();
    assert!(again.kept.contains(&PathBuf::from("src/lib.rs")));
    assert_eq!(
        again.written,
        [PathBuf::from("src/main.rs")],
        "only the missing file"
    );
    assert_eq!(std::fs::read_to_string(&lib).unwrap(), "// my own work\n");
}

#[test]
fn an_exercise_is_its_chapter_with_only_the_step_blanked() {
    let (_dir, lab) = temp_lab();
    for exercise in &EXERCISES {
        let files = lab.files(exercise, false).unwrap();
        let lib = &files
            .iter()
            .find(|(p, _)| p == Path::new(exercise.step))
            .unwrap()
            .1;
        let chapter = std::fs::read_to_string(lab.reference_source(exercise)).unwrap();
        // The tests, the doc comments and the step's signature all stay.
        let tests = chapter.find("#[cfg(test)]").unwrap();
        assert!(
            lib.ends_with(&chapter[tests..]),
            "{exercise} keeps its tests"
        );
        assert!(
            !lib.contains("ANCHOR: todo_"),
            "{exercise}: no marker is left"
        );
        let manifest = &files[0].1;
        assert!(manifest.contains(&format!("name = \"{}\"", exercise.package)));
        assert!(manifest.contains("[workspace]"), "its own workspace");
    }
}

/// Run the `learn` program itself.
fn learn(args: &[&str], dir: &Path) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_learn"))
        .args(args)
        .current_dir(dir)
        .output()
        .unwrap()
}

#[test]
fn a_missing_chapter_is_one_line_that_names_it_and_the_choices() {
    let output = learn(&["check"], &root());
    assert_eq!(output.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(stderr.lines().count(), 1, "{stderr}");
    assert!(stderr.contains("<EXERCISE>"), "{stderr}");
    assert!(stderr.contains("ray, camera, sphere"), "{stderr}");
}

#[test]
fn a_chapter_with_no_exercise_is_one_line_and_exit_code_2() {
    let output = learn(&["check", "9"], &root());
    assert_eq!(output.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(stderr.lines().count(), 1, "{stderr}");
    assert!(stderr.contains("there is no exercise `9`"), "{stderr}");
}

#[test]
fn a_missing_exercise_folder_is_one_line_and_exit_code_2() {
    // A copy of the workspace's layout with no my-lab/ at all.
    let dir = tempfile::tempdir().unwrap();
    std::fs::create_dir_all(dir.path().join("crates/learn")).unwrap();
    std::fs::create_dir_all(dir.path().join("chapters")).unwrap();
    std::fs::write(dir.path().join("crates/learn/Cargo.toml"), "").unwrap();
    let output = learn(&["check", "2"], dir.path());
    assert_eq!(output.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(stderr.lines().count(), 1, "{stderr}");
    assert!(stderr.contains("no exercise `2` in my-lab/"), "{stderr}");
    assert!(stderr.contains("start 2"), "{stderr}");
}
