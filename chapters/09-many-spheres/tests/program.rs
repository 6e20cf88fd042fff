//! Chapter 9's program: `generate-field` prints the field's scene file,
//! and bad input is one line and exit code 2, writing nothing.

use std::process::Command;

use ch09_many_spheres::field::field;

const PROGRAM: &str = env!("CARGO_BIN_EXE_ch09-many-spheres");

#[test]
fn generate_field_prints_the_scene_file_of_that_count_and_seed() {
    let out = Command::new(PROGRAM)
        .args(["generate-field", "40", "--seed", "3"])
        .output()
        .unwrap();
    assert!(out.status.success());
    assert_eq!(String::from_utf8(out.stdout).unwrap(), field(40, 3));
}

#[test]
fn the_shipped_field_of_500_is_generate_field_500_seed_1() {
    let shipped = std::fs::read_to_string("../../scenes/field-500.toml").unwrap();
    assert!(
        shipped == field(500, 1),
        "scenes/field-500.toml is not the generated field"
    );
}

#[test]
fn bad_input_is_one_line_and_exit_code_2() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    for args in [
        &["generate-field", "10001"][..],
        &["generate-field"],
        &["--width", "8", "generate-field", "5"],
        &["--like", "ch06"],
        &["--width", "0"],
    ] {
        let run = Command::new(PROGRAM)
            .args(args)
            .arg("--out")
            .arg(&out)
            .output()
            .unwrap();
        let stderr = String::from_utf8_lossy(&run.stderr);
        assert_eq!(run.status.code(), Some(2), "{args:?}: {stderr}");
        assert_eq!(stderr.lines().count(), 1, "{args:?}: {stderr}");
        assert!(stderr.starts_with("ch09-many-spheres: error: "), "{stderr}");
        assert!(run.stdout.is_empty(), "{args:?}");
    }
    assert!(!out.exists());
}
