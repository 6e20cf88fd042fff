//! The book's extra figures: renders with one flag changed, crops, and two
//! small geometry diagrams drawn from the code's own numbers.

use std::path::{Path, PathBuf};

use image::RgbImage;
use raylab::sampling::LAB_FIVE;
use raylab::{Camera, Keep, NoProgress, Sampling, Scene, Settings, Step, render};
use raylab_cli::output::save_png;
use raylab_plot::colour::{AXIS, GRID, TEXT, TEXT_MUTED, WHITE};
use raylab_plot::{Anchor, Canvas};

use crate::{JobError, Size};

/// The files [`make_extras`] writes.
pub const NAMES: [&str; 8] = [
    "ch02-epsilon-0.png",
    "ch04-depth-2.png",
    "ch04-depth-3.png",
    "ch05-spp1-crop.png",
    "ch05-spp5-crop.png",
    "ch05-spp16-crop.png",
    "shadow-offset.png",
    "five-samples.png",
];

fn settings(size: Size, max_depth: u32, spp: u32, epsilon: f32) -> Settings {
    Settings {
        width: size.width,
        height: size.height,
        max_depth,
        epsilon,
        sampling: Sampling::new(spp, None, 0).expect("1, 5 or a square"),
    }
}

fn render_srgb<S: Step>(step: &S, settings: &Settings) -> RgbImage {
    let (scene, camera) = (Scene::lab(), Camera::lab());
    render(&scene, &camera, step, settings, Keep::IMAGE, &NoProgress).srgb
}

/// The region of the crops, in 120ths of the image's width and height
/// `(left, top, width, height)`: open ground from just above the horizon
/// down, right of the glass ball (which reaches the horizon further left),
/// where the checker squares shrink from a few pixels to far below one.
const HORIZON_CROP: (u32, u32, u32, u32) = (105, 38, 15, 14);

/// How many times the crops are magnified.
const HORIZON_ZOOM: u32 = 4;

/// The horizon region of `image`, magnified [`HORIZON_ZOOM`] times, with
/// a line under it that says which pixels it shows, at what zoom and with
/// how many rays: the three crops step through one place.
fn horizon_crop(image: &RgbImage, spp: u32) -> RgbImage {
    let (w, h) = image.dimensions();
    let (fx, fy, fw, fh) = HORIZON_CROP;
    let (x, y) = (w * fx / 120, h * fy / 120);
    let (cw, ch) = (
        (w * fw / 120).clamp(1, w - x),
        (h * fh / 120).clamp(1, h - y),
    );
    let crop = image::imageops::crop_imm(image, x, y, cw, ch).to_image();
    let zoomed = image::imageops::resize(
        &crop,
        cw * HORIZON_ZOOM,
        ch * HORIZON_ZOOM,
        image::imageops::FilterType::Nearest,
    );
    let strip = 48;
    let mut canvas = Canvas::new(zoomed.width(), zoomed.height() + strip, WHITE);
    canvas.draw_rgb_image(&zoomed, 0, 0, 1);
    let rays = if spp == 1 {
        "1 ray".to_owned()
    } else {
        format!("{spp} rays")
    };
    let lines = [
        format!("{rays} per pixel, magnified {HORIZON_ZOOM}×:"),
        format!(
            "pixels {x}–{} × {y}–{} of the {w}×{h} render",
            x + cw - 1,
            y + ch - 1
        ),
    ];
    for (k, line) in lines.iter().enumerate() {
        canvas.text(
            6.0,
            zoomed.height() as f32 + 6.0 + 20.0 * k as f32,
            line,
            14.0,
            TEXT,
            Anchor::TOP_LEFT,
        );
    }
    canvas.to_rgb_image()
}

/// Write every extra figure into `dir`.
pub fn make_extras(dir: &Path, size: Size) -> Result<Vec<PathBuf>, JobError> {
    raylab_cli::prepare_out_dir(dir)?;
    let shadows = ch02_shadows::Shadows;
    let refraction = ch04_refraction::Refraction;
    let images: [RgbImage; 8] = [
        render_srgb(&shadows, &settings(size, 1, 1, 0.0)),
        render_srgb(&refraction, &settings(size, 2, 1, 1e-4)),
        render_srgb(&refraction, &settings(size, 3, 1, 1e-4)),
        horizon_crop(&render_srgb(&refraction, &settings(size, 10, 1, 1e-4)), 1),
        horizon_crop(&render_srgb(&refraction, &settings(size, 10, 5, 1e-4)), 5),
        horizon_crop(&render_srgb(&refraction, &settings(size, 10, 16, 1e-4)), 16),
        shadow_offset_diagram(),
        five_samples_diagram(),
    ];
    let mut written = Vec::new();
    for (name, image) in NAMES.iter().zip(&images) {
        let path = dir.join(name);
        save_png(image, &path)?;
        written.push(path);
    }
    Ok(written)
}

/// The scene files' renders, each with the chapter and depth that make
/// its point: `(figure, scene file, max depth)`.
pub const SCENE_FIGURES: [(&str, &str, u32); 4] = [
    ("two-mirrors-depth-2.png", "two-mirrors.toml", 2),
    ("two-mirrors-depth-20.png", "two-mirrors.toml", 20),
    ("water-and-glass.png", "water-and-glass.toml", 10),
    (
        "total-internal-reflection.png",
        "total-internal-reflection.toml",
        10,
    ),
];

/// Render the scene files of `scenes` into `dir` with chapter 4's step
/// (which does everything chapters 2 and 3 do, and refraction).
pub fn make_scene_figures(dir: &Path, scenes: &Path, size: Size) -> Result<Vec<PathBuf>, JobError> {
    raylab_cli::prepare_out_dir(dir)?;
    let mut written = Vec::new();
    for (name, file, max_depth) in SCENE_FIGURES {
        let (scene, camera) =
            raylab_cli::scene_file::load(&scenes.join(file)).map_err(raylab_cli::CliError::from)?;
        let settings = settings(size, max_depth, 1, 1e-4);
        let image = render(
            &scene,
            &camera,
            &ch04_refraction::Refraction,
            &settings,
            Keep::IMAGE,
            &NoProgress,
        )
        .srgb;
        let image = label_clear_spheres(&image, &scene, &camera);
        let path = dir.join(name);
        save_png(&image, &path)?;
        written.push(path);
    }
    Ok(written)
}

/// The picture with a strip under it that names each clear ball in view
/// and its index of refraction, under the ball's centre: water and glass
/// look alike until the reader knows which is which. A picture with no
/// clear ball in view comes back as it was.
fn label_clear_spheres(image: &RgbImage, scene: &Scene, camera: &Camera) -> RgbImage {
    let (width, height) = image.dimensions();
    let labels: Vec<(f32, String)> = scene
        .spheres()
        .iter()
        .filter(|sphere| sphere.material.transmission() > 0.0)
        .filter_map(|sphere| {
            let (x, _) = camera.project(sphere.shape.centre, width, height)?;
            let ior = sphere.material.ior();
            (0.0..width as f32)
                .contains(&x)
                .then(|| (x, format!("{}, index {ior}", sphere.name)))
        })
        .collect();
    if labels.is_empty() {
        return image.clone();
    }
    let strip = 30;
    let mut canvas = Canvas::new(width, height + strip, WHITE);
    canvas.draw_rgb_image(image, 0, 0, 1);
    for (x, label) in labels {
        canvas.text(
            x,
            height as f32 + 7.0,
            &label,
            16.0,
            TEXT,
            Anchor::TOP_CENTRE,
        );
    }
    canvas.to_rgb_image()
}

/// Why a shadow ray starts a little way off its surface: rounding puts the
/// computed hit point a hair inside the surface about half the time.
fn shadow_offset_diagram() -> RgbImage {
    let (w, h) = (760, 380);
    let mut canvas = Canvas::new(w, h, WHITE);
    canvas.text(
        w as f32 / 2.0,
        16.0,
        "Why the shadow ray starts ε along L",
        20.0,
        TEXT,
        Anchor::TOP_CENTRE,
    );
    // A patch of surface, hugely magnified: the top of a sphere as a gentle arc.
    let surface_y = |x: f32| 250.0 + ((x - 380.0) / 2400.0).powi(2) * 2400.0;
    let arc: Vec<(f32, f32)> = (0..=76)
        .map(|i| i as f32 * 10.0)
        .map(|x| (x, surface_y(x)))
        .collect();
    canvas.polyline(&arc, AXIS, 3.0);
    canvas.text(
        380.0,
        300.0,
        "inside the sphere",
        14.0,
        TEXT_MUTED,
        Anchor::TOP_CENTRE,
    );
    let shadow = raylab_cli::diagrams::kind_colour(raylab::RayKind::Shadow);
    let blocked = [204, 51, 51];
    // Left: the feeler from the rounded point, just below the surface.
    let p = (220.0, surface_y(220.0) + 10.0);
    canvas.circle(p, 5.0, Some(blocked), None);
    canvas.text(
        p.0,
        p.1 + 14.0,
        "computed p, a hair inside",
        13.0,
        TEXT,
        Anchor::TOP_CENTRE,
    );
    let hit = (p.0 + 10.0, surface_y(p.0 + 10.0));
    canvas.arrow(p, (hit.0 + 6.0, hit.1 - 8.0), blocked, 2.5, 9.0);
    for (n, line) in [
        "ε = 0: the feeler hits its own",
        "surface at t ≈ 0: a dark speck",
        "where the sun shines (acne)",
    ]
    .into_iter()
    .enumerate()
    {
        canvas.text(
            140.0,
            120.0 + 18.0 * n as f32,
            line,
            14.0,
            blocked,
            Anchor::BASELINE_LEFT,
        );
    }
    // Right: the same point moved ε along L first.
    let q = (540.0, surface_y(540.0) + 10.0);
    canvas.circle(q, 5.0, Some(AXIS), None);
    canvas.text(
        q.0,
        q.1 + 14.0,
        "computed p",
        13.0,
        TEXT,
        Anchor::TOP_CENTRE,
    );
    let start = (q.0 + 18.0, q.1 - 28.0);
    canvas.dashed_line(q, start, AXIS, 1.5, 4.0, 3.0);
    canvas.circle(start, 5.0, Some(shadow), None);
    canvas.text(
        start.0 + 10.0,
        start.1 + 4.0,
        "p + ε·L",
        14.0,
        TEXT,
        Anchor::TOP_LEFT,
    );
    let tip = (start.0 + 80.0, start.1 - 120.0);
    canvas.arrow(start, tip, shadow, 2.5, 12.0);
    canvas.text(
        tip.0,
        tip.1 - 8.0,
        "towards the sun (L): escapes",
        14.0,
        TEXT,
        Anchor::BASELINE_CENTRE,
    );
    canvas.text(
        w as f32 / 2.0,
        h as f32 - 16.0,
        "Not to scale: ε = 0.0001 in a scene ten units wide; rounding errors are about 0.0000001.",
        13.0,
        TEXT_MUTED,
        Anchor::BASELINE_CENTRE,
    );
    canvas.to_rgb_image()
}

/// The lab's five sample positions inside one pixel, numbered in the order
/// they are summed: read from `raylab::sampling::LAB_FIVE` itself.
fn five_samples_diagram() -> RgbImage {
    let (w, h) = (520, 520);
    let (left, top, side) = (90.0, 70.0, 360.0);
    let mut canvas = Canvas::new(w, h, WHITE);
    canvas.text(
        w as f32 / 2.0,
        18.0,
        "The lab's five rays through one pixel",
        20.0,
        TEXT,
        Anchor::TOP_CENTRE,
    );
    canvas.fill_rect(left, top, side, side, [246, 246, 246]);
    canvas.dashed_line(
        (left + side / 2.0, top),
        (left + side / 2.0, top + side),
        GRID,
        1.5,
        6.0,
        4.0,
    );
    canvas.dashed_line(
        (left, top + side / 2.0),
        (left + side, top + side / 2.0),
        GRID,
        1.5,
        6.0,
        4.0,
    );
    canvas.stroke_rect(left, top, side, side, AXIS, 2.0);
    for (n, &(sx, sy)) in LAB_FIVE.iter().enumerate() {
        let centre = (left + sx * side, top + sy * side);
        canvas.circle(centre, 16.0, Some([0, 114, 178]), None);
        canvas.text(
            centre.0,
            centre.1,
            &(n + 1).to_string(),
            16.0,
            WHITE,
            Anchor::MIDDLE_CENTRE,
        );
        let label = format!("({sx}, {sy})");
        canvas.text(
            centre.0,
            centre.1 + 22.0,
            &label,
            12.0,
            TEXT_MUTED,
            Anchor::TOP_CENTRE,
        );
    }
    canvas.text(
        left - 6.0,
        top - 6.0,
        "(0, 0)",
        12.0,
        TEXT_MUTED,
        Anchor::BASELINE_RIGHT,
    );
    canvas.text(
        left + side + 6.0,
        top + side + 12.0,
        "(1, 1)",
        12.0,
        TEXT_MUTED,
        Anchor::TOP_LEFT,
    );
    canvas.text(
        left + side,
        top - 6.0,
        "sx to the right, sy down (row 0 is the top)",
        12.0,
        TEXT_MUTED,
        Anchor::BASELINE_RIGHT,
    );
    canvas.text(
        w as f32 / 2.0,
        h as f32 - 20.0,
        "Summed in this order in linear light, then divided by 5.",
        14.0,
        TEXT,
        Anchor::BASELINE_CENTRE,
    );
    canvas.to_rgb_image()
}
