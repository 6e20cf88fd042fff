//! Eight paths at a time (chapter 8) make chapter 6's bytes: the same
//! image, variance, terms, ray count and non-finite count, bit for bit, for
//! every setting.

use std::path::Path;

use ch06_path_tracing::{Materials, PathRender, PathSettings, render_paths};
use ch08_eight_paths::render_eight;
use raylab::NoProgress;
use raylab::linear_image::LinearImage;
use raylab::sampling::{Pattern, Sampling};
use raylab::sphere::Sphere;
use raylab::{Camera, Material, Scene, Vec3};

fn settings(width: u32, height: u32, spp: u32) -> PathSettings {
    PathSettings {
        width,
        height,
        sampling: Sampling::new(spp, Some(Pattern::Random), 1).expect("a valid spp"),
        max_depth: 10,
        epsilon: 1e-4,
        materials: Materials::Lab,
        sun_size: None,
        caustics: false,
        photons_per_sphere: 4_000,
        keep_terms: true,
    }
}

/// Every pixel's three numbers as bits: `==` on floats would call −0 and
/// +0 the same, and a NaN different from itself.
fn bits(image: &LinearImage) -> Vec<[u32; 3]> {
    image
        .pixels()
        .iter()
        .map(|p| p.to_array().map(f32::to_bits))
        .collect()
}

fn assert_same_renders(scalar: &PathRender, eight: &PathRender, what: &str) {
    assert_eq!(
        bits(&scalar.image),
        bits(&eight.image),
        "{what}: the images differ"
    );
    assert_eq!(
        bits(&scalar.variance),
        bits(&eight.variance),
        "{what}: the variances differ"
    );
    for (t, name) in ch06_path_tracing::Terms::NAMES.iter().enumerate() {
        assert_eq!(
            bits(&scalar.terms()[t]),
            bits(&eight.terms()[t]),
            "{what}: the {name} terms differ"
        );
    }
    assert_eq!(scalar.rays, eight.rays, "{what}: rays");
    assert_eq!(scalar.paths, eight.paths, "{what}: paths");
    assert_eq!(
        scalar.non_finite, eight.non_finite,
        "{what}: non-finite samples"
    );
}

/// Render `settings` with both chapters and compare them bit for bit.
fn assert_same(scene: &Scene, camera: &Camera, settings: &PathSettings) {
    let scalar = render_paths(scene, camera, settings, &NoProgress);
    let eight = render_eight(scene, camera, settings, &NoProgress);
    assert_same_renders(&scalar, &eight, &settings.to_string());
}

fn assert_same_in_the_lab(settings: &PathSettings) {
    assert_same(&Scene::lab(), &Camera::lab(), settings);
}

#[test]
fn eight_paths_at_a_time_give_the_scalar_bytes_at_the_lab_settings() {
    assert_same_in_the_lab(&settings(48, 36, 8));
}

#[test]
fn odd_widths_partial_last_groups_and_a_single_pixel_are_the_same() {
    for (width, height, spp) in [(803, 2, 1), (7, 3, 3), (1, 1, 1), (1, 1, 5), (13, 5, 11)] {
        assert_same_in_the_lab(&settings(width, height, spp));
    }
}

#[test]
fn one_path_per_pixel_and_depths_1_3_and_64_are_the_same() {
    for max_depth in [1, 3, 64] {
        for spp in [1, 4] {
            assert_same_in_the_lab(&PathSettings {
                max_depth,
                ..settings(40, 30, spp)
            });
        }
    }
}

#[test]
fn fresnel_materials_are_the_same() {
    for max_depth in [3, 10] {
        assert_same_in_the_lab(&PathSettings {
            materials: Materials::Fresnel,
            max_depth,
            ..settings(40, 30, 6)
        });
    }
}

#[test]
fn the_real_sun_and_a_5_degree_sun_are_the_same() {
    for sun_size in [0.53, 5.0, 180.0] {
        for materials in [Materials::Lab, Materials::Fresnel] {
            assert_same_in_the_lab(&PathSettings {
                sun_size: Some(sun_size),
                materials,
                ..settings(40, 30, 6)
            });
        }
    }
}

#[test]
fn caustics_are_the_same_with_a_point_sun_and_a_disc() {
    for sun_size in [None, Some(5.0)] {
        for max_depth in [2, 10] {
            assert_same_in_the_lab(&PathSettings {
                caustics: true,
                sun_size,
                max_depth,
                ..settings(40, 30, 4)
            });
        }
    }
}

#[test]
fn every_pattern_and_seed_is_the_same() {
    for (spp, pattern, seed) in [
        (9, Pattern::Jittered, 7),
        (5, Pattern::Random, 3),
        (12, Pattern::Halton, 11),
        (1, Pattern::Halton, 0),
    ] {
        assert_same_in_the_lab(&PathSettings {
            sampling: Sampling::new(spp, Some(pattern), seed).expect("a valid pattern"),
            ..settings(33, 25, spp)
        });
    }
    // The pixel centre, which the command line never uses.
    assert_same_in_the_lab(&PathSettings {
        sampling: Sampling::PIXEL_CENTRE,
        ..settings(33, 25, 1)
    });
}

#[test]
fn with_no_offset_the_paths_that_re_hit_their_own_surface_are_the_same() {
    assert_same_in_the_lab(&PathSettings {
        epsilon: 0.0,
        ..settings(40, 30, 4)
    });
}

#[test]
fn a_scene_of_twelve_spheres_is_the_same() {
    // The lab's five and seven more in a row behind them: more spheres
    // than lanes, and a glass and a mirror among the new ones.
    let mut scene = Scene::lab();
    for k in 0..7 {
        let material = match k {
            2 => Material::new(Vec3::ONE, 0.1, 0.8, 1.33).expect("water"),
            5 => Material::new(Vec3::splat(0.9), 0.9, 0.0, 1.0).expect("a mirror"),
            _ => Material::diffuse(Vec3::new(0.2, 0.1 * k as f32, 0.5)).expect("matte"),
        };
        let shape = Sphere {
            centre: Vec3::new(-3.0 + 0.9 * k as f32, 0.35, -1.5 - 0.3 * k as f32),
            radius: 0.35,
        };
        scene
            .add_sphere(&format!("ball {k}"), shape, material)
            .expect("a valid sphere");
    }
    assert_eq!(scene.spheres().len(), 12);
    for sun_size in [None, Some(5.0)] {
        let s = PathSettings {
            sun_size,
            caustics: true,
            ..settings(40, 30, 4)
        };
        assert_same(&scene, &Camera::lab(), &s);
    }
}

#[test]
fn every_scene_file_renders_the_same() {
    let scenes = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../scenes");
    let mut files: Vec<_> = std::fs::read_dir(&scenes)
        .expect("the scenes folder")
        .map(|e| e.expect("a scene file").path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .collect();
    files.sort();
    assert!(files.len() >= 4, "{files:?}");
    for file in files {
        let (scene, camera) = raylab_cli::scene_file::load(&file).expect("the scene loads");
        assert_same(&scene, &camera, &settings(32, 24, 4));
    }
}

#[test]
fn eight_paths_at_a_time_give_the_same_bytes_on_one_thread_and_on_two() {
    let s = PathSettings {
        caustics: true,
        sun_size: Some(5.0),
        ..settings(40, 30, 4)
    };
    let on = |threads| {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .expect("a thread pool");
        pool.install(|| render_eight(&Scene::lab(), &Camera::lab(), &s, &NoProgress))
    };
    let (one, two) = (on(1), on(2));
    assert_same_renders(&one, &two, "one thread against two");
    let scalar = render_paths(&Scene::lab(), &Camera::lab(), &s, &NoProgress);
    assert_same_renders(&scalar, &one, "scalar against eight on one thread");
}

#[test]
fn a_render_without_its_terms_makes_the_same_image_and_variance_eight_at_a_time() {
    let with = settings(41, 7, 4);
    let without = PathSettings {
        keep_terms: false,
        ..with
    };
    let (with, without) = (
        render_eight(&Scene::lab(), &Camera::lab(), &with, &NoProgress),
        render_eight(&Scene::lab(), &Camera::lab(), &without, &NoProgress),
    );
    assert!(with.terms.is_some() && without.terms.is_none());
    assert_eq!(bits(&with.image), bits(&without.image));
    assert_eq!(bits(&with.variance), bits(&without.variance));
    assert_eq!(
        (with.rays, with.non_finite),
        (without.rays, without.non_finite)
    );
}
