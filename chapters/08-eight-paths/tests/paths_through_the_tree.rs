//! Chapter 8's paths with `--objects tree` make chapter 8's own images:
//! every hit found through chapter 9's tree (the paths' eight at a time,
//! the photons' one at a time), to the bit, caustics included.

use ch06_path_tracing::{PathSettings, run};
use ch08_eight_paths::{Objects, program_through, render_eight};
use ch09_many_spheres::field::field_scene;
use raylab::{Camera, NoProgress, Scene};

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
        let settings = path_settings(extra);
        let list = render_eight(&scene, &camera, &settings, &NoProgress);
        // The renderer `--objects tree` chooses: the tree built, then searched.
        let tree = (program_through(Objects::Tree).render)(&scene, &camera, &settings, &NoProgress);
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
