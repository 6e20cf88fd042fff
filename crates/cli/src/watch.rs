//! `--watch`: render, then render again whenever the scene file is saved.
//!
//! The original lab reloaded its shaders on the fly; this is the workbook's
//! version of that loop. Edit `scenes/lab.toml`, save, and look again.

use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc;
use std::time::{Duration, Instant, SystemTime, UNIX_EPOCH};

use notify::{RecursiveMode, Watcher};

use crate::{Chapter, CliError, Options, print_report, run};
use raylab::trace::Step;

/// How long the file must stay quiet before it is read: editors often
/// save in several steps (truncate, write, rename).
const DEBOUNCE: Duration = Duration::from_millis(150);

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

    let stop = Arc::new(AtomicBool::new(false));
    let flag = Arc::clone(&stop);
    // Ctrl-C ends the loop between renders; files are written atomically,
    // so even a Ctrl-C during a render leaves no half-written file.
    let _ = ctrlc::set_handler(move || flag.store(true, Ordering::SeqCst));

    let (tx, rx) = mpsc::channel();
    let watch_error = |e: notify::Error| CliError::Watch(e.to_string());
    let mut watcher = notify::recommended_watcher(move |event| {
        let _ = tx.send(event);
    })
    .map_err(watch_error)?;
    // Watch the folder, not the file: an editor that saves by renaming a
    // new file over the old one would end a watch on the file itself.
    let (folder, name) = folder_and_name(&scene)?;
    watcher
        .watch(&folder, RecursiveMode::NonRecursive)
        .map_err(watch_error)?;
    println!("watching {} (Ctrl-C to stop)", scene.display());

    let mut changed_at: Option<Instant> = None;
    while !stop.load(Ordering::SeqCst) {
        if let Ok(Ok(event)) = rx.recv_timeout(Duration::from_millis(50))
            && event
                .paths
                .iter()
                .any(|p| p.file_name() == Some(name.as_os_str()))
            && !event.kind.is_access()
        {
            changed_at = Some(Instant::now());
        }
        if changed_at.is_some_and(|t| t.elapsed() >= DEBOUNCE) {
            changed_at = None;
            if let Err(error) = render_and_report(chapter, options, &scene) {
                eprintln!(
                    "{}: error: {error}; keeping the last good image",
                    chapter.binary
                );
            }
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

fn folder_and_name(scene: &Path) -> Result<(PathBuf, std::ffi::OsString), CliError> {
    let name = scene.file_name().map(|n| n.to_owned());
    let folder = match scene.parent() {
        Some(p) if !p.as_os_str().is_empty() => p.to_owned(),
        _ => PathBuf::from("."),
    };
    name.map(|n| (folder, n))
        .ok_or_else(|| CliError::Watch(format!("'{}' is not a file", scene.display())))
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
