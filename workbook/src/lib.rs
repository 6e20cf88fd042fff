//! The workbook's main job, as a library so that its tests can run it on
//! a small scale: render every chapter and every figure of the book into
//! `book/src/figures/`, then build the book with mdBook.

pub mod book;
pub mod extras;

use std::path::{Path, PathBuf};

use raylab::Step;
use raylab::cli::{self, Chapter, CliError, Options};

/// Why the main job stopped.
#[derive(Debug, thiserror::Error)]
pub enum JobError {
    #[error(transparent)]
    Chapter(#[from] CliError),
    #[error("{0}")]
    Write(#[from] raylab::output::WriteError),
    #[error("the book did not build: {0}")]
    Book(String),
}

/// Image size for the figures: the chapters' own default, or smaller for tests.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Size {
    pub width: u32,
    pub height: u32,
}

impl Size {
    /// The size every chapter renders by default.
    pub const DEFAULT: Size = Size {
        width: 800,
        height: 600,
    };
}

/// Run one chapter as `cargo run -p <binary> -- --out <figures>/<binary>`
/// would, and print what it did unless quiet.
fn chapter_figures<S: Step>(
    chapter: &Chapter<S>,
    figures: &Path,
    size: Size,
    quiet: bool,
) -> Result<Vec<PathBuf>, CliError> {
    let out = figures.join(chapter.binary);
    let args = [
        chapter.binary.to_owned(),
        format!("--width={}", size.width),
        format!("--height={}", size.height),
        format!("--out={}", out.display()),
    ];
    let mut options =
        Options::parse_for(chapter, args).map_err(|e| CliError::Usage(e.to_string()))?;
    options.quiet = quiet;
    let report = cli::run(chapter, &options)?;
    if !quiet {
        cli::print_report(chapter, &options, &report);
    }
    Ok(report.written)
}

/// Every figure the book shows, written under `figures`; returns the files.
/// `scenes` is the folder of scene files (`scenes/` at the workspace root).
pub fn make_figures(
    figures: &Path,
    scenes: &Path,
    size: Size,
    quiet: bool,
) -> Result<Vec<PathBuf>, JobError> {
    let mut written = Vec::new();
    written.extend(chapter_figures(
        &ch01_ray_cast::CHAPTER,
        figures,
        size,
        quiet,
    )?);
    written.extend(chapter_figures(
        &ch02_shadows::CHAPTER,
        figures,
        size,
        quiet,
    )?);
    written.extend(chapter_figures(
        &ch03_reflection::CHAPTER,
        figures,
        size,
        quiet,
    )?);
    written.extend(chapter_figures(
        &ch04_refraction::CHAPTER,
        figures,
        size,
        quiet,
    )?);
    written.extend(chapter_figures(
        &ch05_antialiasing::CHAPTER,
        figures,
        size,
        quiet,
    )?);
    written.extend(extras::make_extras(&figures.join("extras"), size)?);
    written.extend(extras::make_scene_figures(
        &figures.join("scenes"),
        scenes,
        size,
    )?);
    if !quiet {
        println!(
            "extras: wrote {} figures in {}",
            extras::NAMES.len(),
            figures.join("extras").display()
        );
    }
    Ok(written)
}
