//! The workbook's main job: run every chapter's program with its defaults,
//! as a learner would, one after the other.
//!
//! `cargo run --release -p workbook`

use std::process::ExitCode;

use raylab::Step;
use raylab::cli::{self, Chapter, Options};

/// Render one chapter with its default options and print its summary.
fn render_chapter<S: Step>(chapter: &Chapter<S>) -> Result<(), cli::CliError> {
    let options = Options::defaults(chapter);
    let report = cli::run(chapter, &options)?;
    cli::print_report(chapter, &options, &report);
    Ok(())
}

fn main() -> ExitCode {
    let result = render_chapter(&ch01_ray_cast::CHAPTER)
        .and_then(|()| render_chapter(&ch02_shadows::CHAPTER))
        .and_then(|()| render_chapter(&ch03_reflection::CHAPTER))
        .and_then(|()| render_chapter(&ch04_refraction::CHAPTER))
        .and_then(|()| render_chapter(&ch05_antialiasing::CHAPTER));
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(error) => {
            eprintln!("workbook: error: {error}");
            ExitCode::from(2)
        }
    }
}
