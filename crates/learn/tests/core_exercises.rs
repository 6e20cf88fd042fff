//! The author checks of the core track: every exercise as handed out fails
//! at its own tests, every solution passes its tests and its picture, and
//! a known wrong answer to each is caught, by a test that names it.
//!
//! A core exercise is checked by building a whole core, and the core is
//! the slowest thing here to compile, so the checks share builds: each
//! phase lays the same kind of file for every exercise at once and marks
//! every exercise passed, so that the core the check assembles is the
//! same for all of them (the learner's regions everywhere) and is built
//! once per phase, not once per exercise. The lab is the chapters' author
//! lab, `target/learn-author-checks/`, with its own package version.

use std::path::{Path, PathBuf};
use std::sync::Mutex;
use std::time::Duration;

use learn::core::{CORE_EXERCISES, CoreExercise};
use learn::lab::Lab;
use learn_check::check::{Limits, Verdict};
use learn_check::core_check::check_core;

static LOCK: Mutex<()> = Mutex::new(());

fn author_lab() -> Lab {
    let root: PathBuf = Path::new(env!("CARGO_MANIFEST_DIR"))
        .ancestors()
        .nth(2)
        .expect("crates/learn/ is inside the workspace")
        .to_owned();
    let lab = Lab::in_workspace(&root);
    Lab {
        dir: lab.target.join("learn-author-checks"),
        version: "0.1.0-author-checks".to_owned(),
        ..lab
    }
}

const SHORT: Limits = Limits {
    tests: Duration::from_secs(10),
    render: Duration::from_secs(20),
};

/// Lay every core exercise afresh, as handed out or solved, with every
/// one of them marked passed: the check then takes every region from the
/// lab's files, and all the checks of a phase share one build.
fn lay_all(lab: &Lab, solved: bool) {
    let src = lab.core_src();
    if src.exists() {
        std::fs::remove_dir_all(&src).unwrap();
    }
    let _ = std::fs::remove_file(lab.progress_path());
    for exercise in &CORE_EXERCISES {
        lab.start_core(exercise, solved).unwrap();
    }
    for exercise in &CORE_EXERCISES {
        lab.record_core_pass(exercise.name).unwrap();
    }
}

fn check(lab: &Lab, exercise: &CoreExercise) -> (Verdict, String) {
    let mut out = Vec::new();
    let verdict = check_core(lab, exercise, SHORT, &mut out);
    (verdict, String::from_utf8_lossy(&out).into_owned())
}

/// The task text of a region, as its `todo!` says it.
fn task_of(lab: &Lab, exercise: &CoreExercise, region: &str) -> String {
    for file in exercise.files {
        let source = std::fs::read_to_string(lab.root.join("src").join(file)).unwrap();
        if let Some(task) = learn::exercise::blank(&source)
            .unwrap()
            .tasks
            .into_iter()
            .find(|t| t.name == region)
        {
            return task.text;
        }
    }
    panic!("no region {region}");
}

#[test]
fn every_core_solution_passes_its_tests_and_its_picture() {
    let _turn = LOCK.lock().unwrap_or_else(|e| e.into_inner());
    let lab = author_lab();
    lay_all(&lab, true);
    for exercise in &CORE_EXERCISES {
        let (verdict, text) = check(&lab, exercise);
        assert_eq!(verdict, Verdict::Passed, "`{}`:\n{text}", exercise.name);
        assert!(
            text.contains("with your core matches the reference"),
            "{text}"
        );
    }
}

#[test]
fn every_core_stub_compiles_and_fails_at_its_own_tests() {
    let _turn = LOCK.lock().unwrap_or_else(|e| e.into_inner());
    let lab = author_lab();
    lay_all(&lab, false);
    for exercise in &CORE_EXERCISES {
        let (verdict, text) = check(&lab, exercise);
        assert!(
            matches!(verdict, Verdict::TestsFail { failed, .. } if failed > 0),
            "`{}` must compile and fail its tests, not {verdict:?}:\n{text}",
            exercise.name
        );
        assert!(text.contains("✓ it compiles"), "{text}");
        // Its own stub is what fails, not another exercise's.
        let own = exercise.regions.iter().any(|region| {
            text.contains(&format!(
                "not yet implemented: {}",
                task_of(&lab, exercise, region)
            ))
        });
        assert!(own, "`{}` fails at its own todo:\n{text}", exercise.name);
    }
}

/// A known wrong answer to each exercise: the solution's `from` written
/// as `to`, the test that must catch it, and what its failure must say.
struct Wrong {
    exercise: &'static str,
    file: &'static str,
    from: &'static str,
    to: &'static str,
    caught_by: &'static str,
    saying: &'static str,
}

/// The wrong answers, one to each exercise, laid all at once.
const FIRST: [Wrong; 9] = [
    Wrong {
        exercise: "ray",
        file: "ray.rs",
        from: "self.origin + t * self.direction",
        to: "self.origin + self.direction",
        caught_by: "✗ a point along a ray is origin plus t times direction",
        saying: "left: Vec3A(2.0, 2.0, 3.0)",
    },
    Wrong {
        exercise: "camera",
        file: "camera.rs",
        from: "let y = (1.0 - 2.0 * (j as f32 + sy) / h) * self.half_height;",
        to: "let y = (2.0 * (j as f32 + sy) / h - 1.0) * self.half_height;",
        caught_by: "✗ row 0 is the top of the image and column 0 its left",
        saying: "row 0 must look up",
    },
    Wrong {
        exercise: "sphere",
        // `t0` even when the ray starts inside, where it lies behind.
        file: "sphere.rs",
        from: "if t0 > 0.0 {",
        to: "if t0 != 0.0 {",
        caught_by: "✗ a ray from inside hits the far side",
        saying: "left: Some(-1.0)",
    },
    Wrong {
        exercise: "plane",
        // Truncation instead of `floor`.
        file: "plane.rs",
        from: "let s = point.x.floor() + point.z.floor();",
        to: "let s = (point.x as i32 + point.z as i32) as f32;",
        caught_by: "✗ the checker squares either side of the origin differ",
        saying: "right: Vec3A(0.0, 0.0, 0.0)",
    },
    Wrong {
        exercise: "sky",
        file: "light.rs",
        from: "let t = d.y.clamp(0.0, 1.0).sqrt();",
        to: "let t = d.y.clamp(0.0, 1.0);",
        caught_by: "✗ the sky a quarter up is half way between",
        saying: "",
    },
    Wrong {
        exercise: "srgb",
        // Round half to even, as some languages' `round` does.
        file: "srgb.rs",
        from: "(255.0 * v).round() as u8",
        to: "(255.0 * v).round_ties_even() as u8",
        caught_by: "✗ a level exactly half way rounds away from zero",
        saying: "left: 2",
    },
    Wrong {
        exercise: "reflect",
        file: "optics.rs",
        from: "d - 2.0 * d.dot(n) * n",
        to: "d - d.dot(n) * n",
        caught_by: "✗ reflecting at 45° turns down into up",
        saying: "",
    },
    Wrong {
        exercise: "refract",
        // No test for total internal reflection: √k of a negative k.
        file: "optics.rs",
        from: "if k < 0.0 {\n        return None;\n    }",
        to: "",
        caught_by: "✗ leaving glass beyond the critical angle is total internal reflection",
        saying: "left: Some(Vec3A(NaN, NaN, NaN))",
    },
    Wrong {
        exercise: "stack",
        // A loop that pops before anything was pushed.
        file: "trace.rs",
        from: "self.stack.push(PendingRay {\n            ray: primary,",
        to: "let _never_pushed = (PendingRay {\n            ray: primary,",
        caught_by: "✗ a primary ray that meets nothing sees the sky with weight 1",
        saying: "push the primary ray with weight 1 before the first pop",
    },
];

/// More wrong answers, laid at once in a second build: the aspect ratio,
/// a tangent, one side of the plane, the sky below the horizon, and the
/// weights of the ray stack.
const SECOND: [Wrong; 5] = [
    Wrong {
        exercise: "camera",
        file: "camera.rs",
        from: "* self.half_height * aspect;",
        to: "* self.half_height;",
        caught_by: "✗ a twice as wide image reaches twice as far to the side as up",
        saying: "not −2h",
    },
    Wrong {
        exercise: "sphere",
        file: "sphere.rs",
        from: "if disc < 0.0 {",
        to: "if disc <= 0.0 {",
        caught_by: "✗ a tangent ray touches the sphere once",
        saying: "right: Some(5.0)",
    },
    Wrong {
        exercise: "plane",
        // A plane that is only hit from above.
        file: "plane.rs",
        from: "if denom.abs() < 1e-8 {",
        to: "if denom > -1e-8 {",
        caught_by: "✗ a ray from below the ground meets it from underneath",
        saying: "right: Some(1.0)",
    },
    Wrong {
        exercise: "sky",
        // The square root of a negative height below the horizon.
        file: "light.rs",
        from: "let t = d.y.clamp(0.0, 1.0).sqrt();",
        to: "let t = d.y.sqrt();",
        caught_by: "✗ the sky at the horizon is the horizon colour",
        saying: "NaN",
    },
    Wrong {
        exercise: "stack",
        // A ray's weight is its share alone, not its parent's weight times it.
        file: "trace.rs",
        from: "weight: pending.weight * secondary.share,",
        to: "weight: secondary.share,",
        caught_by: "✗ each bounce carries its parent's weight times its share",
        saying: "Vec3A(1.0, 1.0, 1.0)",
    },
];

#[test]
fn a_known_wrong_answer_to_each_core_exercise_is_caught_by_the_test_that_names_it() {
    let _turn = LOCK.lock().unwrap_or_else(|e| e.into_inner());
    let lab = author_lab();
    for batch in [&FIRST[..], &SECOND[..]] {
        lay_all(&lab, true);
        for wrong in batch {
            let path = lab.core_src().join(wrong.file);
            let text = std::fs::read_to_string(&path).unwrap();
            assert!(
                text.contains(wrong.from),
                "{}: `{}`",
                wrong.file,
                wrong.from
            );
            std::fs::write(&path, text.replacen(wrong.from, wrong.to, 1)).unwrap();
        }
        for wrong in batch {
            caught(&lab, wrong);
        }
    }
}

/// Check `wrong`'s exercise and see the expected test fail as expected.
fn caught(lab: &Lab, wrong: &Wrong) {
    let exercise = CORE_EXERCISES
        .iter()
        .find(|e| e.name == wrong.exercise)
        .unwrap();
    let (verdict, text) = check(lab, exercise);
    assert!(
        matches!(verdict, Verdict::TestsFail { .. }),
        "`{}`: {verdict:?}\n{text}",
        wrong.exercise
    );
    let after = text
        .split_once(wrong.caught_by)
        .unwrap_or_else(|| panic!("`{}`: no `{}` in\n{text}", wrong.exercise, wrong.caught_by))
        .1;
    let message = after.lines().nth(1).unwrap_or("");
    assert!(
        message.contains(wrong.saying),
        "`{}`: the failure says `{message}`, not `{}`",
        wrong.exercise,
        wrong.saying
    );
}

#[test]
fn a_core_exercise_not_started_is_one_clear_line() {
    let dir = tempfile::tempdir().unwrap();
    let lab = Lab {
        dir: dir.path().to_owned(),
        ..author_lab()
    };
    let mut out = Vec::new();
    let verdict = check_core(&lab, &CORE_EXERCISES[0], SHORT, &mut out);
    let text = String::from_utf8_lossy(&out);
    assert_eq!(verdict, Verdict::NoExercise);
    assert_eq!(text.lines().count(), 1, "{text}");
    assert!(text.contains("start ray"), "{text}");
}
