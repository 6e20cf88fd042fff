//! The flags: what each one means, how its value is read, and the
//! defaults a program puts on them. [`CommonFlags`] is what every program
//! takes, [`RayTreeFlags`] what the chapters that trace ray trees add, and
//! [`Options`] the two together.

use std::ffi::OsString;
use std::path::{Path, PathBuf};

use clap::{Args, CommandFactory, FromArgMatches, Parser};

use crate::error::CliError;
use crate::limits::{DEFAULT_EPSILON, MAX_EPSILON, MAX_PIXELS, MAX_SIDE};
use crate::program::{Chapter, Program};
use crate::scene_file;
use raylab::camera::Camera;
use raylab::frame::Settings;
use raylab::sampling::{MAX_SPP, Pattern, Sampling};
use raylab::scene::Scene;
use raylab::stack::MAX_DEPTH_LIMIT;
use raylab::trace::Step;

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

    /// Folder to write into (its `--help` line is the `help` below, which
    /// names the default as `out/<program name>`: the chapter sets it).
    #[arg(
        long,
        value_name = "DIR",
        help = "Folder to write into [default: out/<program name>] (set per chapter)"
    )]
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

fn parse_epsilon(text: &str) -> Result<f32, String> {
    match text.parse::<f32>() {
        Ok(e) if e.is_finite() && (0.0..=MAX_EPSILON).contains(&e) => Ok(e),
        _ => Err(format!(
            "the offset must be a number from 0 to {MAX_EPSILON} (scene units)"
        )),
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
