//! `--like chNN-…`: which of chapters 1–5 a program traces as.
//!
//! Chapters 7, 9 and 10 change how the rays are traced (eight at a time,
//! through a tree, on a GPU), not what they compute, so each can stand in
//! for any of the Whitted chapters: with `--like ch03-reflection` a program
//! has chapter 3's features (shadows and mirrors, no glass), its shading
//! and its defaults (depth 10, one ray per pixel), and its image is
//! chapter 3's. This crate says once what each chapter switches on; the
//! programs share it.

use std::ffi::OsString;
use std::process::ExitCode;

use clap::FromArgMatches;
use clap::builder::PossibleValue;
use raylab::probe::ProbeTarget;
use raylab::{Hit, Ray, Step, Surface, Vec3};
use raylab_cli::{Chapter, CliError, Options, usage_line};

use ch01_ray_cast::RayCast;
use ch02_shadows::Shadows;
use ch03_reflection::Reflection;
use ch04_refraction::Refraction;
use ch05_antialiasing::AntiAliasing;

/// One of the Whitted chapters, as a program imitates it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Like {
    RayCast,
    Shadows,
    Reflection,
    Refraction,
    AntiAliasing,
}

/// What a chapter has switched on (the lab model's chapter table).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Features {
    pub shadows: bool,
    pub reflection: bool,
    pub transmission: bool,
}

/// A chapter's defaults on the command line.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Defaults {
    pub max_depth: u32,
    pub spp: u32,
    /// The pixel whose ray tree is drawn when `--probe` is not given.
    pub probe: ProbeTarget,
}

impl Like {
    pub const ALL: [Like; 5] = [
        Like::RayCast,
        Like::Shadows,
        Like::Reflection,
        Like::Refraction,
        Like::AntiAliasing,
    ];

    /// The program this imitates, e.g. `ch04-refraction`.
    pub fn binary(self) -> &'static str {
        match self {
            Like::RayCast => ch01_ray_cast::CHAPTER.binary,
            Like::Shadows => ch02_shadows::CHAPTER.binary,
            Like::Reflection => ch03_reflection::CHAPTER.binary,
            Like::Refraction => ch04_refraction::CHAPTER.binary,
            Like::AntiAliasing => ch05_antialiasing::CHAPTER.binary,
        }
    }

    /// Each chapter switches on one thing more than the one before it.
    pub fn features(self) -> Features {
        let on = |first: Like| self as usize >= first as usize;
        Features {
            shadows: on(Like::Shadows),
            reflection: on(Like::Reflection),
            transmission: on(Like::Refraction),
        }
    }

    /// The chapter's default `--max-depth`, `--spp` and probed pixel.
    pub fn defaults(self) -> Defaults {
        macro_rules! of {
            ($chapter:expr) => {
                Defaults {
                    max_depth: $chapter.max_depth,
                    spp: $chapter.spp,
                    probe: $chapter.probe,
                }
            };
        }
        match self {
            Like::RayCast => of!(ch01_ray_cast::CHAPTER),
            Like::Shadows => of!(ch02_shadows::CHAPTER),
            Like::Reflection => of!(ch03_reflection::CHAPTER),
            Like::Refraction => of!(ch04_refraction::CHAPTER),
            Like::AntiAliasing => of!(ch05_antialiasing::CHAPTER),
        }
    }
}

/// The imitated chapter's own shading, one ray at a time: the one place a
/// `Like` turns into a chapter's [`Step`].
impl Step for Like {
    fn shade(&self, ray: &Ray, hit: &Hit, surface: &mut Surface) -> Vec3 {
        match self {
            Like::RayCast => RayCast.shade(ray, hit, surface),
            Like::Shadows => Shadows.shade(ray, hit, surface),
            Like::Reflection => Reflection.shade(ray, hit, surface),
            Like::Refraction | Like::AntiAliasing => Refraction.shade(ray, hit, surface),
        }
    }

    fn lab_five(&self) -> [(f32, f32); 5] {
        match self {
            Like::AntiAliasing => AntiAliasing.lab_five(),
            _ => raylab::sampling::LAB_FIVE,
        }
    }
}

/// `--like` on the command line: clap lists the chapters in `--help` and
/// in its error, and the program's name comes first in that error line.
impl clap::ValueEnum for Like {
    fn value_variants<'a>() -> &'a [Self] {
        &Like::ALL
    }

    fn to_possible_value(&self) -> Option<PossibleValue> {
        let short = self.binary().split('-').next().unwrap_or_default();
        Some(PossibleValue::new(self.binary()).alias(short))
    }
}

/// The `--like` flag, chapter 5 when it is not given. A program adds it to
/// its command and, once parsed, applies the chosen chapter's
/// [`Defaults`] to the flags the learner did not give ([`chosen`]).
pub fn arg() -> clap::Arg {
    clap::Arg::new(ID)
        .long("like")
        .value_name("CHAPTER")
        .value_parser(clap::builder::EnumValueParser::<Like>::new())
        .default_value(Like::AntiAliasing.binary())
        .help("Trace as this chapter does, with its features and its defaults for --max-depth, --spp and --probe (ch01 … ch05 for short)")
}

/// The id of [`arg`] in a command's matches.
pub const ID: &str = "like";

/// The chapter `--like` chose, and its defaults for the flags the learner
/// left out: `max_depth` and `spp` were parsed with chapter 5's defaults,
/// and keep a value only where it was typed.
pub fn chosen(matches: &clap::ArgMatches, max_depth: &mut u32, spp: &mut u32) -> Like {
    let like = matches
        .get_one::<Like>(ID)
        .copied()
        .unwrap_or(Like::AntiAliasing);
    let typed = |id: &str| matches.value_source(id) == Some(clap::parser::ValueSource::CommandLine);
    let defaults = like.defaults();
    if !typed("max_depth") {
        *max_depth = defaults.max_depth;
    }
    if !typed("spp") {
        *spp = defaults.spp;
    }
    like
}

/// The whole `main` of a program that traces as any of chapters 1–5:
/// the shared command line with `--like`, then `chapter(like)` run with
/// the chosen chapter's defaults.
pub fn main<S: Step>(
    chapter: impl Fn(Like) -> Chapter<S>,
    args: impl IntoIterator<Item = impl Into<OsString> + Clone>,
) -> ExitCode {
    let fallback = chapter(Like::AntiAliasing);
    raylab_cli::main_of(fallback.binary, command(&fallback), args, |matches| {
        run(matches, chapter)
    })
}

/// The shared command line with `--like`, named after `chapter` and with
/// its defaults: a program with flags of its own (chapter 7's `--objects`,
/// chapter 9's `generate-field`) adds them to it and runs on
/// [`raylab_cli::main_of`] and [`run`].
pub fn command<S: Step>(chapter: &Chapter<S>) -> clap::Command {
    Options::command(&chapter.program()).arg(arg())
}

/// What a program of [`command`] does once its arguments are parsed: the
/// shared options, with the defaults of the chapter `--like` chose, run
/// by `chapter(like)`.
pub fn run<S: Step>(
    matches: &clap::ArgMatches,
    chapter: impl Fn(Like) -> Chapter<S>,
) -> Result<(), CliError> {
    let mut options =
        Options::from_arg_matches(matches).map_err(|e| CliError::Usage(usage_line(&e)))?;
    let common = &mut options.common;
    let like = chosen(matches, &mut common.max_depth, &mut common.spp);
    raylab_cli::run_options(&chapter(like), &options)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn command() -> clap::Command {
        clap::Command::new("ch07-eight-rays")
            .arg(arg())
            .arg(
                clap::Arg::new("max_depth")
                    .long("max-depth")
                    .value_parser(clap::value_parser!(u32))
                    .default_value("10"),
            )
            .arg(
                clap::Arg::new("spp")
                    .long("spp")
                    .value_parser(clap::value_parser!(u32))
                    .default_value("5"),
            )
    }

    fn parse(args: &[&str]) -> Result<(Like, u32, u32), clap::Error> {
        let matches = command().try_get_matches_from(args)?;
        let mut max_depth = *matches.get_one::<u32>("max_depth").expect("a default");
        let mut spp = *matches.get_one::<u32>("spp").expect("a default");
        let like = chosen(&matches, &mut max_depth, &mut spp);
        Ok((like, max_depth, spp))
    }

    #[test]
    fn chapter_3_has_shadows_and_mirrors_but_no_glass() {
        let f = Like::Reflection.features();
        assert!(f.shadows && f.reflection && !f.transmission);
        assert!(!Like::RayCast.features().shadows);
        assert_eq!(Like::Reflection.defaults().max_depth, 10);
        assert_eq!(Like::AntiAliasing.defaults().spp, 5);
    }

    #[test]
    fn like_takes_a_chapter_by_its_program_name_or_its_number() {
        assert_eq!(
            parse(&["ch07", "--like", "ch02-shadows"]).unwrap().0,
            Like::Shadows
        );
        assert_eq!(parse(&["ch07", "--like=ch04"]).unwrap().0, Like::Refraction);
        assert_eq!(parse(&["ch07"]).unwrap().0, Like::AntiAliasing);
    }

    #[test]
    fn the_chosen_chapters_defaults_apply_where_no_flag_was_typed() {
        // Chapter 1 traces depth 1 with one ray a pixel ...
        assert_eq!(
            parse(&["ch07", "--like", "ch01"]).unwrap(),
            (Like::RayCast, 1, 1)
        );
        // ... unless the learner asks for more, even for chapter 5's values.
        assert_eq!(
            parse(&["ch07", "--like", "ch01", "--max-depth", "10", "--spp", "5"]).unwrap(),
            (Like::RayCast, 10, 5)
        );
        assert_eq!(parse(&["ch07"]).unwrap(), (Like::AntiAliasing, 10, 5));
    }

    #[test]
    fn an_unknown_or_missing_chapter_is_an_error_that_lists_the_chapters() {
        let err = parse(&["ch07", "--like", "ch06"]).unwrap_err().to_string();
        assert!(
            err.contains("ch06") && err.contains("ch01-ray-cast"),
            "{err}"
        );
        assert!(parse(&["ch07", "--like"]).is_err());
        assert!(parse(&["ch07", "--like=ch01", "--like=ch02"]).is_err());
    }
}
