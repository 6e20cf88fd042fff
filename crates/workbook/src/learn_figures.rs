//! The figures of the chapters' "Do it yourself" sections: what a learner
//! sees from `learn check` after a typical wrong first attempt.

use std::path::{Path, PathBuf};

use image::RgbImage;
use image::imageops::{FilterType, resize};
use raylab_cli::output::save_png;
use raylab_plot::colour::{TEXT, WHITE};
use raylab_plot::{Anchor, Canvas};

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
        format!("--width={}", learn::limits::WIDTH),
        format!("--height={}", learn::limits::HEIGHT),
        "--no-diagrams".to_owned(),
        "--quiet".to_owned(),
        format!("--out={}", dir.join("ch02-acne").display()),
    ];
    let chapter = &ch02_shadows::CHAPTER;
    let options = raylab_cli::Options::parse_for(chapter, args)
        .map_err(|e| raylab_cli::CliError::Usage(e.to_string()))?;
    let report = raylab_cli::run(chapter, &options)?;
    let acne = report.rendered.srgb;
    let reference = learn_check::picture::reference_image(2);
    let difference = learn_check::compare::signed_difference(&acne, &reference);
    let mut written = Vec::new();
    let difference = with_sign_legend(&magnified(&difference));
    for (name, image) in NAMES.iter().zip([magnified(&acne), difference]) {
        let path = dir.join(name);
        save_png(&image, &path)?;
        written.push(path);
    }
    Ok(written)
}

/// The signed difference with its key under it: what red and blue mean,
/// and how strongly the change is magnified.
fn with_sign_legend(difference: &RgbImage) -> RgbImage {
    let (width, height) = difference.dimensions();
    let mut canvas = Canvas::new(width, height + 48, WHITE);
    canvas.draw_rgb_image(difference, 0, 0, 1);
    let full = 255.0 / learn_check::compare::GAIN;
    let lines = [
        "red: brighter than the reference; blue: darker; black: the same".to_owned(),
        format!("a mean change of {full:.0} levels or more shows at full strength"),
    ];
    for (i, line) in lines.iter().enumerate() {
        let y = height as f32 + 6.0 + 20.0 * i as f32;
        canvas.text(width as f32 / 2.0, y, line, 13.0, TEXT, Anchor::TOP_CENTRE);
    }
    canvas.to_rgb_image()
}

fn magnified(image: &RgbImage) -> RgbImage {
    let (w, h) = image.dimensions();
    resize(image, w * MAGNIFY, h * MAGNIFY, FilterType::Nearest)
}
