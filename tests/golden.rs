//! Every chapter still renders its golden image (160 × 120, the chapter's
//! defaults otherwise). Regenerate them, on purpose only, with
//! `RAYLAB_BLESS=1 cargo test -p raylab-tests --test golden` and look at the result.

use raylab::NoProgress;
use raylab::{Camera, Keep, Scene, Step, render};
use raylab_cli::{Chapter, Options};
use raylab_tests::check_golden;

fn render_small<S: Step>(chapter: &Chapter<S>) -> raylab::Rendered {
    let options = Options::parse_for(
        chapter,
        [chapter.binary, "--width", "160", "--height", "120"],
    )
    .unwrap();
    let settings = options.settings().unwrap();
    let rendered = render(
        &Scene::lab(),
        &Camera::lab(),
        &chapter.step,
        &settings,
        Keep::LINEAR,
        &NoProgress,
    );
    assert_eq!(rendered.non_finite, 0, "no pixel may be NaN or infinite");
    assert!(rendered.linear_image().is_finite());
    rendered
}

#[test]
fn chapter_1_renders_its_golden_image() {
    let rendered = render_small(&ch01_ray_cast::CHAPTER);
    assert_eq!(
        rendered.counts.total(),
        160 * 120,
        "one primary ray per pixel"
    );
    check_golden("ch01-ray-cast", &rendered.srgb);
}

#[test]
fn chapter_2_renders_its_golden_image() {
    let rendered = render_small(&ch02_shadows::CHAPTER);
    check_golden("ch02-shadows", &rendered.srgb);
}

#[test]
fn chapter_3_renders_its_golden_image() {
    let rendered = render_small(&ch03_reflection::CHAPTER);
    check_golden("ch03-reflection", &rendered.srgb);
}

#[test]
fn chapter_4_renders_its_golden_image() {
    let rendered = render_small(&ch04_refraction::CHAPTER);
    check_golden("ch04-refraction", &rendered.srgb);
}

#[test]
fn chapter_5_renders_its_golden_image() {
    let rendered = render_small(&ch05_antialiasing::CHAPTER);
    assert_eq!(rendered.counts.get(raylab::RayKind::Primary), 5 * 160 * 120);
    check_golden("ch05-antialiasing", &rendered.srgb);
}
