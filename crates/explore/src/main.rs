//! `raylab-explore`: the lab live in a window. `--help` lists the flags;
//! `?` in the window lists the keys.

use std::path::PathBuf;
use std::process::ExitCode;

use clap::Parser;
use raylab_explore::driver::{Driver, Messages, run_headless};
use raylab_explore::source::Loaded;
use raylab_explore::state::Explorer;
use raylab_explore::watch::SceneWatch;
use raylab_explore::{ExploreError, figures, measure, script, window};

/// The lab scene live in a window: chapters 1–6 on keys, an orbit camera,
/// ray trees in 3D, scene files reloaded on save.
#[derive(Parser, Debug)]
#[command(name = "raylab-explore", version)]
struct Flags {
    /// Render this scene file, and again every time it is saved
    #[arg(long, value_name = "FILE")]
    scene: Option<PathBuf>,

    /// Window width in pixels
    #[arg(long, value_name = "PIXELS", default_value_t = 640,
          value_parser = clap::value_parser!(u32).range(1..=4096))]
    width: u32,

    /// Window height in pixels
    #[arg(long, value_name = "PIXELS", default_value_t = 480,
          value_parser = clap::value_parser!(u32).range(1..=4096))]
    height: u32,

    /// Inputs to play, e.g. "key:3 click:320,240 drag:100,100,300,100 settle shot:a.png" (see the crate's script module)
    #[arg(long, value_name = "WORDS")]
    script: Option<String>,

    /// Quit once the script is done and this many frames have been shown
    #[arg(long, value_name = "N")]
    frames: Option<u32>,

    /// On quitting, write the last frame shown (overlay and all) as PNG
    #[arg(long, value_name = "FILE")]
    screenshot: Option<PathBuf>,

    /// No window: play the script and --frames, write --screenshot, quit
    #[arg(long)]
    headless: bool,

    /// No window: time chapters 1-6 at one ray per pixel while the camera turns, print a table
    #[arg(long)]
    measure: bool,

    /// No window: write the book's screenshots into DIR
    #[arg(long, value_name = "DIR")]
    figures: Option<PathBuf>,

    /// Where `w` writes frames
    #[arg(long, value_name = "DIR", default_value = "out/raylab-explore")]
    out: PathBuf,
}

fn main() -> ExitCode {
    let flags = match Flags::try_parse() {
        Ok(flags) => flags,
        Err(e) if !e.use_stderr() => {
            let _ = e.print();
            return ExitCode::SUCCESS;
        }
        Err(e) => return fail(&raylab_cli::usage_line(&e)),
    };
    match run(flags) {
        Ok(()) => ExitCode::SUCCESS,
        Err(error) => fail(&error.to_string()),
    }
}

fn fail(error: &str) -> ExitCode {
    eprintln!("raylab-explore: error: {error}");
    ExitCode::from(2)
}

fn load(scene: Option<&PathBuf>) -> Result<Loaded, ExploreError> {
    scene.map_or_else(|| Ok(Loaded::lab()), |path| Loaded::file(path))
}

fn run(flags: Flags) -> Result<(), ExploreError> {
    if let Some(dir) = &flags.figures {
        for path in figures::write_book_figures(dir)? {
            println!("wrote {}", path.display());
        }
        return Ok(());
    }
    let loaded = load(flags.scene.as_ref())?;
    if flags.measure {
        let frames = flags.frames.unwrap_or(30);
        let rows = measure::measure(
            || load(flags.scene.as_ref()).unwrap_or_else(|_| Loaded::lab()),
            flags.width,
            flags.height,
            frames,
        );
        print!("{}", measure::table(flags.width, flags.height, &rows));
        return Ok(());
    }
    let steps = script::parse(flags.script.as_deref().unwrap_or(""))?;
    let mut explorer = Explorer::new(loaded, flags.width, flags.height);
    let mut driver = Driver::new(steps, flags.out.clone());
    if flags.headless {
        let summary = run_headless(
            &mut explorer,
            &mut driver,
            flags.frames.unwrap_or(0),
            flags.screenshot.as_deref(),
            Messages::Print,
        )?;
        println!("raylab-explore: {summary}");
        return Ok(());
    }
    let watch = flags.scene.as_deref().map(SceneWatch::new).transpose()?;
    let summary = window::run(
        explorer,
        window::Run {
            driver,
            watch,
            frames: flags.frames,
            screenshot: flags.screenshot,
        },
    )?;
    println!("raylab-explore: {summary}");
    Ok(())
}
