//! How the chapters relate: each one changes only what its step adds.

use raylab::NoProgress;
use raylab::{Camera, Keep, Rendered, Sampling, Scene, Settings, Step, Tracer, Vec3, render};

fn settings(max_depth: u32, spp: u32) -> Settings {
    Settings {
        width: 80,
        height: 60,
        max_depth,
        epsilon: 1e-4,
        sampling: Sampling::new(spp, None, 0).unwrap(),
    }
}

fn render_lab<S: Step + ?Sized>(step: &S, settings: &Settings) -> Rendered {
    render(
        &Scene::lab(),
        &Camera::lab(),
        step,
        settings,
        Keep::LINEAR,
        &NoProgress,
    )
}

#[test]
fn at_max_depth_1_chapters_3_to_5_are_chapter_2_times_the_kept_share() {
    let scene = Scene::lab();
    let camera = Camera::lab();
    let settings = settings(1, 1);
    let steps: [(&str, &dyn Step); 3] = [
        ("chapter 3", &ch03_reflection::Reflection),
        ("chapter 4", &ch04_refraction::Refraction),
        ("chapter 5", &ch05_antialiasing::Refraction),
    ];
    let (r_enabled, t_enabled) = ([true, true, true], [false, true, true]);
    for (n, (name, step)) in steps.into_iter().enumerate() {
        let mut shadows = Tracer::new(&scene, &ch02_shadows::Shadows, 1, 1e-4).with_log();
        let mut later = Tracer::new(&scene, step, 1, 1e-4);
        for j in 0..settings.height {
            for i in 0..settings.width {
                let ray = camera.ray(i, j, (0.5, 0.5), settings.width, settings.height);
                let base = shadows.trace(ray).colour;
                let hit = scene.nearest_hit(&ray);
                let kept = hit.map_or(1.0, |h| {
                    let r = if r_enabled[n] {
                        h.material.reflection()
                    } else {
                        0.0
                    };
                    let t = if t_enabled[n] {
                        h.material.transmission()
                    } else {
                        0.0
                    };
                    1.0 - r - t
                });
                let colour = later.trace(ray).colour;
                assert!(
                    colour.abs_diff_eq(base * kept, 1e-6),
                    "{name}, pixel ({i}, {j}): {colour} vs {base} × {kept}"
                );
            }
        }
    }
}

#[test]
fn no_chapter_ever_makes_a_nan_or_infinite_pixel() {
    // Every chapter, at the depths that matter, at both sample counts,
    // and with epsilon 0 (rays start exactly on their surfaces).
    let steps: [&dyn Step; 4] = [
        &ch01_ray_cast::RayCast,
        &ch02_shadows::Shadows,
        &ch03_reflection::Reflection,
        &ch04_refraction::Refraction,
    ];
    for step in steps {
        for (max_depth, spp, epsilon) in [(1, 1, 1e-4), (10, 5, 1e-4), (64, 1, 0.0)] {
            let settings = Settings {
                epsilon,
                width: 40,
                height: 30,
                ..settings(max_depth, spp)
            };
            let rendered = render_lab(step, &settings);
            assert_eq!(rendered.non_finite, 0);
            assert!(rendered.linear_image().is_finite());
            // The workers' 8-bit image is the linear one, encoded.
            assert_eq!(rendered.srgb, rendered.linear_image().to_srgb8());
            assert_eq!(rendered.srgb.dimensions(), (40, 30));
            if epsilon > 0.0 {
                assert_eq!(
                    rendered.over_budget, 0,
                    "the defaults never reach the budget"
                );
            }
        }
    }
}

#[test]
fn five_rays_per_pixel_only_soften_edges() {
    // Chapter 5 with --spp 1 is chapter 4; with 5 rays most pixels barely
    // change and the ones that do lie on edges.
    let one = render_lab(&ch05_antialiasing::Refraction, &settings(10, 1));
    let four = render_lab(&ch04_refraction::Refraction, &settings(10, 1));
    assert_eq!(one.linear_image(), four.linear_image());
    let five = render_lab(&ch05_antialiasing::Refraction, &settings(10, 5));
    let agreement = raylab_tests::compare(&one.srgb, &five.srgb);
    assert!(
        agreement.within_3 > 0.6 && agreement.within_3 < 1.0,
        "{agreement:?}"
    );
}

#[test]
fn chapter_2_darkens_only_shadowed_points() {
    let ch1 = render_lab(&ch01_ray_cast::RayCast, &settings(1, 1));
    let ch2 = render_lab(&ch02_shadows::Shadows, &settings(1, 1));
    let mut darker = 0;
    for (a, b) in ch1
        .linear_image()
        .pixels()
        .iter()
        .zip(ch2.linear_image().pixels())
    {
        assert!(
            b.cmple(*a + Vec3::splat(1e-6)).all(),
            "a shadow never brightens"
        );
        darker += usize::from(b != a);
    }
    // The lab scene has visible shadows, but most of the picture is lit.
    let share = darker as f64 / (80.0 * 60.0);
    assert!(share > 0.02 && share < 0.5, "{share}");
}
