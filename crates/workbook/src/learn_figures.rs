//! The figures of the chapters' "Do it yourself" sections: what a learner
//! sees from `learn check` after a typical wrong first attempt.

use std::path::{Path, PathBuf};

use image::RgbImage;
use image::imageops::{FilterType, resize};
use raylab_cli::output::save_png;

use crate::JobError;

/// The files [`make_learn_figures`] writes.
pub const NAMES: [&str; 2] = ["ch02-acne-learner.png", "ch02-acne-difference.png"];

/// How much the check-sized images are magnified for the page.
const MAGNIFY: u32 = 3;

/// Chapter 2 with the feeler started on the surface, exactly as
/// `ch02-shadows --epsilon 0 --width 160 --height 120` renders it, and its
/// signed difference from the reference, as `learn check 2` draws it.
pub fn make_learn_figures(dir: &Path) -> Result<Vec<PathBuf>, JobError> {
    raylab_cli::prepare_out_dir(dir)?;
    let args = [
        "ch02-shadows".to_owned(),
        "--epsilon=0".to_owned(),
        format!("--width={}", learn::check::WIDTH),
        format!("--height={}", learn::check::HEIGHT),
        "--no-diagrams".to_owned(),
        "--quiet".to_owned(),
        format!("--out={}", dir.join("ch02-acne").display()),
    ];
    let chapter = &ch02_shadows::CHAPTER;
    let options = raylab_cli::Options::parse_for(chapter, args)
        .map_err(|e| raylab_cli::CliError::Usage(e.to_string()))?;
    let report = raylab_cli::run(chapter, &options)?;
    let acne = report.rendered.srgb;
    let reference = learn::check::reference_image(2);
    let difference = learn::compare::signed_difference(&acne, &reference);
    let mut written = Vec::new();
    for (name, image) in NAMES.iter().zip([acne, difference]) {
        let path = dir.join(name);
        save_png(&magnified(&image), &path)?;
        written.push(path);
    }
    Ok(written)
}

fn magnified(image: &RgbImage) -> RgbImage {
    let (w, h) = image.dimensions();
    resize(image, w * MAGNIFY, h * MAGNIFY, FilterType::Nearest)
}
