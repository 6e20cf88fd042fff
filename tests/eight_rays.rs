//! Chapter 7 makes the scalar chapters' images to the byte, with the same
//! rays: the same counts by kind and the same per-pixel depth and ray maps.

use std::path::Path;

use ch07_eight_rays::{EightRays, Like, render::render_waves};
use raylab::NoProgress;
use raylab::sampling::Pattern;
use raylab::{Camera, Keep, RayKind, Sampling, Scene, Settings, Step, render};

/// The scalar chapter that `like` imitates, as a step.
fn scalar_step(like: Like) -> &'static dyn Step {
    match like {
        Like::RayCast => &ch01_ray_cast::RayCast,
        Like::Shadows => &ch02_shadows::Shadows,
        Like::Reflection => &ch03_reflection::Reflection,
        Like::Refraction => &ch04_refraction::Refraction,
        Like::AntiAliasing => &ch05_antialiasing::AntiAliasing,
    }
}

fn settings(like: Like, (width, height): (u32, u32)) -> Settings {
    let raylab_like::Defaults { max_depth, spp, .. } = like.defaults();
    Settings {
        width,
        height,
        max_depth,
        epsilon: 1e-4,
        sampling: Sampling::new(spp, None, 0)
            .expect("a chapter's own spp")
            .with_lab_five(scalar_step(like).lab_five()),
    }
}

/// Render with chapter `like`'s scalar step and with chapter 7; both must
/// give the same bytes, ray counts and per-pixel maps.
fn assert_same(like: Like, scene: &Scene, camera: &Camera, settings: &Settings) {
    let hidden = NoProgress;
    let scalar = render(
        scene,
        camera,
        scalar_step(like),
        settings,
        Keep::ALL,
        &hidden,
    );
    let step = EightRays { like };
    let waves = render_waves(scene, camera, &step, settings, Keep::ALL, &hidden);
    let what = format!("like {} at {settings}", like.binary());
    assert!(scalar.srgb == waves.srgb, "{what}: the images differ");
    assert_eq!(
        scalar.linear_image(),
        waves.linear_image(),
        "{what}: the linear colours differ"
    );
    for kind in RayKind::ALL {
        assert_eq!(
            scalar.counts.get(kind),
            waves.counts.get(kind),
            "{what}: {} rays",
            kind.name()
        );
    }
    let (scalar_maps, wave_maps) = (scalar.maps.expect("kept"), waves.maps.expect("kept"));
    assert_eq!(scalar_maps.deepest, wave_maps.deepest, "{what}: depth map");
    assert_eq!(scalar_maps.rays, wave_maps.rays, "{what}: ray-count map");
    assert_eq!(scalar.over_budget, waves.over_budget, "{what}: over budget");
}

#[test]
fn every_chapter_at_its_defaults_is_the_same_image_to_the_byte() {
    let (scene, camera) = (Scene::lab(), Camera::lab());
    for like in Like::ALL {
        assert_same(like, &scene, &camera, &settings(like, (160, 120)));
    }
}

#[test]
fn odd_widths_with_a_partial_last_group_and_a_single_pixel_are_the_same() {
    let (scene, camera) = (Scene::lab(), Camera::lab());
    for size in [(83, 61), (803, 5), (1, 1), (7, 3)] {
        for like in [Like::Shadows, Like::Refraction, Like::AntiAliasing] {
            assert_same(like, &scene, &camera, &settings(like, size));
        }
    }
}

#[test]
fn other_depths_and_one_ray_per_pixel_are_the_same() {
    let (scene, camera) = (Scene::lab(), Camera::lab());
    for max_depth in [1, 2, 3, 17] {
        let mut s = settings(Like::AntiAliasing, (120, 90));
        s.max_depth = max_depth;
        assert_same(Like::AntiAliasing, &scene, &camera, &s);
        s.sampling = Sampling::PIXEL_CENTRE;
        assert_same(Like::AntiAliasing, &scene, &camera, &s);
    }
    // Glass seen by a chapter without shadows: every feature is separate.
    let mut s = settings(Like::Reflection, (120, 90));
    s.max_depth = 3;
    assert_same(Like::Reflection, &scene, &camera, &s);
}

#[test]
fn every_rays_per_pixel_pattern_gives_chapter_5s_bytes_for_the_same_seed() {
    let (scene, camera) = (Scene::lab(), Camera::lab());
    for (spp, pattern, seed) in [
        (16, Pattern::Grid, 0),
        (16, Pattern::Jittered, 7),
        (9, Pattern::Random, 3),
        (12, Pattern::Halton, 11),
    ] {
        let mut s = settings(Like::AntiAliasing, (45, 33));
        s.sampling = Sampling::new(spp, Some(pattern), seed).expect("a valid pattern");
        assert_same(Like::AntiAliasing, &scene, &camera, &s);
    }
}

#[test]
fn points_the_same_in_every_pixel_give_the_same_bytes_whatever_their_period() {
    // Chapter 7 reads such points from a table of one period of groups
    // (lcm(spp, 8) samples): 1 group for 4 points, 9 for 9, 25 for 25, 8
    // for 64; 1024 points are past the table and found lane by lane.
    let (scene, camera) = (Scene::lab(), Camera::lab());
    for (spp, size) in [
        (4, (45, 33)),
        (9, (45, 33)),
        (25, (23, 17)),
        (64, (11, 9)),
        (1024, (5, 3)),
    ] {
        let mut s = settings(Like::AntiAliasing, size);
        s.sampling = Sampling::new(spp, Some(Pattern::Grid), 0).expect("a square");
        assert_same(Like::AntiAliasing, &scene, &camera, &s);
    }
}

#[test]
fn every_scene_file_renders_the_same() {
    let scenes = Path::new(env!("CARGO_MANIFEST_DIR")).join("../scenes");
    let mut files: Vec<_> = std::fs::read_dir(&scenes)
        .expect("the scenes folder")
        .map(|e| e.expect("a scene file").path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .collect();
    files.sort();
    assert!(files.len() >= 4, "{files:?}");
    for file in files {
        let (scene, camera) = raylab_cli::scene_file::load(&file).expect("the scene loads");
        for like in [Like::Reflection, Like::AntiAliasing] {
            assert_same(like, &scene, &camera, &settings(like, (96, 72)));
        }
    }
}

#[test]
fn with_no_offset_the_trees_that_reach_the_ray_budget_are_the_same() {
    // --epsilon 0 lets rays re-hit the surface they leave and split again
    // and again: some trees reach the budget, and are cut where the scalar
    // tracer cuts them.
    let (scene, camera) = (Scene::lab(), Camera::lab());
    let mut s = settings(Like::Refraction, (64, 48));
    s.epsilon = 0.0;
    s.max_depth = 24;
    assert_same(Like::Refraction, &scene, &camera, &s);
}

#[test]
fn keeping_only_the_8_bit_image_both_tracers_make_the_same_one_and_keep_nothing_else() {
    let (scene, camera) = (Scene::lab(), Camera::lab());
    let settings = settings(Like::AntiAliasing, (83, 61));
    let hidden = NoProgress;
    let step = EightRays {
        like: Like::AntiAliasing,
    };
    let kept = render_waves(&scene, &camera, &step, &settings, Keep::ALL, &hidden);
    let scalar = render(&scene, &camera, &step, &settings, Keep::IMAGE, &hidden);
    let waves = render_waves(&scene, &camera, &step, &settings, Keep::IMAGE, &hidden);
    for skipped in [&scalar, &waves] {
        assert!(skipped.maps.is_none());
        assert!(skipped.linear.is_none());
        assert_eq!(skipped.srgb, kept.srgb);
        assert_eq!(skipped.counts, kept.counts);
    }
}
