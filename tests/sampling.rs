//! More rays per pixel: a seeded render is the same bytes whatever the
//! threads or the order of the work, and the seed matters only where a
//! pattern is random.

use raylab::NoProgress;
use raylab::{Camera, Keep, Pattern, Sampling, Scene, Settings, Tracer, Vec3, render};

const STEP: ch05_antialiasing::Refraction = ch05_antialiasing::Refraction;

fn settings(spp: u32, pattern: Pattern, seed: u64) -> Settings {
    Settings {
        width: 48,
        height: 36,
        max_depth: 10,
        epsilon: 1e-4,
        sampling: Sampling::new(spp, Some(pattern), seed).unwrap(),
    }
}

fn render_on(threads: usize, settings: &Settings) -> image::RgbImage {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .unwrap();
    pool.install(|| {
        render(
            &Scene::lab(),
            &Camera::lab(),
            &STEP,
            settings,
            Keep::IMAGE,
            &NoProgress,
        )
    })
    .srgb
}

#[test]
fn the_same_seed_gives_the_same_bytes_on_one_thread_and_on_two() {
    for pattern in Pattern::ALL {
        let settings = settings(16, pattern, 42);
        assert_eq!(
            render_on(1, &settings),
            render_on(2, &settings),
            "{pattern}"
        );
    }
}

#[test]
fn pixels_traced_one_by_one_backwards_match_the_parallel_render() {
    // Every offset is a pure function of (seed, pixel, sample): tracing the
    // pixels last row first, right to left, on one tracer changes nothing.
    let settings = settings(9, Pattern::Halton, 7);
    let (scene, camera) = (Scene::lab(), Camera::lab());
    let rendered = render(&scene, &camera, &STEP, &settings, Keep::LINEAR, &NoProgress);
    let mut tracer = Tracer::new(&scene, &STEP, settings.max_depth, settings.epsilon);
    for j in (0..settings.height).rev() {
        for i in (0..settings.width).rev() {
            let mut sum = Vec3::ZERO;
            for offset in settings.sampling.offsets((i, j)) {
                let ray = camera.ray(i, j, offset, settings.width, settings.height);
                sum += tracer.trace(ray).colour;
            }
            let colour = sum / settings.sampling.spp() as f32;
            assert_eq!(
                rendered.linear_image().pixel(i, j),
                colour,
                "pixel ({i}, {j})"
            );
        }
    }
}

#[test]
fn another_seed_gives_another_image_for_the_random_patterns_only() {
    for pattern in [Pattern::Jittered, Pattern::Random, Pattern::Halton] {
        assert_ne!(
            render_on(2, &settings(4, pattern, 1)),
            render_on(2, &settings(4, pattern, 2)),
            "{pattern}"
        );
    }
    assert_eq!(
        render_on(2, &settings(4, Pattern::Grid, 1)),
        render_on(2, &settings(4, Pattern::Grid, 2)),
        "the grid has no random choice"
    );
}

#[test]
fn a_grid_of_one_is_the_pixel_centre_and_a_random_five_is_not_the_lab_five() {
    let centre = Settings {
        sampling: Sampling::PIXEL_CENTRE,
        ..settings(1, Pattern::Grid, 0)
    };
    assert_eq!(
        render_on(2, &settings(1, Pattern::Grid, 0)),
        render_on(2, &centre)
    );
    let lab = Settings {
        sampling: Sampling::LAB_FIVE,
        ..settings(5, Pattern::Random, 0)
    };
    assert_ne!(
        render_on(2, &settings(5, Pattern::Random, 0)),
        render_on(2, &lab)
    );
}
