//! One run of a chapter: render, write `render.png`, then the figures of
//! the render (heat maps, the probe's ray tree, the depth sweep).

use std::io::IsTerminal;
use std::path::Path;

use indicatif::{ProgressBar, ProgressStyle};

use crate::diagrams::sweep::DepthSweep;
use crate::diagrams::{heatmaps, ray_tree};
use crate::error::CliError;
use crate::flags::Options;
use crate::output::{save_png, save_text};
use crate::probe_text::{self, Listing};
use crate::program::Chapter;
use crate::report::Report;
use raylab::camera::Camera;
use raylab::frame::{Keep, Settings};
use raylab::probe;
use raylab::render::render_every_depth;
use raylab::scene::Scene;
use raylab::trace::Step;

/// The most rays per pixel at which a chapter sweeps the depth by itself:
/// the sweep traces every sample again, so at `--spp 4096` it would double
/// a long render. `--sweep N` makes one at any count.
pub const SWEEP_SPP: u32 = 16;

/// Make sure `dir` exists and takes new files, before any work is done.
pub fn prepare_out_dir(dir: &Path) -> Result<(), CliError> {
    let fail = |source| CliError::OutputFolder {
        path: dir.to_owned(),
        source,
    };
    std::fs::create_dir_all(dir).map_err(fail)?;
    tempfile::tempfile_in(dir).map_err(fail)?;
    Ok(())
}

/// A progress bar on a terminal; nothing when quiet or redirected.
pub fn progress_bar(rows: u64, quiet: bool) -> ProgressBar {
    if quiet || !std::io::stderr().is_terminal() {
        return ProgressBar::hidden();
    }
    let bar = ProgressBar::new(rows);
    bar.set_style(
        ProgressStyle::with_template("{spinner} rendering [{bar:40}] {pos}/{len} rows {elapsed}")
            .expect("a valid template")
            .progress_chars("=> "),
    );
    bar
}

/// Render a chapter with these options and write `render.png`, then,
/// unless `--no-diagrams`, its heat maps, its probe's ray tree and (in
/// chapters that trace beyond depth 1, or with `--sweep`) the depth sweep.
/// A pixel asked for with `--probe` is probed even with `--no-diagrams`.
pub fn run<S: Step>(chapter: &Chapter<S>, options: &Options) -> Result<Report, CliError> {
    let settings = options.settings()?;
    let settings = Settings {
        sampling: settings.sampling.with_lab_five(chapter.step.lab_five()),
        ..settings
    };
    // Read the scene before anything is written: a bad file writes nothing.
    let (scene, camera) = options.common.load_scene()?;
    let out_dir = options.out_dir(chapter);
    prepare_out_dir(&out_dir)?;

    let progress = progress_bar(u64::from(settings.height), options.common.quiet);
    // The program writes the 8-bit image; the linear one is never needed,
    // and the depth and ray-count maps only when the heat maps are drawn.
    let keep = Keep {
        linear: false,
        maps: !options.common.no_diagrams,
    };
    let rendered = (chapter.render)(&scene, &camera, &chapter.step, &settings, keep, &|| {
        progress.inc(1)
    });
    progress.finish_and_clear();

    let render_png = out_dir.join("render.png");
    save_png(&rendered.srgb, &render_png)?;
    let mut report = Report {
        rendered,
        out_dir: out_dir.clone(),
        render_png: render_png.clone(),
        written: vec![render_png],
        probe: None,
        sweep: None,
        sweep_skipped: false,
    };
    if options.common.no_diagrams {
        if let Some(pixel) = options.ray_tree.probe {
            write_probe(chapter, options, &scene, &camera, pixel, &mut report)?;
        }
        return Ok(report);
    }
    write_diagrams(chapter, options, &scene, &camera, &mut report)?;
    Ok(report)
}

/// Trace one pixel's ray tree again, logging every ray, and write it as a
/// figure (`ray-tree.png`) and as text (`probe.txt`).
fn write_probe<S: Step>(
    chapter: &Chapter<S>,
    options: &Options,
    scene: &Scene,
    camera: &Camera,
    pixel: (u32, u32),
    report: &mut Report,
) -> Result<(), CliError> {
    let settings = report.rendered.settings;
    let trees = probe::probe(scene, camera, &chapter.step, &settings, pixel);
    // Past a few trees the figure is a tangle: it draws the first ones.
    let drawn = trees.len().min(probe_text::SHOWN_TREES);
    let title = match (trees.len(), drawn) {
        (1, _) => format!("{}: the ray tree of one pixel", chapter.binary),
        (n, d) if d == n => format!("{}: the {n} ray trees of one pixel", chapter.binary),
        (n, d) => format!(
            "{}: the first {d} of the {n} ray trees of one pixel",
            chapter.binary
        ),
    };
    let listing = if options.ray_tree.probe_full {
        Listing::Full
    } else {
        Listing::Folded
    };
    // The figure draws the rays the text lists: past the first few
    // bounces inside the glass, dozens of rays that cannot change the
    // pixel would bury the ones that do.
    let fold_below = probe_text::fold_below(listing, trees.len());
    let mut rays = Vec::new();
    let mut left_out = 0;
    for tree in &trees[..drawn] {
        let folding = probe_text::Folding::of(&tree.rays, fold_below);
        for (i, ray) in tree.rays.iter().enumerate() {
            if folding.listed(i) {
                rays.push(*ray);
            } else {
                left_out += 1;
            }
        }
    }
    let figure = ray_tree::ray_tree_figure(scene, camera, &title, pixel, &rays, left_out);
    let path = report.out_dir.join("ray-tree.png");
    save_png(&figure, &path)?;
    report.written.push(path);
    let text = probe_text::format_tree(scene, pixel, &trees, listing);
    let path = report.out_dir.join("probe.txt");
    save_text(&text, &path)?;
    report.written.push(path);
    report.probe = Some((pixel, text));
    Ok(())
}

fn write_diagrams<S: Step>(
    chapter: &Chapter<S>,
    options: &Options,
    scene: &Scene,
    camera: &Camera,
    report: &mut Report,
) -> Result<(), CliError> {
    let settings = report.rendered.settings;
    let dir = report.out_dir.clone();
    // `run` asked for the maps whenever diagrams are drawn.
    let heat_maps = report.rendered.maps.as_ref().map(|maps| {
        let rendered = &report.rendered;
        [
            (
                "depth.png",
                heatmaps::depth_figure(chapter.binary, rendered, maps),
            ),
            (
                "rays.png",
                heatmaps::rays_figure(chapter.binary, rendered, maps),
            ),
        ]
    });
    let mut png = |name: &str, image: &image::RgbImage| -> Result<(), CliError> {
        let path = dir.join(name);
        save_png(image, &path)?;
        report.written.push(path);
        Ok(())
    };
    for (name, figure) in heat_maps.iter().flatten() {
        png(name, figure)?;
    }

    let pixel = options.ray_tree.probe.or_else(|| {
        // A scene of one's own may not hold the chapter's sphere: then the
        // image's centre.
        let target = chapter
            .probe
            .pixel(scene, camera, settings.width, settings.height);
        target.or(Some((settings.width / 2, settings.height / 2)))
    });
    if let Some(pixel) = pixel {
        write_probe(chapter, options, scene, camera, pixel, report)?;
    }

    // The sweep costs about one more render; past SWEEP_SPP rays per pixel
    // it is made only when `--sweep` asks for it.
    let sweeps_by_default = chapter.max_depth > 1 && settings.sampling.spp() <= SWEEP_SPP;
    report.sweep_skipped =
        options.ray_tree.sweep.is_none() && chapter.max_depth > 1 && !sweeps_by_default;
    let depth = options
        .ray_tree
        .sweep
        .or(sweeps_by_default.then_some(settings.max_depth));
    if let Some(depth) = depth {
        let start = std::time::Instant::now();
        let sweep_settings = Settings {
            max_depth: depth,
            ..settings
        };
        let progress = progress_bar(u64::from(settings.height), options.common.quiet);
        let images = render_every_depth(scene, camera, &chapter.step, &sweep_settings, &|| {
            progress.inc(1)
        });
        progress.finish_and_clear();
        let sweep = DepthSweep::new(images.iter().map(|i| i.to_srgb8()).collect());
        let sweep_dir = dir.join("depth-sweep");
        prepare_out_dir(&sweep_dir)?;
        let book_dir = format!("figures/{}/depth-sweep", chapter.binary);
        report
            .written
            .extend(sweep.write(&sweep_dir, chapter.binary, &book_dir)?);
        report.sweep = Some((sweep, start.elapsed()));
    }
    Ok(())
}
