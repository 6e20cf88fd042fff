//! Chapter 8's program is chapter 6's with another renderer: the same
//! flags, the same files, to the byte.

use std::path::Path;
use std::process::Command;

use ch06_path_tracing::run::{parse, run};

fn files_of(program: &ch06_path_tracing::PathProgram, args: &[&str], out: &Path) -> Vec<Vec<u8>> {
    let out_flag = out.to_str().expect("a UTF-8 temporary path");
    let argv = [
        &[program.program.binary][..],
        args,
        &["--out", out_flag, "--quiet"],
    ]
    .concat();
    let (common, flags) = parse(&program.program, argv).expect("the flags parse");
    let report = run(program, &common, &flags).expect("the render is written");
    report
        .written
        .iter()
        .map(|path| std::fs::read(path).expect("a written file"))
        .collect()
}

#[test]
fn chapter_8_writes_chapter_6s_files_to_the_byte() {
    let dir = tempfile::tempdir().unwrap();
    let args = [
        "--width",
        "21",
        "--height",
        "9",
        "--spp",
        "3",
        "--sun-size",
        "5",
        "--caustics",
    ];
    let six = files_of(&ch06_path_tracing::PROGRAM, &args, &dir.path().join("six"));
    let eight = files_of(&ch08_eight_paths::PROGRAM, &args, &dir.path().join("eight"));
    // render.png, render.exr, variance.exr, and five terms as EXR and PNG.
    assert_eq!(six.len(), 13);
    assert!(six == eight, "the files differ");
}

#[test]
fn the_program_names_itself_and_refuses_bad_flags_in_one_line() {
    let dir = tempfile::tempdir().unwrap();
    let program = env!("CARGO_BIN_EXE_ch08-eight-paths");
    let help = Command::new(program).arg("--help").output().unwrap();
    let help = String::from_utf8_lossy(&help.stdout);
    assert!(
        help.contains("ch08-eight-paths")
            && help.contains("--caustics")
            && help.contains("--objects"),
        "{help}"
    );
    let out = dir.path().join("out");
    let bad = Command::new(program)
        .args(["--sun-size", "0", "--out"])
        .arg(&out)
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&bad.stderr);
    assert_eq!(bad.status.code(), Some(2), "{stderr}");
    assert_eq!(stderr.lines().count(), 1, "{stderr}");
    assert!(stderr.starts_with("ch08-eight-paths: error: "), "{stderr}");
    assert!(!out.exists());
}

#[test]
fn with_objects_tree_the_program_writes_the_same_files() {
    let dir = tempfile::tempdir().unwrap();
    let program = env!("CARGO_BIN_EXE_ch08-eight-paths");
    let files = |objects: &str| {
        let out = dir.path().join(objects);
        let status = Command::new(program)
            .args(["--width", "21", "--height", "9", "--spp", "3", "--quiet"])
            .args(["--objects", objects, "--out"])
            .arg(&out)
            .status()
            .unwrap();
        assert!(status.success());
        ["render.png", "render.exr", "variance.exr"]
            .map(|name| std::fs::read(out.join(name)).unwrap())
    };
    assert!(files("list") == files("tree"), "the files differ");
}
