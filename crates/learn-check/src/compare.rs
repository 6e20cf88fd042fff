//! The learner's render against the reference, as the lab model's tolerance
//! judges two implementations, and as OpenImageIO's `idiff` reports it;
//! `save_images` writes the images compared where the learner looks.

use std::io::Write;
use std::path::Path;

use image::{Rgb, RgbImage};

/// The comparison and the bar: the lab model's tolerance as the core keeps it,
/// the same copy the golden-image tests use. `compare(learner, reference)`
/// also names the pixel that differs most, with both its values.
pub use raylab::tolerance::{Agreement as Comparison, WorstPixel, compare};

/// How much the signed difference image magnifies: a difference of 16
/// levels (about 6 %) already shows at full strength.
pub const GAIN: f32 = 16.0;

/// A picture of `learner − reference`: black where they agree, red where
/// the learner's pixel is brighter, blue where it is darker, magnified by
/// [`GAIN`]. The sign tells a missing light (blue: a shadow too many, a
/// reflection missing) from an extra one (red).
pub fn signed_difference(learner: &RgbImage, reference: &RgbImage) -> RgbImage {
    assert_eq!(learner.dimensions(), reference.dimensions());
    RgbImage::from_fn(learner.width(), learner.height(), |x, y| {
        let (a, b) = (learner.get_pixel(x, y).0, reference.get_pixel(x, y).0);
        // The mean signed change of the three channels, so that a colour
        // shift counts as much as a brightness one.
        let signed: f32 = (0..3)
            .map(|c| f32::from(a[c]) - f32::from(b[c]))
            .sum::<f32>()
            / 3.0;
        let strength = (signed.abs() / 255.0 * GAIN).min(1.0);
        // Even a one-level change shows, dimly, against pure black.
        let level = if a == b {
            0
        } else {
            (40.0 + 215.0 * strength) as u8
        };
        signed_colour(level, signed >= 0.0 && a != b)
    })
}

/// The difference maps' two colours: red (a touch of green) where the
/// learner's picture is brighter, blue (a touch of green) where darker,
/// at `level`.
pub fn signed_colour(level: u8, brighter: bool) -> Rgb<u8> {
    if brighter {
        Rgb([level, level / 5, 0])
    } else {
        Rgb([0, level / 3, level])
    }
}

/// Write each `(name, image)` into `dir`, saying which could not be
/// written; whether all were.
pub(crate) fn save_images(images: &[(&str, RgbImage)], dir: &Path, out: &mut dyn Write) -> bool {
    let mut saved = true;
    for (name, image) in images {
        if let Err(e) = raylab_cli::output::save_png(image, &dir.join(name)) {
            let _ = writeln!(out, "      could not write {name}: {e}");
            saved = false;
        }
    }
    saved
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_learner_one_pixel_in_two_hundred_off_passes_and_two_do_not() {
        let reference = RgbImage::from_pixel(20, 10, Rgb([100, 100, 100]));
        let mut learner = reference.clone();
        learner.put_pixel(0, 0, Rgb([104, 100, 100]));
        assert!(compare(&learner, &reference).meets_lab_tolerance());
        learner.put_pixel(7, 5, Rgb([130, 100, 100]));
        let c = compare(&learner, &reference);
        assert!(!c.meets_lab_tolerance());
        assert_eq!(
            c.worst.map(|w| (w.x, w.y, w.ours)),
            Some((7, 5, [130, 100, 100]))
        );
    }

    #[test]
    fn a_brighter_pixel_is_red_and_a_darker_one_blue_in_the_difference() {
        let reference = RgbImage::from_pixel(3, 1, Rgb([100, 100, 100]));
        let mut learner = reference.clone();
        learner.put_pixel(0, 0, Rgb([200, 200, 200]));
        learner.put_pixel(2, 0, Rgb([0, 0, 0]));
        let diff = signed_difference(&learner, &reference);
        assert_eq!(diff.get_pixel(0, 0).0, [255, 51, 0]);
        assert_eq!(diff.get_pixel(1, 0).0, [0, 0, 0]);
        assert_eq!(diff.get_pixel(2, 0).0, [0, 85, 255]);
    }
}
