//! Chapter 6's program: its files, and its refusals (a path tracer has
//! no ray tree: `--probe` and `--sweep` are not its flags).

use std::path::Path;
use std::process::Command;

fn run(args: &[&str], out: &Path) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_ch06-path-tracing"))
        .args(args)
        .arg("--out")
        .arg(out)
        .output()
        .expect("the program runs")
}

#[test]
fn bad_sun_sizes_and_materials_give_one_line_exit_2_and_write_nothing() {
    let dir = tempfile::tempdir().unwrap();
    for args in [
        &["--sun-size", "-1"][..],
        &["--sun-size", "200"],
        &["--sun-size", "0"],
        &["--sun-size", "nan"],
        &["--materials", "nope"],
        &["--sweep", "3"],
        &["--pattern", "jittered", "--spp", "8"],
        &["--probe", "1,1"],
    ] {
        let out = dir.path().join("out");
        let output = run(args, &out);
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert_eq!(output.status.code(), Some(2), "{args:?}: {stderr}");
        assert_eq!(stderr.lines().count(), 1, "{args:?}: {stderr}");
        assert!(stderr.starts_with("ch06-path-tracing: error: "), "{stderr}");
        assert!(!out.exists(), "{args:?} wrote {}", out.display());
        if args == ["--materials", "nope"] {
            assert!(stderr.contains("possible values: lab, fresnel"), "{stderr}");
        }
    }
}

#[test]
fn a_run_writes_the_image_its_variance_and_its_terms_as_exr_and_png() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    let output = run(
        &[
            "--width",
            "16",
            "--height",
            "12",
            "--spp",
            "4",
            "--caustics",
        ],
        &out,
    );
    assert!(
        output.status.success(),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
    let stdout = String::from_utf8_lossy(&output.stdout);
    assert!(
        stdout.contains("M paths/s") && stdout.contains("Mrays/s"),
        "{stdout}"
    );
    for name in ch06_path_tracing::run::TERM_FILES {
        for ext in ["exr", "png"] {
            assert!(out.join(format!("{name}.{ext}")).exists(), "{name}.{ext}");
        }
    }
    let image = ch06_path_tracing::exr::load_exr(&out.join("render.exr")).unwrap();
    let variance = ch06_path_tracing::exr::load_exr(&out.join("variance.exr")).unwrap();
    assert_eq!((image.width(), image.height()), (16, 12));
    assert!(image.is_finite() && variance.is_finite());
    let png = image::open(out.join("render.png")).unwrap().into_rgb8();
    assert_eq!(
        png.as_raw(),
        image.to_srgb8().as_raw(),
        "the PNG is the EXR, encoded"
    );
}
