//! `g`: the view rendered again by chapter 10's shader, beside the CPU's.
//!
//! The comparison itself needs a GPU adapter: any Vulkan one will do, and
//! Mesa's lavapipe runs on the CPU (CI installs it). On a machine without
//! one, the test that needs it says so and passes, unless `CI` is set, as
//! chapter 10's own tests do. The refusals need no adapter.

use std::process::Command;

use image::{GenericImageView, RgbImage};
use raylab::tolerance::compare;
use raylab_explore::source::Loaded;
use raylab_explore::{Explorer, Input, Key};

const W: u32 = 160;
const H: u32 = 120;

fn key(explorer: &mut Explorer, c: char) {
    explorer.handle(Input::Key(Key::Char(c)));
}

fn right_half(image: &RgbImage) -> RgbImage {
    let half = image.width() / 2;
    image
        .view(half, 0, image.width() - half, image.height())
        .to_image()
}

fn left_half(image: &RgbImage) -> RgbImage {
    image
        .view(0, 0, image.width() / 2, image.height())
        .to_image()
}

fn overlay_lines(explorer: &Explorer) -> Vec<String> {
    raylab_explore::overlay::status_lines(explorer)
        .into_iter()
        .map(|(line, _)| line)
        .collect()
}

#[test]
fn pressing_g_shows_the_gpu_render_beside_the_cpu_one_within_lab_tolerance() {
    if ch10_gpu::gpu::Gpu::for_tests().is_none() {
        return;
    }
    let mut explorer = Explorer::new(Loaded::lab(), W, H);
    for n in ['1', '2', '3', '4', '5'] {
        key(&mut explorer, n);
        if !explorer.gpu().is_on() {
            key(&mut explorer, 'g');
        }
        explorer.settle(10);
        let cpu = explorer.image().clone();
        let gpu = explorer
            .gpu()
            .frame((W, H))
            .unwrap_or_else(|| panic!("chapter {n}: no GPU frame: {:?}", explorer.gpu().outcome()));
        let shown = explorer.scene_frame();
        // The CPU's image on the left, the GPU's on the right...
        assert!(left_half(&shown) == left_half(&cpu), "chapter {n}");
        assert!(right_half(&shown) == right_half(&gpu.image), "chapter {n}");
        // ... and the GPU's half is the CPU's within the lab model's tolerance,
        // as is the whole GPU image.
        let half = compare(&right_half(&shown), &right_half(&cpu));
        println!(
            "chapter {n}: GPU half {:.3} % within 3 levels, largest difference {}",
            half.within_3 * 100.0,
            half.max
        );
        assert!(half.meets_lab_tolerance(), "chapter {n}: {half:?}");
        assert!(gpu.agreement.meets_lab_tolerance(), "chapter {n}");
        let lines = overlay_lines(&explorer);
        assert!(
            lines.iter().any(|l| l.contains("ms (dispatch + readback)")),
            "{lines:?}"
        );
        assert!(
            lines
                .iter()
                .any(|l| l.contains("% of pixels within 3 levels") && l.contains("tolerance met")),
            "{lines:?}"
        );
    }
    // `g` again: the CPU's frame alone.
    key(&mut explorer, 'g');
    assert!(explorer.scene_frame() == *explorer.image());
    assert!(overlay_lines(&explorer).iter().all(|l| !l.contains("GPU")));
}

#[test]
fn the_explorer_looks_for_no_gpu_until_g_is_pressed() {
    let mut explorer = Explorer::new(Loaded::lab(), W, H);
    explorer.settle(10);
    assert!(explorer.gpu().outcome().is_none());
    assert_eq!(explorer.gpu().adapter(), None);
    assert!(explorer.scene_frame() == *explorer.image());
}

#[test]
fn in_path_tracing_or_at_16_rays_per_pixel_g_says_why_in_one_line_and_the_explorer_goes_on() {
    let mut explorer = Explorer::new(Loaded::lab(), W, H);
    explorer.settle(10);
    key(&mut explorer, 'r');
    key(&mut explorer, 'g');
    explorer.settle(10);
    assert!(explorer.is_settled());
    let gpu_lines = |explorer: &Explorer| -> Vec<String> {
        overlay_lines(explorer)
            .into_iter()
            .filter(|l| l.contains("GPU"))
            .collect()
    };
    let lines = gpu_lines(&explorer);
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].contains("16 rays/px") && lines[0].contains("jittered"),
        "{lines:?}"
    );
    // A refusal needs no device, and the reason reaches the terminal too.
    assert_eq!(explorer.gpu().adapter(), None);
    assert!(
        explorer
            .take_messages()
            .iter()
            .any(|m| m.contains("jittered"))
    );

    key(&mut explorer, '6');
    explorer.frame();
    explorer.frame();
    assert_eq!(explorer.samples().0, 2, "path tracing goes on");
    let lines = gpu_lines(&explorer);
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(lines[0].contains("path tracing"), "{lines:?}");
    assert!(explorer.scene_frame() == *explorer.image());
}

#[test]
fn with_no_gpu_adapter_g_says_so_in_one_line_and_the_explorer_goes_on() {
    let dir = tempfile::tempdir().unwrap();
    let shot = dir.path().join("shot.png");
    let shot_text = shot.display().to_string();
    let output = Command::new(env!("CARGO_BIN_EXE_raylab-explore"))
        .args([
            "--headless",
            "--width",
            "96",
            "--height",
            "64",
            "--script",
            "key:g settle key:3 settle",
            "--screenshot",
            &shot_text,
        ])
        .env(ch10_gpu::gpu::NO_ADAPTER_VAR, "1")
        .env_remove("DISPLAY")
        .output()
        .unwrap();
    assert!(
        output.status.success(),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
    let stdout = String::from_utf8_lossy(&output.stdout);
    let said: Vec<&str> = stdout.lines().filter(|l| l.contains("GPU")).collect();
    // Said once, though two chapters were rendered after it.
    assert_eq!(said.len(), 1, "{stdout}");
    assert!(said[0].contains("no GPU adapter found"), "{stdout}");
    let image = image::open(&shot).unwrap().to_rgb8();
    assert_eq!(image.dimensions(), (96, 64));
}

#[test]
fn while_the_camera_moves_the_gpu_half_waits_for_the_view_to_be_still() {
    if ch10_gpu::gpu::Gpu::for_tests().is_none() {
        return;
    }
    let mut explorer = Explorer::new(Loaded::lab(), W, H);
    key(&mut explorer, 'g');
    explorer.settle(10);
    assert!(explorer.gpu().frame((W, H)).is_some());
    // A drag: a preview of one ray per pixel, with no GPU frame behind it.
    let button = raylab_explore::Button::Left;
    explorer.handle(Input::Press {
        button,
        x: 50.0,
        y: 50.0,
    });
    explorer.handle(Input::Move { x: 90.0, y: 60.0 });
    assert!(explorer.frame());
    assert_eq!(explorer.samples(), (1, 5));
    assert!(
        explorer.gpu().is_pending(),
        "{:?}",
        explorer.gpu().outcome()
    );
    assert!(
        explorer.scene_frame() == *explorer.image(),
        "the CPU's image alone"
    );
    explorer.handle(Input::Release {
        button,
        x: 90.0,
        y: 60.0,
    });
    explorer.settle(10);
    let gpu = explorer
        .gpu()
        .frame((W, H))
        .expect("a GPU frame once still");
    assert!(gpu.agreement.meets_lab_tolerance());
}
