//! # raylab-cli: the lab bench every chapter stands on
//!
//! What turns a chapter's [`Step`] into a program a learner runs: the
//! command line every chapter binary shares, writing files, scene files,
//! `--watch`, the probe's text, and the figures of a render (depth and ray
//! heat maps, the ray-tree diagram, the depth sweep). The tracer itself is
//! the core crate `raylab`; the drawing is `raylab-plot`'s.

pub mod diagrams;
pub mod output;
pub mod probe_text;
pub mod saves;
pub mod scene_file;
pub mod watch;

use std::ffi::OsString;
use std::io::{IsTerminal, Write};
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use clap::{Args, CommandFactory, FromArgMatches, Parser};
use indicatif::{ProgressBar, ProgressStyle};

use crate::diagrams::sweep::DepthSweep;
use crate::diagrams::{heatmaps, ray_tree};
use crate::output::{WriteError, save_png, save_text};
use crate::probe_text::Listing;
use crate::scene_file::SceneFileError;
use raylab::camera::Camera;
use raylab::frame::{Keep, Rendered, Settings};
use raylab::probe::{self, ProbeTarget};
use raylab::render::{Progress, render_every_depth};
use raylab::sampling::{MAX_SPP, Pattern, Sampling, SamplingError};
use raylab::scene::Scene;
use raylab::stack::MAX_DEPTH_LIMIT;
use raylab::trace::Step;

/// How a program renders its whole image with its step: the core's
/// [`raylab::render`], one ray at a time, unless the chapter brings a
/// faster renderer of its own that makes the same bytes (chapter 7's
/// waves). The probe and the depth sweep always trace one ray at a time.
pub type Renderer<S> = fn(&Scene, &Camera, &S, &Settings, Keep, &dyn Progress) -> Rendered;

/// One step of the workbook: its program's name, its defaults, its step.
pub struct Chapter<S: Step> {
    /// The binary's name, e.g. `ch01-ray-cast`; also the default output folder.
    pub binary: &'static str,
    /// One line for `--help`.
    pub about: &'static str,
    /// The default `--max-depth` (the lab model's chapter table).
    pub max_depth: u32,
    /// The default `--spp`.
    pub spp: u32,
    /// The pixel whose ray tree is drawn when `--probe` is not given.
    pub probe: ProbeTarget,
    pub step: S,
    /// How the program renders its image.
    pub render: Renderer<S>,
}

/// The largest image side accepted.
pub const MAX_SIDE: u32 = 16_384;
/// The most pixels accepted in all: 64 Mi (8192 × 8192).
pub const MAX_PIXELS: u64 = 64 * 1024 * 1024;

/// The flags every program takes: what to render, and where to write it.
#[derive(Args, Debug, Clone, PartialEq)]
pub struct CommonFlags {
    /// Image width in pixels
    #[arg(long, value_name = "PIXELS", default_value_t = 800, allow_negative_numbers = true,
          value_parser = clap::value_parser!(u32).range(1..=MAX_SIDE as i64))]
    pub width: u32,

    /// Image height in pixels
    #[arg(long, value_name = "PIXELS", default_value_t = 600, allow_negative_numbers = true,
          value_parser = clap::value_parser!(u32).range(1..=MAX_SIDE as i64))]
    pub height: u32,

    /// The deepest ray traced: 1 traces only the rays from the eye
    #[arg(long, value_name = "N", allow_negative_numbers = true,
          value_parser = clap::value_parser!(u32).range(1..=MAX_DEPTH_LIMIT as i64))]
    pub max_depth: u32,

    /// Rays per pixel, 1 to 4096: 1 is the pixel centre and 5 the lab's five rays, unless --pattern is given
    #[arg(long, value_name = "N", value_parser = parse_spp, allow_negative_numbers = true)]
    pub spp: u32,

    /// Where a pixel's rays go: grid (N = m²), jittered (N = m²), random or halton [default: for --spp other than 1 and 5, jittered where N is a square, else halton]
    #[arg(long, value_name = "PATTERN", value_parser = parse_pattern)]
    pub pattern: Option<Pattern>,

    /// The seed of every random choice: the same seed gives the same image, on any number of cores
    #[arg(long, value_name = "S", default_value_t = 0, value_parser = parse_seed,
          allow_negative_numbers = true)]
    pub seed: u64,

    /// How far shadow and secondary rays start from their surface (try 0 for shadow acne) [default: the scene file's `epsilon`, else 1e-4]
    #[arg(long, value_name = "DISTANCE", value_parser = parse_epsilon,
          allow_negative_numbers = true)]
    pub epsilon: Option<f32>,

    /// Render this scene file instead of the lab scene (see scenes/lab.toml)
    #[arg(long, value_name = "FILE")]
    pub scene: Option<PathBuf>,

    /// Folder to write into [default: out/<program name>] (set per chapter)
    #[arg(long, value_name = "DIR")]
    pub out: Option<PathBuf>,

    /// Write only the render: no heat maps, ray tree or depth sweep (what --probe asks for is still written)
    #[arg(long)]
    pub no_diagrams: bool,

    /// Print nothing but errors and the tree --probe asks for: no progress bar, no summary
    #[arg(long, short)]
    pub quiet: bool,
}

/// The flags of the programs that trace ray trees (chapters 1–5 and 7):
/// one pixel's tree, the depth sweep, and rendering again on every save.
#[derive(Args, Debug, Clone, PartialEq)]
pub struct RayTreeFlags {
    /// Render again whenever the --scene file is saved, until Ctrl-C
    #[arg(long, requires = "scene")]
    pub watch: bool,

    /// Print the ray tree of pixel X,Y (0,0 = top left), write it to probe.txt and draw it in
    /// ray-tree.png; always, even with --quiet or --no-diagrams. Subtrees too faint to change
    /// the pixel are folded into one line each
    #[arg(long, value_name = "X,Y", value_parser = parse_pixel)]
    pub probe: Option<(u32, u32)>,

    /// List every ray of the probe's tree, printed and in probe.txt: fold nothing
    #[arg(long)]
    pub probe_full: bool,

    /// Sweep the max depth from 1 to N into depth-sweep/ [default: --max-depth, in chapters 3-5, up to 16 rays per pixel]
    #[arg(long, value_name = "N", allow_negative_numbers = true,
          value_parser = clap::value_parser!(u32).range(1..=MAX_DEPTH_LIMIT as i64))]
    pub sweep: Option<u32>,
}

/// Render one step of the lab scene to a PNG: the command line of the
/// chapters that trace ray trees.
#[derive(Parser, Debug, Clone, PartialEq)]
#[command(version)]
pub struct Options {
    #[command(flatten)]
    pub common: CommonFlags,
    #[command(flatten)]
    pub ray_tree: RayTreeFlags,
}

fn parse_pixel(text: &str) -> Result<(u32, u32), String> {
    let parsed = text
        .split_once(',')
        .and_then(|(x, y)| Some((x.trim().parse().ok()?, y.trim().parse().ok()?)));
    parsed.ok_or_else(|| {
        "a pixel is two whole numbers X,Y, e.g. 600,320 (0,0 is the top left)".into()
    })
}

fn parse_spp(text: &str) -> Result<u32, String> {
    match text.parse::<u32>() {
        Ok(n) if (1..=MAX_SPP).contains(&n) => Ok(n),
        _ => Err(format!(
            "rays per pixel must be a whole number from 1 to {MAX_SPP} \
             (1 is the pixel centre, 5 the lab's five rays)"
        )),
    }
}

fn parse_pattern(text: &str) -> Result<Pattern, String> {
    Pattern::from_name(text).ok_or_else(|| {
        let names: Vec<&str> = Pattern::ALL.iter().map(|p| p.name()).collect();
        format!("the pattern must be one of {}", names.join(", "))
    })
}

fn parse_seed(text: &str) -> Result<u64, String> {
    text.parse::<u64>()
        .map_err(|_| format!("the seed must be a whole number from 0 to {}", u64::MAX))
}

/// The lab's offset of shadow and secondary rays, in scene units.
pub const DEFAULT_EPSILON: f32 = 1e-4;
/// The largest offset `--epsilon` or a scene file may ask for.
pub const MAX_EPSILON: f32 = 0.1;

fn parse_epsilon(text: &str) -> Result<f32, String> {
    match text.parse::<f32>() {
        Ok(e) if e.is_finite() && (0.0..=MAX_EPSILON).contains(&e) => Ok(e),
        _ => Err(format!(
            "the offset must be a number from 0 to {MAX_EPSILON} (scene units)"
        )),
    }
}

/// Why a chapter could not render; each is one line for the learner.
#[derive(Debug, thiserror::Error)]
pub enum CliError {
    #[error("{0}")]
    Usage(String),
    #[error(
        "--width {width} × --height {height} is {pixels} pixels, more than the {MAX_PIXELS} \
         (8192 × 8192) allowed: make the image smaller"
    )]
    TooManyPixels {
        width: u32,
        height: u32,
        pixels: u64,
    },
    #[error("cannot use output folder '{}': {source}; choose another with --out", path.display())]
    OutputFolder {
        path: PathBuf,
        source: std::io::Error,
    },
    #[error("{0}; choose another folder with --out")]
    Write(#[from] WriteError),
    #[error("{0}")]
    Scene(#[from] SceneFileError),
    #[error("{0}")]
    Sampling(#[from] SamplingError),
    #[error("--watch needs --scene FILE: it renders again when that file is saved")]
    WatchNeedsScene,
    #[error("cannot watch the scene file: {0}")]
    Watch(String),
    #[error(
        "--probe {x},{y} is outside the {width}×{height} image: X must be below {width}, Y below {height}"
    )]
    ProbeOutside {
        x: u32,
        y: u32,
        width: u32,
        height: u32,
    },
}

/// What the shared command line needs to know of a program: its name, its
/// line of help and its defaults. Every [`Chapter`] has one; a program
/// that does not render through the Whitted [`Step`] (chapters 6 and 8,
/// path tracers) names its own, adds its own flags to [`CommonFlags::command`]
/// and runs on [`main_of`], so that its command line and its errors are
/// the same as every other chapter's.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Program {
    pub binary: &'static str,
    pub about: &'static str,
    pub max_depth: u32,
    pub spp: u32,
}

impl<S: Step> Chapter<S> {
    /// This chapter's name and defaults on the command line.
    pub fn program(&self) -> Program {
        Program {
            binary: self.binary,
            about: self.about,
            max_depth: self.max_depth,
            spp: self.spp,
        }
    }
}

/// Refuse an image of more than [`MAX_PIXELS`] pixels in all (each side is
/// already checked by its own flag).
pub fn check_pixel_count(width: u32, height: u32) -> Result<(), CliError> {
    let pixels = u64::from(width) * u64::from(height);
    if pixels > MAX_PIXELS {
        return Err(CliError::TooManyPixels {
            width,
            height,
            pixels,
        });
    }
    Ok(())
}

impl CommonFlags {
    /// The flags every program takes, with a program's name and defaults.
    pub fn command(program: &Program) -> clap::Command {
        let command = clap::Command::new(program.binary).version(env!("CARGO_PKG_VERSION"));
        with_program(CommonFlags::augment_args(command), program)
    }

    /// The folder a program writes into.
    pub fn out_dir(&self, binary: &str) -> PathBuf {
        self.out
            .clone()
            .unwrap_or_else(|| Path::new("out").join(binary))
    }

    /// The render settings these flags ask for, once checked together.
    pub fn settings(&self) -> Result<Settings, CliError> {
        check_pixel_count(self.width, self.height)?;
        Ok(Settings {
            width: self.width,
            height: self.height,
            max_depth: self.max_depth,
            epsilon: self.epsilon()?,
            sampling: Sampling::new(self.spp, self.pattern, self.seed)?,
        })
    }

    /// The offset of shadow and secondary rays: `--epsilon` where given,
    /// else the scene file's own `epsilon` where it sets one (a scene far
    /// larger than the lab's needs a larger one), else the lab's
    /// [`DEFAULT_EPSILON`].
    pub fn epsilon(&self) -> Result<f32, CliError> {
        if let Some(epsilon) = self.epsilon {
            return Ok(epsilon);
        }
        let from_scene = match &self.scene {
            Some(path) => scene_file::load_file(path)?.epsilon,
            None => None,
        };
        Ok(from_scene.unwrap_or(DEFAULT_EPSILON))
    }

    /// Read `--scene`, or the lab's scene and camera without it.
    pub fn load_scene(&self) -> Result<(Scene, Camera), CliError> {
        Ok(match &self.scene {
            Some(path) => scene_file::load(path)?,
            None => (Scene::lab(), Camera::lab()),
        })
    }
}

/// `command` named after `program`, with its defaults.
fn with_program(command: clap::Command, program: &Program) -> clap::Command {
    command
        .name(program.binary)
        .bin_name(program.binary)
        .about(program.about)
        .mut_arg("max_depth", |a| {
            a.default_value(program.max_depth.to_string())
                .required(false)
        })
        .mut_arg("spp", |a| {
            a.default_value(program.spp.to_string()).required(false)
        })
        .mut_arg("out", |a| {
            a.help(format!(
                "Folder to write into [default: out/{}]",
                program.binary
            ))
        })
}

impl Options {
    /// The flags of a chapter that traces ray trees, with a program's name
    /// and defaults.
    pub fn command(program: &Program) -> clap::Command {
        with_program(<Options as CommandFactory>::command(), program)
    }

    /// The options of a chapter's program, parsed from `args` (the first
    /// one is the program's name), with that chapter's defaults.
    pub fn parse_for<S: Step>(
        chapter: &Chapter<S>,
        args: impl IntoIterator<Item = impl Into<OsString> + Clone>,
    ) -> Result<Self, clap::Error> {
        let command = Options::command(&chapter.program());
        Options::from_arg_matches(&command.try_get_matches_from(args)?)
    }

    /// A chapter's options when no flag is given.
    pub fn defaults<S: Step>(chapter: &Chapter<S>) -> Self {
        Options::parse_for(chapter, [chapter.binary]).expect("the defaults parse")
    }

    /// The folder the chapter writes into.
    pub fn out_dir<S: Step>(&self, chapter: &Chapter<S>) -> PathBuf {
        self.common.out_dir(chapter.binary)
    }

    /// The render settings these options ask for, once checked together.
    pub fn settings(&self) -> Result<Settings, CliError> {
        let common = &self.common;
        let settings = common.settings()?;
        if let Some((x, y)) = self.ray_tree.probe
            && (x >= common.width || y >= common.height)
        {
            return Err(CliError::ProbeOutside {
                x,
                y,
                width: common.width,
                height: common.height,
            });
        }
        Ok(settings)
    }
}

/// What a chapter run made.
#[derive(Debug)]
pub struct Report {
    pub rendered: Rendered,
    pub out_dir: PathBuf,
    pub render_png: PathBuf,
    /// Every file written, `render.png` first.
    pub written: Vec<PathBuf>,
    /// The probed pixel and its ray tree as text, when diagrams are drawn
    /// or `--probe` asks for it.
    pub probe: Option<((u32, u32), String)>,
    /// The depth sweep's numbers and its time, when one was made.
    pub sweep: Option<(DepthSweep, std::time::Duration)>,
    /// Whether the chapter's own depth sweep was left out because the
    /// render has more than [`SWEEP_SPP`] rays per pixel.
    pub sweep_skipped: bool,
}

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

/// Print what a run did: the summary line, the probe when asked for, the
/// sweep's conclusion, and where the files are. With `--quiet`, only the
/// probe's tree when `--probe` asked for one.
///
/// A reader that stops reading (`… | head -1`) is not an error: the files
/// are written by then, so a closed standard output is left at that.
pub fn print_report<S: Step>(chapter: &Chapter<S>, options: &Options, report: &Report) {
    let text = report_text(chapter, options, report);
    if let Err(error) = std::io::stdout().lock().write_all(text.as_bytes())
        && error.kind() != std::io::ErrorKind::BrokenPipe
    {
        eprintln!("{}: could not print the summary: {error}", chapter.binary);
    }
}

/// The text [`print_report`] prints.
fn report_text<S: Step>(chapter: &Chapter<S>, options: &Options, report: &Report) -> String {
    let asked_tree = match (options.ray_tree.probe, &report.probe) {
        (Some(_), Some((_, tree))) => tree.as_str(),
        _ => "",
    };
    if options.common.quiet {
        return asked_tree.to_owned();
    }
    let mut text = format!("{}: {}\n", chapter.binary, report.rendered);
    text.push_str(asked_tree);
    if let Some((sweep, elapsed)) = &report.sweep {
        text.push_str(&format!(
            "  depth sweep 1 to {} in {:.0} ms: no pixel changes by more than {} level after depth {}\n",
            sweep.images.len(),
            elapsed.as_secs_f64() * 1e3,
            crate::diagrams::sweep::SETTLED,
            sweep.settles_at()
        ));
    }
    if report.sweep_skipped {
        text.push_str(&format!(
            "  no depth sweep at {} rays per pixel (it would trace every sample again): \
             ask for one with --sweep {}\n",
            report.rendered.settings.sampling.spp(),
            report.rendered.settings.max_depth
        ));
    }
    let names: Vec<String> = report
        .written
        .iter()
        .filter(|p| p.parent() == Some(report.out_dir.as_path()))
        .filter_map(|p| p.file_name().map(|n| n.to_string_lossy().into_owned()))
        .chain(report.sweep.as_ref().map(|_| "depth-sweep/".to_owned()))
        .collect();
    text.push_str(&format!(
        "  wrote {} in {}\n",
        names.join(", "),
        report.out_dir.display()
    ));
    text
}

/// Turn a clap error into the one line the learner sees.
pub fn usage_line(error: &clap::Error) -> String {
    let text = error.render().to_string();
    let mut lines = text.lines().map(str::trim).filter(|l| !l.is_empty());
    let first = lines.next().unwrap_or("invalid arguments");
    let first = first.strip_prefix("error: ").unwrap_or(first);
    // What clap adds below the first line that helps: a tip, or the values
    // a flag takes (`--materials nope`).
    match lines.find(|l| l.starts_with("tip:") || l.starts_with("[possible values:")) {
        Some(hint) => format!("{first} ({})", hint.trim_matches(['[', ']'])),
        None => format!("{first} (see --help)"),
    }
}

/// A chapter program's whole `main`: parse, render, write, report.
/// Bad input gives one line on stderr and exit code 2.
pub fn main<S: Step>(chapter: &Chapter<S>) -> ExitCode {
    main_with_args(chapter, std::env::args_os())
}

/// [`main`] with the arguments given (the first is the program's name),
/// for a test or a program that hands its own arguments.
pub fn main_with_args<S: Step>(
    chapter: &Chapter<S>,
    args: impl IntoIterator<Item = impl Into<OsString> + Clone>,
) -> ExitCode {
    let command = Options::command(&chapter.program());
    main_of(chapter.binary, command, args, |matches| {
        let options =
            Options::from_arg_matches(matches).map_err(|e| CliError::Usage(usage_line(&e)))?;
        run_options(chapter, &options)
    })
}

/// What a chapter's program does once its options are parsed: render and
/// report, or render again on every save with `--watch`.
pub fn run_options<S: Step>(chapter: &Chapter<S>, options: &Options) -> Result<(), CliError> {
    if options.ray_tree.watch {
        return crate::watch::watch(chapter, options);
    }
    let report = run(chapter, options)?;
    // Quiet or not: with --quiet the report is only what was asked for.
    print_report(chapter, options, &report);
    Ok(())
}

/// The `main` of every program on the shared command line, the Whitted
/// chapters' and the path tracers' alike: parse `args` with `command` (the
/// shared flags, and any of the program's own), hand the matches to `run`,
/// and [`exit`]. `--help` and `--version` print and stop; any other
/// parsing error is the one line of [`usage_line`] and exit code 2, like
/// every error `run` gives.
pub fn main_of(
    binary: &str,
    command: clap::Command,
    args: impl IntoIterator<Item = impl Into<OsString> + Clone>,
    run: impl FnOnce(&clap::ArgMatches) -> Result<(), CliError>,
) -> ExitCode {
    let matches = match command.try_get_matches_from(args) {
        Ok(matches) => matches,
        Err(e) => {
            if matches!(
                e.kind(),
                clap::error::ErrorKind::DisplayHelp | clap::error::ErrorKind::DisplayVersion
            ) {
                let _ = e.print();
                return ExitCode::SUCCESS;
            }
            return exit(binary, Err(CliError::Usage(usage_line(&e))));
        }
    };
    exit(binary, run(&matches))
}

/// The exit of every chapter program: success (a render written, or the end
/// of `--watch` by Ctrl-C), or one line on stderr and exit code 2.
pub fn exit(binary: &str, result: Result<(), CliError>) -> ExitCode {
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(error) => {
            eprintln!("{binary}: error: {error}");
            ExitCode::from(2)
        }
    }
}
