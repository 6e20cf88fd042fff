//! Chapter 6's figures, 2: the image split by the terms of its light, and
//! each term's share.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use ch06_path_tracing::{PathRender, Terms};
use image::RgbImage;
use raylab::Scene;
use raylab::linear_image::LinearImage;
use raylab_plot::montage;

use super::{SPP, percent, save_all, triple};
use crate::JobError;
use crate::measure::{GroundMasks, lab_shadow_ratio, luminance, mean_over_albedo, shares};

pub(super) fn terms_figure(
    dir: &Path,
    path: &PathRender,
    masks: &GroundMasks,
    scene: &Scene,
) -> Result<Vec<PathBuf>, JobError> {
    let images: Vec<RgbImage> = path.terms().iter().map(|t| t.to_srgb8()).collect();
    let total = path.image.to_srgb8();
    let whole = shares(path.terms(), None);
    // sRGB lifts dark values: a term with a twentieth of the light looks
    // far more than a twentieth as bright, so each tile says its share.
    let mut tiles: Vec<(String, &RgbImage)> = Terms::NAMES
        .iter()
        .zip(&images)
        .zip(whole)
        .map(|((name, image), share)| (format!("{name}: {}", percent(share)), image))
        .collect();
    tiles.push(("their sum: the image (100 %)".to_owned(), &total));
    let refs: Vec<(&str, &RgbImage)> = tiles.iter().map(|(l, i)| (l.as_str(), *i)).collect();
    let (w, h) = (path.settings.width, path.settings.height);
    let figure = montage(
        &format!(
            "Chapter 6's image split by term, {w}×{h}, {SPP} paths per pixel: all at the same \
             exposure, in sRGB; each term's share of the image's luminance"
        ),
        &refs,
        3,
    );

    let count = |m: &[bool]| m.iter().filter(|&&b| b).count();
    let shadow = shares(path.terms(), Some(&masks.shadowed));
    let lit = shares(path.terms(), Some(&masks.lit));
    let mut text = format!(
        "| term | whole image ({} pixels) | ground in the sun ({} pixels) | ground in the sun's \
         shadow ({} pixels) |\n|---|---:|---:|---:|\n",
        w * h,
        count(&masks.lit),
        count(&masks.shadowed)
    );
    for (k, name) in Terms::NAMES.iter().enumerate() {
        let _ = writeln!(
            text,
            "| {name} | {} | {} | {} |",
            percent(whole[k]),
            percent(lit[k]),
            percent(shadow[k])
        );
    }
    let _ = writeln!(
        text,
        "\nEach term's share of the luminance summed over the pixels. A pixel is \"ground in \
         the sun's shadow\" when the ray through its centre meets the ground first and the \
         shadow ray from there to the sun is blocked.\n"
    );

    // What the lab's constants stand in for.
    let e_sky = scene.sky.irradiance_facing_up();
    let sky_radiance = e_sky / std::f32::consts::PI;
    let ambient = 0.04;
    let ratio = sky_radiance / ambient;
    let _ = writeln!(
        text,
        "**The sky against the ambient constant.** The sky's irradiance on open ground is \
         π (0.2 · horizon + 0.8 · zenith) = {}; as light leaving a matte ground that is \
         albedo/π · E_sky = albedo · {}, against the lab's ambient albedo · {ambient}: the sky \
         gives open ground {:.1}, {:.1} and {:.1} times (red, green, blue) as much light as \
         the constant that stands in for it.",
        triple(e_sky),
        triple(sky_radiance),
        ratio.x,
        ratio.y,
        ratio.z
    );
    let received =
        |image: &LinearImage, mask: &[bool]| mean_over_albedo(image, &masks.albedo, mask);
    let sky_term = &path.terms()[2];
    if let Some(sky_lit) = received(sky_term, &masks.lit) {
        let _ = writeln!(
            text,
            "\nMeasured in the image: the sky-direct term over the sunlit ground, divided by \
             the albedo, is {} on average, {:.0} % of the open-sky value {} (the spheres hide \
             part of the sky; light bounced off them is in the indirect term).",
            triple(sky_lit),
            100.0 * luminance(sky_lit) / luminance(sky_radiance),
            triple(sky_radiance)
        );
    }
    let to_sun = scene.sun.direction;
    let lab = lab_shadow_ratio(scene.sun.brightness, to_sun.y);
    if let (Some(in_shadow), Some(in_sun)) = (
        received(&path.image, &masks.shadowed),
        received(&path.image, &masks.lit),
    ) {
        let ratio = in_shadow / in_sun;
        let _ = writeln!(
            text,
            "\n**The light in a shadow against the shadow factor.** Per unit albedo, the \
             ground in the sun's shadow sends {} on average and the ground in the sun {}: the \
             shadow gets {:.2}, {:.2} and {:.2} (red, green, blue; {:.2} in luminance) of \
             the light of the lit ground. The lab's shading, 0.01 of the sun plus the ambient \
             0.04 against 0.1 of the sun plus the ambient, gives (0.01 · 25 · cos/π + 0.04) / \
             (0.1 · 25 · cos/π + 0.04) = {lab:.3} in every channel (cos = L.y = {:.3}): its \
             shadows are {:.1} times too dark in luminance, and not blue.",
            triple(in_shadow),
            triple(in_sun),
            ratio.x,
            ratio.y,
            ratio.z,
            luminance(in_shadow) / luminance(in_sun),
            to_sun.y,
            (luminance(in_shadow) / luminance(in_sun)) / lab
        );
    }
    save_all(dir, &[("terms.png", &figure)], &[("shares.md", &text)])
}
