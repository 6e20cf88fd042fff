//! Chapter 6 against what is known: closed forms, a furnace, itself.

use ch06_path_tracing::agreement::{sidak_threshold, z_test};
use ch06_path_tracing::random::Random;
use ch06_path_tracing::sun::Sunlight;
use ch06_path_tracing::{Materials, PathRender, PathSettings, PathTracer, Terms, render_paths};
use raylab::NoProgress;
use raylab::light::{Sky, Sun};
use raylab::plane::{Checker, Plane};
use raylab::sampling::{Pattern, Sampling, Stream, sample_rng};
use raylab::scene::Ground;
use raylab::sphere::Sphere;
use raylab::{Camera, Material, Ray, Scene, Vec3};

fn settings(width: u32, height: u32, spp: u32, seed: u64) -> PathSettings {
    PathSettings {
        width,
        height,
        sampling: Sampling::new(spp, Some(Pattern::Random), seed).unwrap(),
        max_depth: 10,
        epsilon: 1e-4,
        materials: Materials::Lab,
        sun_size: None,
        caustics: false,
        photons_per_sphere: 50_000,
        keep_terms: true,
    }
}

fn lab(settings: &PathSettings) -> PathRender {
    render_paths(&Scene::lab(), &Camera::lab(), settings, &NoProgress)
}

#[test]
fn an_open_unshadowed_ground_point_at_max_depth_1_converges_to_albedo_over_pi_times_sun_plus_sky() {
    // Far out on the sun's side of the spheres: nothing shadows it, and the
    // spheres, 28 units away, hide less of its sky than the test can see.
    let scene = Scene::lab();
    let point = Vec3::new(-20.5, 0.0, 19.5);
    let albedo = scene.ground.checker.albedo_at(point);
    assert_eq!(albedo, Vec3::splat(0.75));
    let tracer = PathTracer {
        scene: &scene,
        objects: &scene,
        sun: Sunlight::new(&scene.sun, None),
        materials: Materials::Lab,
        max_depth: 1,
        epsilon: 1e-4,
        caustics: None,
    };
    let l_y = scene.sun.direction.y;
    let e_sky = scene.sky.irradiance_facing_up();
    let expected = albedo / std::f32::consts::PI * (2.5 * l_y + e_sky);
    let n = 200_000;
    let (mut sum, mut sum_sq) = ([0f64; 3], [0f64; 3]);
    let mut rays = 0;
    for sample in 0..n {
        let mut random = Random(sample_rng(3, (0, 0), sample, Stream::Path));
        let ray = Ray::new(point + Vec3::Y, Vec3::NEG_Y);
        let terms = tracer.trace(ray, &mut random, &mut rays);
        assert_eq!(
            terms.indirect,
            Vec3::ZERO,
            "max depth 1 has no indirect light"
        );
        for (c, x) in terms.total().to_array().into_iter().enumerate() {
            sum[c] += f64::from(x);
            sum_sq[c] += f64::from(x) * f64::from(x);
        }
    }
    let n = f64::from(n);
    for c in 0..3 {
        let mean = sum[c] / n;
        let standard_error = ((sum_sq[c] / n - mean * mean) / (n - 1.0)).sqrt();
        let z = (mean - f64::from(expected[c])) / standard_error;
        assert!(
            z.abs() < sidak_threshold(0.01, 3),
            "channel {c}: {mean} vs {} (z = {z:.2}, standard error {standard_error:.2e})",
            expected[c]
        );
    }
}

/// A white world under a constant sky: white ground, white spheres whose
/// shares are the lab's, no sun. Light is neither made nor lost anywhere,
/// so every point, seen from any direction, has the sky's radiance.
fn furnace(materials: [(f32, f32); 3]) -> Scene {
    let white = Vec3::ONE;
    let mut scene = Scene::new(
        Ground {
            plane: Plane {
                point: Vec3::ZERO,
                normal: Vec3::Y,
            },
            checker: Checker {
                even: white,
                odd: white,
            },
        },
        Sky {
            horizon: Vec3::splat(0.7),
            zenith: Vec3::splat(0.7),
        },
        Sun {
            direction: Vec3::Y,
            brightness: 0.0,
        },
    )
    .unwrap();
    let places = [
        (-1.25, 0.5, 0.5, 0.5),
        (1.0, 0.6, 0.8, 0.6),
        (0.0, 1.0, -1.5, 1.0),
    ];
    for (&(r, t), (x, y, z, radius)) in materials.iter().zip(places) {
        let shape = Sphere {
            centre: Vec3::new(x, y, z),
            radius,
        };
        let material = Material::new(white, r, t, 1.5).unwrap();
        scene.add_sphere("white", shape, material).unwrap();
    }
    scene
}

#[test]
fn a_white_world_under_a_constant_sky_is_as_bright_as_the_sky_everywhere() {
    // A diffuse ball, a mirror and the lab's glass, in both material models.
    let scene = furnace([(0.6, 0.0), (0.1, 0.7), (0.0, 0.0)]);
    for materials in [Materials::Lab, Materials::Fresnel] {
        let settings = PathSettings {
            max_depth: 64,
            materials,
            ..settings(40, 30, 16, 5)
        };
        let rendered = render_paths(&scene, &Camera::lab(), &settings, &NoProgress);
        for (p, (mean, var)) in rendered
            .image
            .pixels()
            .iter()
            .zip(rendered.variance.pixels())
            .enumerate()
        {
            for c in 0..3 {
                let error = (mean[c] - 0.7).abs();
                let allowed = 5.0 * var[c].sqrt() + 1e-4;
                assert!(
                    error <= allowed,
                    "{materials:?}, pixel {p}: {} (± {})",
                    mean[c],
                    var[c].sqrt()
                );
            }
        }
    }
}

#[test]
fn two_seeds_give_images_that_agree_within_their_own_variance() {
    let a = lab(&settings(40, 30, 64, 1));
    let b = lab(&settings(40, 30, 64, 2));
    assert_ne!(a.image, b.image, "different seeds, different noise");
    let threshold = sidak_threshold(0.01, 40 * 30 * 3);
    let agreement = z_test((&a.image, &a.variance), (&b.image, &b.variance));
    let worst = agreement.worst.expect("the images have pixels");
    assert!(
        worst.z.abs() < threshold,
        "pixel ({}, {}) channel {}: z = {:.2} (threshold {threshold:.2})",
        worst.x,
        worst.y,
        worst.channel,
        worst.z
    );
    println!(
        "largest |z| of 3600: {:.2} (threshold {threshold:.2})",
        worst.z.abs()
    );
}

#[test]
fn the_same_seed_gives_the_same_image_on_one_thread_and_on_two() {
    let settings = PathSettings {
        caustics: true,
        sun_size: Some(5.0),
        ..settings(40, 30, 4, 9)
    };
    let on = |threads| {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        pool.install(|| lab(&settings))
    };
    let (one, two) = (on(1), on(2));
    assert_eq!(one.image.to_srgb8().as_raw(), two.image.to_srgb8().as_raw());
    assert_eq!(one.image, two.image);
    assert_eq!(one.variance, two.variance);
    assert_eq!(one.terms, two.terms);
}

#[test]
fn the_terms_sum_to_the_image() {
    for caustics in [false, true] {
        let rendered = lab(&PathSettings {
            caustics,
            sun_size: Some(2.0),
            ..settings(40, 30, 16, 4)
        });
        for (p, total) in rendered.image.pixels().iter().enumerate() {
            let sum: Vec3 = rendered.terms().iter().map(|t| t.pixels()[p]).sum();
            assert!(
                sum.abs_diff_eq(*total, 1e-5 * (1.0 + total.max_element())),
                "pixel {p}: terms {sum} vs image {total}"
            );
        }
    }
}

#[test]
fn a_render_without_its_terms_makes_the_same_image_and_variance() {
    let with = lab(&settings(41, 7, 4, 2));
    let without = lab(&PathSettings {
        keep_terms: false,
        ..settings(41, 7, 4, 2)
    });
    assert!(with.terms.is_some() && without.terms.is_none());
    assert_eq!(with.image, without.image);
    assert_eq!(with.variance, without.variance);
    assert_eq!(
        (with.rays, with.non_finite),
        (without.rays, without.non_finite)
    );
}

#[test]
fn with_caustics_no_light_is_counted_twice() {
    // The eye's paths draw the same random numbers with and without
    // --caustics; only who counts the sunlight that mirrors and glass
    // bring to a diffuse surface changes.
    let names = Terms::NAMES;
    // A disc 30° across, so that paths from the eye often reach it through glass.
    for sun_size in [None, Some(30.0)] {
        let base = PathSettings {
            sun_size,
            ..settings(40, 30, 16, 8)
        };
        let without = lab(&base);
        let with = lab(&PathSettings {
            caustics: true,
            ..base
        });
        // The light seen directly and the sky's light do not change at all.
        for t in [0, 2] {
            assert_eq!(with.terms()[t], without.terms()[t], "{}", names[t]);
        }
        assert_eq!(without.terms()[4].pixels().iter().sum::<Vec3>(), Vec3::ZERO);
        let caustic: f32 = with.terms()[4]
            .pixels()
            .iter()
            .map(|p| p.element_sum())
            .sum();
        assert!(caustic > 0.0, "the photons find the caustic");
        // The sun through mirrors and glass, found by the eye's paths only
        // with a disc, is no longer counted by them.
        let (mut less, mut same) = (0, 0);
        for t in [1, 3] {
            for (a, b) in with.terms()[t]
                .pixels()
                .iter()
                .zip(without.terms()[t].pixels())
            {
                assert!(a.cmple(*b + 1e-6).all(), "{}: {a} > {b}", names[t]);
                if a == b {
                    same += 1;
                } else {
                    less += 1;
                }
            }
        }
        match sun_size {
            None => assert_eq!(less, 0, "a point sun is never reached through glass"),
            Some(_) => assert!(
                less > 0 && same > 0,
                "{less} pixels lose light, {same} keep it"
            ),
        }
    }
}

#[test]
fn no_pixel_term_or_variance_is_ever_nan_or_infinite() {
    for sun_size in [None, Some(0.01), Some(0.53), Some(90.0), Some(180.0)] {
        for materials in [Materials::Lab, Materials::Fresnel] {
            let rendered = lab(&PathSettings {
                sun_size,
                materials,
                caustics: true,
                photons_per_sphere: 20_000,
                ..settings(32, 24, 8, 6)
            });
            assert_eq!(rendered.non_finite, 0, "{sun_size:?} {materials:?}");
            assert!(rendered.image.is_finite());
            assert!(rendered.variance.is_finite());
            assert!(rendered.terms().iter().all(|t| t.is_finite()));
        }
    }
}
