//! A path tracer's program on the shared command line: the flags every
//! program takes, the path tracer's own (`--materials`, `--sun-size`,
//! `--caustics`), and its files. Chapter 6 runs it with its definition,
//! one path at a time; a faster renderer of the same paths can run it too.

use std::ffi::OsString;
use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Args, FromArgMatches};
use raylab::render::Progress;
use raylab::sampling::{Pattern, Sampling};
use raylab::{Camera, Scene};
use raylab_cli::output::save_png;
use raylab_cli::{self as cli, CliError, CommonFlags, Program};
use rayon::prelude::*;

use crate::exr::{Packing, save_exr};
use crate::integrator::{Materials, Terms};
use crate::render::{PathRender, PathSettings, render_paths};
use crate::sun::MAX_SUN_SIZE;

/// How a path-tracing program renders: every pixel's paths, and what they
/// add up to.
pub type PathRenderer = fn(&Scene, &Camera, &PathSettings, &dyn Progress) -> PathRender;

/// A path-tracing program: its name and defaults on the command line, and
/// its renderer.
#[derive(Clone, Copy, Debug)]
pub struct PathProgram {
    pub program: Program,
    pub render: PathRenderer,
}

/// Chapter 6's program: 256 paths per pixel, ten hits per path, traced one
/// path at a time by the chapter's definition.
pub const PROGRAM: PathProgram = PathProgram {
    program: Program {
        binary: "ch06-path-tracing",
        about: "Chapter 6, the rendering equation: the lab scene path traced, with sky light, \
                bounced light and (with --caustics) the light the glass focuses.",
        max_depth: 10,
        spp: 256,
    },
    render: render_paths,
};

/// The flags only chapter 6 has.
#[derive(Args, Debug, Clone, PartialEq)]
pub struct Flags {
    /// What the lab's shares mean: a fixed mixture (lab) or exact Fresnel on the glass
    #[arg(long, value_enum, default_value_t = Materials::Lab)]
    pub materials: Materials,

    /// The sun as a disc DEGREES across, more than 0 and at most 180 (the real sun: 0.53) [default: a point]
    #[arg(long, value_name = "DEGREES", value_parser = parse_sun_size, allow_negative_numbers = true)]
    pub sun_size: Option<f32>,

    /// Add the caustics: light traced from the sun through mirror and glass onto the ground
    #[arg(long)]
    pub caustics: bool,
}

/// `--materials` on the command line: the physics file's [`Materials`]
/// knows nothing of clap, so its names and help are given here.
impl clap::ValueEnum for Materials {
    fn value_variants<'a>() -> &'a [Self] {
        &Materials::ALL
    }

    fn to_possible_value(&self) -> Option<clap::builder::PossibleValue> {
        let help = match self {
            Materials::Lab => "The lab's shares as a mixture of three BSDFs, whatever the angle",
            Materials::Fresnel => {
                "A transmitting material splits its specular share by exact Fresnel"
            }
        };
        Some(clap::builder::PossibleValue::new(self.name()).help(help))
    }
}

fn parse_sun_size(text: &str) -> Result<f32, String> {
    match text.parse::<f32>() {
        Ok(d) if d.is_finite() && d > 0.0 && d <= MAX_SUN_SIZE => Ok(d),
        _ => Err(format!(
            "the sun's size is its angular diameter in degrees, more than 0 and at most \
             {MAX_SUN_SIZE} (the real sun is 0.53)"
        )),
    }
}

/// The flags every program takes, with a path tracer's defaults, and its own.
pub fn command(program: &Program) -> clap::Command {
    Flags::augment_args(CommonFlags::command(program))
        .mut_arg("spp", |a| a.help("Paths per pixel, 1 to 4096"))
        .mut_arg("pattern", |a| {
            a.help("Where a pixel's paths start: jittered (N = m²), random or halton [default: random]")
        })
}

/// Parse a path tracer's command line (`args` starts with the program's name).
pub fn parse(
    program: &Program,
    args: impl IntoIterator<Item = impl Into<OsString> + Clone>,
) -> Result<(CommonFlags, Flags), clap::Error> {
    let matches = command(program).try_get_matches_from(args)?;
    Ok((
        CommonFlags::from_arg_matches(&matches)?,
        Flags::from_arg_matches(&matches)?,
    ))
}

/// The render settings the flags ask for, once checked together.
pub fn settings(options: &CommonFlags, flags: &Flags) -> Result<PathSettings, CliError> {
    cli::check_pixel_count(options.width, options.height)?;
    // A path tracer's pixel is the average over its whole area (the lab model),
    // so its samples are spread at random, even for one path per pixel;
    // by default independently, so that the variance estimated from them
    // is exactly the variance of the mean.
    let pattern = options.pattern.unwrap_or(Pattern::Random);
    if pattern == Pattern::Grid {
        return Err(CliError::Usage(
            "a path tracer cannot use --pattern grid: its samples must be spread at random \
             over the pixel (use jittered, random or halton)"
                .into(),
        ));
    }
    let sampling = Sampling::new(options.spp, Some(pattern), options.seed)?;
    Ok(PathSettings {
        width: options.width,
        height: options.height,
        sampling,
        max_depth: options.max_depth,
        epsilon: options.epsilon()?,
        materials: flags.materials,
        sun_size: flags.sun_size,
        caustics: flags.caustics,
        photons_per_sphere: crate::caustics::PHOTONS_PER_SPHERE,
        keep_terms: !options.no_diagrams,
    })
}

/// What a file is written as.
#[derive(Clone, Copy)]
enum Format {
    /// 8-bit sRGB, for looking at.
    Png,
    /// 32-bit float linear light, for measuring.
    Exr(Packing),
}

impl Format {
    fn extension(self) -> &'static str {
        match self {
            Format::Png => "png",
            Format::Exr(_) => "exr",
        }
    }
}

/// What a run made.
#[derive(Debug)]
pub struct PathReport {
    pub render: PathRender,
    pub out_dir: PathBuf,
    /// Every file written, `render.png` first.
    pub written: Vec<PathBuf>,
}

/// The file name of each term's image, without its extension.
pub const TERM_FILES: [&str; 5] = [
    "term-seen",
    "term-sun-direct",
    "term-sky-direct",
    "term-indirect",
    "term-caustics",
];

/// Render and write `render.png`, `render.exr`, `variance.exr` (with two or
/// more paths per pixel) and, unless `--no-diagrams`, each term as EXR and PNG.
pub fn run(
    program: &PathProgram,
    options: &CommonFlags,
    flags: &Flags,
) -> Result<PathReport, CliError> {
    let settings = settings(options, flags)?;
    let (scene, camera) = options.load_scene()?;
    let out_dir = options.out_dir(program.program.binary);
    cli::prepare_out_dir(&out_dir)?;

    let progress = cli::progress_bar(u64::from(settings.height), options.quiet);
    let rendered = (program.render)(&scene, &camera, &settings, &|| progress.inc(1));
    progress.finish_and_clear();

    // The files in the order they are listed, render.png first, written
    // on every core at once: each encoder is one thread's work, and an
    // 800 × 600 EXR takes as long to write as a few paths per pixel take to
    // render. The render and its variance are noise to a lossless coder
    // (see `Packing::Raw`); the terms are black wherever their light is
    // absent, and run-length coded.
    let raw = Format::Exr(Packing::Raw);
    let mut files = vec![
        ("render.png".to_owned(), &rendered.image, Format::Png),
        ("render.exr".to_owned(), &rendered.image, raw),
    ];
    if settings.sampling.spp() > 1 {
        files.push(("variance.exr".to_owned(), &rendered.variance, raw));
    }
    if let Some(terms) = &rendered.terms {
        for format in [Format::Exr(Packing::RunLength), Format::Png] {
            for (name, image) in TERM_FILES.iter().zip(terms) {
                files.push((format!("{name}.{}", format.extension()), image, format));
            }
        }
    }
    let written = files
        .par_iter()
        .map(|(name, image, format)| {
            let path = out_dir.join(name);
            match *format {
                Format::Png => save_png(&image.to_srgb8(), &path),
                Format::Exr(packing) => save_exr(image, &path, packing),
            }
            .map(|()| path)
        })
        .collect::<Result<Vec<_>, _>>()?;
    Ok(PathReport {
        render: rendered,
        out_dir,
        written,
    })
}

/// What a run prints: the summary line and where the files are.
pub fn report_text(binary: &str, report: &PathReport) -> String {
    let names: Vec<String> = report
        .written
        .iter()
        .filter_map(|p| p.file_name().map(|n| n.to_string_lossy().into_owned()))
        .collect();
    let mut text = format!("{binary}: {}\n", report.render);
    if report.render.settings.sampling.spp() == 1 {
        text.push_str("  (one path per pixel: no variance.exr, it needs two or more)\n");
    }
    text.push_str(&format!(
        "  wrote {} in {}\n",
        names.join(", "),
        report.out_dir.display()
    ));
    text
}

/// A path tracer's whole `main`, on the shared one ([`cli::main_of`]):
/// parse, render, write, report; bad input gives one line on stderr and
/// exit code 2.
pub fn main(program: &PathProgram) -> ExitCode {
    let binary = program.program.binary;
    cli::main_of(
        binary,
        command(&program.program),
        std::env::args_os(),
        |matches| run_matches(program, matches),
    )
}

/// What a path tracer's program does once its arguments are parsed:
/// render, write and report. A program with flags of its own (chapter 8's
/// `--objects`) adds them to [`command`], chooses its [`PathProgram`] from
/// them, and runs this on [`cli::main_of`].
pub fn run_matches(program: &PathProgram, matches: &clap::ArgMatches) -> Result<(), CliError> {
    let usage = |e: clap::Error| CliError::Usage(cli::usage_line(&e));
    let options = CommonFlags::from_arg_matches(matches).map_err(usage)?;
    let flags = Flags::from_arg_matches(matches).map_err(usage)?;
    let report = run(program, &options, &flags)?;
    if !options.quiet {
        use std::io::Write;
        let text = report_text(program.program.binary, &report);
        let _ = std::io::stdout().lock().write_all(text.as_bytes());
    }
    Ok(())
}

// Every term has its file.
const _: () = assert!(Terms::NAMES.len() == TERM_FILES.len());
