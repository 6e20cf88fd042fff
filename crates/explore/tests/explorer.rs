//! The explorer driven without a screen: synthetic keys and mouse, frames
//! compared with the chapters' own renders.

use std::path::Path;
use std::process::Command;

use image::RgbImage;
use raylab::probe::ProbeTarget;
use raylab::{Camera, Scene, Step};
use raylab_cli::{Chapter, Options};
use raylab_explore::source::Loaded;
use raylab_explore::state::Action;
use raylab_explore::{Button, Explorer, Input, Key};

const W: u32 = 160;
const H: u32 = 120;

fn explorer() -> Explorer {
    Explorer::new(Loaded::lab(), W, H)
}

fn key(explorer: &mut Explorer, c: char) -> Action {
    explorer.handle(Input::Key(Key::Char(c)))
}

/// What the chapter's program writes as render.png for these flags.
fn chapter_render<S: Step>(chapter: &Chapter<S>, flags: &[&str]) -> RgbImage {
    let out = tempfile::tempdir().unwrap();
    let mut args = vec![chapter.binary.to_owned()];
    let size = ["--width", &W.to_string(), "--height", &H.to_string()].map(String::from);
    args.extend(size);
    args.extend(flags.iter().map(|s| s.to_string()));
    args.extend(["--no-diagrams", "--quiet", "--out"].map(String::from));
    args.push(out.path().display().to_string());
    let options = Options::parse_for(chapter, args).unwrap();
    raylab_cli::run(chapter, &options).unwrap().rendered.srgb
}

fn whitted_render(n: u32, flags: &[&str]) -> RgbImage {
    match n {
        1 => chapter_render(&ch01_ray_cast::CHAPTER, flags),
        2 => chapter_render(&ch02_shadows::CHAPTER, flags),
        3 => chapter_render(&ch03_reflection::CHAPTER, flags),
        4 => chapter_render(&ch04_refraction::CHAPTER, flags),
        _ => chapter_render(&ch05_antialiasing::CHAPTER, flags),
    }
}

fn drag(explorer: &mut Explorer, from: (f64, f64), to: (f64, f64)) {
    let button = Button::Left;
    explorer.handle(Input::Press {
        button,
        x: from.0,
        y: from.1,
    });
    explorer.handle(Input::Move { x: to.0, y: to.1 });
    explorer.frame();
    explorer.handle(Input::Release {
        button,
        x: to.0,
        y: to.1,
    });
}

#[test]
fn a_still_frame_of_each_whitted_chapter_is_the_chapters_render_to_the_byte() {
    for n in 1..=5 {
        let mut explorer = explorer();
        key(&mut explorer, char::from_digit(n, 10).unwrap());
        explorer.settle(10);
        assert!(explorer.is_settled());
        assert!(
            *explorer.image() == whitted_render(n, &[]),
            "chapter {n}'s still frame differs from its program's render"
        );
    }
}

#[test]
fn epsilon_zero_brings_shadow_acne_live_as_the_chapter_draws_it() {
    let mut explorer = explorer();
    key(&mut explorer, '2');
    explorer.settle(10);
    let clean = explorer.image().clone();
    key(&mut explorer, 'e');
    explorer.settle(10);
    assert_ne!(*explorer.image(), clean, "acne changes the picture");
    assert!(*explorer.image() == whitted_render(2, &["--epsilon", "0"]));
}

#[test]
fn depth_and_rays_per_pixel_keys_give_the_chapters_image_with_those_flags() {
    let mut explorer = explorer();
    key(&mut explorer, '4');
    explorer.handle(Input::Key(Key::Down));
    explorer.handle(Input::Key(Key::Down));
    key(&mut explorer, 'r'); // 1 → 5
    key(&mut explorer, 'r'); // 5 → 16
    explorer.settle(10);
    assert_eq!(explorer.samples(), (16, 16));
    assert!(*explorer.image() == whitted_render(4, &["--max-depth", "8", "--spp", "16"]));
}

#[test]
fn a_moving_camera_shows_one_ray_per_pixel_then_refines_when_it_stops() {
    let mut explorer = explorer();
    let button = Button::Left;
    explorer.handle(Input::Press {
        button,
        x: 50.0,
        y: 50.0,
    });
    explorer.handle(Input::Move { x: 90.0, y: 60.0 });
    assert!(explorer.frame());
    assert_eq!(explorer.samples(), (1, 5));
    // Held still with the button down: nothing more to draw.
    assert!(!explorer.frame());
    explorer.handle(Input::Release {
        button,
        x: 90.0,
        y: 60.0,
    });
    assert!(explorer.frame());
    assert_eq!(explorer.samples(), (5, 5));
    assert!(!explorer.view.is_home());
}

#[test]
fn a_saved_frame_after_orbiting_is_what_the_printed_command_renders() {
    let dir = tempfile::tempdir().unwrap();
    let mut explorer = explorer();
    key(&mut explorer, '3');
    drag(&mut explorer, (40.0, 60.0), (100.0, 40.0));
    explorer.handle(Input::Wheel(2.0));
    explorer.frame();
    let saved = raylab_explore::save::save(&mut explorer, dir.path()).unwrap();
    let scene = saved.scene.expect("a moved camera writes its scene");
    assert!(
        saved.command.contains("-p ch03-reflection"),
        "{}",
        saved.command
    );
    assert!(
        saved
            .command
            .contains(&format!("--scene {}", scene.display()))
    );
    let png = image::open(&saved.png).unwrap().to_rgb8();
    assert!(png == *explorer.image());
    let scene = scene.display().to_string();
    assert!(png == whitted_render(3, &["--scene", &scene]));
}

#[test]
fn the_camera_key_goes_back_to_the_lab_camera_exactly() {
    let mut explorer = explorer();
    drag(&mut explorer, (10.0, 10.0), (80.0, 90.0));
    explorer.handle(Input::Key(Key::Left));
    assert_ne!(explorer.camera(), Camera::lab());
    key(&mut explorer, 'c');
    assert_eq!(explorer.camera(), Camera::lab());
    explorer.settle(10);
    assert!(*explorer.image() == whitted_render(5, &[]));
}

#[test]
fn path_tracing_accumulates_one_path_per_pixel_a_frame_and_starts_again_when_moved() {
    let mut explorer = explorer();
    key(&mut explorer, '6');
    assert!(explorer.frame());
    // The first pass is chapter 8's one-path image, seed 0.
    let settings = explorer.knobs.path_pass(W, H, 0).unwrap();
    let one = ch08_eight_paths::render_eight(
        &Scene::lab(),
        &Camera::lab(),
        &settings,
        &raylab::NoProgress,
    );
    assert!(*explorer.image() == one.image.to_srgb8());
    for _ in 0..3 {
        explorer.frame();
    }
    assert_eq!(explorer.samples(), (4, 256));
    let four = explorer.image().clone();
    assert_ne!(four, one.image.to_srgb8());
    explorer.handle(Input::Key(Key::Right));
    explorer.frame();
    assert_eq!(explorer.samples().0, 1);
}

#[test]
fn path_tracing_stops_at_the_paths_per_pixel_asked_for() {
    let mut explorer = explorer();
    key(&mut explorer, '6');
    explorer.knobs.spp = 3;
    explorer.settle(100);
    assert_eq!(explorer.samples(), (3, 3));
    assert!(!explorer.frame());
    // The sun's size and the materials start the average again.
    key(&mut explorer, ']');
    key(&mut explorer, 'm');
    assert!(explorer.frame());
    assert_eq!(explorer.samples().0, 1);
}

fn glass_pixel() -> (u32, u32) {
    ProbeTarget::centre_of("glass")
        .pixel(&Scene::lab(), &Camera::lab(), W, H)
        .unwrap()
}

#[test]
fn a_click_shows_the_pixels_ray_tree_in_the_scene_and_prints_its_text() {
    let mut explorer = explorer();
    key(&mut explorer, '4');
    explorer.settle(10);
    let plain = explorer.compose();
    let (x, y) = glass_pixel();
    let button = Button::Left;
    let (fx, fy) = (f64::from(x) + 0.5, f64::from(y) + 0.5);
    explorer.handle(Input::Press {
        button,
        x: fx,
        y: fy,
    });
    explorer.handle(Input::Release {
        button,
        x: fx,
        y: fy,
    });
    let probe = explorer.probe().expect("a click probes").clone();
    assert_eq!(probe.pixel, (x, y));
    let kinds: Vec<_> = probe.trees[0].rays.iter().map(|r| r.kind).collect();
    assert!(kinds.contains(&raylab::RayKind::Refraction), "{kinds:?}");
    let messages = explorer.take_messages();
    assert_eq!(messages, vec![probe.text.clone()]);
    assert!(probe.text.contains("glass"), "{}", probe.text);
    assert_ne!(
        explorer.compose(),
        plain,
        "the tree is drawn over the scene"
    );
    // It stays while orbiting, seen from the side.
    drag(&mut explorer, (10.0, 60.0), (120.0, 60.0));
    explorer.settle(10);
    assert!(explorer.probe().is_some());
    // Chapter 3 has no glass: the same pixel's tree loses its refraction.
    key(&mut explorer, '3');
    let kinds: Vec<_> = explorer.probe().unwrap().trees[0]
        .rays
        .iter()
        .map(|r| r.kind)
        .collect();
    assert!(!kinds.contains(&raylab::RayKind::Refraction));
    // Path tracing has no tree: the click keeps chapter 3's, at its one ray.
    key(&mut explorer, '6');
    assert_eq!(explorer.probe().unwrap().trees.len(), 1);
    explorer.handle(Input::Key(Key::Escape));
    assert!(explorer.probe().is_none());
}

#[test]
fn a_click_outside_the_image_probes_nothing_and_says_so() {
    let mut explorer = explorer();
    let button = Button::Left;
    for (x, y) in [
        (-3.0, 10.0),
        (10.0, f64::from(H)),
        (f64::from(W) + 20.0, 5.0),
    ] {
        explorer.handle(Input::Press { button, x, y });
        explorer.handle(Input::Release { button, x, y });
        assert!(explorer.probe().is_none());
        assert!(explorer.status().unwrap().contains("outside"));
    }
}

#[test]
fn a_window_minimised_or_resized_to_nothing_renders_nothing_until_it_is_back() {
    let mut explorer = explorer();
    explorer.settle(10);
    explorer.handle(Input::Resize {
        width: 0,
        height: 0,
    });
    explorer.handle(Input::Key(Key::Right));
    assert!(!explorer.frame());
    let _ = explorer.compose();
    explorer.handle(Input::Resize {
        width: 80,
        height: 0,
    });
    assert!(!explorer.frame());
    explorer.handle(Input::Resize {
        width: 100,
        height: 70,
    });
    assert!(explorer.frame());
    assert_eq!(explorer.image().dimensions(), (100, 70));
    assert_eq!(explorer.compose().dimensions(), (100, 70));
}

#[test]
fn a_broken_scene_save_shows_its_error_and_keeps_the_last_good_scene() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("scene.toml");
    std::fs::write(&path, raylab_explore::source::LAB_TOML).unwrap();
    let mut explorer = Explorer::new(Loaded::file(&path).unwrap(), W, H);
    explorer.settle(10);
    let good = explorer.image().clone();
    std::fs::write(&path, "[camera]\neye = [0, 1,").unwrap();
    raylab_explore::watch::reload(&mut explorer, &path);
    let status = explorer.status().unwrap().to_owned();
    assert!(status.contains("keeping the last good scene"), "{status}");
    assert!(!status.contains('\n'), "one line: {status}");
    explorer.settle(10);
    assert_eq!(*explorer.image(), good);
    // Deleted while watched: the same.
    std::fs::remove_file(&path).unwrap();
    raylab_explore::watch::reload(&mut explorer, &path);
    assert!(explorer.status().unwrap().contains("cannot read"));
    // A good save again: the new scene, the error gone.
    let moved = raylab_explore::source::LAB_TOML.replace("radius = 1.0", "radius = 0.5");
    std::fs::write(&path, moved).unwrap();
    raylab_explore::watch::reload(&mut explorer, &path);
    assert!(explorer.status().is_none());
    explorer.settle(10);
    assert_ne!(*explorer.image(), good);
}

#[test]
fn a_scene_file_saved_in_an_editor_is_picked_up_by_the_watch() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("scene.toml");
    std::fs::write(&path, raylab_explore::source::LAB_TOML).unwrap();
    let mut explorer = Explorer::new(Loaded::file(&path).unwrap(), W, H);
    let mut watch = raylab_explore::watch::SceneWatch::new(&path).unwrap();
    std::fs::write(&path, "not a scene").unwrap();
    let start = std::time::Instant::now();
    while !watch.poll(&mut explorer) {
        assert!(start.elapsed().as_secs() < 10, "no reload within 10 s");
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
    assert!(explorer.status().is_some());
}

#[test]
fn the_overlay_shows_the_knobs_their_values_and_the_frame_time() {
    let mut explorer = explorer();
    explorer.settle(10);
    let lines: Vec<String> = raylab_explore::overlay::status_lines(&explorer)
        .into_iter()
        .map(|(l, _)| l)
        .collect();
    assert!(
        lines[0].contains("chapter 5") && lines[0].contains("depth 10"),
        "{lines:?}"
    );
    assert!(
        lines[0].contains("5 rays/px") && lines[0].contains("ε 0.0001"),
        "{lines:?}"
    );
    assert!(
        lines[1].contains("ms/frame") && lines[1].contains("Mrays/s"),
        "{lines:?}"
    );
    key(&mut explorer, '6');
    let lines = raylab_explore::overlay::status_lines(&explorer);
    assert!(lines[0].0.contains("sun point") && lines[0].0.contains("lab materials"));
    key(&mut explorer, '?');
    assert!(explorer.knobs.help);
}

#[test]
fn q_quits_and_w_asks_to_save() {
    let mut explorer = explorer();
    assert_eq!(key(&mut explorer, 'q'), Action::Quit);
    assert_eq!(key(&mut explorer, 'w'), Action::Save);
    assert_eq!(key(&mut explorer, 'x'), Action::None);
}

fn explore(args: &[&str], display: Option<&str>) -> std::process::Output {
    let mut command = Command::new(env!("CARGO_BIN_EXE_raylab-explore"));
    command.args(args);
    match display {
        Some(d) => command.env("DISPLAY", d),
        None => command.env_remove("DISPLAY"),
    };
    command.output().unwrap()
}

fn one_error_line(output: &std::process::Output) -> String {
    assert_eq!(output.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&output.stderr).into_owned();
    assert_eq!(stderr.lines().count(), 1, "{stderr}");
    assert!(stderr.starts_with("raylab-explore: error: "), "{stderr}");
    stderr
}

#[test]
fn without_a_display_the_explorer_says_so_in_one_line_and_exits_2() {
    let stderr = one_error_line(&explore(&[], None));
    assert!(stderr.contains("no display"), "{stderr}");
    let stderr = one_error_line(&explore(&[], Some(":4242")));
    assert!(stderr.contains("display"), "{stderr}");
}

#[test]
fn bad_flags_scenes_and_scripts_are_one_line_and_exit_2() {
    one_error_line(&explore(&["--width", "0"], None));
    one_error_line(&explore(&["--scene", "no/such/scene.toml"], None));
    let stderr = one_error_line(&explore(&["--headless", "--script", "jump:1"], None));
    assert!(stderr.contains("jump"), "{stderr}");
}

#[test]
fn a_headless_script_writes_the_frame_it_would_show() {
    let dir = tempfile::tempdir().unwrap();
    let shot = dir.path().join("shot.png");
    let shot_text = shot.display().to_string();
    let output = explore(
        &[
            "--headless",
            "--width",
            "96",
            "--height",
            "64",
            "--script",
            "key:2 click:40,50 settle",
            "--screenshot",
            &shot_text,
        ],
        None,
    );
    assert!(
        output.status.success(),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
    let stdout = String::from_utf8_lossy(&output.stdout);
    assert!(
        stdout.contains("ray tree") || stdout.contains("primary"),
        "{stdout}"
    );
    let image = image::open(Path::new(&shot)).unwrap().to_rgb8();
    assert_eq!(image.dimensions(), (96, 64));
}

#[test]
fn a_saved_frame_of_a_scene_file_keeps_the_scene_as_it_was_when_saved() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("mine.toml");
    let text = raylab_explore::source::LAB_TOML.replace("radius = 1.0", "radius = 0.7");
    std::fs::write(&path, &text).unwrap();
    let mut explorer = Explorer::new(Loaded::file(&path).unwrap(), W, H);
    let saved = raylab_explore::save::save(&mut explorer, &dir.path().join("out")).unwrap();
    std::fs::remove_file(&path).unwrap();
    let scene = saved.scene.expect("a scene file's frame carries its scene");
    assert_eq!(std::fs::read_to_string(&scene).unwrap(), text);
    let png = image::open(&saved.png).unwrap().to_rgb8();
    assert!(png == whitted_render(5, &["--scene", &scene.display().to_string()]));
}

#[test]
fn the_lab_from_the_lab_camera_saves_with_no_scene_file() {
    let dir = tempfile::tempdir().unwrap();
    let mut explorer = explorer();
    key(&mut explorer, '1');
    let saved = raylab_explore::save::save(&mut explorer, dir.path()).unwrap();
    assert!(saved.scene.is_none());
    assert!(!saved.command.contains("--scene"), "{}", saved.command);
    assert!(
        saved.command.contains("-p ch01-ray-cast -- --spp 1"),
        "{}",
        saved.command
    );
}

#[test]
fn every_book_figure_script_is_a_valid_script() {
    for (name, text) in raylab_explore::figures::scripts() {
        assert!(
            raylab_explore::script::parse(&text).is_ok(),
            "{name}: {text}"
        );
    }
}

#[test]
fn the_book_figures_keys_set_what_their_names_say() {
    let knobs_after = |name: &str| {
        let (_, text) = raylab_explore::figures::scripts()
            .into_iter()
            .find(|(n, _)| *n == name)
            .unwrap();
        let mut explorer = explorer();
        for step in raylab_explore::script::parse(&text).unwrap() {
            if let raylab_explore::script::Instruction::Input(input @ Input::Key(_)) = step {
                explorer.handle(input);
            }
        }
        explorer.knobs
    };
    let ch03 = knobs_after("explorer-ch03-depth-1.png");
    assert_eq!((ch03.chapter_number(), ch03.max_depth, ch03.spp), (3, 1, 1));
    let paths = knobs_after("explorer-paths.png");
    assert_eq!((paths.chapter_number(), paths.spp), (6, 64));
    let sun = knobs_after("explorer-sun-20.png");
    assert_eq!((sun.sun_size, sun.spp), (Some(20.0), 64));
    let acne = knobs_after("explorer-acne.png");
    assert_eq!((acne.chapter_number(), acne.epsilon), (2, 0.0));
}
