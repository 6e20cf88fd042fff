//! Scene files: `scenes/lab.toml` is the lab scene in every chapter, and
//! the other scenes render cleanly.

use std::path::{Path, PathBuf};

use raylab::Step;
use raylab_cli::{Chapter, Report};

fn scene(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../scenes")
        .join(name)
}

/// Render a chapter at 96 × 72 with extra flags, without diagrams.
fn run_small<S: Step>(chapter: &Chapter<S>, dir: &Path, extra: &[&str]) -> Report {
    let mut flags = vec!["--no-diagrams"];
    flags.extend_from_slice(extra);
    let report = raylab_tests::run_chapter(chapter, (96, 72), dir, &flags);
    assert_eq!(report.rendered.non_finite, 0);
    assert_eq!(report.rendered.over_budget, 0);
    report
}

/// The 8-bit image such a run wrote.
fn render_png<S: Step>(chapter: &Chapter<S>, dir: &Path, extra: &[&str]) -> image::RgbImage {
    let report = run_small(chapter, dir, extra);
    image::open(&report.render_png).unwrap().to_rgb8()
}

#[test]
fn lab_toml_reproduces_the_default_image_of_every_chapter() {
    let dir = tempfile::tempdir().unwrap();
    let lab = scene("lab.toml");
    let lab = lab.to_str().unwrap();
    fn same<S: Step>(chapter: &Chapter<S>, dir: &Path, lab: &str) {
        let built_in = render_png(chapter, dir, &[]);
        let from_file = render_png(chapter, dir, &["--scene", lab]);
        assert_eq!(built_in, from_file, "{}", chapter.binary);
    }
    same(&ch01_ray_cast::CHAPTER, dir.path(), lab);
    same(&ch02_shadows::CHAPTER, dir.path(), lab);
    same(&ch03_reflection::CHAPTER, dir.path(), lab);
    same(&ch04_refraction::CHAPTER, dir.path(), lab);
    same(&ch05_antialiasing::CHAPTER, dir.path(), lab);
}

#[test]
fn the_extra_scenes_render_without_nan_and_show_what_they_are_for() {
    let dir = tempfile::tempdir().unwrap();
    let path = |name: &str| scene(name).to_str().unwrap().to_owned();
    let mirrors = path("two-mirrors.toml");
    let shallow = render_png(
        &ch03_reflection::CHAPTER,
        dir.path(),
        &["--scene", &mirrors, "--max-depth", "2"],
    );
    let deep = render_png(
        &ch03_reflection::CHAPTER,
        dir.path(),
        &["--scene", &mirrors, "--max-depth", "20"],
    );
    assert_ne!(shallow, deep, "more depth shows more nested reflections");

    let water = path("water-and-glass.toml");
    render_png(&ch04_refraction::CHAPTER, dir.path(), &["--scene", &water]);

    // Snell's window: the scene exists to show total internal reflection.
    let tir = path("total-internal-reflection.toml");
    let report = run_small(&ch04_refraction::CHAPTER, dir.path(), &["--scene", &tir]);
    let counts = report.rendered.counts;
    assert!(
        counts.get(raylab::RayKind::TotalInternalReflection)
            > counts.get(raylab::RayKind::Primary) / 4,
        "{counts:?}"
    );
}
