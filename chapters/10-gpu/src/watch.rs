//! `--watch`: render, then render again whenever the shader or the scene
//! file is saved — the original lab's reload-on-save, for the shader
//! itself.
//!
//! A save that does not compile prints naga's message, with its line and
//! column, and the last good tracer stays in use: the image on screen is
//! the last one that worked until the file is fixed.

use std::ffi::OsString;
use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc;
use std::time::{Duration, Instant};

use notify::{RecursiveMode, Watcher};
use raylab::{Camera, Scene};
use raylab_cli::{CliError, CommonFlags};

use crate::BINARY;
use crate::gpu::{Gpu, Tracer};
use crate::like::Like;
use crate::run::{self, Error};
use crate::shader::Source;

/// How long a file must stay quiet before it is read: editors often save
/// in several steps (truncate, write, rename).
const DEBOUNCE: Duration = Duration::from_millis(150);

/// A file being watched: its folder (watched, so that an editor that
/// saves by renaming a new file over the old one does not end the watch)
/// and its name.
struct Watched {
    folder: PathBuf,
    name: OsString,
}

impl Watched {
    fn new(path: &Path) -> Result<Watched, Error> {
        let name = path
            .file_name()
            .ok_or_else(|| Error::Usage(format!("'{}' is not a file", path.display())))?;
        let folder = match path.parent() {
            Some(p) if !p.as_os_str().is_empty() => p.to_owned(),
            _ => PathBuf::from("."),
        };
        Ok(Watched {
            folder,
            name: name.to_owned(),
        })
    }

    fn is(&self, path: &Path) -> bool {
        path.file_name() == Some(self.name.as_os_str())
    }
}

/// Render, then watch the shader file (if one is given) and `--scene` (if
/// given), rendering again after every save, until Ctrl-C.
pub fn watch(
    gpu: &Gpu,
    mut tracer: Tracer,
    like: Like,
    options: &CommonFlags,
    shader: Option<&Path>,
) -> Result<(), Error> {
    let mut scene = run::load_scene(options)?;
    // The first render must work: there is no good image to keep yet.
    render_and_print(gpu, &tracer, like, options, &scene)?;

    let stop = Arc::new(AtomicBool::new(false));
    let flag = Arc::clone(&stop);
    // Ctrl-C ends the loop between renders; files are written atomically,
    // so even a Ctrl-C during a render leaves no half-written file.
    let _ = ctrlc::set_handler(move || flag.store(true, Ordering::SeqCst));

    let shader = shader.map(Watched::new).transpose()?;
    let scene_file = options.scene.as_deref().map(Watched::new).transpose()?;
    let (tx, rx) = mpsc::channel();
    let watch_error = |e: notify::Error| Error::Cli(CliError::Watch(e.to_string()));
    let mut watcher = notify::recommended_watcher(move |event| {
        let _ = tx.send(event);
    })
    .map_err(watch_error)?;
    let mut folders: Vec<&Path> = shader
        .iter()
        .chain(&scene_file)
        .map(|w| w.folder.as_path())
        .collect();
    folders.dedup();
    for folder in folders {
        watcher
            .watch(folder, RecursiveMode::NonRecursive)
            .map_err(watch_error)?;
    }
    let names: Vec<String> = shader
        .iter()
        .chain(&scene_file)
        .map(|w| w.folder.join(&w.name).display().to_string())
        .collect();
    println!("watching {} (Ctrl-C to stop)", names.join(" and "));

    let mut shader_saved: Option<Instant> = None;
    let mut scene_saved: Option<Instant> = None;
    while !stop.load(Ordering::SeqCst) {
        if let Ok(Ok(event)) = rx.recv_timeout(Duration::from_millis(50))
            && !event.kind.is_access()
        {
            for path in &event.paths {
                if shader.as_ref().is_some_and(|w| w.is(path)) {
                    shader_saved = Some(Instant::now());
                }
                if scene_file.as_ref().is_some_and(|w| w.is(path)) {
                    scene_saved = Some(Instant::now());
                }
            }
        }
        let settled = |saved: Option<Instant>| saved.is_some_and(|t| t.elapsed() >= DEBOUNCE);
        let (new_shader, new_scene) = (settled(shader_saved), settled(scene_saved));
        if !new_shader && !new_scene {
            continue;
        }
        let mut changed = false;
        if new_shader {
            shader_saved = None;
            let path = shader.as_ref().map(|w| w.folder.join(&w.name));
            let compiled = path.as_deref().map(|p| {
                Source::read(p).and_then(|source| gpu.compile(&source, options.max_depth))
            });
            match compiled {
                Some(Ok(new)) => {
                    tracer = new;
                    changed = true;
                }
                Some(Err(error)) => {
                    eprintln!("{BINARY}: error: {error}; keeping the last good shader")
                }
                None => {}
            }
        }
        if new_scene {
            scene_saved = None;
            match run::load_scene(options) {
                Ok(new) => {
                    scene = new;
                    changed = true;
                }
                Err(error) => eprintln!("{BINARY}: error: {error}; keeping the last good scene"),
            }
        }
        if changed && let Err(error) = render_and_print(gpu, &tracer, like, options, &scene) {
            eprintln!("{BINARY}: error: {error}; keeping the last good image");
        }
    }
    println!("stopped watching");
    Ok(())
}

fn render_and_print(
    gpu: &Gpu,
    tracer: &Tracer,
    like: Like,
    options: &CommonFlags,
    scene: &(Scene, Camera),
) -> Result<(), Error> {
    let report = run::render(gpu, tracer, like, options, scene)?;
    if !options.quiet {
        println!(
            "[{}] rendered with {}",
            raylab_cli::watch::clock(),
            tracer.name
        );
        print!("{}", run::report_text(&report, tracer, gpu));
    }
    Ok(())
}
