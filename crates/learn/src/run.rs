//! Running cargo and the learner's programs, with a time limit, and
//! reading what they say.

use std::io::Read;
use std::path::Path;
use std::process::{Command, ExitStatus, Stdio};
use std::time::{Duration, Instant};

/// What a finished (or stopped) program printed.
#[derive(Clone, Debug)]
pub struct Output {
    /// `None` if it ran past its time limit and was stopped.
    pub status: Option<ExitStatus>,
    pub stdout: String,
    pub stderr: String,
}

impl Output {
    pub fn timed_out(&self) -> bool {
        self.status.is_none()
    }

    pub fn success(&self) -> bool {
        self.status.is_some_and(|s| s.success())
    }
}

/// Run `command` to its end, or stop it after `limit`. Its output is read
/// on two threads as it comes, so a chatty program never blocks on a full
/// pipe.
pub fn run_with_limit(mut command: Command, limit: Duration) -> std::io::Result<Output> {
    command
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped());
    let mut child = command.spawn()?;
    let stdout = reader(child.stdout.take());
    let stderr = reader(child.stderr.take());
    let start = Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait()? {
            break Some(status);
        }
        if start.elapsed() > limit {
            // Only this child, by its own handle: nothing else is touched.
            let _ = child.kill();
            let _ = child.wait();
            break None;
        }
        std::thread::sleep(Duration::from_millis(5));
    };
    Ok(Output {
        status,
        stdout: stdout.join().unwrap_or_default(),
        stderr: stderr.join().unwrap_or_default(),
    })
}

fn reader(pipe: Option<impl Read + Send + 'static>) -> std::thread::JoinHandle<String> {
    std::thread::spawn(move || {
        let mut bytes = Vec::new();
        if let Some(mut pipe) = pipe {
            let _ = pipe.read_to_end(&mut bytes);
        }
        String::from_utf8_lossy(&bytes).into_owned()
    })
}

/// The cargo that runs us (`cargo run` says which), or the one on `PATH`.
pub fn cargo() -> Command {
    Command::new(std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into()))
}

/// One test of the step, as the harness reported it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TestResult {
    /// The test's full name, as the harness gives it: `tests::a_b_c`.
    pub name: String,
    /// The test's name as a sentence: `tests::a_b_c` → "a b c", or its
    /// title (see [`test_titles`]).
    pub sentence: String,
    pub passed: bool,
    /// Why it failed: the panic's message.
    pub message: Option<String>,
}

/// Read libtest's plain output: one `test NAME ... ok|FAILED` line per
/// test, then a `---- NAME stdout ----` section per failure.
pub fn parse_test_output(stdout: &str) -> Vec<TestResult> {
    let mut results: Vec<(String, TestResult)> = Vec::new();
    for line in stdout.lines() {
        let Some(rest) = line.strip_prefix("test ") else {
            continue;
        };
        let Some((name, verdict)) = rest.split_once(" ... ") else {
            continue;
        };
        let passed = match verdict.trim() {
            "ok" => true,
            "FAILED" => false,
            _ => continue,
        };
        results.push((
            name.to_owned(),
            TestResult {
                name: name.to_owned(),
                sentence: sentence(name),
                passed,
                message: None,
            },
        ));
    }
    for (name, result) in &mut results {
        if !result.passed {
            result.message = failure_message(stdout, name);
        }
    }
    results.into_iter().map(|(_, r)| r).collect()
}

/// `tests::a_surface_facing_away_gets_only_ambient` → its words.
pub fn sentence(name: &str) -> String {
    let last = name.rsplit("::").next().unwrap_or(name);
    last.replace('_', " ")
}

/// The most a failure's message shows: about three lines of a terminal.
pub const MESSAGE_CHARS: usize = 320;

/// `message` cut to [`MESSAGE_CHARS`], at a character boundary, with "…"
/// where it was cut: a test that prints a whole ray log shows its start.
pub fn shortened(message: &str) -> String {
    match message.char_indices().nth(MESSAGE_CHARS) {
        Some((at, _)) => format!("{} …", &message[..at]),
        None => message.to_owned(),
    }
}

/// A test's title: a one-line doc comment just above its `#[test]`,
/// shown instead of its function name's words where those lose what a
/// name cannot spell ("tan 22.5°", not "tan 22 5 degrees"). Read from the
/// `.rs` files under `src`: `(module path, function, title)`.
pub fn test_titles(src: &Path) -> Vec<(String, String, String)> {
    let mut titles = Vec::new();
    let files = crate::lab::rust_files(src, Path::new("")).unwrap_or_default();
    for file in files {
        let Ok(text) = std::fs::read_to_string(src.join(&file)) else {
            continue;
        };
        let module = file
            .with_extension("")
            .to_string_lossy()
            .replace(['/', '\\'], "::");
        let module = match module.as_str() {
            "lib" | "main" => String::new(),
            other => other.strip_suffix("::mod").unwrap_or(other).to_owned(),
        };
        let lines: Vec<&str> = text.lines().map(str::trim).collect();
        for (n, line) in lines.iter().enumerate() {
            let Some(rest) = line.strip_prefix("fn ") else {
                continue;
            };
            let Some(name) = rest.split('(').next() else {
                continue;
            };
            // Up past the attributes to the doc comment.
            let mut above = n;
            let mut tested = false;
            while above > 0 && lines[above - 1].starts_with("#[") {
                tested |= lines[above - 1] == "#[test]";
                above -= 1;
            }
            let is_doc = |i: usize| lines[i].starts_with("///");
            if tested && above > 0 && is_doc(above - 1) && (above < 2 || !is_doc(above - 2)) {
                let title = lines[above - 1].trim_start_matches('/').trim();
                titles.push((module.clone(), name.to_owned(), title.to_owned()));
            }
        }
    }
    titles
}

/// The title of the test the harness calls `name` (`camera::tests::x`,
/// or `tests::x` in a chapter's crate), if it has one.
pub fn title_of(titles: &[(String, String, String)], name: &str) -> Option<String> {
    let function = name.rsplit("::").next()?;
    titles
        .iter()
        .filter(|(_, f, _)| f == function)
        .find(|(module, ..)| module.is_empty() || name.starts_with(&format!("{module}::")))
        .map(|(.., title)| title.clone())
}

/// The panic message of test `name`, from its section of the output.
fn failure_message(stdout: &str, name: &str) -> Option<String> {
    let header = format!("---- {name} stdout ----");
    let section = &stdout[stdout.find(&header)? + header.len()..];
    let mut lines = section.lines().skip_while(|l| !l.contains("panicked at"));
    lines.next()?;
    let message: Vec<&str> = lines
        .take_while(|l| {
            !l.is_empty()
                && !l.starts_with("note:")
                && !l.starts_with("---- ")
                && !l.starts_with("stack backtrace:")
        })
        .collect();
    (!message.is_empty()).then(|| message.join(" "))
}

/// The last panic message in a program's standard error, if it panicked.
pub fn panic_message(stderr: &str) -> Option<String> {
    let mut lines = stderr.lines().skip_while(|l| !l.contains("panicked at"));
    lines.next()?;
    let message: Vec<&str> = lines
        .take_while(|l| {
            !l.is_empty() && !l.starts_with("note:") && !l.starts_with("stack backtrace:")
        })
        .collect();
    Some(message.join(" "))
}

/// `path` relative to `base` if it is inside it: shorter to read.
pub fn shown(path: &Path, base: &Path) -> String {
    path.strip_prefix(base)
        .unwrap_or(path)
        .display()
        .to_string()
}

#[cfg(test)]
mod tests {
    use super::*;

    const HARNESS: &str = "\
running 2 tests
test tests::the_lit_side_of_a_sphere_is_not_shadowed ... ok
test tests::the_plane_does_not_shadow_itself ... FAILED

failures:

---- tests::the_plane_does_not_shadow_itself stdout ----

thread 'tests::the_plane_does_not_shadow_itself' panicked at src/lib.rs:22:5:
not yet implemented: Cast a feeler ray.
note: run with `RUST_BACKTRACE=1` environment variable to display a backtrace


failures:
    tests::the_plane_does_not_shadow_itself

test result: FAILED. 1 passed; 1 failed; 0 ignored; 0 measured; 0 filtered out; finished in 0.00s
";

    #[test]
    fn each_test_is_read_as_a_sentence_with_its_verdict() {
        let results = parse_test_output(HARNESS);
        assert_eq!(results.len(), 2);
        assert_eq!(
            results[0].sentence,
            "the lit side of a sphere is not shadowed"
        );
        assert!(results[0].passed);
        assert!(!results[1].passed);
    }

    #[test]
    fn a_failed_test_carries_its_panic_message() {
        let results = parse_test_output(HARNESS);
        assert_eq!(
            results[1].message.as_deref(),
            Some("not yet implemented: Cast a feeler ray.")
        );
    }

    #[test]
    fn a_test_with_a_one_line_doc_comment_is_shown_by_it() {
        let dir = tempfile::tempdir().unwrap();
        let source = "#[cfg(test)]\nmod tests {\n    /// tan 22.5°, in f32\n    #[test]\n    \
                      fn tan_22_5_degrees() {}\n\n    /// Two lines of doc:\n    /// not a title.\n    \
                      #[test]\n    fn two_lines() {}\n}\n";
        std::fs::write(dir.path().join("camera.rs"), source).unwrap();
        let titles = test_titles(dir.path());
        let title = |name| title_of(&titles, name);
        assert_eq!(
            title("camera::tests::tan_22_5_degrees").as_deref(),
            Some("tan 22.5°, in f32")
        );
        assert_eq!(title("camera::tests::two_lines"), None);
        assert_eq!(
            title("sphere::tests::tan_22_5_degrees"),
            None,
            "another module's"
        );
    }

    #[test]
    fn a_long_message_is_cut_to_a_few_lines() {
        let log = "TracedRay { kind: Primary, depth: 1 }, ".repeat(80);
        let short = shortened(&log);
        assert_eq!(short.chars().count(), MESSAGE_CHARS + 2);
        assert!(short.ends_with(" …"));
        assert_eq!(shortened("left: 1 right: 0"), "left: 1 right: 0");
    }

    #[test]
    fn a_program_that_runs_past_its_limit_is_stopped() {
        let mut sleep = Command::new("sleep");
        sleep.arg("10");
        let start = Instant::now();
        let output = run_with_limit(sleep, Duration::from_millis(200)).unwrap();
        assert!(output.timed_out());
        assert!(start.elapsed() < Duration::from_secs(5));
    }
}
