//! Chapter 9's figures and numbers: a field of 500 spheres rendered
//! through the tree, the tree's boxes over it, the boxes each pixel's ray
//! tested, rays per second against the number of spheres, and the build
//! time. What they measure is in [`measure`], how they are drawn in
//! [`figures`].

pub mod figures;
pub mod measure;

use std::path::{Path, PathBuf};

use ch07_eight_rays::{EightRays, Objects};
use ch09_many_spheres::field::field_scene;
use ch09_many_spheres::{BINARY, Bvh, Like};
use figures::{build_time_figure, speed_figure, tree_figure, visits_figure};
use measure::{LIST_FULL_SIZE_UP_TO, SpeedPoint, measure_build, measure_speed};
use raylab::frame::thousands;
use raylab_cli::output::{save_png, save_text};
use raylab_cli::{self as cli, CliError, Options};

use crate::{JobError, Size, speed};

/// The sizes of field the speed figure measures.
pub const SPEED_COUNTS: [usize; 5] = [5, 50, 500, 5_000, 10_000];

/// The image the speed figure renders, list and tree alike: small, since
/// testing each of 10,000 spheres for every ray takes seconds even here.
pub const SPEED_SIZE: Size = Size {
    width: 120,
    height: 90,
};

/// The sizes of field whose build the build-time figure measures.
pub const BUILD_COUNTS: [usize; 6] = [10, 100, 300, 1_000, 3_000, 10_000];

/// Every figure of chapter 9's page, into `dir`; returns the files.
/// `scenes` is the folder of scene files.
pub fn make_figures(
    dir: &Path,
    scenes: &Path,
    size: Size,
    quiet: bool,
) -> Result<Vec<PathBuf>, JobError> {
    // The field as a learner renders it with chapter 9, but traced by
    // chapter 7 through the same tree (`--objects tree`), for the main
    // job's time: the same bytes.
    let field = scenes.join("field-500.toml");
    let args = [
        BINARY.to_owned(),
        format!("--width={}", size.width),
        format!("--height={}", size.height),
        format!("--scene={}", field.display()),
        format!("--out={}", dir.display()),
        // The render alone: its depth sweep would take most of a minute.
        "--no-diagrams".to_owned(),
    ];
    let chapter = ch07_eight_rays::chapter_through(Like::AntiAliasing, Objects::Tree);
    let mut options =
        Options::parse_for(&chapter, args.clone()).map_err(|e| CliError::Usage(e.to_string()))?;
    options.common.quiet = quiet;
    let report = cli::run(&chapter, &options)?;
    if !quiet {
        cli::print_report(&chapter, &options, &report);
    }
    let mut written = report.written.clone();
    let description = raylab_cli::scene_file::load_file(&field).map_err(CliError::from)?;
    let (scene, camera) = (description.scene.clone(), description.camera);
    written.extend(acne_figures(
        dir,
        &args,
        &chapter,
        &report.rendered.srgb,
        description.epsilon.unwrap_or(raylab_cli::DEFAULT_EPSILON),
    )?);

    let mut save = |name: &str, image: &image::RgbImage| -> Result<(), JobError> {
        let path = dir.join(name);
        save_png(image, &path)?;
        written.push(path);
        Ok(())
    };
    save(
        "tree.png",
        &tree_figure(&scene, &camera, &report.rendered.srgb, 4),
    )?;
    save(
        "visits.png",
        &visits_figure(&scene, &camera, size.width / 2, size.height / 2),
    )?;
    let points = measure_speed(&SPEED_COUNTS, SPEED_SIZE)?;
    save("speed.png", &speed_figure(&points))?;
    let builds = measure_build(&BUILD_COUNTS, 5);
    save("build-time.png", &build_time_figure(&builds))?;

    let (big, _) = field_scene(10_000);
    let tree = Bvh::build(&big);
    let text = numbers_text(&points, &builds, &tree, &speed::machine());
    let path = dir.join("numbers.md");
    save_text(&text, &path)?;
    written.push(path);
    Ok(written)
}

/// An offset far above any rounding error in the field and far below the
/// size of anything in it: the render without acne to compare with.
pub const LARGE_EPSILON: f32 = 1e-2;

/// The window of the crop of chapter 9's "ε at scale", in pixels.
pub const ACNE_WINDOW: (u32, u32) = (96, 72);

/// Chapter 9's "ε at scale": the field rendered again at the lab's 1e-4
/// (into `lab-epsilon/`), the window where it differs most from the render
/// at the field's own `epsilon`, enlarged (`acne.png`), and the count of
/// speckled pixels (`acne.md`).
fn acne_figures(
    dir: &Path,
    args: &[String],
    chapter: &raylab_cli::Chapter<EightRays>,
    own: &image::RgbImage,
    epsilon: f32,
) -> Result<Vec<PathBuf>, JobError> {
    use ch09_many_spheres::acne::{SPECKLE, speckled};
    use figures::acne_figure;
    use measure::densest_window;
    let lab_epsilon = raylab_cli::DEFAULT_EPSILON;
    let render_at = |folder: &str, epsilon: f32| {
        let mut at = args.to_vec();
        at.retain(|a| !a.starts_with("--out="));
        at.push(format!("--out={}", dir.join(folder).display()));
        at.push(format!("--epsilon={epsilon}"));
        let mut options =
            Options::parse_for(chapter, at).map_err(|e| CliError::Usage(e.to_string()))?;
        options.common.quiet = true;
        cli::run(chapter, &options)
    };
    let report = render_at("lab-epsilon", lab_epsilon)?;
    let large = render_at("large-epsilon", LARGE_EPSILON)?;
    let left = speckled(own, &large.rendered.srgb)
        .iter()
        .filter(|&&s| s)
        .count();
    let lab = &report.rendered.srgb;
    let mask = speckled(lab, own);
    let width = lab.width();
    let window = (ACNE_WINDOW.0.min(width), ACNE_WINDOW.1.min(lab.height()));
    let (corner, in_window) = densest_window(&mask, width, window.0, window.1);
    let count = mask.iter().filter(|&&s| s).count();
    let zoom = 4;
    let figure = acne_figure(lab, own, (lab_epsilon, epsilon), (corner, window), zoom);
    let mut written = report.written;
    written.extend(large.written);
    let png = dir.join("acne.png");
    save_png(&figure, &png)?;
    written.push(png);
    let pixels = u64::from(width) * u64::from(lab.height());
    let text = format!(
        "![The field at the lab's ε = {lab_epsilon:e} and at its own ε = {epsilon:e}: a \
         {}×{} window at ({}, {}), {zoom}× enlarged, with the pixels that differ by more than \
         {SPECKLE} levels in red](figures/ch09-many-spheres/acne.png)\n\n\
         *At the lab's ε = {lab_epsilon:e}, {} of the render's {} pixels ({:.2} %) differ from \
         the render at the field's own ε = {epsilon:e} by more than {SPECKLE} levels, \
         {in_window} of them in this window. Against a render at ε = {LARGE_EPSILON:e}, the \
         showcase at its own ε has {left} pixels that differ by as much.*\n",
        window.0,
        window.1,
        corner.0,
        corner.1,
        thousands(count as u64),
        thousands(pixels),
        100.0 * count as f64 / pixels as f64,
    );
    let md = dir.join("acne.md");
    save_text(&text, &md)?;
    written.push(md);
    Ok(written)
}

/// The page's numbers, as the main job measured them on this machine: a
/// table of rays per second, list against tree, the build times, and the
/// tree's size over 10,000 spheres.
pub fn numbers_text(
    points: &[SpeedPoint],
    builds: &[(usize, f64)],
    tree: &Bvh,
    machine: &str,
) -> String {
    let mut text = String::from(
        "| spheres | every sphere tested (Mrays/s) | its image | the tree (Mrays/s) | tree ÷ list |\n\
         |---:|---:|---:|---:|---:|\n",
    );
    for p in points {
        text.push_str(&format!(
            "| {} | {:.3} | {}×{} | {:.3} | {:.1} |\n",
            thousands(p.spheres as u64),
            p.list,
            p.list_size.width,
            p.list_size.height,
            p.tree,
            p.tree / p.list
        ));
    }
    let spheres = tree.order().len().max(1);
    let build = |n: usize| {
        builds
            .iter()
            .find(|(count, _)| *count == n)
            .map_or("—".to_owned(), |(_, ms)| format!("{ms:.2} ms"))
    };
    text.push_str(&format!(
        "\nThe fastest of up to five renders of each (one where a render takes a third of a \
         second or more; the tree's build included) at chapter 5's settings, {}×{}; the list \
         past {LIST_FULL_SIZE_UP_TO} spheres on a smaller image of the same view, with about \
         as many ray–sphere tests as at {LIST_FULL_SIZE_UP_TO}, on {machine}. The tree over {} spheres took {} to build on one core \
         ({} for 1,000; the best of five), and keeps {} nodes, {:.1} bytes per sphere, {} \
         levels deep.\n",
        SPEED_SIZE.width,
        SPEED_SIZE.height,
        thousands(spheres as u64),
        build(spheres),
        build(1_000),
        thousands(tree.nodes().len() as u64),
        tree.bytes() as f64 / spheres as f64,
        tree.depth()
    ));
    text
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_numbers_give_each_field_a_row_and_name_the_machine() {
        let points = [
            SpeedPoint {
                spheres: 5,
                list: 10.0,
                list_size: SPEED_SIZE,
                tree: 5.0,
            },
            SpeedPoint {
                spheres: 10_000,
                list: 0.01,
                list_size: measure::list_size(SPEED_SIZE, 10_000),
                tree: 2.0,
            },
        ];
        let (scene, _) = field_scene(40);
        let tree = Bvh::build(&scene);
        let text = numbers_text(&points, &[(40, 0.25), (1_000, 1.5)], &tree, "a test CPU");
        assert!(
            text.contains("| 5 | 10.000 | 120×90 | 5.000 | 0.5 |"),
            "{text}"
        );
        assert!(
            text.contains("| 10,000 | 0.010 | 27×20 | 2.000 | 200.0 |"),
            "{text}"
        );
        assert!(text.contains("40 spheres took 0.25 ms"), "{text}");
        assert!(text.contains("1.50 ms for 1,000"), "{text}");
        assert!(text.contains("a test CPU"), "{text}");
    }
}
