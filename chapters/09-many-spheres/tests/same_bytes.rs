//! Through the tree, the same bytes: chapters 1–5's images and chapter
//! 6's, on the lab scene and on a field of spheres.

use ch06_path_tracing::{PathSettings, render_paths, render_paths_with_query};
use ch09_many_spheres::field::field_scene;
use ch09_many_spheres::{Bvh, Like};
use raylab::{Camera, Keep, NoProgress, Scene, Settings, Step};
use raylab_cli::{Chapter, Options};

/// Chapter `chapter`'s own render and chapter 9's `--like` it, at its
/// defaults and a small size: the same bytes.
fn same_as<S: Step>(chapter: &Chapter<S>, like: Like, scene: &Scene, camera: &Camera) {
    let nine = ch09_many_spheres::chapter(like);
    let args = [chapter.binary, "--width", "96", "--height", "72"];
    let settings = Options::parse_for(chapter, args)
        .unwrap()
        .settings()
        .unwrap();
    let settings = Settings {
        sampling: settings.sampling.with_lab_five(chapter.step.lab_five()),
        ..settings
    };
    let nine_settings = Options::parse_for(&nine, args).unwrap().settings().unwrap();
    let nine_settings = Settings {
        sampling: nine_settings.sampling.with_lab_five(nine.step.lab_five()),
        ..nine_settings
    };
    assert_eq!(settings, nine_settings, "{}", chapter.binary);
    let theirs = (chapter.render)(
        scene,
        camera,
        &chapter.step,
        &settings,
        Keep::IMAGE,
        &NoProgress,
    );
    let ours = (nine.render)(
        scene,
        camera,
        &nine.step,
        &nine_settings,
        Keep::IMAGE,
        &NoProgress,
    );
    assert!(theirs.srgb == ours.srgb, "{} differs", chapter.binary);
    assert_eq!(theirs.counts, ours.counts, "{}", chapter.binary);
}

fn every_chapter(scene: &Scene, camera: &Camera) {
    same_as(&ch01_ray_cast::CHAPTER, Like::RayCast, scene, camera);
    same_as(&ch02_shadows::CHAPTER, Like::Shadows, scene, camera);
    same_as(&ch03_reflection::CHAPTER, Like::Reflection, scene, camera);
    same_as(&ch04_refraction::CHAPTER, Like::Refraction, scene, camera);
    same_as(
        &ch05_antialiasing::CHAPTER,
        Like::AntiAliasing,
        scene,
        camera,
    );
}

#[test]
fn like_each_whitted_chapter_it_makes_that_chapters_lab_image() {
    every_chapter(&Scene::lab(), &Camera::lab());
}

#[test]
fn like_each_whitted_chapter_it_makes_that_chapters_image_of_a_field() {
    let (scene, camera) = field_scene(300);
    every_chapter(&scene, &camera);
}

fn path_settings(spp: &str) -> PathSettings {
    use ch06_path_tracing::run;
    let program = &ch06_path_tracing::PROGRAM.program;
    let args = [
        "ch06-path-tracing",
        "--spp",
        spp,
        "--width",
        "64",
        "--height",
        "48",
    ];
    let (options, flags) = run::parse(program, args).unwrap();
    run::settings(&options, &flags).unwrap()
}

#[test]
fn chapter_6_through_the_tree_makes_chapter_6s_images() {
    for (scene, camera) in [(Scene::lab(), Camera::lab()), field_scene(200)] {
        let settings = path_settings("8");
        let tree = Bvh::build(&scene);
        let list = render_paths(&scene, &camera, &settings, &NoProgress);
        let ours = render_paths_with_query(&scene, &tree, &camera, &settings, &NoProgress);
        let bits = |img: &raylab::linear_image::LinearImage| {
            img.pixels()
                .iter()
                .flat_map(|p| p.to_array().map(f32::to_bits))
                .collect::<Vec<_>>()
        };
        assert!(bits(&list.image) == bits(&ours.image));
        assert!(bits(&list.variance) == bits(&ours.variance));
        assert_eq!(list.rays, ours.rays);
    }
}

#[test]
fn the_step_is_the_imitated_chapters_own() {
    let nine = ch09_many_spheres::chapter(Like::AntiAliasing);
    assert_eq!(nine.step.lab_five(), ch05_antialiasing::lab_five());
}
