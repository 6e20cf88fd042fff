//! Chapter 6's figures that answer the lab's first question, "is the
//! result realistic?": the Whitted image against the path-traced one, the
//! terms of the light, the materials, the sun's size, the caustic, the
//! convergence and the depth limit.
//!
//! Every render is one a learner can make with the chapter's program: each
//! is described by the flags it would be given, and parsed by the
//! program's own command line.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use ch06_path_tracing::sun::Sunlight;
use ch06_path_tracing::{PathRender, Terms, run};
use image::RgbImage;
use raylab::frame::thousands;
use raylab::linear_image::LinearImage;
use raylab::scene::Object;
use raylab::{Camera, Hit, NoProgress, Sampling, Scene, Settings, Vec3};
use raylab_cli::CliError;
use raylab_cli::output::{save_png, save_text};
use raylab_plot::colour::{WHITE, series_colour};
use raylab_plot::{
    Anchor, Canvas, Colormap, ColourScale, Corner, HeatmapFigure, LinePlot, Rgb, Series, montage,
};

use crate::measure::{
    GroundMasks, ground_masks, lab_shadow_ratio, log2_ratio, luminance, mean_luminance,
    mean_over_albedo, mean_variance, primary_hits, rmse, shares, signed_difference,
    symmetric_range,
};
use crate::penumbra;
use crate::{JobError, Size};

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

// ---------------------------------------------------------------------------
// 1. Whitted against path traced

/// The exposure of the comparison figures: the largest power of two in
/// thirds of a stop, at most 1, at which no channel of any of `images`
/// exceeds 1, so that nothing clips when it is encoded.
pub fn exposure_without_clipping(images: &[&LinearImage]) -> f32 {
    let brightest = images
        .iter()
        .flat_map(|image| image.pixels())
        .map(|p| p.max_element())
        .fold(0.0, f32::max);
    (0..=60)
        .map(|third: i32| 2f32.powf(-third as f32 / 3.0))
        .find(|&exposure| brightest * exposure <= 1.0)
        .unwrap_or(2f32.powi(-20))
}

/// `image` with every channel scaled by `exposure`.
pub fn exposed(image: &LinearImage, exposure: f32) -> LinearImage {
    let pixels = image.pixels().iter().map(|&p| p * exposure).collect();
    LinearImage::from_pixels(image.width(), image.height(), pixels)
}

/// The channels of `image` above 1, which the encoding clips to white.
pub fn clipped_channels(image: &LinearImage) -> usize {
    image
        .pixels()
        .iter()
        .map(|p| p.to_array().iter().filter(|&&c| c > 1.0).count())
        .sum()
}

/// An exposure as the book states it: the factor and its stops.
pub fn exposure_name(exposure: f32) -> String {
    let thirds = (-3.0 * exposure.log2()).round() as i32;
    let stops = match (thirds / 3, thirds % 3) {
        (0, 0) => "no change".to_owned(),
        (0, t) => format!("−{t}/3 stop"),
        (s, 0) => format!("−{s} stop{}", if s == 1 { "" } else { "s" }),
        (s, t) => format!("−{s} {t}/3 stops"),
    };
    format!("exposure ×{exposure:.2} ({stops})")
}

/// Where `image` clips: the pixels with a channel above 1 in red, the rest
/// faded to grey.
fn clip_mask(image: &LinearImage) -> RgbImage {
    let srgb = image.to_srgb8();
    RgbImage::from_fn(image.width(), image.height(), |x, y| {
        if image.pixel(x, y).max_element() > 1.0 {
            image::Rgb([220, 20, 60])
        } else {
            let p = srgb.get_pixel(x, y).0;
            let grey = (u16::from(p[0]) + u16::from(p[1]) + u16::from(p[2])) / 3;
            image::Rgb([(160 + grey / 3) as u8; 3])
        }
    })
}

fn comparison(
    dir: &Path,
    whitted: &LinearImage,
    path: &PathRender,
    masks: &GroundMasks,
) -> Result<Vec<PathBuf>, JobError> {
    let (w, h) = (whitted.width(), whitted.height());
    // One exposure for both, so that they compare, and low enough that
    // nothing clips: at 1 the lit ground of the path-traced image is
    // brighter than white.
    let exposure = exposure_without_clipping(&[whitted, &path.image]);
    let (whitted_exposed, path_exposed) =
        (exposed(whitted, exposure), exposed(&path.image, exposure));
    let clipped_before = clipped_channels(&path.image) + clipped_channels(whitted);
    let clipped_after = clipped_channels(&path_exposed) + clipped_channels(&whitted_exposed);
    let stated = exposure_name(exposure);
    let side_by_side = montage(
        &format!("The lab scene, {w}×{h}: chapter 5 and chapter 6, both at {stated}"),
        &[
            (
                "chapter 5: Whitted, the lab's 5 rays per pixel",
                &whitted_exposed.to_srgb8(),
            ),
            (
                &format!("chapter 6: path traced, {SPP} paths per pixel, caustics"),
                &path_exposed.to_srgb8(),
            ),
        ],
        2,
    );
    let clip_figure = montage(
        "Where the encoding clips a channel to white (red)",
        &[
            (
                "chapter 6 at exposure ×1, as its render.png",
                &clip_mask(&path.image),
            ),
            (&format!("chapter 6 at {stated}"), &clip_mask(&path_exposed)),
        ],
        2,
    );
    let clipped_pixels = path
        .image
        .pixels()
        .iter()
        .filter(|p| p.max_element() > 1.0)
        .count();
    let exposure_text = format!(
        "![Chapter 5's Whitted image and chapter 6's path-traced image, {w} × {h}, both at \
         {stated}](figures/ch06-path-tracing/compare/whitted-and-path-traced.png)\n\n\
         *Both images at one {stated}, the largest in thirds of a stop at which no channel of \
         either is above 1: at ×1, {} channels ({} pixels of \
         chapter 6's, mostly the lit ground's light squares) would clip to white, and at \
         this exposure {clipped_after} do. The light of the two compares directly; only \
         the brightness of the page is lower.*\n",
        thousands(clipped_before as u64),
        thousands(clipped_pixels as u64),
    );
    let render_text = format!(
        "![Chapter 6: the lab scene, path traced, {w} × {h}, {SPP} paths per pixel, with \
         caustics, at {stated}](figures/ch06-path-tracing/compare/path-traced-exposed.png)\n\n\
         *Shown at {stated}, the exposure of every comparison with chapter 5 on these pages: \
         the program's own `render.png` is at ×1, where {} of its pixels, most \
         of the lit ground's light squares, are brighter than white in some channel and \
         clip.*\n",
        thousands(clipped_pixels as u64),
    );
    let difference = signed_difference(whitted, &path.image);
    let range = symmetric_range(&difference, 0.99);
    let caption = format!(
        "Each pixel: chapter 6's luminance minus chapter 5's, in linear radiance \
         (Y = 0.2126 R + 0.7152 G + 0.0722 B), from −{range} (blue) to +{range} (red), \
         clamped beyond; grey: the same."
    );
    let figure = HeatmapFigure {
        title: "Path tracing minus Whitted: red brighter, blue darker",
        caption: &caption,
        values: &difference,
        width: w as usize,
        height: h as usize,
        colour_scale: ColourScale::linear(-range, range),
        colour_bar_label: "luminance difference",
        colormap: Colormap::Diverging,
        pixel_scale: Some(1),
    }
    .render();

    // The same comparison as a ratio, where the text speaks of ratios.
    let ratio = log2_ratio(whitted, &path.image);
    let ratio_figure = HeatmapFigure {
        title: "Path tracing over Whitted: how many times brighter",
        caption: "Each pixel: log2 of chapter 6's luminance over chapter 5's, from −3 (an eighth \
                  of the light, blue) to +3 (eight times, red), clamped beyond; grey: the same. \
                  A ratio, so a dark pixel that doubles is as red as a bright one that doubles.",
        values: &ratio,
        width: w as usize,
        height: h as usize,
        colour_scale: ColourScale::linear(-3.0, 3.0),
        colour_bar_label: "log2 (chapter 6 ÷ chapter 5)",
        colormap: Colormap::Diverging,
        pixel_scale: Some(1),
    }
    .render();

    let brighter = difference.iter().filter(|&&d| d > 0.01).count();
    let darker = difference.iter().filter(|&&d| d < -0.01).count();
    let mut text = String::from(
        "| pixels | count | chapter 5 (Whitted) | chapter 6 (path traced) | ratio |\n\
         |---|---:|---:|---:|---:|\n",
    );
    for (name, mask) in [
        ("the whole image", None),
        ("ground in the sun", Some(masks.lit.as_slice())),
        (
            "ground in the sun's shadow",
            Some(masks.shadowed.as_slice()),
        ),
    ] {
        let ((a, count), (b, _)) = (
            mean_luminance(whitted, mask),
            mean_luminance(&path.image, mask),
        );
        ratio_row(&mut text, name, count, a, b);
    }
    let _ = writeln!(
        text,
        "\nMean luminance (linear) over each set of pixels. Of the {} pixels, {} are brighter \
         by more than 0.01 in chapter 6 and {} darker by more than 0.01.",
        difference.len(),
        brighter,
        darker
    );
    save_all(
        dir,
        &[
            ("whitted-and-path-traced.png", &side_by_side),
            ("whitted.png", &whitted.to_srgb8()),
            ("whitted-exposed.png", &whitted_exposed.to_srgb8()),
            ("path-traced-exposed.png", &path_exposed.to_srgb8()),
            ("clip-mask.png", &clip_figure),
            ("difference.png", &figure),
            ("ratio.png", &ratio_figure),
        ],
        &[
            ("difference.md", &text),
            ("exposure.md", &exposure_text),
            ("render-exposed.md", &render_text),
        ],
    )
}

// ---------------------------------------------------------------------------
// 2. The terms

fn terms_figure(
    dir: &Path,
    path: &PathRender,
    masks: &GroundMasks,
    scene: &Scene,
) -> Result<Vec<PathBuf>, JobError> {
    let images: Vec<RgbImage> = path.terms().iter().map(|t| t.to_srgb8()).collect();
    let total = path.image.to_srgb8();
    let whole = shares(path.terms(), None);
    // sRGB lifts dark values: a term with a twentieth of the light looks
    // far more than a twentieth as bright, so each tile says its share.
    let mut tiles: Vec<(String, &RgbImage)> = Terms::NAMES
        .iter()
        .zip(&images)
        .zip(whole)
        .map(|((name, image), share)| (format!("{name}: {}", percent(share)), image))
        .collect();
    tiles.push(("their sum: the image (100 %)".to_owned(), &total));
    let refs: Vec<(&str, &RgbImage)> = tiles.iter().map(|(l, i)| (l.as_str(), *i)).collect();
    let (w, h) = (path.settings.width, path.settings.height);
    let figure = montage(
        &format!(
            "Chapter 6's image split by term, {w}×{h}, {SPP} paths per pixel: all at the same \
             exposure, in sRGB; each term's share of the image's luminance"
        ),
        &refs,
        3,
    );

    let count = |m: &[bool]| m.iter().filter(|&&b| b).count();
    let shadow = shares(path.terms(), Some(&masks.shadowed));
    let lit = shares(path.terms(), Some(&masks.lit));
    let mut text = format!(
        "| term | whole image ({} pixels) | ground in the sun ({} pixels) | ground in the sun's \
         shadow ({} pixels) |\n|---|---:|---:|---:|\n",
        w * h,
        count(&masks.lit),
        count(&masks.shadowed)
    );
    for (k, name) in Terms::NAMES.iter().enumerate() {
        let _ = writeln!(
            text,
            "| {name} | {} | {} | {} |",
            percent(whole[k]),
            percent(lit[k]),
            percent(shadow[k])
        );
    }
    let _ = writeln!(
        text,
        "\nEach term's share of the luminance summed over the pixels. A pixel is \"ground in \
         the sun's shadow\" when the ray through its centre meets the ground first and the \
         shadow ray from there to the sun is blocked.\n"
    );

    // What the lab's constants stand in for.
    let e_sky = scene.sky.irradiance_facing_up();
    let sky_radiance = e_sky / std::f32::consts::PI;
    let ambient = 0.04;
    let ratio = sky_radiance / ambient;
    let _ = writeln!(
        text,
        "**The sky against the ambient constant.** The sky's irradiance on open ground is \
         π (0.2 · horizon + 0.8 · zenith) = {}; as light leaving a matte ground that is \
         albedo/π · E_sky = albedo · {}, against the lab's ambient albedo · {ambient}: the sky \
         gives open ground {:.1}, {:.1} and {:.1} times (red, green, blue) as much light as \
         the constant that stands in for it.",
        triple(e_sky),
        triple(sky_radiance),
        ratio.x,
        ratio.y,
        ratio.z
    );
    let received =
        |image: &LinearImage, mask: &[bool]| mean_over_albedo(image, &masks.albedo, mask);
    let sky_term = &path.terms()[2];
    if let Some(sky_lit) = received(sky_term, &masks.lit) {
        let _ = writeln!(
            text,
            "\nMeasured in the image: the sky-direct term over the sunlit ground, divided by \
             the albedo, is {} on average, {:.0} % of the open-sky value {} (the spheres hide \
             part of the sky; light bounced off them is in the indirect term).",
            triple(sky_lit),
            100.0 * luminance(sky_lit) / luminance(sky_radiance),
            triple(sky_radiance)
        );
    }
    let to_sun = scene.sun.direction;
    let lab = lab_shadow_ratio(scene.sun.brightness, to_sun.y);
    if let (Some(in_shadow), Some(in_sun)) = (
        received(&path.image, &masks.shadowed),
        received(&path.image, &masks.lit),
    ) {
        let ratio = in_shadow / in_sun;
        let _ = writeln!(
            text,
            "\n**The light in a shadow against the shadow factor.** Per unit albedo, the \
             ground in the sun's shadow sends {} on average and the ground in the sun {}: the \
             shadow gets {:.2}, {:.2} and {:.2} (red, green, blue; {:.2} in luminance) of \
             the light of the lit ground. The lab's shading, 0.01 of the sun plus the ambient \
             0.04 against 0.1 of the sun plus the ambient, gives (0.01 · 25 · cos/π + 0.04) / \
             (0.1 · 25 · cos/π + 0.04) = {lab:.3} in every channel (cos = L.y = {:.3}): its \
             shadows are {:.1} times too dark in luminance, and not blue.",
            triple(in_shadow),
            triple(in_sun),
            ratio.x,
            ratio.y,
            ratio.z,
            luminance(in_shadow) / luminance(in_sun),
            to_sun.y,
            (luminance(in_shadow) / luminance(in_sun)) / lab
        );
    }
    save_all(dir, &[("terms.png", &figure)], &[("shares.md", &text)])
}

// ---------------------------------------------------------------------------
// 3. The materials

fn glass_ball(scene: &Scene) -> (Vec3, f32) {
    let glass = scene
        .sphere_named("glass")
        .expect("the lab has a glass ball");
    let shape = scene.spheres()[glass].shape;
    (shape.centre, shape.radius)
}

fn materials_figure(
    dir: &Path,
    lab: &PathRender,
    fresnel: &PathRender,
    hits: &[Option<Hit>],
) -> Result<Vec<PathBuf>, JobError> {
    let (scene, camera) = (Scene::lab(), Camera::lab());
    let (w, h) = (lab.settings.width, lab.settings.height);
    let (centre, radius) = glass_ball(&scene);
    // The ball's upper right rim, where the eye sees it at a grazing angle.
    let diagonal = (camera.up() + camera.right()).normalize();
    let at = seen_at(&camera, centre + 0.8 * radius * diagonal, w, h);
    let side = (w / 8).max(4);
    let scale = (h / side).max(1);
    let (lab8, fresnel8) = (lab.image.to_srgb8(), fresnel.image.to_srgb8());
    let crops = [&lab8, &fresnel8].map(|image| magnified_crop(image, at, (side, side), scale));
    let rim_box = [255, 200, 0];
    let [lab_boxed, fresnel_boxed] =
        [&lab8, &fresnel8].map(|image| outline_crop(image, at, (side, side), rim_box));
    let figure = montage(
        &format!(
            "The glass ball, {w}×{h}, {COMPARE_SPP} paths per pixel: lab materials and Fresnel"
        ),
        &[
            ("--materials lab (yellow box: the rim crop)", &lab_boxed),
            ("--materials fresnel", &fresnel_boxed),
            (
                &format!("lab: the rim, {side}×{side} pixels, ×{scale}"),
                &crops[0],
            ),
            (&format!("fresnel: the rim, ×{scale}"), &crops[1]),
        ],
        2,
    );

    // The rim and the middle of the ball, by the angle the eye sees it at.
    let glass = Object::Sphere(scene.sphere_named("glass").expect("the glass"));
    let band = |low: f32, high: f32| -> Vec<bool> {
        hits.iter()
            .enumerate()
            .map(|(k, hit)| {
                let (i, j) = ((k as u32 % w), (k as u32 / w));
                hit.filter(|x| x.object == glass).is_some_and(|x| {
                    let d = camera.ray(i, j, (0.5, 0.5), w, h).direction;
                    let cos = -d.dot(x.normal);
                    (low..high).contains(&cos)
                })
            })
            .collect()
    };
    let mut text = String::from(
        "| pixels of the glass ball | count | lab | fresnel | fresnel / lab |\n\
         |---|---:|---:|---:|---:|\n",
    );
    for (name, low, high) in [
        ("rim: cos θ below 0.5", 0.0, 0.5),
        ("middle: cos θ above 0.9", 0.9, 1.01),
    ] {
        let mask = band(low, high);
        let ((a, n), (b, _)) = (
            mean_luminance(&lab.image, Some(&mask)),
            mean_luminance(&fresnel.image, Some(&mask)),
        );
        ratio_row(&mut text, name, n, a, b);
    }
    let _ = writeln!(
        text,
        "\nMean luminance (linear) of the pixels whose centre sees the glass ball, by the \
         cosine θ between the eye's ray and the ball's normal there. Exact Fresnel reflects \
         {:.1} % head on (cos θ = 1) and {:.1} % at cos θ = 0.2; the lab's glass reflects 0.1 \
         of its light (and refracts 0.7) at every angle.",
        100.0 * raylab::optics::fresnel(-1.0, 1.0 / 1.5),
        100.0 * raylab::optics::fresnel(-0.2, 1.0 / 1.5)
    );
    // Where the two differ, as a ratio: at this size the pictures look
    // alike, and the table's few per cent would not show by eye. Both use
    // the same seed, so a pixel whose paths never meet the glass is the
    // same in both, and its ratio exactly 1.
    let ratio = log2_ratio(&lab.image, &fresnel.image);
    let range = symmetric_range(&ratio, 0.999).min(3.0);
    let caption = format!(
        "Each pixel: log2 of the Fresnel render's luminance over the lab render's, from −{range} \
         (blue, {:.0} % of the light) to +{range} (red, {:.0} %), clamped beyond; grey: the same. \
         Both use the same seed, so only pixels whose paths meet the glass can differ.",
        100.0 * 2f32.powf(-range),
        100.0 * 2f32.powf(range)
    );
    let ratio_figure = HeatmapFigure {
        title: "Fresnel over the lab's materials: where the glass differs",
        caption: &caption,
        values: &ratio,
        width: w as usize,
        height: h as usize,
        colour_scale: ColourScale::linear(-range, range),
        colour_bar_label: "log2 (fresnel ÷ lab)",
        colormap: Colormap::Diverging,
        pixel_scale: Some(1),
    }
    .render();
    save_all(
        dir,
        &[("materials.png", &figure), ("ratio.png", &ratio_figure)],
        &[("materials.md", &text)],
    )
}

// ---------------------------------------------------------------------------
// 4. The sun's size

fn sun_figure(dir: &Path, suns: &[PathRender]) -> Result<Vec<PathBuf>, JobError> {
    let camera = Camera::lab();
    let (w, h) = (suns[0].settings.width, suns[0].settings.height);
    // The far tips of the glass ball's and the mirror ball's shadows,
    // where the ground is furthest from the edge that casts them (1.5 to 2
    // units), so the penumbra is widest: that distance × the sun's angle.
    let tips = [
        ("the glass ball's shadow", Vec3::new(2.15, 0.0, -0.12)),
        ("the mirror ball's shadow", Vec3::new(-0.28, 0.0, -0.27)),
    ];
    // A tenth of the picture each way, magnified back to the picture's
    // size, so that every tile of the montage is the same size.
    let crop = ((w / 10).max(4), (h / 10).max(3));
    let scale = (w / crop.0).max(1);
    let images: Vec<RgbImage> = suns.iter().map(|r| r.image.to_srgb8()).collect();
    let boxes = [[255, 200, 0], [255, 64, 160]];
    let mut tiles: Vec<(String, RgbImage)> = Vec::new();
    for (sun, image) in SUN_SIZES.iter().zip(&images) {
        let mut outlined = image.clone();
        for ((_, point), colour) in tips.iter().zip(boxes) {
            outlined = outline_crop(&outlined, seen_at(&camera, *point, w, h), crop, colour);
        }
        tiles.push((
            format!("{} (boxes: the crops below)", sun_name(*sun)),
            outlined,
        ));
    }
    for ((name, point), colour) in tips.iter().zip(boxes) {
        let at = seen_at(&camera, *point, w, h);
        let frame = if colour == boxes[0] { "yellow" } else { "pink" };
        for (sun, image) in SUN_SIZES.iter().zip(&images) {
            tiles.push((
                format!(
                    "{}: {name} ({frame} box), {}×{} pixels ×{scale}",
                    sun_name(*sun),
                    crop.0,
                    crop.1
                ),
                magnified_crop(image, at, crop, scale),
            ));
        }
    }
    let refs: Vec<(&str, &RgbImage)> = tiles.iter().map(|(l, i)| (l.as_str(), i)).collect();
    let figure = montage(
        &format!(
            "The sun as a point, as the real 0.53° disc and as 5°: {w}×{h}, {COMPARE_SPP} paths \
             per pixel"
        ),
        &refs,
        3,
    );
    let table = penumbra_table(&Scene::lab(), &camera, w, h);
    save_all(
        dir,
        &[("penumbrae.png", &figure)],
        &[("penumbrae.md", &table)],
    )
}

/// The penumbrae at the far tips of the glass and the mirror ball's
/// shadows, measured on the ground for each disc of [`SUN_SIZES`], against
/// the first-order estimate, and in pixels of the figure's images.
fn penumbra_table(scene: &Scene, camera: &Camera, w: u32, h: u32) -> String {
    let mut text = format!(
        "| sun | ball | from the ball | width on the ground | estimate d·D/sin e | pixels at {w}×{h} |\n\
         |---|---|---:|---:|---:|---:|\n"
    );
    for size in SUN_SIZES.iter().flatten() {
        let sun = Sunlight::new(&scene.sun, Some(*size));
        for name in ["glass", "mirror"] {
            let Some(ball) = scene.sphere_named(name).map(|i| &scene.spheres()[i]) else {
                continue;
            };
            let p = penumbra::at_shadow_tip(&sun, ball);
            let pixels = p
                .pixels(camera, w, h)
                .map_or("off the image".to_owned(), |px| format!("{px:.2}"));
            let _ = writeln!(
                text,
                "| {size}° | {name} | {:.2} | {:.4} | {:.4} | {pixels} |",
                p.distance_to_ball,
                p.width(),
                p.estimate(*size, sun.direction),
            );
        }
    }
    text
}

// ---------------------------------------------------------------------------
// 5. The caustic

/// The scene file that looks at the glass ball's caustic.
pub const CAUSTIC_VIEW: &str = "caustic-view.toml";

fn caustic_figure(
    dir: &Path,
    scenes: &Path,
    size: Size,
    quiet: bool,
) -> Result<Vec<PathBuf>, JobError> {
    // Small and few paths: with --caustics every path that reaches the
    // ground reads the photon map, which makes this view's run slow.
    let (w, h) = ((size.width / 4).max(8), (size.height / 4).max(6));
    let scene_flag = format!("--scene={}", scenes.join(CAUSTIC_VIEW).display());
    let flags = with(size_flags(w, h, CAUSTIC_SPP), &[&scene_flag]);
    let eye_only = path_render(&flags, quiet)?;
    let traced = path_render(&with(flags, &["--caustics"]), quiet)?;
    let caustic = &traced.terms()[4];
    // Crop around the brightest caustic pixel.
    let (k, _) = caustic
        .pixels()
        .iter()
        .enumerate()
        .fold((0, f32::MIN), |best, (k, &c)| {
            if luminance(c) > best.1 {
                (k, luminance(c))
            } else {
                best
            }
        });
    let at = ((k as u32 % w) as f32, (k as u32 / w) as f32);
    let crop = ((w / 4).max(4), (h / 4).max(3));
    let scale = (240 / crop.0).max(1);
    let images = [
        eye_only.image.to_srgb8(),
        traced.image.to_srgb8(),
        caustic.to_srgb8(),
    ];
    let crops = [&images[0], &images[1]].map(|i| magnified_crop(i, at, crop, scale));
    let peak = luminance(caustic.pixels()[k]);
    let figure = montage(
        &format!(
            "The glass ball's caustic, seen from the side: {w}×{h}, {CAUSTIC_SPP} paths per pixel"
        ),
        &[
            ("from the eye only: no caustic", &images[0]),
            ("with --caustics: traced from the sun", &images[1]),
            ("the caustics term alone", &images[2]),
            (
                &format!("from the eye only, {}×{} pixels, ×{scale}", crop.0, crop.1),
                &crops[0],
            ),
            (&format!("with --caustics, ×{scale}"), &crops[1]),
        ],
        3,
    );
    let mean_lit_ground = 2.5 * Scene::lab().sun.direction.y / std::f32::consts::PI;
    let text = format!(
        "The caustic's brightest pixel adds a luminance of {peak:.3} (linear), where the sun \
         alone gives open ground {mean_lit_ground:.3} per unit albedo (albedo/π · 2.5 · cos): \
         {} photons were traced from the sun, {} of them landed on the ground.\n",
        traced.caustics.map_or(0, |c| c.sent),
        traced.caustics.map_or(0, |c| c.landed)
    );
    save_all(dir, &[("caustic.png", &figure)], &[("caustic.md", &text)])
}

// ---------------------------------------------------------------------------
// 6. Convergence

/// One measured count: its RMSE against the reference, and the RMSE its own
/// variance estimate predicts.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ConvergencePoint {
    pub spp: u32,
    pub rmse: f64,
    /// `sqrt(measured² − the reference's own variance)`: the error against
    /// the true image, as far as the reference can tell.
    pub corrected: f64,
    /// `sqrt(mean variance of the mean)` from the render's own samples
    /// (`None` with one sample per pixel, where it is unknown).
    pub predicted: Option<f64>,
}

/// The convergence image size: a tenth of the job's each way.
fn convergence_size(size: Size) -> (u32, u32) {
    ((size.width / 10).max(8), (size.height / 10).max(6))
}

fn convergence_figures(dir: &Path, size: Size, quiet: bool) -> Result<Vec<PathBuf>, JobError> {
    let (w, h) = convergence_size(size);
    let reference = path_render(&with(size_flags(w, h, REFERENCE_SPP), &["--seed=1"]), quiet)?;
    let reference_variance = mean_variance(&reference.variance);
    let mut points = Vec::new();
    let mut noise: Vec<(u32, RgbImage)> = Vec::new();
    for spp in COUNTS {
        let render = path_render(&with(size_flags(w, h, spp), &["--seed=0"]), true)?;
        let measured = rmse(&render.image, &reference.image);
        points.push(ConvergencePoint {
            spp,
            rmse: measured,
            corrected: (measured * measured - reference_variance).max(0.0).sqrt(),
            predicted: (spp > 1).then(|| mean_variance(&render.variance).sqrt()),
        });
        if [1, 16, 256].contains(&spp) {
            noise.push((spp, render.image.to_srgb8()));
        }
    }
    noise.push((REFERENCE_SPP, reference.image.to_srgb8()));
    let scale = (240 / w).max(1);
    let magnified: Vec<(String, RgbImage)> = noise
        .into_iter()
        .map(|(spp, image)| {
            let label = match spp {
                REFERENCE_SPP => format!("{spp} (the reference, seed 1)"),
                1 => "1 path per pixel".to_owned(),
                _ => format!("{spp} paths per pixel"),
            };
            (label, magnified_crop(&image, (0.0, 0.0), (w, h), scale))
        })
        .collect();
    let refs: Vec<(&str, &RgbImage)> = magnified.iter().map(|(l, i)| (l.as_str(), i)).collect();
    let crops = montage(
        &format!("The noise: the whole {w}×{h} image, magnified ×{scale}"),
        &refs,
        4,
    );
    let csv = convergence_csv(&points);
    let table = convergence_markdown(&points, (w, h), reference_variance.sqrt());
    let plot = convergence_plot(&points, (w, h), reference_variance.sqrt());
    save_all(
        dir,
        &[("convergence.png", &plot), ("noise.png", &crops)],
        &[("convergence.csv", &csv), ("convergence.md", &table)],
    )
}

/// Two panels. Above, the error as measured on log–log axes with the
/// 1/√N line and the reference's own noise as a dashed floor. Below, the
/// series the page reads, each times √N, where 1/√N is a flat line: the
/// error as measured, the error without the reference's noise, and what
/// the render's own variance predicts.
fn convergence_plot(points: &[ConvergencePoint], (w, h): (u32, u32), floor: f64) -> RgbImage {
    let start = points[0].corrected;
    let guide: Vec<(f64, f64)> = COUNTS
        .iter()
        .map(|&n| (f64::from(n), start / f64::from(n).sqrt()))
        .collect();
    let series = |f: fn(&ConvergencePoint) -> Option<f64>| -> Vec<(f64, f64)> {
        points
            .iter()
            .filter_map(|p| f(p).map(|v| (f64::from(p.spp), v.max(1e-6))))
            .collect()
    };
    let times_root_n = |f: fn(&ConvergencePoint) -> Option<f64>| -> Vec<(f64, f64)> {
        series(f)
            .into_iter()
            .map(|(n, v)| (n, v * n.sqrt()))
            .collect()
    };
    let last = f64::from(COUNTS[COUNTS.len() - 1]);
    let error = LinePlot::new("The error, as measured")
        .x_label("paths per pixel N (log scale)")
        .y_label("RMSE, linear radiance")
        .log_x()
        .x_range(1.0, last)
        .log_y(1e-3)
        .legend(Corner::TopRight)
        .series(Series::new(
            "measured against the reference",
            series_colour(0),
            series(|p| Some(p.rmse)),
        ))
        .series(Series::new("1/√N from N = 1", [150, 150, 150], guide).without_markers());
    let highest = times_root_n(|p| Some(p.rmse))
        .iter()
        .map(|p| p.1)
        .fold(start, f64::max);
    let flat = LinePlot::new("The same times √N: flat where the error falls as 1/√N")
        .x_label("paths per pixel N (log scale)")
        .y_label("RMSE × √N")
        .log_x()
        .x_range(1.0, last)
        .y_range(0.0, highest * 1.25)
        .legend(Corner::BottomLeft)
        .series(Series::new(
            "measured against the reference",
            series_colour(0),
            times_root_n(|p| Some(p.rmse)),
        ))
        .series(Series::new(
            "without the reference's own noise",
            series_colour(2),
            times_root_n(|p| Some(p.corrected)),
        ))
        .series(Series::new(
            "predicted by the render's own variance",
            series_colour(1),
            times_root_n(|p| p.predicted),
        ));
    let (width, panel_h, title_h) = (820u32, 420u32, 44u32);
    let mut top = error.render_canvas(width, panel_h);
    let from = error.data_to_pixel(width, panel_h, 1.0, floor);
    let to = error.data_to_pixel(width, panel_h, last, floor);
    top.dashed_line(from, to, [85, 85, 85], 1.5, 6.0, 4.0);
    // Under the line at its left end, far below the error at few paths.
    top.text(
        from.0 + 8.0,
        from.1 + 5.0,
        &format!("the reference's own noise, {floor:.4}"),
        13.0,
        [85, 85, 85],
        Anchor::TOP_LEFT,
    );
    let mut canvas = Canvas::new(width, title_h + 2 * panel_h, WHITE);
    canvas.text(
        width as f32 / 2.0,
        14.0,
        &format!("Chapter 6's error against a {REFERENCE_SPP}-path render, {w}×{h}"),
        20.0,
        raylab_plot::colour::TEXT,
        Anchor::TOP_CENTRE,
    );
    canvas.draw_rgb_image(&top.to_rgb_image(), 0, title_h as i32, 1);
    canvas.draw_rgb_image(
        &flat.render(width, panel_h),
        0,
        (title_h + panel_h) as i32,
        1,
    );
    canvas.to_rgb_image()
}

fn convergence_csv(points: &[ConvergencePoint]) -> String {
    let mut text = String::from("spp,rmse,rmse_corrected,rmse_predicted\n");
    for p in points {
        let _ = writeln!(
            text,
            "{},{:.6},{:.6},{}",
            p.spp,
            p.rmse,
            p.corrected,
            p.predicted.map_or(String::new(), |v| format!("{v:.6}"))
        );
    }
    text
}

/// The slope of log RMSE against log N between the first and last points.
pub fn log_log_slope(points: &[(f64, f64)]) -> f64 {
    let (first, last) = (points[0], points[points.len() - 1]);
    (last.1.ln() - first.1.ln()) / (last.0.ln() - first.0.ln())
}

fn convergence_markdown(points: &[ConvergencePoint], (w, h): (u32, u32), floor: f64) -> String {
    let mut text = String::from(
        "| paths per pixel | RMSE | without the reference's noise | predicted by its own variance | \
         RMSE × √N |\n|---:|---:|---:|---:|---:|\n",
    );
    for p in points {
        let _ = writeln!(
            text,
            "| {} | {:.4} | {:.4} | {} | {:.3} |",
            p.spp,
            p.rmse,
            p.corrected,
            p.predicted.map_or("—".to_owned(), |v| format!("{v:.4}")),
            p.rmse * f64::from(p.spp).sqrt()
        );
    }
    let measured: Vec<(f64, f64)> = points
        .iter()
        .map(|p| (f64::from(p.spp), p.corrected.max(1e-9)))
        .collect();
    let _ = writeln!(
        text,
        "\nRMSE over every channel of every pixel of the {w}×{h} image, in linear radiance, \
         against a {REFERENCE_SPP}-path render with another seed (seed 1; these use seed 0). \
         The reference's own noise, from its variance, is {floor:.4}; without it, the error \
         falls with a log–log slope of {:.2} from 1 to {} paths (−0.5 is 1/√N).",
        log_log_slope(&measured),
        COUNTS[COUNTS.len() - 1]
    );
    text
}

// ---------------------------------------------------------------------------
// 7. The depth limit

fn depth_figures(dir: &Path, size: Size, quiet: bool) -> Result<Vec<PathBuf>, JobError> {
    let (w, h) = ((size.width / 5).max(8), (size.height / 5).max(6));
    let mut renders = Vec::new();
    for depth in DEPTHS {
        let flags = with(size_flags(w, h, SPP), &[&format!("--max-depth={depth}")]);
        renders.push(path_render(&flags, quiet)?);
    }
    let images: Vec<RgbImage> = renders.iter().map(|r| r.image.to_srgb8()).collect();
    let scale = (320 / w).max(1);
    let magnify = |image: &RgbImage| magnified_crop(image, (0.0, 0.0), (w, h), scale);
    let big: Vec<RgbImage> = images.iter().map(magnify).collect();
    let labels: Vec<String> = DEPTHS.iter().map(|d| format!("max depth {d}")).collect();
    let refs: Vec<(&str, &RgbImage)> = labels.iter().map(String::as_str).zip(&big).collect();
    let sweep = montage(
        &format!(
            "Chapter 6 at max depth 1, 2, 3, 5 and 10: {w}×{h}, {SPP} paths per pixel, the same seed"
        ),
        &refs,
        5,
    );
    let mut diffs = Vec::new();
    let mut text = String::from(
        "| depth | pixels changed (8-bit, by more than 1 level) | largest change (levels) | light \
         added (share of depth 10's) |\n|---|---:|---:|---:|\n",
    );
    let total = |r: &PathRender| -> f64 {
        r.image
            .pixels()
            .iter()
            .map(|&c| f64::from(luminance(c)))
            .sum()
    };
    let last = total(&renders[renders.len() - 1]);
    for k in 1..DEPTHS.len() {
        let (a, b) = (&images[k - 1], &images[k]);
        let changed = raylab_plot::changed_pixels(a, b, 1);
        let largest = raylab_plot::max_change(a, b);
        let added = (total(&renders[k]) - total(&renders[k - 1])) / last;
        let _ = writeln!(
            text,
            "| {} → {} | {changed} of {} | {largest} | {} |",
            DEPTHS[k - 1],
            DEPTHS[k],
            w * h,
            percent(added)
        );
        diffs.push((
            format!("{} → {}: {changed} pixels", DEPTHS[k - 1], DEPTHS[k]),
            magnify(&raylab_plot::magnified_difference(a, b, 8.0)),
        ));
    }
    let _ = writeln!(
        text,
        "\nEvery render uses seed 0, so a path follows the same random choices at every \
         depth limit and the images differ only by the light of the longer paths, not by \
         noise. Depth 1 ({:.1} % of depth 10's light) already has the sun and the sky seen \
         from the first surface.",
        100.0 * total(&renders[0]) / last
    );
    let refs: Vec<(&str, &RgbImage)> = diffs.iter().map(|(l, i)| (l.as_str(), i)).collect();
    let changes = raylab_plot::with_change_scale(
        &montage(
            "What each deeper limit adds (each change magnified 8 times; black: unchanged)",
            &refs,
            4,
        ),
        8.0,
    );
    save_all(
        dir,
        &[("depth.png", &sweep), ("changes.png", &changes)],
        &[("depth.md", &text)],
    )
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

    #[test]
    fn the_exposure_is_the_largest_third_of_a_stop_that_keeps_every_channel_at_most_1() {
        let image = |c: f32| LinearImage::from_pixels(1, 1, vec![Vec3::new(0.2, c, 0.1)]);
        assert_eq!(exposure_without_clipping(&[&image(0.9)]), 1.0);
        // 1.06 needs a third of a stop: 2^(−1/3) = 0.794, and 1.06 · 0.794 = 0.84.
        let e = exposure_without_clipping(&[&image(0.5), &image(1.06)]);
        assert!((e - 0.793_700_5).abs() < 1e-6, "{e}");
        assert_eq!(clipped_channels(&image(1.06)), 1);
        assert_eq!(clipped_channels(&exposed(&image(1.06), e)), 0);
        assert_eq!(exposure_name(e), "exposure ×0.79 (−1/3 stop)");
        assert_eq!(exposure_name(0.5), "exposure ×0.50 (−1 stop)");
        assert_eq!(
            exposure_name(2f32.powf(-5.0 / 3.0)),
            "exposure ×0.31 (−1 2/3 stops)"
        );
    }

    #[test]
    fn the_comparison_at_its_exposure_clips_nothing_though_chapter_6_alone_would() {
        let (w, h) = (80, 60);
        let whitted = whitted_image(w, h);
        let path = path_render(&with(size_flags(w, h, 16), &["--caustics"]), true).unwrap();
        assert!(
            clipped_channels(&path.image) > 0,
            "at ×1 the lit ground clips"
        );
        let e = exposure_without_clipping(&[&whitted, &path.image]);
        assert_eq!(clipped_channels(&exposed(&whitted, e)), 0);
        assert_eq!(clipped_channels(&exposed(&path.image, e)), 0);
        assert!(
            e >= 0.5,
            "the exposure is not made dark by a stray bright pixel: {e}"
        );
    }

    #[test]
    fn one_over_root_n_has_a_log_log_slope_of_minus_a_half() {
        let points: Vec<(f64, f64)> = [1.0, 4.0, 16.0, 64.0]
            .iter()
            .map(|&n: &f64| (n, 0.3 / n.sqrt()))
            .collect();
        assert!((log_log_slope(&points) + 0.5).abs() < 1e-12);
    }
}
