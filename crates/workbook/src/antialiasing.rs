//! Chapter 5's figures on more rays per pixel: the four patterns, crops of
//! an edge and of the horizon as the count grows, and the error of each
//! pattern against a 4096-ray reference.
//!
//! Only two small windows of the image are rendered (an edge and the
//! horizon, each a twentieth of the image across), so that a 4096-ray
//! reference costs about a second of the main job rather than minutes.

use std::path::{Path, PathBuf};

use image::RgbImage;
use raylab::linear_image::LinearImage;
use raylab::sampling::{Layout, Pattern, Sampling};
use raylab::{Camera, Scene, Settings, Step, Tracer, Vec3};
use raylab_cli::output::{save_png, save_text};
use raylab_plot::colour::{AXIS, GRID, TEXT, TEXT_MUTED, WHITE, series_colour};
use raylab_plot::{Anchor, Canvas, Corner, LinePlot, Series, montage};
use rayon::prelude::*;

use crate::{JobError, Size};

/// The files [`make_figures`] writes.
pub const NAMES: [&str; 5] = [
    "sample-patterns.png",
    "spp-crops.png",
    "spp-error.png",
    "spp-error.csv",
    "spp-error.md",
];

/// The counts the error is measured at: the squares a grid can take.
pub const COUNTS: [u32; 6] = [1, 4, 16, 64, 256, 1024];

/// The reference: a 64 × 64 grid in every pixel.
pub const REFERENCE_SPP: u32 = 4096;

/// A rectangle of the full image, in pixels.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Window {
    pub x: u32,
    pub y: u32,
    pub width: u32,
    pub height: u32,
}

impl Window {
    /// A window a twentieth of the image across, centred on the point seen
    /// at `(fx, fy)` (fractions of the image's width and height).
    fn around(size: Size, (fx, fy): (f32, f32)) -> Window {
        let (width, height) = ((size.width / 20).max(2), (size.height / 20).max(2));
        let centre = |f: f32, side: u32, full: u32| {
            ((f * full as f32) as u32)
                .saturating_sub(side / 2)
                .min(full - side)
        };
        Window {
            x: centre(fx, width, size.width),
            y: centre(fy, height, size.height),
            width,
            height,
        }
    }

    /// The top of the red sphere against the sky: a curved edge.
    pub fn edge(size: Size) -> Window {
        let camera = Camera::lab();
        let top = raylab::Vec3::new(0.0, 2.0, -1.5);
        let (x, y) = camera
            .project(top, size.width, size.height)
            .expect("the red sphere is in view");
        Window::around(size, (x / size.width as f32, y / size.height as f32))
    }

    /// The checkerboard where it meets the sky, right of the red sphere.
    pub fn horizon(size: Size) -> Window {
        Window::around(size, (0.8, 0.345))
    }
}

fn settings(size: Size, sampling: Sampling) -> Settings {
    Settings {
        width: size.width,
        height: size.height,
        max_depth: 10,
        epsilon: 1e-4,
        sampling,
    }
}

/// Chapter 5's colours of the pixels of `window` (row by row), rendered as
/// `raylab::render` does, each pixel the average of its samples.
pub fn render_window<S: Step + ?Sized>(step: &S, settings: &Settings, window: Window) -> Vec<Vec3> {
    let (scene, camera) = (Scene::lab(), Camera::lab());
    let rows: Vec<Vec<Vec3>> = (window.y..window.y + window.height)
        .into_par_iter()
        .map_init(
            || Tracer::new(&scene, step, settings.max_depth, settings.epsilon),
            |tracer, j| {
                (window.x..window.x + window.width)
                    .map(|i| {
                        let mut sum = Vec3::ZERO;
                        for offset in settings.sampling.offsets((i, j)) {
                            let ray = camera.ray(i, j, offset, settings.width, settings.height);
                            sum += tracer.trace(ray).colour;
                        }
                        sum / settings.sampling.spp() as f32
                    })
                    .collect()
            },
        )
        .collect();
    rows.concat()
}

fn to_srgb(window: Window, pixels: Vec<Vec3>) -> RgbImage {
    LinearImage::from_pixels(window.width, window.height, pixels).to_srgb8()
}

// ANCHOR: rmse
/// The root-mean-square difference, in 8-bit levels over the three
/// channels, between `image` and `reference` over the pixels where the
/// reference differs from `one_ray` (the edges and the horizon: elsewhere
/// every count gets the same answer and would only dilute the error).
pub fn rmse_where_it_matters(image: &RgbImage, reference: &RgbImage, one_ray: &RgbImage) -> f64 {
    let (mut sum, mut count) = (0.0f64, 0usize);
    for ((p, r), o) in image.pixels().zip(reference.pixels()).zip(one_ray.pixels()) {
        if r == o {
            continue;
        }
        for c in 0..3 {
            let d = f64::from(p.0[c]) - f64::from(r.0[c]);
            sum += d * d;
        }
        count += 3;
    }
    if count == 0 {
        0.0
    } else {
        (sum / count as f64).sqrt()
    }
}
// ANCHOR_END: rmse

/// One measured point: a sampling's error on the edge, the horizon and both.
#[derive(Clone, Debug, PartialEq)]
pub struct ErrorPoint {
    pub name: &'static str,
    pub spp: u32,
    pub edge: f64,
    pub horizon: f64,
    pub both: f64,
}

/// The two windows at a sampling, as 8-bit images.
fn windows<S: Step + ?Sized>(step: &S, size: Size, sampling: Sampling) -> [RgbImage; 2] {
    let settings = settings(size, sampling);
    [Window::edge(size), Window::horizon(size)]
        .map(|w| to_srgb(w, render_window(step, &settings, w)))
}

/// Side by side, so that one RMSE covers both windows.
fn both(images: &[RgbImage; 2]) -> RgbImage {
    let (w0, h0) = images[0].dimensions();
    let (w1, h1) = images[1].dimensions();
    let mut out = RgbImage::new(w0 + w1, h0.max(h1));
    image::imageops::replace(&mut out, &images[0], 0, 0);
    image::imageops::replace(&mut out, &images[1], i64::from(w0), 0);
    out
}

/// The error of every pattern at every count in [`COUNTS`] (and of the
/// lab's five), against a `reference_spp`-ray grid, with chapter 5's step.
pub fn measure_errors<S: Step + ?Sized>(
    step: &S,
    size: Size,
    reference_spp: u32,
    seed: u64,
) -> Vec<ErrorPoint> {
    let sampling = |spp, pattern| Sampling::new(spp, pattern, seed).expect("a valid sampling");
    let reference = windows(step, size, sampling(reference_spp, Some(Pattern::Grid)));
    let one_ray = windows(step, size, Sampling::PIXEL_CENTRE);
    let point = |name, spp, sampling| {
        let images = windows(step, size, sampling);
        let rmse = |k: usize| rmse_where_it_matters(&images[k], &reference[k], &one_ray[k]);
        ErrorPoint {
            name,
            spp,
            edge: rmse(0),
            horizon: rmse(1),
            both: rmse_where_it_matters(&both(&images), &both(&reference), &both(&one_ray)),
        }
    };
    let mut points = Vec::new();
    for pattern in Pattern::ALL {
        for spp in COUNTS {
            points.push(point(pattern.name(), spp, sampling(spp, Some(pattern))));
        }
    }
    points.push(point("lab five", 5, Sampling::LAB_FIVE));
    // The floor of this measure: how far another 4096-ray image (jittered)
    // lies from the reference. No count can be shown to do better.
    let floor = sampling(reference_spp, Some(Pattern::Jittered));
    points.push(point("jittered reference check", reference_spp, floor));
    points
}

fn error_csv(points: &[ErrorPoint]) -> String {
    let mut text = String::from("pattern,spp,rmse_edge,rmse_horizon,rmse_both\n");
    for p in points {
        text.push_str(&format!(
            "{},{},{:.4},{:.4},{:.4}\n",
            p.name, p.spp, p.edge, p.horizon, p.both
        ));
    }
    text
}

/// The smallest count at which a pattern's error (as `error` reads it)
/// is below one level.
fn first_below_one(
    points: &[ErrorPoint],
    name: &str,
    error: fn(&ErrorPoint) -> f64,
) -> Option<u32> {
    points
        .iter()
        .filter(|p| p.name == name && COUNTS.contains(&p.spp) && error(p) < 1.0)
        .map(|p| p.spp)
        .min()
}

/// The table the book shows, and the sentence that reads it.
fn error_markdown(points: &[ErrorPoint], size: Size) -> String {
    let mut text = String::from("| rays per pixel |");
    for pattern in Pattern::ALL {
        text.push_str(&format!(" {pattern} |"));
    }
    text.push_str("\n|---:|");
    text.push_str(&"---:|".repeat(Pattern::ALL.len()));
    text.push('\n');
    for spp in COUNTS {
        text.push_str(&format!("| {spp} |"));
        for pattern in Pattern::ALL {
            let p = points
                .iter()
                .find(|p| p.name == pattern.name() && p.spp == spp)
                .expect("measured");
            text.push_str(&format!(" {:.2} ({:.2}) |", p.both, p.horizon));
        }
        text.push('\n');
    }
    if let Some(lab) = points.iter().find(|p| p.spp == 5) {
        text.push_str(&format!(
            "\nThe lab's five: {:.2} ({:.2} on the horizon).\n",
            lab.both, lab.horizon
        ));
    }
    text.push_str(&format!(
        "\nRMSE in 8-bit levels over both windows (in brackets: the horizon window \
         alone), against a {REFERENCE_SPP}-ray grid, at {}×{}. ",
        size.width, size.height
    ));
    for (window, error) in [
        ("edge", (|p: &ErrorPoint| p.edge) as fn(&ErrorPoint) -> f64),
        ("horizon", |p: &ErrorPoint| p.horizon),
    ] {
        let firsts: Vec<String> = Pattern::ALL
            .iter()
            .map(|p| match first_below_one(points, p.name(), error) {
                Some(n) => format!("{p} at {n}"),
                None => format!("{p} not by {}", COUNTS[COUNTS.len() - 1]),
            })
            .collect();
        text.push_str(&format!(
            "The {window} window's error falls below one level: {}. ",
            firsts.join(", ")
        ));
    }
    if let Some(check) = points.iter().find(|p| p.name == "jittered reference check") {
        text.push_str(&format!(
            "A jittered {REFERENCE_SPP}-ray image lies {:.2} levels from the reference on the \
             edge and {:.2} on the horizon: the floor of this measure.",
            check.edge, check.horizon
        ));
    }
    text.push('\n');
    text
}

/// Which window's error a panel shows, read off a measured point.
type WindowError = fn(&ErrorPoint) -> f64;

/// The error plot: two panels, the edge window above the horizon window,
/// each with its own floor (a jittered reference-sized image against the
/// reference), since the two windows tell different stories.
fn error_plot(points: &[ErrorPoint], size: Size) -> RgbImage {
    let floor = points.iter().find(|p| p.name == "jittered reference check");
    let panels: [(&str, WindowError); 2] = [
        ("The edge: the top of the red ball against the sky", |p| {
            p.edge
        }),
        (
            "The horizon: the checkerboard where it meets the sky",
            |p| p.horizon,
        ),
    ];
    let (panel_w, panel_h, title_h) = (820u32, 440u32, 44u32);
    let mut canvas = Canvas::new(panel_w, title_h + 2 * panel_h, WHITE);
    canvas.text(
        panel_w as f32 / 2.0,
        14.0,
        &format!(
            "Error against a {REFERENCE_SPP}-ray grid in two windows of the {}×{} image",
            size.width, size.height
        ),
        20.0,
        TEXT,
        Anchor::TOP_CENTRE,
    );
    for (k, (title, error)) in panels.into_iter().enumerate() {
        // One legend, in the upper panel: the colours are the same below.
        let panel = error_panel(
            points,
            title,
            error,
            floor.map(error),
            (panel_w, panel_h),
            k == 0,
        );
        canvas.draw_rgb_image(&panel, 0, (title_h + k as u32 * panel_h) as i32, 1);
    }
    canvas.to_rgb_image()
}

/// One window's error per pattern against N, with the 1/√N and 1/N slopes
/// from the grid's one-ray error, the reference's floor as a dashed line,
/// and the lab's five ringed so that its single point is found.
fn error_panel(
    points: &[ErrorPoint],
    title: &str,
    error: WindowError,
    floor: Option<f64>,
    (width, height): (u32, u32),
    legend: bool,
) -> RgbImage {
    const LOWEST: f64 = 0.1;
    let series_of = |name: &str| -> Vec<(f64, f64)> {
        points
            .iter()
            .filter(|p| p.name == name)
            .map(|p| (f64::from(p.spp), error(p).max(LOWEST)))
            .collect()
    };
    // The guides start where one ray per pixel does, and stop at the
    // bottom of the axis rather than lie flat along it.
    let start = series_of("grid")[0].1;
    let guide = |power: f64| {
        COUNTS
            .iter()
            .map(move |&n| (f64::from(n), start / f64::from(n).powf(power)))
            .filter(|&(_, y)| y >= LOWEST)
            .collect::<Vec<_>>()
    };
    let last = f64::from(COUNTS[COUNTS.len() - 1]);
    let mut plot = LinePlot::new(title)
        .x_label("rays per pixel N (log scale)")
        .y_label("RMSE, 8-bit levels")
        .log_x()
        .x_range(1.0, last)
        .log_y(LOWEST)
        .y_range(LOWEST, 100.0);
    plot = if legend {
        plot.legend(Corner::TopRight)
    } else {
        plot.no_legend()
    };
    for (k, pattern) in Pattern::ALL.iter().enumerate() {
        plot = plot.series(Series::new(
            pattern.name(),
            series_colour(k),
            series_of(pattern.name()),
        ));
    }
    let lab = series_of("lab five");
    plot = plot
        .series(Series::new("the lab's five", series_colour(4), lab.clone()))
        .series(Series::new("1/√N", GRID_GUIDE, guide(0.5)).without_markers())
        .series(Series::new("1/N", GRID_GUIDE_DARK, guide(1.0)).without_markers());
    let mut canvas = plot.render_canvas(width, height);
    if let Some(floor) = floor {
        let from = plot.data_to_pixel(width, height, 1.0, floor);
        let to = plot.data_to_pixel(width, height, last, floor);
        canvas.dashed_line(from, to, TEXT_MUTED, 1.5, 6.0, 4.0);
        // Under the line at its left end, where no series runs: they all
        // start far above the floor.
        canvas.text(
            from.0 + 8.0,
            from.1 + 5.0,
            &format!("floor: a jittered {REFERENCE_SPP}-ray image is {floor:.2} off"),
            13.0,
            TEXT_MUTED,
            Anchor::TOP_LEFT,
        );
    }
    if let Some(&(n, e)) = lab.first() {
        let at = plot.data_to_pixel(width, height, n, e);
        canvas.circle(at, 9.0, None, Some((series_colour(4), 2.0)));
        canvas.text(
            at.0 + 12.0,
            at.1 - 10.0,
            "the lab's five",
            13.0,
            series_colour(4),
            Anchor::BASELINE_LEFT,
        );
    }
    canvas.to_rgb_image()
}

const GRID_GUIDE: [u8; 3] = [170, 170, 170];
const GRID_GUIDE_DARK: [u8; 3] = [110, 110, 110];

/// One pixel's sample points for each pattern at N = 16, and the lab's five.
fn patterns_figure() -> RgbImage {
    let side = 170.0;
    let (gap, top) = (28.0, 64.0);
    let panels: [(&str, Sampling); 5] = [
        ("the lab's five", Sampling::LAB_FIVE),
        (
            "grid, 16",
            Sampling::new(16, Some(Pattern::Grid), 0).expect("valid"),
        ),
        (
            "jittered, 16",
            Sampling::new(16, Some(Pattern::Jittered), 0).expect("valid"),
        ),
        (
            "random, 16",
            Sampling::new(16, Some(Pattern::Random), 0).expect("valid"),
        ),
        (
            "halton, 16",
            Sampling::new(16, Some(Pattern::Halton), 0).expect("valid"),
        ),
    ];
    let width = (gap + panels.len() as f32 * (side + gap)) as u32;
    let height = (top + side + 60.0) as u32;
    let mut canvas = Canvas::new(width, height, WHITE);
    canvas.text(
        width as f32 / 2.0,
        14.0,
        "Where one pixel's rays go (pixel (0, 0), seed 0)",
        20.0,
        TEXT,
        Anchor::TOP_CENTRE,
    );
    for (n, (name, sampling)) in panels.iter().enumerate() {
        let left = gap + n as f32 * (side + gap);
        canvas.fill_rect(left, top, side, side, [246, 246, 246]);
        let cells = match sampling.layout() {
            Layout::LabFive => 2,
            Layout::Pattern(p) if p.needs_square() => sampling.spp().isqrt(),
            _ => 1,
        };
        for c in 1..cells {
            let at = c as f32 / cells as f32 * side;
            canvas.dashed_line(
                (left + at, top),
                (left + at, top + side),
                GRID,
                1.0,
                4.0,
                3.0,
            );
            canvas.dashed_line(
                (left, top + at),
                (left + side, top + at),
                GRID,
                1.0,
                4.0,
                3.0,
            );
        }
        canvas.stroke_rect(left, top, side, side, AXIS, 1.5);
        for (sx, sy) in sampling.offsets((0, 0)) {
            canvas.circle(
                (left + sx * side, top + sy * side),
                4.5,
                Some([0, 114, 178]),
                None,
            );
        }
        canvas.text(
            left + side / 2.0,
            top - 10.0,
            name,
            15.0,
            TEXT,
            Anchor::BASELINE_CENTRE,
        );
    }
    canvas.text(
        width as f32 / 2.0,
        top + side + 30.0,
        "Dashed: the cells of the grid and jittered patterns (and the lab's quarters). \
         Random and halton points change with the seed and the pixel.",
        13.0,
        TEXT_MUTED,
        Anchor::TOP_CENTRE,
    );
    canvas.to_rgb_image()
}

/// The edge and the horizon windows at 1, 5, 16, 64 and 256 rays.
fn crops_figure<S: Step + ?Sized>(step: &S, size: Size) -> RgbImage {
    let counts: [(u32, &str); 5] = [
        (1, "1 ray (centre)"),
        (5, "5 (the lab's)"),
        (16, "16 jittered"),
        (64, "64 jittered"),
        (256, "256 jittered"),
    ];
    let magnify = |image: RgbImage| {
        let scale = (160 / image.width()).max(1);
        let (w, h) = image.dimensions();
        image::imageops::resize(
            &image,
            w * scale,
            h * scale,
            image::imageops::FilterType::Nearest,
        )
    };
    let mut tiles: Vec<(String, RgbImage)> = Vec::new();
    for (which, label) in [(0, "edge"), (1, "horizon")] {
        for (spp, name) in counts {
            let sampling = Sampling::new(spp, None, 0).expect("valid");
            let [edge, horizon] = windows(step, size, sampling);
            let image = if which == 0 { edge } else { horizon };
            tiles.push((format!("{label}: {name}"), magnify(image)));
        }
    }
    let refs: Vec<(&str, &RgbImage)> = tiles.iter().map(|(l, i)| (l.as_str(), i)).collect();
    let w = Window::edge(size);
    montage(
        &format!(
            "The top of the red sphere and the horizon, {}×{} pixels each, magnified",
            w.width, w.height
        ),
        &refs,
        counts.len(),
    )
}

/// Write chapter 5's sampling figures into `dir`.
pub fn make_figures(dir: &Path, size: Size) -> Result<Vec<PathBuf>, JobError> {
    raylab_cli::prepare_out_dir(dir)?;
    let step = ch05_antialiasing::Refraction;
    let points = measure_errors(&step, size, REFERENCE_SPP, 0);
    let images = [
        patterns_figure(),
        crops_figure(&step, size),
        error_plot(&points, size),
    ];
    let mut written = Vec::new();
    for (name, image) in NAMES.iter().zip(&images) {
        let path = dir.join(name);
        save_png(image, &path)?;
        written.push(path);
    }
    for (name, text) in [
        (NAMES[3], error_csv(&points)),
        (NAMES[4], error_markdown(&points, size)),
    ] {
        let path = dir.join(name);
        save_text(&text, &path)?;
        written.push(path);
    }
    Ok(written)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_error_of_jittered_sampling_falls_as_the_rays_grow() {
        // A coarse check at 160 × 120 (windows of 8 × 6 pixels) against a
        // 32 × 32 grid: 64 jittered rays leave well under half the error of 4.
        let size = Size {
            width: 160,
            height: 120,
        };
        let step = ch05_antialiasing::Refraction;
        let reference = windows(
            &step,
            size,
            Sampling::new(1024, Some(Pattern::Grid), 0).unwrap(),
        );
        let one_ray = windows(&step, size, Sampling::PIXEL_CENTRE);
        let error = |spp| {
            let images = windows(
                &step,
                size,
                Sampling::new(spp, Some(Pattern::Jittered), 3).unwrap(),
            );
            rmse_where_it_matters(&both(&images), &both(&reference), &both(&one_ray))
        };
        let (four, sixty_four) = (error(4), error(64));
        assert!(four > 1.0, "4 rays leave a visible error: {four}");
        assert!(
            sixty_four < four / 2.0,
            "4 rays: {four}, 64 rays: {sixty_four}"
        );
    }

    #[test]
    fn the_error_counts_only_pixels_the_reference_changed() {
        let grey = |v| RgbImage::from_pixel(2, 1, image::Rgb([v, v, v]));
        let mut reference = grey(100);
        reference.put_pixel(1, 0, image::Rgb([110, 110, 110]));
        // Pixel 0 is the same in the reference and the 1-ray image: ignored.
        let image = grey(0);
        let rmse = rmse_where_it_matters(&image, &reference, &grey(100));
        assert_eq!(rmse, 110.0);
    }

    #[test]
    fn the_windows_lie_inside_the_image_at_every_size() {
        for (width, height) in [(800, 600), (160, 120), (40, 30)] {
            let size = Size { width, height };
            for w in [Window::edge(size), Window::horizon(size)] {
                assert!(w.x + w.width <= width && w.y + w.height <= height, "{w:?}");
            }
        }
    }
}
