//! The shader against chapters 1–5: the same images, within the lab model's
//! tolerance, on the lab scene and on every scene in `scenes/`.
//!
//! These tests need a GPU adapter: any Vulkan one will do, and Mesa's
//! lavapipe runs on the CPU (CI installs it). On a machine without one
//! they say so and pass, unless `CI` is set: there a missing adapter fails.

use std::path::{Path, PathBuf};

use ch10_gpu::gpu::Gpu;
use ch10_gpu::like::Like;
use ch10_gpu::run::render_image;
use ch10_gpu::shader::Source;
use raylab::NoProgress;
use raylab::tolerance::compare;
use raylab::{Camera, Keep, Sampling, Scene, Settings, Step};

/// A chapter's settings at 320 × 240, with its default depth and samples.
fn settings(like: Like) -> Settings {
    let raylab_like::Defaults { max_depth, spp, .. } = like.defaults();
    Settings {
        width: 320,
        height: 240,
        max_depth,
        epsilon: 1e-4,
        sampling: Sampling::new(spp, None, 0).unwrap(),
    }
}

/// The chapter's own image, by its own step on the CPU.
fn reference(like: Like, settings: &Settings, scene: &(Scene, Camera)) -> image::RgbImage {
    let steps: [&dyn Step; 5] = [
        &ch01_ray_cast::RayCast,
        &ch02_shadows::Shadows,
        &ch03_reflection::Reflection,
        &ch04_refraction::Refraction,
        &ch05_antialiasing::AntiAliasing,
    ];
    let step = steps[like as usize];
    let settings = Settings {
        sampling: settings.sampling.with_lab_five(step.lab_five()),
        ..*settings
    };
    raylab::render(
        &scene.0,
        &scene.1,
        step,
        &settings,
        Keep::IMAGE,
        &NoProgress,
    )
    .srgb
}

/// Render with the shader and compare with the chapter; the figures are
/// printed (`cargo test -- --nocapture` shows them).
fn check(gpu: &Gpu, like: Like, scene: &(Scene, Camera), what: &str, (width, height): (u32, u32)) {
    let settings = Settings {
        width,
        height,
        ..settings(like)
    };
    let tracer = gpu
        .compile(&Source::built_in(), settings.max_depth)
        .unwrap();
    let ours = render_image(gpu, &tracer, like, &settings, scene, false).unwrap();
    let theirs = reference(like, &settings, scene);
    let agreement = compare(&ours.rendered.srgb, &theirs);
    println!(
        "{what}, like {}: {:.3} % of pixels within 3 levels, mean difference {:.4}, max {}, \
         {} of {} pixels identical",
        like.binary(),
        agreement.within_3 * 100.0,
        agreement.mean,
        agreement.max,
        agreement.identical,
        settings.width * settings.height
    );
    assert!(
        agreement.meets_lab_tolerance(),
        "{what}, like {}: {agreement:?}",
        like.binary()
    );
    assert_eq!(ours.rendered.non_finite, 0);
}

#[test]
fn like_chapters_1_to_5_the_shader_matches_each_chapter_within_lab_tolerance() {
    let Some(gpu) = Gpu::for_tests() else { return };
    let lab = (Scene::lab(), Camera::lab());
    for like in Like::ALL {
        check(&gpu, like, &lab, "lab scene", (320, 240));
    }
}

fn scenes() -> Vec<PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../scenes");
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .collect();
    files.sort();
    assert!(files.len() >= 4, "{files:?}");
    files
}

#[test]
fn every_scene_file_renders_on_the_gpu_as_chapter_5_renders_it() {
    let Some(gpu) = Gpu::for_tests() else { return };
    for path in scenes() {
        let name = path.file_name().unwrap().to_string_lossy().into_owned();
        let scene = raylab_cli::scene_file::load(&path).unwrap();
        // A field of 500 spheres is slow on lavapipe: a glass pixel's tree
        // of a thousand rays, each tested against every sphere, keeps its
        // lanes busy while the rest of their group waits, dispatch after
        // dispatch (about 150 s at 320 × 240). A quarter of the size each
        // way still crosses dozens of glass spheres.
        let size = if scene.0.spheres().len() > 50 {
            (80, 60)
        } else {
            (320, 240)
        };
        check(&gpu, Like::AntiAliasing, &scene, &name, size);
    }
}

#[test]
fn the_gpu_counts_the_rays_chapter_4_traces() {
    // Counting is arithmetic on whole numbers, but which ray goes where
    // rests on floats: a grazing ray may split differently. Within a
    // thousandth, by kind.
    let Some(gpu) = Gpu::for_tests() else { return };
    let lab = (Scene::lab(), Camera::lab());
    let settings = settings(Like::Refraction);
    let tracer = gpu
        .compile(&Source::built_in(), settings.max_depth)
        .unwrap();
    let ours = render_image(&gpu, &tracer, Like::Refraction, &settings, &lab, true).unwrap();
    let theirs = raylab::render(
        &lab.0,
        &lab.1,
        &ch04_refraction::Refraction,
        &settings,
        Keep::IMAGE,
        &NoProgress,
    );
    for kind in raylab::RayKind::ALL {
        let (a, b) = (ours.rendered.counts.get(kind), theirs.counts.get(kind));
        assert!(
            a.abs_diff(b) * 1000 <= b.max(1),
            "{kind:?}: {a} against {b}"
        );
    }
    let maps = ours.rendered.maps.unwrap();
    assert_eq!(maps.deepest.len(), 320 * 240);
    assert_eq!(
        maps.rays.iter().map(|&r| u64::from(r)).sum::<u64>(),
        ours.rendered.counts.total()
    );
}

#[test]
fn with_epsilon_0_the_ray_budget_cuts_short_as_many_samples_as_chapter_4() {
    // Rays that start on their own surface split again and again: the
    // budget of 4096 rays per sample is what stops them, on the GPU too.
    // Which rays re-hit their surface rests on rounding, so the counts
    // agree closely, not exactly.
    let Some(gpu) = Gpu::for_tests() else { return };
    let lab = (Scene::lab(), Camera::lab());
    let settings = Settings {
        width: 160,
        height: 120,
        max_depth: 64,
        epsilon: 0.0,
        sampling: Sampling::new(1, None, 0).unwrap(),
    };
    let tracer = gpu
        .compile(&Source::built_in(), settings.max_depth)
        .unwrap();
    let ours = render_image(&gpu, &tracer, Like::Refraction, &settings, &lab, false).unwrap();
    let theirs = raylab::render(
        &lab.0,
        &lab.1,
        &ch04_refraction::Refraction,
        &settings,
        Keep::IMAGE,
        &NoProgress,
    );
    let close = |a: u64, b: u64| a.abs_diff(b) * 50 <= b.max(1);
    let (a, b) = (ours.rendered.over_budget, theirs.over_budget);
    assert!(b > 0 && close(a, b), "samples over budget: {a} against {b}");
    let (a, b) = (ours.rendered.counts.total(), theirs.counts.total());
    assert!(close(a, b), "rays: {a} against {b}");
}

#[test]
fn an_image_too_big_for_one_buffer_renders_in_bands_to_the_same_pixels() {
    // Bands of 7 rows (the last one shorter) against the whole image at once.
    let Some(gpu) = Gpu::for_tests() else { return };
    let settings = Settings {
        width: 64,
        height: 48,
        ..settings(Like::AntiAliasing)
    };
    let features = Like::AntiAliasing.features();
    let inputs =
        ch10_gpu::scene_buffer::pack(&Scene::lab(), &Camera::lab(), &settings, features).unwrap();
    let tracer = gpu
        .compile(&Source::built_in(), settings.max_depth)
        .unwrap();
    let whole = gpu.render(&tracer, &inputs).unwrap();
    let bands = gpu.render_in_bands(&tracer, &inputs, 7).unwrap();
    assert_eq!(bands.pixels, whole.pixels);
    assert_eq!(bands.maps, whole.maps);
    assert_eq!(bands.counts, whole.counts);
}
