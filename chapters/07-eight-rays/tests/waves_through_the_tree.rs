//! Chapter 7's waves with `--objects tree` make chapter 7's own images:
//! every hit found through chapter 9's tree, eight rays against each node,
//! the same bytes, counts and maps as the list, on the lab scene and on a
//! field of spheres, like each Whitted chapter.

use ch07_eight_rays::render::render_waves;
use ch07_eight_rays::{EightRays, Like, Objects};
use ch09_many_spheres::field::field_scene;
use raylab::{Camera, Keep, NoProgress, Scene, Settings, Step};
use raylab_cli::Options;

#[test]
fn chapter_7s_waves_through_the_tree_make_chapter_7s_images_like_each_chapter() {
    for (scene, camera) in [(Scene::lab(), Camera::lab()), field_scene(300)] {
        for like in Like::ALL {
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
            // The renderer `--objects tree` chooses: the tree built, then searched.
            let through_tree = ch07_eight_rays::chapter_through(like, Objects::Tree).render;
            let tree = through_tree(&scene, &camera, &step, &settings, keep, &NoProgress);
            assert!(list.srgb == tree.srgb, "{like:?}: the images differ");
            assert_eq!(list.counts, tree.counts, "{like:?}");
            assert!(list.maps == tree.maps, "{like:?}: the maps differ");
        }
    }
}

#[test]
fn the_program_with_objects_tree_writes_the_lists_files_and_refuses_other_objects() {
    let dir = tempfile::tempdir().unwrap();
    let program = env!("CARGO_BIN_EXE_ch07-eight-rays");
    let files = |objects: &str| {
        let out = dir.path().join(objects);
        let status = std::process::Command::new(program)
            .args([
                "--width",
                "40",
                "--height",
                "30",
                "--quiet",
                "--objects",
                objects,
            ])
            .arg("--out")
            .arg(&out)
            .status()
            .unwrap();
        assert!(status.success());
        ["render.png", "depth.png", "rays.png", "probe.txt"]
            .map(|name| std::fs::read(out.join(name)).unwrap())
    };
    assert!(files("list") == files("tree"), "the files differ");
    let bad = std::process::Command::new(program)
        .args(["--objects", "grid"])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&bad.stderr);
    assert_eq!(bad.status.code(), Some(2), "{stderr}");
    assert_eq!(stderr.lines().count(), 1, "{stderr}");
    assert!(
        stderr.contains("list") && stderr.contains("tree"),
        "{stderr}"
    );
}
