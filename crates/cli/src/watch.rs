//! `--watch`: render, then render again whenever the scene file is saved.
//!
//! The original lab reloaded its shaders on the fly; this is the workbook's
//! version of that loop. Edit `scenes/lab.toml`, save, and look again.

use std::path::Path;
use std::sync::atomic::Ordering;
use std::time::{Duration, SystemTime, UNIX_EPOCH};

use crate::error::CliError;
use crate::flags::Options;
use crate::program::Chapter;
use crate::report::print_report;
use crate::run::run;
use crate::saves::{Saves, Watched, ctrl_c};
use raylab::trace::Step;

/// Render, then watch `--scene` and render again after every save, until
/// Ctrl-C. A save that is not a valid scene prints its error and keeps the
/// last good image.
pub fn watch<S: Step>(chapter: &Chapter<S>, options: &Options) -> Result<(), CliError> {
    let scene = options
        .common
        .scene
        .clone()
        .ok_or(CliError::WatchNeedsScene)?;
    // The first render must work: there is no good image to keep yet.
    render_and_report(chapter, options, &scene)?;

    let stop = ctrl_c();
    let mut saves = Saves::new(vec![Watched::File(scene.clone())]).map_err(CliError::Watch)?;
    println!("watching {} (Ctrl-C to stop)", scene.display());
    while !stop.load(Ordering::SeqCst) {
        if saves.saved(Duration::from_millis(50)).is_empty() {
            continue;
        }
        if let Err(error) = render_and_report(chapter, options, &scene) {
            eprintln!(
                "{}: error: {error}; keeping the last good image",
                chapter.binary
            );
        }
    }
    println!("stopped watching {}", scene.display());
    Ok(())
}

fn render_and_report<S: Step>(
    chapter: &Chapter<S>,
    options: &Options,
    scene: &Path,
) -> Result<(), CliError> {
    let report = run(chapter, options)?;
    if !options.common.quiet {
        println!("[{}] rendered {}", clock(), scene.display());
    }
    // Quiet or not: it prints the tree --probe asked for.
    print_report(chapter, options, &report);
    Ok(())
}

/// The time of day, UTC, as HH:MM:SS: when a watched render was made.
pub fn clock() -> String {
    let seconds = SystemTime::now()
        .duration_since(UNIX_EPOCH)
        .map_or(0, |d| d.as_secs())
        % 86_400;
    format!(
        "{:02}:{:02}:{:02} UTC",
        seconds / 3600,
        seconds / 60 % 60,
        seconds % 60
    )
}
