//! The check's picture: the learner's program renders small, and the
//! render is compared with the reference chapter's, pixel by pixel within
//! the lab model's tolerance (chapters 1 to 5) or within the two renders'
//! own noise (chapter 6, [`crate::noisy`]).

pub mod report;

use std::io::Write;
use std::path::{Path, PathBuf};
use std::time::Duration;

use image::RgbImage;
use learn::limits::{HEIGHT, WIDTH};
use learn::run::{panic_message, run_with_limit};
use raylab::{Camera, Keep, NoProgress, Scene, Step, render};
use raylab_cli::{Chapter, Options};

use crate::compare::compare;
use crate::verdict::Verdict;
use report::report_difference;

/// The size flags both renders use.
pub(crate) fn size_flags() -> [String; 2] {
    [format!("--width={WIDTH}"), format!("--height={HEIGHT}")]
}

/// What the picture check renders, and where it writes what it finds.
#[derive(Default)]
pub(crate) struct Picture<'a> {
    /// The chapter whose reference image it is compared with.
    pub number: u8,
    /// That chapter's package, for the reference's probe command.
    pub package: &'a str,
    /// Flags besides the size.
    pub flags: &'a [&'a str],
    /// Where the learner's, the reference's and the difference images go.
    pub dir: PathBuf,
    /// What the mismatch's first line says: "its render (160×120) differs
    /// from the reference" when `None`.
    pub headline: Option<String>,
    /// For a program that traces no single pixel (chapter 10 on the GPU
    /// has no `--probe`): the command that renders the learner's image
    /// again, shown instead of the probe of theirs.
    pub again: Option<String>,
    /// Words in the program's error that mean it cannot run on this
    /// machine at all ("no GPU adapter found"): not the learner's doing.
    pub unavailable: Option<&'a str>,
    /// A scene file to render instead of the lab scene, both the
    /// learner's image and the reference.
    pub scene: Option<PathBuf>,
}

/// Render the learner's program small into `picture.dir/render/`: the
/// folder, or why it made no picture.
fn render_learner(
    picture: &Picture,
    program: &Path,
    limit: Duration,
    out: &mut dyn Write,
) -> Result<PathBuf, Verdict> {
    let scratch = picture.dir.join("render");
    let mut command = std::process::Command::new(program);
    command
        .args(size_flags())
        .args(picture.flags)
        .args(
            picture
                .scene
                .as_ref()
                .map(|f| format!("--scene={}", f.display())),
        )
        .arg("--no-diagrams")
        .arg(format!("--out={}", scratch.display()))
        .env("RUST_BACKTRACE", "0");
    let output = run_with_limit(command, limit)
        .map_err(|e| Verdict::Broken(format!("cannot run {}: {e}", program.display())))?;
    if output.timed_out() {
        let _ = writeln!(
            out,
            "  ✗ its render ({WIDTH}×{HEIGHT}) did not finish in {} s and was stopped: does a loop never end?",
            limit.as_secs_f64()
        );
        return Err(Verdict::RenderTimedOut);
    }
    if !output.success() {
        let why = panic_message(&output.stderr)
            .unwrap_or_else(|| output.stderr.lines().last().unwrap_or("").to_owned());
        if picture.unavailable.is_some_and(|words| why.contains(words)) {
            // The program's own error, without its name: learn says it.
            let why = why
                .split_once(": error: ")
                .map_or(why.as_str(), |(_, rest)| rest);
            return Err(Verdict::Broken(why.to_owned()));
        }
        let _ = writeln!(out, "  ✗ its render stopped: {why}");
        return Err(Verdict::RenderPanicked(why));
    }
    if let Some(n) = non_finite(&output.stdout) {
        let _ = writeln!(
            out,
            "  ✗ its render made {n} NaN or infinite pixels (shown black): a division by zero, \
             or the square root of a negative number?"
        );
        return Err(Verdict::NonFinite(n));
    }
    Ok(scratch)
}

/// Render the learner's program small and compare it with the reference.
pub(crate) fn render_and_compare(
    picture: &Picture,
    program: &Path,
    here: &Path,
    limit: Duration,
    out: &mut dyn Write,
) -> Verdict {
    let dir = &picture.dir;
    let reference = match reference_image_in(picture.number, picture.scene.as_deref()) {
        Ok(reference) => reference,
        Err(why) => return Verdict::Broken(why),
    };
    let scratch = match render_learner(picture, program, limit, out) {
        Ok(scratch) => scratch,
        Err(verdict) => return verdict,
    };
    let learner = match image::open(scratch.join("render.png")) {
        Ok(image) => image.to_rgb8(),
        Err(e) => return Verdict::Broken(format!("cannot read the render: {e}")),
    };
    let comparison = compare(&learner, &reference);
    if comparison.meets_lab_tolerance() {
        return Verdict::Passed;
    }
    report_difference(
        picture,
        &comparison,
        (&learner, &reference),
        program,
        dir,
        here,
        out,
    );
    Verdict::Differs(comparison)
}

/// Render the learner's path tracer small and judge it against the
/// reference, rendered with the same flags, within their noise.
pub(crate) fn render_and_judge(
    picture: &Picture,
    program: &Path,
    here: &Path,
    limit: Duration,
    out: &mut dyn Write,
) -> Verdict {
    let scratch = match render_learner(picture, program, limit, out) {
        Ok(scratch) => scratch,
        Err(verdict) => return verdict,
    };
    let learner = match crate::noisy::read_render(&scratch) {
        Ok(learner) => learner,
        Err(why) => return Verdict::Broken(why),
    };
    let mut args = vec![ch06_path_tracing::PROGRAM.program.binary.to_owned()];
    args.extend(size_flags());
    args.extend(picture.flags.iter().map(|f| (*f).to_owned()));
    let reference = crate::noisy::reference(args);
    let agreement = crate::noisy::judge(&learner, &reference, &picture.dir, here, out);
    if agreement.passes() {
        let _ = writeln!(
            out,
            "  ✓ its render ({WIDTH}×{HEIGHT}, {}) matches the reference within the two renders' \
             own noise: {:.3} % of pixel channels over {} standard errors (chance allows {} %), \
             mean z {:+.3}, largest |z| {:.1}",
            picture.flags.join(" "),
            agreement.far_share() * 100.0,
            ch06_path_tracing::agreement::FAR,
            crate::noisy::MAX_FAR_SHARE * 100.0,
            agreement.mean_z,
            agreement.worst.map_or(0.0, |w| w.z.abs()),
        );
        Verdict::Passed
    } else {
        Verdict::NoisyDiffers(agreement)
    }
}

/// The count in the summary's "N pixels were NaN or infinite" warning.
fn non_finite(summary: &str) -> Option<usize> {
    let before = summary.split(" pixels were NaN or infinite").next()?;
    if before.len() == summary.len() {
        return None;
    }
    before.rsplit(' ').next()?.parse().ok()
}

/// The reference chapter's render at the check's size.
pub fn reference_image(number: u8) -> RgbImage {
    let lab = (Scene::lab(), Camera::lab());
    match number {
        1 => small_render(&ch01_ray_cast::CHAPTER, &lab),
        2 => small_render(&ch02_shadows::CHAPTER, &lab),
        3 => small_render(&ch03_reflection::CHAPTER, &lab),
        4 => small_render(&ch04_refraction::CHAPTER, &lab),
        5 => small_render(&ch05_antialiasing::CHAPTER, &lab),
        _ => small_path_traced(),
    }
}

/// The reference chapter's render of a scene file (chapters 1–5), or of
/// the lab scene when there is none.
pub fn reference_image_in(number: u8, scene: Option<&Path>) -> Result<RgbImage, String> {
    let Some(file) = scene else {
        return Ok(reference_image(number));
    };
    let scene = raylab_cli::scene_file::load(file).map_err(|e| e.to_string())?;
    Ok(match number {
        1 => small_render(&ch01_ray_cast::CHAPTER, &scene),
        2 => small_render(&ch02_shadows::CHAPTER, &scene),
        3 => small_render(&ch03_reflection::CHAPTER, &scene),
        4 => small_render(&ch04_refraction::CHAPTER, &scene),
        5 => small_render(&ch05_antialiasing::CHAPTER, &scene),
        _ => return Err(format!("chapter {number} renders no scene file in a check")),
    })
}

/// Chapter 6's reference at the check's size and flags (as 8-bit sRGB).
fn small_path_traced() -> RgbImage {
    let mut args = vec![ch06_path_tracing::PROGRAM.program.binary.to_owned()];
    args.extend(size_flags());
    let flags = learn::exercise::exercise(6).map_or(&[][..], |e| e.flags);
    args.extend(flags.iter().map(|f| (*f).to_owned()));
    crate::noisy::reference(args).image.to_srgb8()
}

fn small_render<S: Step>(chapter: &Chapter<S>, (scene, camera): &(Scene, Camera)) -> RgbImage {
    let mut args = vec![chapter.binary.to_owned()];
    args.extend(size_flags());
    let options = Options::parse_for(chapter, args).expect("the check's flags parse");
    let settings = options.settings().expect("the check's size is allowed");
    let rendered = render(
        scene,
        camera,
        &chapter.step,
        &settings,
        Keep::IMAGE,
        &NoProgress,
    );
    rendered.srgb
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_count_of_nan_pixels_is_read_from_the_summary() {
        let line = "ch02-shadows: 160×120 …; WARNING: 37 pixels were NaN or infinite\n";
        assert_eq!(non_finite(line), Some(37));
        assert_eq!(non_finite("ch02-shadows: 160×120, 1 spp\n"), None);
    }

    #[cfg(unix)]
    #[test]
    fn a_program_that_finds_no_gpu_adapter_is_a_check_that_could_not_run() {
        let dir = tempfile::tempdir().unwrap();
        let program = dir.path().join("no-gpu");
        // Written by a shell, not by this process: a file this process
        // held open for writing while another test forked could not be run
        // ("text file busy").
        let script =
            "#!/bin/sh\necho 'ch10-gpu: error: no GPU adapter found (none here)' >&2\nexit 2\n";
        let made = std::process::Command::new("sh")
            .arg("-c")
            .arg(format!(
                "printf '%s' \"$0\" > '{0}' && chmod +x '{0}'",
                program.display()
            ))
            .arg(script)
            .status()
            .unwrap();
        assert!(made.success());
        let picture = Picture {
            number: 2,
            package: "ch02-shadows",
            dir: dir.path().join("check"),
            unavailable: Some("no GPU adapter found"),
            ..Picture::default()
        };
        let mut out = Vec::new();
        let limit = Duration::from_secs(10);
        let verdict = render_and_compare(&picture, &program, dir.path(), limit, &mut out);
        assert_eq!(
            verdict,
            Verdict::Broken("no GPU adapter found (none here)".into())
        );
        assert!(out.is_empty(), "{}", String::from_utf8_lossy(&out));
    }
}
