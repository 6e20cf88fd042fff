//! `learn check N`: does the learner's step compile, pass the chapter's
//! tests, and render the reference image?

use std::io::Write;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use image::RgbImage;
use raylab::{Camera, Keep, NoProgress, Scene, Step, render};
use raylab_cli::{Chapter, Options};

use crate::compare::{Comparison, GAIN, compare, signed_difference};
use crate::core::CoreExercise;
use crate::core_lab::{package_name, program_name};
use crate::exercise::Exercise;
use crate::lab::Lab;
use crate::noisy::NoiseAgreement;
use crate::run::{
    Built, TestResult, built_from_messages, cargo, panic_message, parse_test_output,
    run_with_limit, shown,
};

/// The check's image size: small enough to render in a blink, large
/// enough that every object, shadow and reflection covers many pixels.
pub const WIDTH: u32 = 160;
pub const HEIGHT: u32 = 120;

/// How long the step's tests may run before the check stops them: far
/// more than they need (milliseconds), so only a step that never ends
/// reaches it.
pub const TEST_TIME_LIMIT: Duration = Duration::from_secs(30);
/// The same for the small render.
pub const RENDER_TIME_LIMIT: Duration = Duration::from_secs(30);
/// The build's limit: the first build compiles the core (a few minutes on
/// a slow machine); after that a build takes a second or two.
pub const BUILD_TIME_LIMIT: Duration = Duration::from_secs(60 * 60);

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

/// How long the tests and the render may run.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Limits {
    pub tests: Duration,
    pub render: Duration,
}

impl Limits {
    pub const DEFAULT: Limits = Limits {
        tests: TEST_TIME_LIMIT,
        render: RENDER_TIME_LIMIT,
    };
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

/// After a failed check: the mistake of the catalogue it matches, or that
/// none does; and for a picture that differs, what it shows.
fn after_failure(
    lab: &Lab,
    name: &str,
    verdict: &Verdict,
    picture_dir: &Path,
    out: &mut dyn Write,
) {
    let matchable = matches!(
        verdict,
        Verdict::TestsFail { .. }
            | Verdict::Differs(_)
            | Verdict::NoisyDiffers(_)
            | Verdict::NonFinite(_)
    );
    // A region still a `todo!` is no mistake: nothing to match.
    let unwritten = matches!(
        verdict,
        Verdict::TestsFail { messages, .. }
            if !messages.is_empty() && messages.iter().all(|m| m.starts_with("not yet implemented"))
    );
    let Some(item) = crate::path::find(name).filter(|_| matchable && !unwritten) else {
        return;
    };
    // Only a picture this check wrote: an older learner.png says nothing.
    let read = |name: &str| {
        matches!(verdict, Verdict::Differs(_))
            .then(|| image::open(picture_dir.join(name)).ok())
            .flatten()
            .map(|image| image.to_rgb8())
    };
    let learner = read("learner.png");
    let prints = crate::mistakes::fingerprints(lab, item, out);
    let shown = learner.as_ref().map_or(
        crate::mistakes::Picture::Unknown,
        crate::mistakes::Picture::Differs,
    );
    let mut diagnosis = crate::mistakes::diagnose(&prints, verdict, shown);
    if diagnosis == crate::mistakes::Diagnosis::Tied
        && let crate::path::Item::Chapter(exercise) = item
    {
        // Mistakes that fail the same tests differ in their pictures:
        // render the learner's too, though its tests failed.
        let _ = std::fs::remove_file(picture_dir.join("learner.png"));
        let mut quiet = Vec::new();
        let picture = check_picture_with(lab, exercise, Limits::DEFAULT, &mut quiet);
        let image = matches!(picture, Verdict::Differs(_))
            .then(|| image::open(picture_dir.join("learner.png")).ok())
            .flatten()
            .map(|image| image.to_rgb8());
        let shown = match &image {
            Some(image) => crate::mistakes::Picture::Differs(image),
            None if picture.passed() => crate::mistakes::Picture::AsReference,
            None => crate::mistakes::Picture::Unknown,
        };
        diagnosis = crate::mistakes::diagnose(&prints, verdict, shown);
    }
    let src = match item {
        crate::path::Item::Core(_) => lab.core_build().join("raylab/src"),
        crate::path::Item::Chapter(exercise) => lab.folder(exercise).join("src"),
        crate::path::Item::Shader => lab.shader_folder().join("src"),
    };
    let titles = crate::run::test_titles(&src);
    let title = |name: &str| {
        crate::run::title_of(&titles, name).unwrap_or_else(|| crate::run::sentence(name))
    };
    crate::mistakes::report(&diagnosis, verdict, &title, out);
    if !matches!(diagnosis, crate::mistakes::Diagnosis::Likely(_))
        && let (Some(learner), Some(reference)) = (&learner, read("reference.png"))
        && let Some(symptom) = crate::mistakes::symptom(learner, &reference)
    {
        let _ = writeln!(
            out,
            "What the picture shows: {symptom}; probe its worst pixel with the commands above, \
             and read {}",
            item.page()
        );
    }
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
            crate::path::next_line(&exercise.name(), &lab.progress())
        );
    }
    verdict
}

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

/// [`check_core`] without matching a failure with the catalogue.
pub(crate) fn check_core_quietly(
    lab: &Lab,
    exercise: &CoreExercise,
    limits: Limits,
    out: &mut dyn Write,
) -> Verdict {
    check_core_steps(lab, exercise, limits, out)
}

fn check_core_steps(
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
            crate::lab::LabError::Manifest { path, what } if path.starts_with(lab.core_src()) => {
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
    // The tests first: when they fail, nothing else needs building.
    // Most of a first check: the core, compiled for its tests, on top of
    // the libraries learn's own build compiled already.
    let note = "compiling the core with your code for its tests, the first time: about a \
                minute on a quiet 2-core machine, two or three when it is busy; later checks \
                recompile only what you change …";
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
            crate::path::next_line(exercise.name, &lab.progress())
        );
    }
    verdict
}

/// Build the exercise's program and test harness in the shared target.
fn build(lab: &Lab, exercise: &Exercise, out: &mut dyn Write) -> Result<Built, Verdict> {
    let folder = lab.folder(exercise);
    // The first build of an exercise compiles the core and the chapters
    // under it for it (the libraries under those come from learn's own
    // build); later ones, only the learner's crate.
    let note = format!(
        "compiling {exercise} with the core and chapters under it, the first time: under a \
         minute on a quiet 2-core machine; later checks recompile only your crate …"
    );
    noted_build(lab, &lab.program_name(exercise), &note, out, |out| {
        cargo_build(
            &folder.join("Cargo.toml"),
            &lab.target,
            &["--all-targets"],
            &[],
            Builds::Lab,
            out,
        )
    })
}

/// A build that takes a while the first time: say what it compiles
/// before it starts, and how long it took after. "The first time" is
/// kept as a stamp in the target folder (`learn-built/KEY-VERSION`),
/// written once the build succeeded: a build that failed, or a target
/// folder cleaned, is first again.
pub(crate) fn noted_build(
    lab: &Lab,
    key: &str,
    note: &str,
    out: &mut dyn Write,
    build: impl FnOnce(&mut dyn Write) -> Result<Built, Verdict>,
) -> Result<Built, Verdict> {
    let stamp = lab
        .target
        .join("learn-built")
        .join(format!("{key}-{}", lab.version));
    let first = !stamp.exists();
    if first {
        let _ = writeln!(out, "  {note}");
        let _ = out.flush();
    }
    let start = Instant::now();
    let built = build(out)?;
    if first {
        if let Some(parent) = stamp.parent() {
            let _ = std::fs::create_dir_all(parent);
        }
        let _ = std::fs::write(&stamp, "built once by `learn check`\n");
        took(start, out);
    }
    Ok(built)
}

/// How long a first build took, when it was long enough to wonder.
pub(crate) fn took(start: Instant, out: &mut dyn Write) {
    let seconds = start.elapsed().as_secs();
    if seconds >= 5 {
        let _ = writeln!(
            out,
            "  (compiled in {} min {:02} s)",
            seconds / 60,
            seconds % 60
        );
    }
}

/// What a [`cargo_build`] compiles, which decides how.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Builds {
    /// The learner's lab, built again after every small edit: incrementally.
    Lab,
    /// The workspace's own program, built as the workspace's build chose.
    Workspace,
}

/// `cargo build` of the workspace at `manifest` into `target`, with the
/// compiler's messages shown as they are, each `(from, to)` of `shown_as`
/// replaced (the learner's files are compiled from a copy).
pub(crate) fn cargo_build(
    manifest: &Path,
    target: &Path,
    args: &[&str],
    shown_as: &[(String, String)],
    builds: Builds,
    out: &mut dyn Write,
) -> Result<Built, Verdict> {
    let mut command = cargo();
    command
        .arg("build")
        .arg("--quiet")
        .args(args)
        .arg("--message-format=json-render-diagnostics")
        .arg("--manifest-path")
        .arg(manifest)
        .arg("--target-dir")
        .arg(target)
        .env("CARGO_TERM_COLOR", "never");
    if builds == Builds::Lab {
        // A check rebuilds the learner's crate after a small edit, which is
        // what incremental compilation is for: a second instead of the
        // whole crate's compile. It is cargo's default for these builds;
        // say so, for environments that turn it off for one-shot builds
        // (CI does).
        command.env("CARGO_INCREMENTAL", "1");
    }
    let output = run_with_limit(command, BUILD_TIME_LIMIT)
        .map_err(|e| Verdict::Broken(format!("cannot run cargo: {e}")))?;
    if output.timed_out() {
        let _ = writeln!(
            out,
            "  ✗ the build took more than {} minutes and was stopped",
            BUILD_TIME_LIMIT.as_secs() / 60
        );
        return Err(Verdict::DoesNotCompile);
    }
    if !output.success() {
        let mut messages = output.stderr.clone();
        for (from, to) in shown_as {
            messages = messages.replace(from, to);
        }
        let _ = write!(out, "{messages}");
        let _ = writeln!(
            out,
            "  ✗ it does not compile: the compiler's messages are above"
        );
        return Err(Verdict::DoesNotCompile);
    }
    Ok(built_from_messages(&output.stdout))
}

/// Run the step's tests (the chapter's own), and list them as sentences.
fn run_tests(
    harness: &Path,
    folder: &Path,
    src: &Path,
    filters: &[&str],
    limit: Duration,
    out: &mut dyn Write,
) -> Result<(), Verdict> {
    let mut command = std::process::Command::new(harness);
    command
        .current_dir(folder)
        .arg("--color=never")
        .args(filters)
        .env("RUST_BACKTRACE", "0");
    let output = run_with_limit(command, limit)
        .map_err(|e| Verdict::Broken(format!("cannot run the tests: {e}")))?;
    if output.timed_out() {
        let _ = writeln!(
            out,
            "  ✗ its tests did not finish in {} s and were stopped: does a loop never end?",
            limit.as_secs_f64()
        );
        return Err(Verdict::TestsTimedOut);
    }
    let mut results = parse_test_output(&output.stdout);
    let titles = crate::run::test_titles(src);
    for result in &mut results {
        if let Some(title) = crate::run::title_of(&titles, &result.name) {
            result.sentence = title;
        }
    }
    let failed: Vec<&TestResult> = results.iter().filter(|r| !r.passed).collect();
    if results.is_empty() || (!output.success() && failed.is_empty()) {
        let why = panic_message(&output.stderr).unwrap_or_else(|| "no test ran".into());
        let _ = writeln!(out, "  ✗ its tests could not run: {why}");
        return Err(Verdict::TestsFail {
            failed: 0,
            of: 0,
            failing: Vec::new(),
            messages: Vec::new(),
        });
    }
    if failed.is_empty() {
        let _ = writeln!(out, "  ✓ its {} tests pass:", results.len());
    } else {
        let _ = writeln!(
            out,
            "  ✗ {} of its {} tests fail:",
            failed.len(),
            results.len()
        );
    }
    // A message is a few lines at most, and the same `todo!` once.
    let mut shown_before: Vec<&str> = Vec::new();
    for result in &results {
        let mark = if result.passed { "✓" } else { "✗" };
        let _ = writeln!(out, "      {mark} {}", result.sentence);
        if let Some(message) = &result.message {
            let todo = message.starts_with("not yet implemented");
            if todo && shown_before.contains(&message.as_str()) {
                let _ = writeln!(out, "          (the same todo! as above)");
            } else {
                let _ = writeln!(out, "          {}", crate::run::shortened(message));
                shown_before.push(message);
            }
        }
    }
    if failed.is_empty() {
        Ok(())
    } else {
        Err(Verdict::TestsFail {
            failed: failed.len(),
            of: results.len(),
            failing: failed.iter().map(|r| r.name.clone()).collect(),
            messages: failed
                .iter()
                .map(|r| r.message.clone().unwrap_or_default())
                .collect(),
        })
    }
}

/// The size flags both renders use.
pub(crate) fn size_flags() -> [String; 2] {
    [format!("--width={WIDTH}"), format!("--height={HEIGHT}")]
}

/// What the picture check renders, and where it writes what it finds.
#[derive(Default)]
pub(crate) struct Picture<'a> {
    /// The chapter whose reference image it is compared with.
    pub number: u8,
    /// That chapter's package, for the reference's probe command.
    pub package: &'a str,
    /// Flags besides the size.
    pub flags: &'a [&'a str],
    /// Where the learner's, the reference's and the difference images go.
    pub dir: PathBuf,
    /// What the mismatch's first line says: "its render (160×120) differs
    /// from the reference" when `None`.
    pub headline: Option<String>,
    /// For a program that traces no single pixel (chapter 10 on the GPU
    /// has no `--probe`): the command that renders the learner's image
    /// again, shown instead of the probe of theirs.
    pub again: Option<String>,
    /// Words in the program's error that mean it cannot run on this
    /// machine at all ("no GPU adapter found"): not the learner's doing.
    pub unavailable: Option<&'a str>,
    /// A scene file to render instead of the lab scene, both the
    /// learner's image and the reference.
    pub scene: Option<PathBuf>,
}

/// Render the learner's program small into `picture.dir/render/`: the
/// folder, or why it made no picture.
fn render_learner(
    picture: &Picture,
    program: &Path,
    limit: Duration,
    out: &mut dyn Write,
) -> Result<PathBuf, Verdict> {
    let scratch = picture.dir.join("render");
    let mut command = std::process::Command::new(program);
    command
        .args(size_flags())
        .args(picture.flags)
        .args(
            picture
                .scene
                .as_ref()
                .map(|f| format!("--scene={}", f.display())),
        )
        .arg("--no-diagrams")
        .arg(format!("--out={}", scratch.display()))
        .env("RUST_BACKTRACE", "0");
    let output = run_with_limit(command, limit)
        .map_err(|e| Verdict::Broken(format!("cannot run {}: {e}", program.display())))?;
    if output.timed_out() {
        let _ = writeln!(
            out,
            "  ✗ its render ({WIDTH}×{HEIGHT}) did not finish in {} s and was stopped: does a loop never end?",
            limit.as_secs_f64()
        );
        return Err(Verdict::RenderTimedOut);
    }
    if !output.success() {
        let why = panic_message(&output.stderr)
            .unwrap_or_else(|| output.stderr.lines().last().unwrap_or("").to_owned());
        if picture.unavailable.is_some_and(|words| why.contains(words)) {
            // The program's own error, without its name: learn says it.
            let why = why
                .split_once(": error: ")
                .map_or(why.as_str(), |(_, rest)| rest);
            return Err(Verdict::Broken(why.to_owned()));
        }
        let _ = writeln!(out, "  ✗ its render stopped: {why}");
        return Err(Verdict::RenderPanicked(why));
    }
    if let Some(n) = non_finite(&output.stdout) {
        let _ = writeln!(
            out,
            "  ✗ its render made {n} NaN or infinite pixels (shown black): a division by zero, \
             or the square root of a negative number?"
        );
        return Err(Verdict::NonFinite(n));
    }
    Ok(scratch)
}

/// Write each `(name, image)` into `dir`, saying which could not be
/// written; whether all were.
pub(crate) fn save_images(images: &[(&str, RgbImage)], dir: &Path, out: &mut dyn Write) -> bool {
    let mut saved = true;
    for (name, image) in images {
        if let Err(e) = raylab_cli::output::save_png(image, &dir.join(name)) {
            let _ = writeln!(out, "      could not write {name}: {e}");
            saved = false;
        }
    }
    saved
}

/// Render the learner's program small and compare it with the reference.
pub(crate) fn render_and_compare(
    picture: &Picture,
    program: &Path,
    here: &Path,
    limit: Duration,
    out: &mut dyn Write,
) -> Verdict {
    let dir = &picture.dir;
    let reference = match reference_image_in(picture.number, picture.scene.as_deref()) {
        Ok(reference) => reference,
        Err(why) => return Verdict::Broken(why),
    };
    let scratch = match render_learner(picture, program, limit, out) {
        Ok(scratch) => scratch,
        Err(verdict) => return verdict,
    };
    let learner = match image::open(scratch.join("render.png")) {
        Ok(image) => image.to_rgb8(),
        Err(e) => return Verdict::Broken(format!("cannot read the render: {e}")),
    };
    let comparison = compare(&learner, &reference);
    if comparison.meets_lab_tolerance() {
        return Verdict::Passed;
    }
    report_difference(
        picture,
        &comparison,
        (&learner, &reference),
        program,
        dir,
        here,
        out,
    );
    Verdict::Differs(comparison)
}

/// Render the learner's path tracer small and judge it against the
/// reference, rendered with the same flags, within their noise.
fn render_and_judge(
    picture: &Picture,
    program: &Path,
    here: &Path,
    limit: Duration,
    out: &mut dyn Write,
) -> Verdict {
    let scratch = match render_learner(picture, program, limit, out) {
        Ok(scratch) => scratch,
        Err(verdict) => return verdict,
    };
    let learner = match crate::noisy::read_render(&scratch) {
        Ok(learner) => learner,
        Err(why) => return Verdict::Broken(why),
    };
    let mut args = vec![ch06_path_tracing::PROGRAM.program.binary.to_owned()];
    args.extend(size_flags());
    args.extend(picture.flags.iter().map(|f| (*f).to_owned()));
    let reference = crate::noisy::reference(args);
    let agreement = crate::noisy::judge(&learner, &reference, &picture.dir, here, out);
    if agreement.passes() {
        let _ = writeln!(
            out,
            "  ✓ its render ({WIDTH}×{HEIGHT}, {}) matches the reference within the two renders' \
             own noise: {:.3} % of pixel channels over {} standard errors (chance allows {} %), \
             mean z {:+.3}, largest |z| {:.1}",
            picture.flags.join(" "),
            agreement.far_share() * 100.0,
            ch06_path_tracing::agreement::FAR,
            crate::noisy::MAX_FAR_SHARE * 100.0,
            agreement.mean_z,
            agreement.worst.map_or(0.0, |w| w.z.abs()),
        );
        Verdict::Passed
    } else {
        Verdict::NoisyDiffers(agreement)
    }
}

/// The mismatch, as `idiff` would put it, with the three images and the
/// probe commands that show the worst pixel's ray trees.
fn report_difference(
    picture: &Picture,
    comparison: &Comparison,
    (learner, reference): (&RgbImage, &RgbImage),
    program: &Path,
    dir: &Path,
    here: &Path,
    out: &mut dyn Write,
) {
    let headline = picture
        .headline
        .clone()
        .unwrap_or_else(|| format!("its render ({WIDTH}×{HEIGHT}) differs from the reference"));
    let _ = writeln!(
        out,
        "  ✗ {headline}: {:.1} % of pixels within 3 of 255 (needs 99.5 %), mean difference {:.2} \
         (needs under 0.5)",
        comparison.within_3 * 100.0,
        comparison.mean
    );
    if let Some(w) = comparison.worst {
        let _ = writeln!(
            out,
            "      worst pixel ({}, {}): yours ({}, {}, {}), the reference ({}, {}, {})",
            w.x,
            w.y,
            w.ours[0],
            w.ours[1],
            w.ours[2],
            w.reference[0],
            w.reference[1],
            w.reference[2]
        );
    }
    let images = [
        ("learner.png", learner.clone()),
        ("reference.png", reference.clone()),
        ("difference.png", signed_difference(learner, reference)),
    ];
    if save_images(&images, dir, out) {
        let _ = writeln!(
            out,
            "      look at {}/learner.png, reference.png and difference.png (red: yours brighter, \
             blue: darker, magnified ×{GAIN})",
            shown(dir, here)
        );
    }
    let Some(w) = comparison.worst else { return };
    let [width, height] = size_flags();
    let package = picture.package;
    let scene = picture
        .scene
        .as_ref()
        .map(|file| format!(" --scene={}", shown(file, here)))
        .unwrap_or_default();
    if let Some(again) = &picture.again {
        let _ = writeln!(
            out,
            "      that pixel's ray tree in the reference: cargo run -p {package} --{scene} {width} \
             {height} --probe={},{} --out={}\n      your render again (the GPU traces no single \
             pixel): {again}",
            w.x,
            w.y,
            shown(&dir.join("probe-reference"), here),
        );
    } else {
        let _ = writeln!(
            out,
            "      that pixel's ray tree, yours:        {} {width} {height} --probe={},{} --out={}\n      \
             and the reference's: cargo run -p {} --{scene} {width} {height} --probe={},{} --out={}",
            shown(program, here),
            w.x,
            w.y,
            shown(&dir.join("probe"), here),
            package,
            w.x,
            w.y,
            shown(&dir.join("probe-reference"), here),
        );
    }
}

/// The count in the summary's "N pixels were NaN or infinite" warning.
fn non_finite(summary: &str) -> Option<usize> {
    let before = summary.split(" pixels were NaN or infinite").next()?;
    if before.len() == summary.len() {
        return None;
    }
    before.rsplit(' ').next()?.parse().ok()
}

/// The reference chapter's render at the check's size.
pub fn reference_image(number: u8) -> RgbImage {
    let lab = (Scene::lab(), Camera::lab());
    match number {
        1 => small_render(&ch01_ray_cast::CHAPTER, &lab),
        2 => small_render(&ch02_shadows::CHAPTER, &lab),
        3 => small_render(&ch03_reflection::CHAPTER, &lab),
        4 => small_render(&ch04_refraction::CHAPTER, &lab),
        5 => small_render(&ch05_antialiasing::CHAPTER, &lab),
        _ => small_path_traced(),
    }
}

/// The reference chapter's render of a scene file (chapters 1–5), or of
/// the lab scene when there is none.
pub fn reference_image_in(number: u8, scene: Option<&Path>) -> Result<RgbImage, String> {
    let Some(file) = scene else {
        return Ok(reference_image(number));
    };
    let scene = raylab_cli::scene_file::load(file).map_err(|e| e.to_string())?;
    Ok(match number {
        1 => small_render(&ch01_ray_cast::CHAPTER, &scene),
        2 => small_render(&ch02_shadows::CHAPTER, &scene),
        3 => small_render(&ch03_reflection::CHAPTER, &scene),
        4 => small_render(&ch04_refraction::CHAPTER, &scene),
        5 => small_render(&ch05_antialiasing::CHAPTER, &scene),
        _ => return Err(format!("chapter {number} renders no scene file in a check")),
    })
}

/// Chapter 6's reference at the check's size and flags (as 8-bit sRGB).
fn small_path_traced() -> RgbImage {
    let mut args = vec![ch06_path_tracing::PROGRAM.program.binary.to_owned()];
    args.extend(size_flags());
    let flags = crate::exercise::exercise(6).map_or(&[][..], |e| e.flags);
    args.extend(flags.iter().map(|f| (*f).to_owned()));
    crate::noisy::reference(args).image.to_srgb8()
}

fn small_render<S: Step>(chapter: &Chapter<S>, (scene, camera): &(Scene, Camera)) -> RgbImage {
    let mut args = vec![chapter.binary.to_owned()];
    args.extend(size_flags());
    let options = Options::parse_for(chapter, args).expect("the check's flags parse");
    let settings = options.settings().expect("the check's size is allowed");
    let rendered = render(
        scene,
        camera,
        &chapter.step,
        &settings,
        Keep::IMAGE,
        &NoProgress,
    );
    rendered.srgb
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_count_of_nan_pixels_is_read_from_the_summary() {
        let line = "ch02-shadows: 160×120 …; WARNING: 37 pixels were NaN or infinite\n";
        assert_eq!(non_finite(line), Some(37));
        assert_eq!(non_finite("ch02-shadows: 160×120, 1 spp\n"), None);
    }

    #[cfg(unix)]
    #[test]
    fn a_program_that_finds_no_gpu_adapter_is_a_check_that_could_not_run() {
        let dir = tempfile::tempdir().unwrap();
        let program = dir.path().join("no-gpu");
        // Written by a shell, not by this process: a file this process
        // held open for writing while another test forked could not be run
        // ("text file busy").
        let script =
            "#!/bin/sh\necho 'ch10-gpu: error: no GPU adapter found (none here)' >&2\nexit 2\n";
        let made = std::process::Command::new("sh")
            .arg("-c")
            .arg(format!(
                "printf '%s' \"$0\" > '{0}' && chmod +x '{0}'",
                program.display()
            ))
            .arg(script)
            .status()
            .unwrap();
        assert!(made.success());
        let picture = Picture {
            number: 2,
            package: "ch02-shadows",
            dir: dir.path().join("check"),
            unavailable: Some("no GPU adapter found"),
            ..Picture::default()
        };
        let mut out = Vec::new();
        let limit = Duration::from_secs(10);
        let verdict = render_and_compare(&picture, &program, dir.path(), limit, &mut out);
        assert_eq!(
            verdict,
            Verdict::Broken("no GPU adapter found (none here)".into())
        );
        assert!(out.is_empty(), "{}", String::from_utf8_lossy(&out));
    }
}
