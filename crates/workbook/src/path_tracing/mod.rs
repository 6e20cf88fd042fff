//! Chapter 6's figures that answer the lab's first question, "is the
//! result realistic?": the Whitted image against the path-traced one, the
//! terms of the light, the materials, the sun's size, the caustic, the
//! convergence and the depth limit.
//!
//! Every render is one a learner can make with the chapter's program: each
//! is described by the flags it would be given, and parsed by the
//! program's own command line.

mod caustic;
mod compare;
mod convergence;
mod depth;
mod materials;
mod sun_size;
mod terms;

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use ch06_path_tracing::{PathRender, run};
use image::RgbImage;
use raylab::linear_image::LinearImage;
use raylab::{Camera, NoProgress, Sampling, Scene, Settings, Vec3};
use raylab_cli::CliError;
use raylab_cli::output::{save_png, save_text};
use raylab_plot::colour::WHITE;
use raylab_plot::{Canvas, Rgb};

use crate::measure::{ground_masks, primary_hits};
use crate::{JobError, Size};
use caustic::caustic_figure;
use compare::comparison;
use convergence::convergence_figures;
use depth::depth_figures;
use materials::materials_figure;
use sun_size::sun_figure;
use terms::terms_figure;

pub use caustic::CAUSTIC_VIEW;
pub use compare::{clipped_channels, exposed, exposure_name, exposure_without_clipping};
pub use convergence::{ConvergencePoint, log_log_slope};

/// Paths per pixel of chapter 6's own run (figures 1 and 2).
pub const SPP: u32 = 64;
/// Paths per pixel of the runs that change one flag (figures 3 and 4), at
/// the same size, without caustics (tracing them makes a run several times
/// slower, and the flags compared do not need them).
pub const COMPARE_SPP: u32 = 32;
/// Paths per pixel of the caustic's close-up.
pub const CAUSTIC_SPP: u32 = 16;
/// The rays per pixel the convergence is measured at.
pub const COUNTS: [u32; 6] = [1, 4, 16, 64, 256, 1024];
/// The long render the convergence is measured against.
pub const REFERENCE_SPP: u32 = 4096;
/// The depth limits of the depth figure.
pub const DEPTHS: [u32; 5] = [1, 2, 3, 5, 10];
/// The sun's sizes of the penumbra figure (`None`: a point).
pub const SUN_SIZES: [Option<f32>; 3] = [None, Some(0.53), Some(5.0)];

/// One chapter 6 render, from the flags the program would be given (a
/// learner can type them), without writing files: traced eight paths at a
/// time by chapter 8, to chapter 6's bytes.
fn path_render(flags: &[String], quiet: bool) -> Result<PathRender, JobError> {
    let program = &ch08_eight_paths::PROGRAM.program;
    let args = std::iter::once(program.binary.to_owned()).chain(flags.iter().cloned());
    let (options, chapter_flags) =
        run::parse(program, args).map_err(|e| CliError::Usage(e.to_string()))?;
    let settings = run::settings(&options, &chapter_flags)?;
    let (scene, camera) = options.load_scene()?;
    let rendered = ch08_eight_paths::render_eight(&scene, &camera, &settings, &NoProgress);
    if !quiet {
        println!("{}: {rendered}", program.binary);
    }
    Ok(rendered)
}

fn size_flags(width: u32, height: u32, spp: u32) -> Vec<String> {
    vec![
        format!("--width={width}"),
        format!("--height={height}"),
        format!("--spp={spp}"),
    ]
}

fn with(mut flags: Vec<String>, more: &[&str]) -> Vec<String> {
    flags.extend(more.iter().map(|s| (*s).to_owned()));
    flags
}

/// `--sun-size D` for a disc, nothing for a point.
fn sun_flag(size: Option<f32>) -> Vec<String> {
    size.map(|d| vec![format!("--sun-size={d}")])
        .unwrap_or_default()
}

fn sun_name(size: Option<f32>) -> String {
    size.map_or("a point sun".to_owned(), |d| format!("a {d}° sun"))
}

/// The rectangle `(left, top, width, height)` of `image` of `width` ×
/// `height` around `(x, y)`, moved inside the image where it would stick out.
fn crop_rect(
    image: &RgbImage,
    (x, y): (f32, f32),
    (width, height): (u32, u32),
) -> (u32, u32, u32, u32) {
    let (width, height) = (width.min(image.width()), height.min(image.height()));
    let left = (x - width as f32 / 2.0).max(0.0) as u32;
    let top = (y - height as f32 / 2.0).max(0.0) as u32;
    (
        left.min(image.width() - width),
        top.min(image.height() - height),
        width,
        height,
    )
}

/// `image` with the outline of the crop [`magnified_crop`] takes around
/// `at`, so that a reader can find a zoomed detail in the whole picture.
fn outline_crop(image: &RgbImage, at: (f32, f32), size: (u32, u32), colour: Rgb) -> RgbImage {
    let (left, top, width, height) = crop_rect(image, at, size);
    let mut canvas = Canvas::new(image.width(), image.height(), WHITE);
    canvas.draw_rgb_image(image, 0, 0, 1);
    canvas.stroke_rect(
        left as f32 - 1.0,
        top as f32 - 1.0,
        width as f32 + 2.0,
        height as f32 + 2.0,
        colour,
        2.0,
    );
    canvas.to_rgb_image()
}

/// A rectangle of `image` of `width` × `height` around `(x, y)` (kept
/// inside the image), magnified `scale` times with hard pixel edges.
pub fn magnified_crop(
    image: &RgbImage,
    (x, y): (f32, f32),
    (width, height): (u32, u32),
    scale: u32,
) -> RgbImage {
    let (left, top, width, height) = crop_rect(image, (x, y), (width, height));
    let crop = image::imageops::crop_imm(image, left, top, width, height).to_image();
    image::imageops::resize(
        &crop,
        width * scale,
        height * scale,
        image::imageops::FilterType::Nearest,
    )
}

/// The pixel where `point` is seen, for crops (the image's centre if it is
/// behind the camera).
fn seen_at(camera: &Camera, point: Vec3, width: u32, height: u32) -> (f32, f32) {
    camera
        .project(point, width, height)
        .unwrap_or((width as f32 / 2.0, height as f32 / 2.0))
}

fn percent(x: f64) -> String {
    format!("{:.1} %", 100.0 * x)
}

fn triple(v: Vec3) -> String {
    format!("({:.3}, {:.3}, {:.3})", v.x, v.y, v.z)
}

/// Chapter 5's image of the lab scene: five rays per pixel, depth 10.
fn whitted_image(width: u32, height: u32) -> LinearImage {
    let settings = Settings {
        width,
        height,
        max_depth: 10,
        epsilon: 1e-4,
        sampling: Sampling::LAB_FIVE,
    };
    raylab::render(
        &Scene::lab(),
        &Camera::lab(),
        &ch05_antialiasing::CHAPTER.step,
        &settings,
        raylab::Keep::LINEAR,
        &NoProgress,
    )
    .linear
    .expect("kept")
}

/// Write chapter 6's study figures under `dir` (`figures/ch06-path-tracing`).
/// `main` is the chapter's own run, at half the job's size with
/// [`SPP`] paths per pixel, lab materials, a point sun and caustics.
pub fn make_figures(
    dir: &Path,
    scenes: &Path,
    size: Size,
    main: &PathRender,
    quiet: bool,
) -> Result<Vec<PathBuf>, JobError> {
    let mut written = Vec::new();
    let (w, h) = (main.settings.width, main.settings.height);
    let half = size_flags(w, h, COMPARE_SPP);
    let (scene, camera) = (Scene::lab(), Camera::lab());
    let hits = primary_hits(&scene, &camera, w, h);
    let masks = ground_masks(&hits, &scene, 1e-4);

    // 1. Whitted against path traced.
    let whitted = whitted_image(w, h);
    written.extend(comparison(&dir.join("compare"), &whitted, main, &masks)?);
    // 2. The terms and their shares.
    written.extend(terms_figure(&dir.join("terms"), main, &masks, &scene)?);
    // 3. Lab against Fresnel materials.
    let lab = path_render(&half, quiet)?;
    let fresnel = path_render(&with(half.clone(), &["--materials=fresnel"]), quiet)?;
    written.extend(materials_figure(
        &dir.join("materials"),
        &lab,
        &fresnel,
        &hits,
    )?);
    // 4. The sun's size.
    let mut suns = vec![lab];
    for sun in &SUN_SIZES[1..] {
        suns.push(path_render(
            &[half.clone(), sun_flag(*sun)].concat(),
            quiet,
        )?);
    }
    written.extend(sun_figure(&dir.join("sun-size"), &suns)?);
    // 5. The caustic, seen from where it is not hidden by the ball.
    written.extend(caustic_figure(&dir.join("caustics"), scenes, size, quiet)?);
    // 6. Convergence.
    written.extend(convergence_figures(&dir.join("convergence"), size, quiet)?);
    // 7. The depth limit.
    written.extend(depth_figures(&dir.join("depth"), size, quiet)?);
    Ok(written)
}

fn save_all(
    dir: &Path,
    images: &[(&str, &RgbImage)],
    texts: &[(&str, &str)],
) -> Result<Vec<PathBuf>, JobError> {
    raylab_cli::prepare_out_dir(dir)?;
    let mut written = Vec::new();
    for (name, image) in images {
        let path = dir.join(name);
        save_png(image, &path)?;
        written.push(path);
    }
    for (name, text) in texts {
        let path = dir.join(name);
        save_text(text, &path)?;
        written.push(path);
    }
    Ok(written)
}

/// A table row comparing one set of `count` pixels in two images: the
/// mean luminance in each, and the second over the first.
fn ratio_row(text: &mut String, name: &str, count: usize, a: f64, b: f64) {
    let _ = writeln!(
        text,
        "| {name} | {count} | {a:.4} | {b:.4} | {:.2} |",
        b / a.max(1e-9)
    );
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_magnified_crop_stays_inside_the_image_and_keeps_hard_pixels() {
        let image = RgbImage::from_fn(10, 8, |x, y| image::Rgb([x as u8, y as u8, 0]));
        let crop = magnified_crop(&image, (9.5, 0.0), (4, 2), 3);
        assert_eq!(crop.dimensions(), (12, 6));
        // The crop was pushed left to x = 6..10 and down to y = 0..2.
        assert_eq!(crop.get_pixel(0, 0).0, [6, 0, 0]);
        assert_eq!(crop.get_pixel(2, 2).0, [6, 0, 0]);
        assert_eq!(crop.get_pixel(11, 5).0, [9, 1, 0]);
    }
}
