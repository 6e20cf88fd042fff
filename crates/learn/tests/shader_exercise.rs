//! The author checks of chapter 10's shader exercise: the shader as handed
//! out compiles and fails at chapter 2's shadows, the reference shader
//! pasted back passes every picture, and a known wrong answer to each of
//! the three tasks is caught by the picture that judges it.
//!
//! The checks render on a GPU adapter: any Vulkan one will do, and Mesa's
//! lavapipe runs on the CPU (CI installs it). Without one they say so and
//! pass, unless `CI` is set, as chapter 10's own tests do. Each test lays
//! its shader in a lab of its own (a temporary folder); all of them run
//! the workspace's `ch10-gpu`, which the first check builds in the shared
//! target folder if `cargo test` has not.

use std::path::Path;
use std::time::Duration;

use learn::lab::Lab;
use learn_check::check::{Limits, Verdict};
use learn_check::shader_check::check_shader;

/// A lab in a fresh temporary folder, building into the shared target.
fn temp_lab() -> (tempfile::TempDir, Lab) {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"))
        .ancestors()
        .nth(2)
        .expect("crates/learn/ is inside the workspace")
        .to_owned();
    let dir = tempfile::tempdir().unwrap();
    let lab = Lab {
        dir: dir.path().to_owned(),
        ..Lab::in_workspace(&root)
    };
    (dir, lab)
}

/// Short limits: four small renders take well under a second each.
const SHORT: Limits = Limits {
    tests: Duration::from_secs(10),
    render: Duration::from_secs(20),
};

fn check(lab: &Lab) -> (Verdict, String) {
    let mut out = Vec::new();
    let verdict = check_shader(lab, SHORT, &mut out);
    (verdict, String::from_utf8_lossy(&out).into_owned())
}

/// The reference shader with `from` written as `to`, laid in `lab`.
fn solution_with(lab: &Lab, from: &str, to: &str) {
    lab.start_shader(true).unwrap();
    let file = lab.shader_file();
    let text = std::fs::read_to_string(&file).unwrap();
    assert!(text.contains(from), "the reference shader has `{from}`");
    std::fs::write(&file, text.replacen(from, to, 1)).unwrap();
}

#[test]
fn the_shader_as_handed_out_compiles_and_has_no_shadows() {
    if ch10_gpu::gpu::Gpu::for_tests().is_none() {
        return;
    }
    let (_dir, lab) = temp_lab();
    lab.start_shader(false).unwrap();
    let (verdict, text) = check(&lab);
    assert!(
        matches!(verdict, Verdict::Differs(_)),
        "{verdict:?}:\n{text}"
    );
    assert!(text.contains("✓ it compiles"), "{text}");
    assert!(
        text.contains("like ch02-shadows, the render differs from chapter 2's, which adds the shadows: the feeler (`shadow_feeler`) is not right yet"),
        "{text}"
    );
    assert!(text.contains("worst pixel ("), "{text}");
    assert!(text.contains("--probe="), "{text}");
    for name in ["learner.png", "reference.png", "difference.png"] {
        assert!(lab.shader_check_dir().join(name).is_file(), "{name}");
    }
}

#[test]
fn the_reference_shader_pasted_back_passes_every_picture() {
    if ch10_gpu::gpu::Gpu::for_tests().is_none() {
        return;
    }
    let (_dir, lab) = temp_lab();
    lab.start_shader(true).unwrap();
    let (verdict, text) = check(&lab);
    assert_eq!(verdict, Verdict::Passed, "{text}");
    assert_eq!(text.matches("  ✓ like ").count(), 4, "{text}");
    assert!(text.contains("Done: the shader passes"), "{text}");
    assert!(lab.progress().passed.contains(&10), "the pass is recorded");
}

/// A known wrong answer: the reference's `from` written as `to`, and the
/// picture that must catch it.
struct Wrong {
    what: &'static str,
    from: &'static str,
    to: &'static str,
    caught_by: &'static str,
}

const WRONG: [Wrong; 4] = [
    Wrong {
        what: "a feeler started on the surface (shadow acne)",
        from: "let feeler = hit.point + params.to_sun * params.epsilon;",
        to: "let feeler = hit.point;",
        caught_by: "✗ like ch02-shadows,",
    },
    Wrong {
        what: "a mirror that keeps all of its own colour as well",
        from: "        kept -= r;\n",
        to: "",
        caught_by: "✗ like ch03-reflection,",
    },
    Wrong {
        what: "a refracted share weighted by its parent twice (`push` multiplies it in)",
        from: "transmitted = Pending(hit.point + d * params.epsilon, d, t, 0u, REFRACTED);",
        to: "transmitted = Pending(hit.point + d * params.epsilon, d, t * ray.weight, 0u, REFRACTED);",
        caught_by: "✗ like ch04-refraction,",
    },
    Wrong {
        what: "glass that always refracts, past the critical angle too",
        from: "if all(bent == vec3<f32>(0.0)) {",
        to: "if false {",
        caught_by: "✗ like ch04-refraction on scenes/total-internal-reflection.toml,",
    },
];

#[test]
fn a_known_wrong_answer_to_each_task_is_caught_by_the_picture_that_judges_it() {
    if ch10_gpu::gpu::Gpu::for_tests().is_none() {
        return;
    }
    for wrong in &WRONG {
        let (_dir, lab) = temp_lab();
        solution_with(&lab, wrong.from, wrong.to);
        let (verdict, text) = check(&lab);
        assert!(
            matches!(verdict, Verdict::Differs(_)),
            "{}: {verdict:?}\n{text}",
            wrong.what
        );
        assert!(
            text.contains(wrong.caught_by),
            "{}: no `{}` in\n{text}",
            wrong.what,
            wrong.caught_by
        );
    }
}

#[test]
fn a_mistake_in_the_shader_is_one_line_with_its_line_and_column() {
    // naga's verdict comes before any GPU is looked for: no adapter needed.
    let (_dir, lab) = temp_lab();
    solution_with(&lab, "k = SUN_IN_SHADOW;", "k = SUN_IN_SHADOW + foo;");
    let (verdict, text) = check(&lab);
    assert_eq!(verdict, Verdict::DoesNotCompile, "{text}");
    let line = text
        .lines()
        .find(|l| l.contains("✗ it does not compile: "))
        .unwrap_or_else(|| panic!("{text}"));
    let place = line.split("tracer.wgsl:").nth(1).unwrap_or("");
    let mut numbers = place.split(':').take(2).map(str::parse::<u32>);
    assert!(
        matches!((numbers.next(), numbers.next()), (Some(Ok(_)), Some(Ok(_)))),
        "line and column: {line}"
    );
    assert!(line.contains("`foo`"), "{line}");
}

#[test]
fn a_shader_exercise_not_started_is_one_clear_line() {
    let (_dir, lab) = temp_lab();
    let (verdict, text) = check(&lab);
    assert_eq!(verdict, Verdict::NoExercise);
    assert_eq!(text.lines().count(), 1, "{text}");
    assert!(text.contains("start shader"), "{text}");
}

#[test]
fn start_shader_never_overwrites_a_learners_shader() {
    let (_dir, lab) = temp_lab();
    let first = lab.start_shader(false).unwrap();
    assert_eq!(first.written.len(), 1);
    std::fs::write(lab.shader_file(), "// my own work\n").unwrap();
    let again = lab.start_shader(false).unwrap();
    assert!(again.written.is_empty() && again.kept.len() == 1);
    assert_eq!(
        std::fs::read_to_string(lab.shader_file()).unwrap(),
        "// my own work\n"
    );
}
