//! Running the exercise's tests: the harness its build made, under a time
//! limit, each test listed as the sentence its name (or its title) says.

use std::io::Write;
use std::path::Path;
use std::time::Duration;

use learn::run::{TestResult, panic_message, parse_test_output, run_with_limit};

use crate::verdict::Verdict;

/// Run the step's tests (the chapter's own), and list them as sentences.
pub(crate) fn run_tests(
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
    let titles = learn::run::test_titles(src);
    for result in &mut results {
        if let Some(title) = learn::run::title_of(&titles, &result.name) {
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
                let _ = writeln!(out, "          {}", learn::run::shortened(message));
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
