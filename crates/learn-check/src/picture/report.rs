//! What a check says when the learner's picture differs from the
//! reference: the numbers `idiff` would give, the three images, and the
//! probe commands that show the worst pixel's ray trees.

use std::io::Write;
use std::path::Path;

use image::RgbImage;
use learn::limits::{HEIGHT, WIDTH};
use learn::run::shown;

use super::{Picture, size_flags};
use crate::compare::{Comparison, GAIN, save_images, signed_difference};

/// The mismatch, as `idiff` would put it, with the three images and the
/// probe commands that show the worst pixel's ray trees.
pub(crate) fn report_difference(
    picture: &Picture,
    comparison: &Comparison,
    (learner, reference): (&RgbImage, &RgbImage),
    program: &Path,
    dir: &Path,
    here: &Path,
    out: &mut dyn Write,
) {
    let headline = picture
        .headline
        .clone()
        .unwrap_or_else(|| format!("its render ({WIDTH}×{HEIGHT}) differs from the reference"));
    let _ = writeln!(
        out,
        "  ✗ {headline}: {:.1} % of pixels within 3 of 255 (needs 99.5 %), mean difference {:.2} \
         (needs under 0.5)",
        comparison.within_3 * 100.0,
        comparison.mean
    );
    if let Some(w) = comparison.worst {
        let _ = writeln!(
            out,
            "      worst pixel ({}, {}): yours ({}, {}, {}), the reference ({}, {}, {})",
            w.x,
            w.y,
            w.ours[0],
            w.ours[1],
            w.ours[2],
            w.reference[0],
            w.reference[1],
            w.reference[2]
        );
    }
    let images = [
        ("learner.png", learner.clone()),
        ("reference.png", reference.clone()),
        ("difference.png", signed_difference(learner, reference)),
    ];
    if save_images(&images, dir, out) {
        let _ = writeln!(
            out,
            "      look at {}/learner.png, reference.png and difference.png (red: yours brighter, \
             blue: darker, magnified ×{GAIN})",
            shown(dir, here)
        );
    }
    let Some(w) = comparison.worst else { return };
    let [width, height] = size_flags();
    let package = picture.package;
    let scene = picture
        .scene
        .as_ref()
        .map(|file| format!(" --scene={}", shown(file, here)))
        .unwrap_or_default();
    if let Some(again) = &picture.again {
        let _ = writeln!(
            out,
            "      that pixel's ray tree in the reference: cargo run -p {package} --{scene} {width} \
             {height} --probe={},{} --out={}\n      your render again (the GPU traces no single \
             pixel): {again}",
            w.x,
            w.y,
            shown(&dir.join("probe-reference"), here),
        );
    } else {
        let _ = writeln!(
            out,
            "      that pixel's ray tree, yours:        {} {width} {height} --probe={},{} --out={}\n      \
             and the reference's: cargo run -p {} --{scene} {width} {height} --probe={},{} --out={}",
            shown(program, here),
            w.x,
            w.y,
            shown(&dir.join("probe"), here),
            package,
            w.x,
            w.y,
            shown(&dir.join("probe-reference"), here),
        );
    }
}
