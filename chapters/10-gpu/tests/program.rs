//! The program as a learner runs it: its messages, its exit codes, and
//! `--watch` picking up a saved shader.
//!
//! The tests that render need a GPU adapter (lavapipe will do; CI
//! installs it). Without one they say so and pass, unless `CI` is set.

use std::io::{BufRead, BufReader};
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Output, Stdio};
use std::sync::mpsc;
use std::time::{Duration, Instant};

const BIN: &str = env!("CARGO_BIN_EXE_ch10-gpu");

/// The program, with a private runtime folder for the Vulkan loader and
/// Mesa (without one they print warnings on every run).
fn program(runtime: &Path) -> Command {
    let mut command = Command::new(BIN);
    command.env("XDG_RUNTIME_DIR", runtime);
    command
}

/// A temporary folder, and a private runtime folder inside it.
fn folders() -> (tempfile::TempDir, PathBuf) {
    let dir = tempfile::tempdir().unwrap();
    let runtime = dir.path().join("runtime");
    std::fs::create_dir(&runtime).unwrap();
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        std::fs::set_permissions(&runtime, std::fs::Permissions::from_mode(0o700)).unwrap();
    }
    (dir, runtime)
}

fn stderr(output: &Output) -> String {
    String::from_utf8_lossy(&output.stderr).into_owned()
}

/// Whether the program finds an adapter; when it does not, a note, or a
/// failure under CI.
fn has_adapter(runtime: &Path, out: &Path) -> bool {
    let output = program(runtime)
        .args([
            "--like",
            "ch01",
            "--width",
            "8",
            "--height",
            "8",
            "--no-diagrams",
            "--quiet",
        ])
        .arg("--out")
        .arg(out)
        .output()
        .unwrap();
    if output.status.success() {
        return true;
    }
    let message = stderr(&output);
    assert!(message.contains("no GPU adapter"), "{message}");
    assert!(
        std::env::var_os("CI").is_none(),
        "this test needs a GPU adapter (CI installs lavapipe): {message}"
    );
    eprintln!("this test needs a GPU adapter and found none, so it checked nothing: {message}");
    false
}

fn the_tracer() -> String {
    std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("src/tracer.wgsl")).unwrap()
}

#[test]
fn a_broken_shader_reports_its_line_and_column_and_exit_code_2() {
    let (dir, runtime) = folders();
    let text = the_tracer();
    let (line, _) = text
        .lines()
        .enumerate()
        .find(|(_, l)| l.contains("let t = sqrt(clamp(direction.y, 0.0, 1.0));"))
        .unwrap();
    let broken = text.replace(
        "let t = sqrt(clamp(direction.y, 0.0, 1.0));",
        "let t = sqrt(clamp(foo.y, 0.0, 1.0));",
    );
    let shader = dir.path().join("tracer.wgsl");
    std::fs::write(&shader, broken).unwrap();
    let out = dir.path().join("out");
    let output = program(&runtime)
        .arg("--shader")
        .arg(&shader)
        .arg("--out")
        .arg(&out)
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(2));
    let message = stderr(&output);
    assert_eq!(message.lines().count(), 1, "{message}");
    let place = format!("{}:{}:", shader.display(), line + 1);
    assert!(
        message.starts_with(&format!("ch10-gpu: error: {place}")),
        "{message}"
    );
    assert!(message.contains("foo"), "{message}");
    assert!(!out.join("render.png").exists(), "no image is written");
}

#[test]
fn with_no_adapter_the_program_says_so_in_one_line_and_exits_2() {
    let (dir, runtime) = folders();
    let output = program(&runtime)
        .env("RAYLAB_NO_GPU", "1")
        .arg("--out")
        .arg(dir.path().join("out"))
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(2));
    let message = stderr(&output);
    assert_eq!(message.lines().count(), 1, "{message}");
    assert!(
        message.starts_with("ch10-gpu: error: no GPU adapter found"),
        "{message}"
    );
}

#[test]
fn a_pattern_drawn_per_pixel_or_a_probe_is_refused_in_one_line() {
    let (dir, runtime) = folders();
    for args in [
        &["--spp", "16", "--pattern", "random"][..],
        &["--probe", "1,1"],
        &["--like", "ch09"],
    ] {
        let output = program(&runtime)
            .args(args)
            .arg("--out")
            .arg(dir.path().join("out"))
            .output()
            .unwrap();
        assert_eq!(output.status.code(), Some(2), "{args:?}");
        assert_eq!(stderr(&output).lines().count(), 1, "{}", stderr(&output));
    }
}

#[test]
fn like_ch03_writes_render_png_and_a_summary_with_the_frame_s_parts() {
    let (dir, runtime) = folders();
    let out = dir.path().join("out");
    if !has_adapter(&runtime, &out) {
        return;
    }
    let output = program(&runtime)
        .args([
            "--like",
            "ch03-reflection",
            "--width",
            "64",
            "--height",
            "48",
        ])
        .arg("--out")
        .arg(&out)
        .output()
        .unwrap();
    assert!(output.status.success(), "{}", stderr(&output));
    let text = String::from_utf8_lossy(&output.stdout);
    let summary = text.lines().next().unwrap();
    assert!(
        summary.starts_with("ch10-gpu: 64×48, 1 spp, max depth 10: "),
        "{summary}"
    );
    for part in ["dispatch", "readback", "encoding", "Mrays/s"] {
        assert!(summary.contains(part), "{summary}");
    }
    let image = image::open(out.join("render.png")).unwrap();
    assert_eq!((image.width(), image.height()), (64, 48));
    assert!(out.join("depth.png").exists() && out.join("rays.png").exists());
}

/// Lines of a child's output, as they come.
fn lines_of(output: impl std::io::Read + Send + 'static) -> mpsc::Receiver<String> {
    let (tx, rx) = mpsc::channel();
    std::thread::spawn(move || {
        for line in BufReader::new(output).lines().map_while(Result::ok) {
            if tx.send(line).is_err() {
                break;
            }
        }
    });
    rx
}

/// Wait (at most `limit`) for a line that starts with `start`.
fn wait_for(lines: &mpsc::Receiver<String>, start: &str, limit: Duration) -> Option<String> {
    let deadline = Instant::now() + limit;
    while let Some(left) = deadline.checked_duration_since(Instant::now()) {
        match lines.recv_timeout(left) {
            Ok(line) if line.starts_with(start) => return Some(line),
            Ok(_) => {}
            Err(_) => return None,
        }
    }
    None
}

/// Stops the watching program however the test ends.
struct Stop(Child);

impl Drop for Stop {
    fn drop(&mut self) {
        let _ = self.0.kill();
        let _ = self.0.wait();
    }
}

#[test]
fn watch_renders_again_when_the_shader_is_saved_and_keeps_the_last_good_one() {
    let (dir, runtime) = folders();
    let out = dir.path().join("out");
    if !has_adapter(&runtime, &out) {
        return;
    }
    let shader = dir.path().join("tracer.wgsl");
    let text = the_tracer();
    std::fs::write(&shader, &text).unwrap();
    let child = program(&runtime)
        .args([
            "--watch", "--like", "ch01", "--width", "32", "--height", "24",
        ])
        .arg("--shader")
        .arg(&shader)
        .arg("--out")
        .arg(&out)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut child = Stop(child);
    let lines = lines_of(child.0.stdout.take().unwrap());
    let errors = lines_of(child.0.stderr.take().unwrap());
    let limit = Duration::from_secs(60);
    wait_for(&lines, "watching", limit).expect("the first render, then the watch");
    let first = image::open(out.join("render.png")).unwrap().to_rgb8();

    // A black sky: the top left pixel, sky in the lab scene, goes black.
    let dark = text.replace(
        "return (1.0 - t) * params.horizon + t * params.zenith;",
        "return vec3<f32>(0.0 * t);",
    );
    assert_ne!(dark, text);
    std::fs::write(&shader, &dark).unwrap();
    wait_for(&lines, "[", limit).expect("a render after the save");
    wait_for(&lines, "ch10-gpu: ", limit).expect("its summary");
    let second = image::open(out.join("render.png")).unwrap().to_rgb8();
    assert_ne!(first.get_pixel(0, 0), second.get_pixel(0, 0));
    assert_eq!(second.get_pixel(0, 0).0, [0, 0, 0]);

    // A broken save prints naga's message and keeps the last good shader;
    // the next good save renders again.
    std::fs::write(&shader, dark.replace("0.0 * t", "0.0 * foo")).unwrap();
    let error = wait_for(&errors, "ch10-gpu: error: ", limit).expect("naga's message");
    assert!(error.contains("tracer.wgsl:"), "{error}");
    assert!(error.ends_with("keeping the last good shader"), "{error}");
    std::fs::write(&shader, &text).unwrap();
    wait_for(&lines, "ch10-gpu: ", limit).expect("a render after the fix");
    let third = image::open(out.join("render.png")).unwrap().to_rgb8();
    assert_eq!(third, first);
}
