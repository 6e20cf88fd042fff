//! Eight at a time through the tree, the same bytes: chapter 7's waves and
//! chapter 8's paths, given the tree, make their own images, on the lab
//! scene and on a field of spheres.

use ch06_path_tracing::{PathSettings, run};
use ch07_eight_rays::EightRays;
use ch07_eight_rays::render::render_waves;
use ch08_eight_paths::render_eight;
use ch09_many_spheres::figures::field_scene;
use ch09_many_spheres::{Like, render_tree_paths, render_tree_waves};
use raylab::{Camera, Keep, NoProgress, Scene, Settings, Step};
use raylab_cli::Options;

fn scenes() -> [(Scene, Camera); 2] {
    [(Scene::lab(), Camera::lab()), field_scene(300)]
}

#[test]
fn chapter_7s_waves_through_the_tree_make_chapter_7s_images_like_each_chapter() {
    for (scene, camera) in scenes() {
        for like in [
            Like::RayCast,
            Like::Shadows,
            Like::Reflection,
            Like::Refraction,
            Like::AntiAliasing,
        ] {
            let chapter = ch07_eight_rays::chapter(like);
            let args = [chapter.binary, "--width", "96", "--height", "72"];
            let settings = Options::parse_for(&chapter, args)
                .unwrap()
                .settings()
                .unwrap();
            let step = EightRays { like };
            let settings = Settings {
                sampling: settings.sampling.with_lab_five(step.lab_five()),
                ..settings
            };
            let keep = Keep {
                linear: false,
                maps: true,
            };
            let list = render_waves(&scene, &camera, &step, &settings, keep, &NoProgress);
            let tree = render_tree_waves(&scene, &camera, &step, &settings, keep, &NoProgress);
            assert!(list.srgb == tree.srgb, "{like:?}: the images differ");
            assert_eq!(list.counts, tree.counts, "{like:?}");
            assert!(list.maps == tree.maps, "{like:?}: the maps differ");
        }
    }
}

fn path_settings(extra: &[&str]) -> PathSettings {
    let program = &ch08_eight_paths::PROGRAM.program;
    let mut args = vec![
        program.binary,
        "--spp",
        "8",
        "--width",
        "64",
        "--height",
        "48",
    ];
    args.extend_from_slice(extra);
    let (options, flags) = run::parse(program, args).unwrap();
    PathSettings {
        // Enough photons to land some on the ground, few enough to be quick.
        photons_per_sphere: 4_000,
        ..run::settings(&options, &flags).unwrap()
    }
}

#[test]
fn chapter_8s_paths_through_the_tree_make_chapter_8s_images_caustics_included() {
    // Photons are sent towards every glass or mirror sphere: caustics on a
    // small field, to keep the test quick.
    let runs = [
        (Scene::lab(), Camera::lab(), &["--caustics"][..]),
        (field_scene(300).0, field_scene(300).1, &[][..]),
        (field_scene(30).0, field_scene(30).1, &["--caustics"][..]),
    ];
    for (scene, camera, extra) in runs {
        {
            let settings = path_settings(extra);
            let list = render_eight(&scene, &camera, &settings, &NoProgress);
            let tree = render_tree_paths(&scene, &camera, &settings, &NoProgress);
            let bits = |img: &raylab::linear_image::LinearImage| {
                img.pixels()
                    .iter()
                    .flat_map(|p| p.to_array().map(f32::to_bits))
                    .collect::<Vec<_>>()
            };
            assert!(bits(&list.image) == bits(&tree.image), "{extra:?}");
            assert!(bits(&list.variance) == bits(&tree.variance), "{extra:?}");
            assert_eq!(list.rays, tree.rays, "{extra:?}");
        }
    }
}
