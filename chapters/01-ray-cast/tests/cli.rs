//! The program as a learner runs it: what it writes, and how it refuses bad input.

use std::path::Path;
use std::process::{Command, Output};

fn run(args: &[&str], dir: &Path) -> Output {
    Command::new(env!("CARGO_BIN_EXE_ch01-ray-cast"))
        .args(args)
        .current_dir(dir)
        .output()
        .expect("the chapter program runs")
}

fn files_in(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = walk(dir)
        .into_iter()
        .map(|p| p.strip_prefix(dir).unwrap().display().to_string())
        .collect();
    names.sort();
    names
}

fn walk(dir: &Path) -> Vec<std::path::PathBuf> {
    std::fs::read_dir(dir)
        .unwrap()
        .flat_map(|e| {
            let path = e.unwrap().path();
            if path.is_dir() {
                walk(&path)
            } else {
                vec![path]
            }
        })
        .collect()
}

#[test]
fn by_default_it_writes_its_render_and_diagrams_into_out_and_says_so() {
    let dir = tempfile::tempdir().unwrap();
    let output = run(&["--width", "40", "--height", "30"], dir.path());
    assert!(output.status.success(), "{output:?}");
    let stdout = String::from_utf8(output.stdout).unwrap();
    assert!(
        stdout.contains("40×30, 1 spp, max depth 1: 1,200 rays"),
        "{stdout}"
    );
    assert!(stdout.contains("Mrays/s"), "{stdout}");
    assert!(
        stdout.contains(
            "wrote render.png, depth.png, rays.png, ray-tree.png, probe.txt in out/ch01-ray-cast"
        ),
        "{stdout}"
    );
    let written = [
        "depth.png",
        "probe.txt",
        "ray-tree.png",
        "rays.png",
        "render.png",
    ];
    let expected: Vec<String> = written
        .iter()
        .map(|f| format!("out/ch01-ray-cast/{f}"))
        .collect();
    assert_eq!(files_in(dir.path()), expected);
    let image = image_size(&dir.path().join("out/ch01-ray-cast/render.png"));
    assert_eq!(image, (40, 30));
}

fn image_size(path: &Path) -> (u32, u32) {
    // The PNG header holds the size at bytes 16..24.
    let bytes = std::fs::read(path).unwrap();
    assert_eq!(&bytes[1..4], b"PNG");
    let word = |at: usize| u32::from_be_bytes(bytes[at..at + 4].try_into().unwrap());
    (word(16), word(20))
}

#[test]
fn a_probe_prints_the_ray_tree() {
    let dir = tempfile::tempdir().unwrap();
    let output = run(
        &["--width", "40", "--height", "30", "--probe", "20,20"],
        dir.path(),
    );
    let stdout = String::from_utf8(output.stdout).unwrap();
    assert!(
        stdout.contains("ray tree of pixel (20, 20): 1 ray, colour"),
        "{stdout}"
    );
    assert!(
        stdout.contains("primary (depth 1, weight 1.0000)"),
        "{stdout}"
    );
}

#[test]
fn an_explicit_probe_is_answered_even_when_quiet_and_without_diagrams() {
    let dir = tempfile::tempdir().unwrap();
    let args = ["--width", "40", "--height", "30", "--probe", "20,20"];
    let output = run(
        &[&args[..], &["--quiet", "--no-diagrams"]].concat(),
        dir.path(),
    );
    assert!(output.status.success(), "{output:?}");
    let stdout = String::from_utf8(output.stdout).unwrap();
    assert!(
        stdout.starts_with("ray tree of pixel (20, 20): 1 ray"),
        "--quiet still prints the tree asked for, and only that: {stdout}"
    );
    assert!(!stdout.contains("Mrays/s"), "no summary: {stdout}");
    let out = dir.path().join("out/ch01-ray-cast");
    let probe = std::fs::read_to_string(out.join("probe.txt")).unwrap();
    assert_eq!(probe, stdout, "probe.txt holds what was printed");
    assert_eq!(
        files_in(&out),
        ["probe.txt", "ray-tree.png", "render.png"],
        "--no-diagrams leaves out the heat maps, not the probe"
    );
}

#[test]
fn help_says_what_quiet_and_no_diagrams_do_to_a_probe() {
    let output = run(&["--help"], &std::env::temp_dir());
    let help = String::from_utf8(output.stdout).unwrap();
    assert!(
        help.contains("even with --quiet or --no-diagrams"),
        "{help}"
    );
    assert!(help.contains("--probe-full"), "{help}");
}

#[test]
fn quiet_prints_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let output = run(&["--width", "8", "--height", "8", "--quiet"], dir.path());
    assert!(output.status.success());
    assert!(output.stdout.is_empty() && output.stderr.is_empty());
}

/// Each bad input: exit code 2, one line on stderr naming the flag or path,
/// no panic, and no file written.
#[test]
fn bad_input_gets_one_clear_line_and_exit_code_2() {
    let cases: &[(&[&str], &str)] = &[
        (&["--width", "0"], "--width"),
        (&["--height", "0"], "--height"),
        (&["--width", "16385"], "1..=16384"),
        (&["--width", "-3"], "--width"),
        (&["--width", "lots"], "--width"),
        (
            &["--width", "16384", "--height", "16384"],
            "make the image smaller",
        ),
        (&["--max-depth", "0"], "--max-depth"),
        (&["--max-depth", "65"], "1..=64"),
        (&["--spp", "0"], "a whole number from 1 to 4096"),
        (&["--spp", "5000"], "a whole number from 1 to 4096"),
        (&["--spp", "2.5"], "--spp"),
        (
            &["--pattern", "grid", "--spp", "10"],
            "--pattern grid needs a square number of rays per pixel (m × m), and 10 is not one: \
             try --spp 9 or --spp 16",
        ),
        (
            &["--pattern", "jittered", "--spp", "5"],
            "try --spp 4 or --spp 9",
        ),
        (
            &["--pattern", "nope"],
            "the pattern must be one of grid, jittered, random, halton",
        ),
        (
            &["--seed", "-1"],
            "the seed must be a whole number from 0 to",
        ),
        (&["--seed", "1e3"], "--seed"),
        (&["--epsilon", "NaN"], "--epsilon"),
        (&["--epsilon", "-1"], "from 0 to 0.1"),
        (
            &["--out", "a-file/inside"],
            "cannot use output folder 'a-file/inside'",
        ),
        (&["--widht", "3"], "--width"),
        (
            &["--scene", "missing.toml"],
            "cannot read scene 'missing.toml'",
        ),
        (&["--scene", "a-file"], "a-file:1:"),
        (
            &["--probe", "800,10"],
            "--probe 800,10 is outside the 800×600 image",
        ),
        (&["--probe", "12"], "X,Y"),
        (&["--sweep", "0"], "--sweep"),
        (&["--sweep", "65"], "1..=64"),
    ];
    for (args, expected) in cases {
        let dir = tempfile::tempdir().unwrap();
        std::fs::write(dir.path().join("a-file"), "not a folder").unwrap();
        let output = run(args, dir.path());
        let stderr = String::from_utf8(output.stderr).unwrap();
        assert_eq!(output.status.code(), Some(2), "{args:?}: {stderr}");
        assert_eq!(stderr.lines().count(), 1, "{args:?}: {stderr}");
        assert!(
            stderr.starts_with("ch01-ray-cast: error: "),
            "{args:?}: {stderr}"
        );
        assert!(stderr.contains(expected), "{args:?}: {stderr}");
        assert!(!stderr.contains("panicked"), "{args:?}: {stderr}");
        assert_eq!(files_in(dir.path()), ["a-file"], "{args:?} wrote a file");
    }
}

#[test]
fn help_names_every_flag_with_the_chapters_defaults() {
    let dir = tempfile::tempdir().unwrap();
    let output = run(&["--help"], dir.path());
    assert!(output.status.success());
    let help = String::from_utf8(output.stdout).unwrap();
    for flag in [
        "--width",
        "--height",
        "--max-depth",
        "--spp",
        "--pattern",
        "--seed",
        "--epsilon",
        "--out",
        "--quiet",
    ] {
        assert!(help.contains(flag), "{flag} missing from --help");
    }
    assert!(help.contains("[default: out/ch01-ray-cast]"), "{help}");
    assert!(
        help.contains("jittered where N is a square, else halton"),
        "--help names the default pattern: {help}"
    );
}

/// `--watch`: a save renders again; a bad save keeps watching; Ctrl-C ends it.
#[test]
fn a_watched_scene_is_rendered_again_after_each_save() {
    watched_scene_renders_again(true);
}

/// The same where the file system sends no file events (network shares,
/// some containers): the watch sees the saves by looking.
#[test]
fn a_watched_scene_is_rendered_again_where_no_file_events_arrive() {
    watched_scene_renders_again(false);
}

fn watched_scene_renders_again(file_events: bool) {
    use std::io::{BufRead, BufReader};
    use std::sync::mpsc;
    use std::time::Duration;

    let dir = tempfile::tempdir().unwrap();
    let lab = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../scenes/lab.toml");
    let scene = dir.path().join("scene.toml");
    std::fs::copy(&lab, &scene).unwrap();
    let mut child = Command::new(env!("CARGO_BIN_EXE_ch01-ray-cast"))
        .args([
            "--width",
            "16",
            "--height",
            "12",
            "--no-diagrams",
            "--watch",
            "--scene",
            "scene.toml",
        ])
        .env(
            raylab_cli::saves::EVENTS_VAR,
            if file_events { "on" } else { "off" },
        )
        .current_dir(dir.path())
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    let lines = |stream: Box<dyn std::io::Read + Send>| {
        let (tx, rx) = mpsc::channel();
        std::thread::spawn(move || {
            for line in BufReader::new(stream).lines().map_while(Result::ok) {
                let _ = tx.send(line);
            }
        });
        rx
    };
    let stdout = lines(Box::new(child.stdout.take().unwrap()));
    let stderr = lines(Box::new(child.stderr.take().unwrap()));
    let wait_for = |rx: &mpsc::Receiver<String>, text: &str| loop {
        let line = rx.recv_timeout(Duration::from_secs(20)).expect(text);
        if line.contains(text) {
            break;
        }
    };
    wait_for(&stdout, "watching scene.toml");
    let first = std::fs::read(dir.path().join("out/ch01-ray-cast/render.png")).unwrap();

    // A new colour for the red sphere: a new image.
    let text = std::fs::read_to_string(&scene).unwrap();
    std::fs::write(&scene, text.replace("[0.8, 0.2, 0.15]", "[0.1, 0.2, 0.9]")).unwrap();
    wait_for(&stdout, "rendered scene.toml");
    wait_for(&stdout, "wrote render.png");
    let second = std::fs::read(dir.path().join("out/ch01-ray-cast/render.png")).unwrap();
    assert_ne!(first, second, "the save changed the image");

    // A save that does not parse: one error, the image stays, it keeps watching.
    std::fs::write(&scene, "[camera\n").unwrap();
    wait_for(&stderr, "keeping the last good image");
    assert_eq!(
        std::fs::read(dir.path().join("out/ch01-ray-cast/render.png")).unwrap(),
        second
    );
    std::fs::write(&scene, &text).unwrap();
    wait_for(&stdout, "rendered scene.toml");

    // Ctrl-C: a clean stop.
    let status = Command::new("kill")
        .args(["-INT", &child.id().to_string()])
        .status()
        .unwrap();
    assert!(status.success());
    wait_for(&stdout, "stopped watching");
    assert!(child.wait().unwrap().success());
}

#[test]
fn a_reader_that_stops_reading_does_not_make_it_fail() {
    // As in `ch01-ray-cast | head -0`: standard output is closed before
    // the program prints its summary.
    let dir = tempfile::tempdir().unwrap();
    let mut child = Command::new(env!("CARGO_BIN_EXE_ch01-ray-cast"))
        .args(["--width", "40", "--height", "30", "--no-diagrams"])
        .current_dir(dir.path())
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .expect("the chapter program runs");
    drop(child.stdout.take());
    let output = child.wait_with_output().unwrap();
    let stderr = String::from_utf8(output.stderr).unwrap();
    assert!(output.status.success(), "{:?}: {stderr}", output.status);
    assert!(!stderr.contains("panicked"), "{stderr}");
    assert!(dir.path().join("out/ch01-ray-cast/render.png").exists());
}
