//! The workbook's main job, as a library so that its tests can run it on
//! a small scale: render every chapter and every figure of the book into
//! `book/src/figures/`, then build the book with mdBook.

pub mod antialiasing;
pub mod book;
pub mod claims;
pub mod concepts;
pub mod extras;
pub mod gpu_speed;
pub mod lab_page;
pub mod lane_use;
pub mod learn_figures;
pub mod many_spheres;
pub mod math;
pub mod measure;
pub mod parts;
pub mod path_tracing;
pub mod penumbra;
pub mod speed;
pub mod waves;

use std::path::{Path, PathBuf};
use std::time::Duration;

pub use parts::Parts;
use raylab::frame::thousands;
use raylab::{Settings, Step};
use raylab_cli::output::{save_png, save_text};
use raylab_cli::{self as cli, Chapter, CliError, Options};

/// Why the main job stopped.
#[derive(Debug, thiserror::Error)]
pub enum JobError {
    #[error(transparent)]
    Chapter(#[from] CliError),
    #[error("{0}")]
    Write(#[from] raylab_cli::output::WriteError),
    #[error("the book did not build: {0}")]
    Book(String),
    #[error("the explorer's figures: {0}")]
    Explorer(#[from] raylab_explore::ExploreError),
    #[error("a figure's measurements: {0}")]
    Measured(String),
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

/// What one chapter's run did, for the book's table of speeds.
#[derive(Clone, Debug, PartialEq)]
pub struct Timing {
    pub binary: &'static str,
    pub settings: Settings,
    pub rays: u64,
    pub elapsed: Duration,
    pub mrays_per_second: f64,
}

/// Run one chapter as `cargo run -p <binary> -- --out <figures>/<binary>`
/// would, and print what it did unless quiet.
fn chapter_figures<S: Step>(
    chapter: &Chapter<S>,
    figures: &Path,
    size: Size,
    quiet: bool,
    timings: &mut Vec<Timing>,
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
    options.common.quiet = quiet;
    let report = cli::run(chapter, &options)?;
    if !quiet {
        cli::print_report(chapter, &options, &report);
    }
    let rendered = &report.rendered;
    timings.push(Timing {
        binary: chapter.binary,
        settings: rendered.settings,
        rays: rendered.counts.total(),
        elapsed: rendered.elapsed,
        mrays_per_second: rendered.mrays_per_second(),
    });
    Ok(report.written)
}

/// The book's table of what each chapter's run cost on this machine.
pub fn speed_table(timings: &[Timing]) -> String {
    let mut text = String::from(
        "| program | image | rays traced | render time | Mrays/s |\n|---|---|---:|---:|---:|\n",
    );
    for t in timings {
        text.push_str(&format!(
            "| `{}` | {} | {} | {:.1} ms | {:.1} |\n",
            t.binary,
            t.settings,
            thousands(t.rays),
            t.elapsed.as_secs_f64() * 1e3,
            t.mrays_per_second
        ));
    }
    text.push_str(&format!(
        "\nOne cold run of each program, as the main job ran it on the machine that built \
         this book: {}.\n",
        speed::machine()
    ));
    text
}

/// Chapter 6's run for the book: half the chapters' size each way, 64
/// paths per pixel, with caustics, as
/// `cargo run --release -p ch08-eight-paths -- --width 400 --height 300
/// --spp 64 --caustics --out book/src/figures/ch06-path-tracing` (about
/// 8 million paths: a few seconds on two cores); then the figures that
/// compare it ([`path_tracing::make_figures`]). Chapter 8 traces chapter
/// 6's paths eight at a time, to the same bytes (its tests compare them),
/// so chapter 6's figures are its.
fn path_tracing_figures(
    figures: &Path,
    scenes: &Path,
    size: Size,
    quiet: bool,
) -> Result<Vec<PathBuf>, JobError> {
    use ch06_path_tracing::run;
    let program = &ch08_eight_paths::PROGRAM;
    let out = figures.join(ch06_path_tracing::PROGRAM.program.binary);
    let args = [
        program.program.binary.to_owned(),
        format!("--width={}", size.width / 2),
        format!("--height={}", size.height / 2),
        format!("--spp={}", path_tracing::SPP),
        "--caustics".to_owned(),
        format!("--out={}", out.display()),
    ];
    let (mut options, flags) =
        run::parse(&program.program, args).map_err(|e| CliError::Usage(e.to_string()))?;
    options.quiet = quiet;
    let report = run::run(program, &options, &flags)?;
    if !quiet {
        print!("{}", run::report_text(program.program.binary, &report));
    }
    let mut written = report.written;
    written.extend(path_tracing::make_figures(
        &out,
        scenes,
        size,
        &report.render,
        quiet,
    )?);
    Ok(written)
}

/// Every figure the book shows, written under `figures`; returns the files.
/// `scenes` is the folder of scene files (`scenes/` at the workspace root).
pub fn make_figures(
    figures: &Path,
    scenes: &Path,
    size: Size,
    quiet: bool,
    parts: &mut Parts,
) -> Result<Vec<PathBuf>, JobError> {
    let mut written = Vec::new();
    let mut timings = Vec::new();
    parts.time("chapters 1-5", || -> Result<(), JobError> {
        let t = &mut timings;
        let w = &mut written;
        w.extend(chapter_figures(
            &ch01_ray_cast::CHAPTER,
            figures,
            size,
            quiet,
            t,
        )?);
        w.extend(chapter_figures(
            &ch02_shadows::CHAPTER,
            figures,
            size,
            quiet,
            t,
        )?);
        w.extend(chapter_figures(
            &ch03_reflection::CHAPTER,
            figures,
            size,
            quiet,
            t,
        )?);
        w.extend(chapter_figures(
            &ch04_refraction::CHAPTER,
            figures,
            size,
            quiet,
            t,
        )?);
        w.extend(chapter_figures(
            &ch05_antialiasing::CHAPTER,
            figures,
            size,
            quiet,
            t,
        )?);
        Ok(())
    })?;
    written.extend(parts.time("chapter 6's figures", || {
        path_tracing_figures(figures, scenes, size, quiet)
    })?);
    parts.time(
        "chapters 7-8 and the speed tables",
        || -> Result<(), JobError> {
            written.extend(chapter_figures(
                &ch07_eight_rays::chapter(ch07_eight_rays::Like::AntiAliasing),
                figures,
                size,
                quiet,
                &mut timings,
            )?);
            let speed = figures.join("speed.md");
            save_text(&speed_table(&timings), &speed)?;
            written.push(speed);
            written.extend(lane_use::make_figure(
                &figures.join(ch08_eight_paths::PROGRAM.program.binary),
                size,
            )?);
            let pairs = speed::measure(size)?;
            let pairs_path = figures.join("speed-pairs.md");
            save_text(&speed::pairs_table(&pairs, &speed::machine()), &pairs_path)?;
            written.push(pairs_path);
            let pairs_figure = figures.join("speed-pairs.png");
            save_png(&speed::pairs_figure(&pairs), &pairs_figure)?;
            written.push(pairs_figure);
            Ok(())
        },
    )?;
    parts.time("chapter 10 on the GPU", || -> Result<(), JobError> {
        // Chapter 10's frames on this machine's GPU adapter, if it has
        // one, at half the size each way: lavapipe takes seconds per
        // 800 × 600 frame.
        let gpu_size = Size {
            width: size.width / 2,
            height: size.height / 2,
        };
        let gpu = gpu_speed::measure(gpu_size);
        if let Err(why) = &gpu {
            println!("workbook: chapter 10's speed table says there is no GPU adapter: {why}");
        }
        let gpu_path = figures.join("speed-gpu.md");
        save_text(&gpu_speed::table(gpu_size, &gpu), &gpu_path)?;
        written.push(gpu_path);
        written.extend(gpu_speed::figures(&figures.join("ch10-gpu"), gpu_size)?);
        Ok(())
    })?;
    parts.time("extras and sampling", || -> Result<(), JobError> {
        written.extend(extras::make_extras(&figures.join("extras"), size)?);
        written.extend(antialiasing::make_figures(&figures.join("sampling"), size)?);
        Ok(())
    })?;
    parts.time(
        "learn, the browser page, the explorer",
        || -> Result<(), JobError> {
            written.extend(learn_figures::make_learn_figures(&figures.join("learn"))?);
            // The lab in the browser: chapter 10's shader, its blank, the
            // packed scenes and the CPU renders its page judges by.
            written.extend(lab_page::make_lab_page(
                &figures.join("lab-in-browser"),
                scenes,
            )?);
            // The explorer's screenshots, made through its own state and
            // scripts without a window, at its window's size.
            written.extend(raylab_explore::figures::write_book_figures(
                &figures.join("explorer"),
            )?);
            Ok(())
        },
    )?;
    parts.time("concepts and waves", || -> Result<(), JobError> {
        written.extend(concepts::make_concepts(&figures.join("concepts"), figures)?);
        written.extend(waves::make_figures(&figures.join("waves"), size)?);
        Ok(())
    })?;
    written.extend(parts.time("chapter 9", || {
        many_spheres::make_figures(
            &figures.join(ch09_many_spheres::BINARY),
            scenes,
            size,
            quiet,
        )
    })?);
    written.extend(parts.time("scenes", || {
        extras::make_scene_figures(&figures.join("scenes"), scenes, size)
    })?);
    if !quiet {
        println!(
            "extras: wrote {} figures in {}",
            extras::NAMES.len(),
            figures.join("extras").display()
        );
    }
    Ok(written)
}

#[cfg(test)]
mod tests {
    use super::*;
    use raylab::Sampling;

    #[test]
    fn the_speed_table_has_a_row_per_run_with_grouped_rays_and_milliseconds() {
        let settings = Settings {
            width: 800,
            height: 600,
            max_depth: 10,
            epsilon: 1e-4,
            sampling: Sampling::PIXEL_CENTRE,
        };
        let timing = Timing {
            binary: "ch04-refraction",
            settings,
            rays: 2_323_022,
            elapsed: Duration::from_micros(25_700),
            mrays_per_second: 90.39,
        };
        let table = speed_table(&[timing.clone(), timing]);
        let row =
            "| `ch04-refraction` | 800×600, 1 spp, max depth 10 | 2,323,022 | 25.7 ms | 90.4 |";
        assert_eq!(table.matches(row).count(), 2, "{table}");
        assert!(table.starts_with("| program | image |"), "{table}");
        assert!(table.contains("a debug build") || table.contains("a release build"));
        assert!(table.contains(std::env::consts::ARCH), "{table}");
    }
}
