//! The check's builds: the learner's exercise (and, for a core exercise,
//! their core) compiled into the shared target folder with cargo, the
//! compiler's messages shown as they are, and what the build made read
//! from cargo's own messages.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use learn::exercise::Exercise;
use learn::lab::Lab;
use learn::run::{cargo, run_with_limit};

use crate::verdict::Verdict;

/// The build's limit: the first build compiles the core (a few minutes on
/// a slow machine); after that a build takes a second or two.
pub const BUILD_TIME_LIMIT: Duration = Duration::from_secs(60 * 60);

/// The programs one build of an exercise made.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Built {
    /// The chapter's program, `chNN-…`.
    pub program: Option<PathBuf>,
    /// The test harness of its library: the step's tests.
    pub tests: Option<PathBuf>,
}

/// Read cargo's `--message-format=json` lines for the executables made.
pub fn built_from_messages(stdout: &str) -> Built {
    let mut built = Built::default();
    for line in stdout.lines() {
        let Ok(message) = serde_json::from_str::<serde_json::Value>(line) else {
            continue;
        };
        if message["reason"] != "compiler-artifact" {
            continue;
        }
        let Some(executable) = message["executable"].as_str() else {
            continue;
        };
        let kinds = message["target"]["kind"]
            .as_array()
            .cloned()
            .unwrap_or_default();
        let is = |kind: &str| kinds.iter().any(|k| k == kind);
        let test = message["profile"]["test"].as_bool() == Some(true);
        if is("lib") && test {
            built.tests = Some(PathBuf::from(executable));
        } else if is("bin") && !test {
            built.program = Some(PathBuf::from(executable));
        }
    }
    built
}

/// Build the exercise's program and test harness in the shared target.
pub(crate) fn build(lab: &Lab, exercise: &Exercise, out: &mut dyn Write) -> Result<Built, Verdict> {
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
