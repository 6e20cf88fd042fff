//! Why a program stops: every error is one line for the learner, and exit
//! code 2.

use std::path::PathBuf;

use crate::limits::MAX_PIXELS;
use crate::output::WriteError;
use crate::scene_file::SceneFileError;
use raylab::sampling::SamplingError;

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
