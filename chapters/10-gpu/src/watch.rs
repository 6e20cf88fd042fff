//! `--watch`: render, then render again whenever the shader or the scene
//! file is saved — the original lab's reload-on-save, for the shader
//! itself.
//!
//! A save that does not compile prints naga's message, with its line and
//! column, and the last good tracer stays in use: the image on screen is
//! the last one that worked until the file is fixed.

use std::path::{Path, PathBuf};
use std::sync::atomic::Ordering;
use std::time::Duration;

use raylab::{Camera, Scene};
use raylab_cli::saves::{Saves, Watched, ctrl_c};
use raylab_cli::{CliError, CommonFlags};

use crate::BINARY;
use crate::gpu::{Gpu, Pipeline};
use crate::like::Like;
use crate::run::{self, Error};
use crate::shader::Source;

/// Render, then watch the shader file (if one is given) and `--scene` (if
/// given), rendering again after every save, until Ctrl-C.
pub fn watch(
    gpu: &Gpu,
    mut tracer: Pipeline,
    like: Like,
    options: &CommonFlags,
    shader: Option<&Path>,
) -> Result<(), Error> {
    let mut scene = run::load_scene(options)?;
    // The first render must work: there is no good image to keep yet.
    render_and_print(gpu, &tracer, like, options, &scene)?;

    let stop = ctrl_c();
    let shader: Option<PathBuf> = shader.map(Path::to_owned);
    let files: Vec<PathBuf> = shader.iter().chain(&options.scene).cloned().collect();
    let mut saves = Saves::new(files.iter().cloned().map(Watched::File).collect())
        .map_err(|e| Error::Cli(CliError::Watch(e)))?;
    let names: Vec<String> = files.iter().map(|f| f.display().to_string()).collect();
    println!("watching {} (Ctrl-C to stop)", names.join(" and "));

    while !stop.load(Ordering::SeqCst) {
        let saved = saves.saved(Duration::from_millis(50));
        let is_saved =
            |file: Option<&PathBuf>| file.is_some_and(|f| saved.iter().any(|&i| &files[i] == f));
        let (new_shader, new_scene) = (is_saved(shader.as_ref()), is_saved(options.scene.as_ref()));
        if !new_shader && !new_scene {
            continue;
        }
        let mut changed = false;
        if new_shader {
            let compiled = shader.as_deref().map(|p| {
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
    tracer: &Pipeline,
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
