//! Chapter 6's figures, 1: the Whitted image against the path-traced one,
//! at one exposure that clips neither, their difference and their ratio.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use ch06_path_tracing::PathRender;
use image::RgbImage;
use raylab::frame::thousands;
use raylab::linear_image::LinearImage;
use raylab_plot::{Colormap, ColourScale, HeatmapFigure, montage};

use super::{SPP, ratio_row, save_all};
use crate::JobError;
use crate::measure::{GroundMasks, log2_ratio, mean_luminance, signed_difference, symmetric_range};

/// The exposure of the comparison figures: the largest power of two in
/// thirds of a stop, at most 1, at which no channel of any of `images`
/// exceeds 1, so that nothing clips when it is encoded.
pub fn exposure_without_clipping(images: &[&LinearImage]) -> f32 {
    let brightest = images
        .iter()
        .flat_map(|image| image.pixels())
        .map(|p| p.max_element())
        .fold(0.0, f32::max);
    (0..=60)
        .map(|third: i32| 2f32.powf(-third as f32 / 3.0))
        .find(|&exposure| brightest * exposure <= 1.0)
        .unwrap_or(2f32.powi(-20))
}

/// `image` with every channel scaled by `exposure`.
pub fn exposed(image: &LinearImage, exposure: f32) -> LinearImage {
    let pixels = image.pixels().iter().map(|&p| p * exposure).collect();
    LinearImage::from_pixels(image.width(), image.height(), pixels)
}

/// The channels of `image` above 1, which the encoding clips to white.
pub fn clipped_channels(image: &LinearImage) -> usize {
    image
        .pixels()
        .iter()
        .map(|p| p.to_array().iter().filter(|&&c| c > 1.0).count())
        .sum()
}

/// An exposure as the book states it: the factor and its stops.
pub fn exposure_name(exposure: f32) -> String {
    let thirds = (-3.0 * exposure.log2()).round() as i32;
    let stops = match (thirds / 3, thirds % 3) {
        (0, 0) => "no change".to_owned(),
        (0, t) => format!("−{t}/3 stop"),
        (s, 0) => format!("−{s} stop{}", if s == 1 { "" } else { "s" }),
        (s, t) => format!("−{s} {t}/3 stops"),
    };
    format!("exposure ×{exposure:.2} ({stops})")
}

/// Where `image` clips: the pixels with a channel above 1 in red, the rest
/// faded to grey.
fn clip_mask(image: &LinearImage) -> RgbImage {
    let srgb = image.to_srgb8();
    RgbImage::from_fn(image.width(), image.height(), |x, y| {
        if image.pixel(x, y).max_element() > 1.0 {
            image::Rgb([220, 20, 60])
        } else {
            let p = srgb.get_pixel(x, y).0;
            let grey = (u16::from(p[0]) + u16::from(p[1]) + u16::from(p[2])) / 3;
            image::Rgb([(160 + grey / 3) as u8; 3])
        }
    })
}

pub(super) fn comparison(
    dir: &Path,
    whitted: &LinearImage,
    path: &PathRender,
    masks: &GroundMasks,
) -> Result<Vec<PathBuf>, JobError> {
    let (w, h) = (whitted.width(), whitted.height());
    // One exposure for both, so that they compare, and low enough that
    // nothing clips: at 1 the lit ground of the path-traced image is
    // brighter than white.
    let exposure = exposure_without_clipping(&[whitted, &path.image]);
    let (whitted_exposed, path_exposed) =
        (exposed(whitted, exposure), exposed(&path.image, exposure));
    let clipped_before = clipped_channels(&path.image) + clipped_channels(whitted);
    let clipped_after = clipped_channels(&path_exposed) + clipped_channels(&whitted_exposed);
    let stated = exposure_name(exposure);
    let side_by_side = montage(
        &format!("The lab scene, {w}×{h}: chapter 5 and chapter 6, both at {stated}"),
        &[
            (
                "chapter 5: Whitted, the lab's 5 rays per pixel",
                &whitted_exposed.to_srgb8(),
            ),
            (
                &format!("chapter 6: path traced, {SPP} paths per pixel, caustics"),
                &path_exposed.to_srgb8(),
            ),
        ],
        2,
    );
    let clip_figure = montage(
        "Where the encoding clips a channel to white (red)",
        &[
            (
                "chapter 6 at exposure ×1, as its render.png",
                &clip_mask(&path.image),
            ),
            (&format!("chapter 6 at {stated}"), &clip_mask(&path_exposed)),
        ],
        2,
    );
    let clipped_pixels = path
        .image
        .pixels()
        .iter()
        .filter(|p| p.max_element() > 1.0)
        .count();
    let exposure_text = format!(
        "![Chapter 5's Whitted image and chapter 6's path-traced image, {w} × {h}, both at \
         {stated}](figures/ch06-path-tracing/compare/whitted-and-path-traced.png)\n\n\
         *Both images at one {stated}, the largest in thirds of a stop at which no channel of \
         either is above 1: at ×1, {} channels ({} pixels of \
         chapter 6's, mostly the lit ground's light squares) would clip to white, and at \
         this exposure {clipped_after} do. The light of the two compares directly; only \
         the brightness of the page is lower.*\n",
        thousands(clipped_before as u64),
        thousands(clipped_pixels as u64),
    );
    let render_text = format!(
        "![Chapter 6: the lab scene, path traced, {w} × {h}, {SPP} paths per pixel, with \
         caustics, at {stated}](figures/ch06-path-tracing/compare/path-traced-exposed.png)\n\n\
         *Shown at {stated}, the exposure of every comparison with chapter 5 on these pages: \
         the program's own `render.png` is at ×1, where {} of its pixels, most \
         of the lit ground's light squares, are brighter than white in some channel and \
         clip.*\n",
        thousands(clipped_pixels as u64),
    );
    let difference = signed_difference(whitted, &path.image);
    let range = symmetric_range(&difference, 0.99);
    let caption = format!(
        "Each pixel: chapter 6's luminance minus chapter 5's, in linear radiance \
         (Y = 0.2126 R + 0.7152 G + 0.0722 B), from −{range} (blue) to +{range} (red), \
         clamped beyond; grey: the same."
    );
    let figure = HeatmapFigure {
        title: "Path tracing minus Whitted: red brighter, blue darker",
        caption: &caption,
        values: &difference,
        width: w as usize,
        height: h as usize,
        colour_scale: ColourScale::linear(-range, range),
        colour_bar_label: "luminance difference",
        colormap: Colormap::Diverging,
        pixel_scale: Some(1),
    }
    .render();

    // The same comparison as a ratio, where the text speaks of ratios.
    let ratio = log2_ratio(whitted, &path.image);
    let ratio_figure = HeatmapFigure {
        title: "Path tracing over Whitted: how many times brighter",
        caption: "Each pixel: log2 of chapter 6's luminance over chapter 5's, from −3 (an eighth \
                  of the light, blue) to +3 (eight times, red), clamped beyond; grey: the same. \
                  A ratio, so a dark pixel that doubles is as red as a bright one that doubles.",
        values: &ratio,
        width: w as usize,
        height: h as usize,
        colour_scale: ColourScale::linear(-3.0, 3.0),
        colour_bar_label: "log2 (chapter 6 ÷ chapter 5)",
        colormap: Colormap::Diverging,
        pixel_scale: Some(1),
    }
    .render();

    let brighter = difference.iter().filter(|&&d| d > 0.01).count();
    let darker = difference.iter().filter(|&&d| d < -0.01).count();
    let mut text = String::from(
        "| pixels | count | chapter 5 (Whitted) | chapter 6 (path traced) | ratio |\n\
         |---|---:|---:|---:|---:|\n",
    );
    for (name, mask) in [
        ("the whole image", None),
        ("ground in the sun", Some(masks.lit.as_slice())),
        (
            "ground in the sun's shadow",
            Some(masks.shadowed.as_slice()),
        ),
    ] {
        let ((a, count), (b, _)) = (
            mean_luminance(whitted, mask),
            mean_luminance(&path.image, mask),
        );
        ratio_row(&mut text, name, count, a, b);
    }
    let _ = writeln!(
        text,
        "\nMean luminance (linear) over each set of pixels. Of the {} pixels, {} are brighter \
         by more than 0.01 in chapter 6 and {} darker by more than 0.01.",
        difference.len(),
        brighter,
        darker
    );
    save_all(
        dir,
        &[
            ("whitted-and-path-traced.png", &side_by_side),
            ("whitted.png", &whitted.to_srgb8()),
            ("whitted-exposed.png", &whitted_exposed.to_srgb8()),
            ("path-traced-exposed.png", &path_exposed.to_srgb8()),
            ("clip-mask.png", &clip_figure),
            ("difference.png", &figure),
            ("ratio.png", &ratio_figure),
        ],
        &[
            ("difference.md", &text),
            ("exposure.md", &exposure_text),
            ("render-exposed.md", &render_text),
        ],
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::path_tracing::{path_render, size_flags, whitted_image, with};
    use raylab::Vec3;

    #[test]
    fn the_exposure_is_the_largest_third_of_a_stop_that_keeps_every_channel_at_most_1() {
        let image = |c: f32| LinearImage::from_pixels(1, 1, vec![Vec3::new(0.2, c, 0.1)]);
        assert_eq!(exposure_without_clipping(&[&image(0.9)]), 1.0);
        // 1.06 needs a third of a stop: 2^(−1/3) = 0.794, and 1.06 · 0.794 = 0.84.
        let e = exposure_without_clipping(&[&image(0.5), &image(1.06)]);
        assert!((e - 0.793_700_5).abs() < 1e-6, "{e}");
        assert_eq!(clipped_channels(&image(1.06)), 1);
        assert_eq!(clipped_channels(&exposed(&image(1.06), e)), 0);
        assert_eq!(exposure_name(e), "exposure ×0.79 (−1/3 stop)");
        assert_eq!(exposure_name(0.5), "exposure ×0.50 (−1 stop)");
        assert_eq!(
            exposure_name(2f32.powf(-5.0 / 3.0)),
            "exposure ×0.31 (−1 2/3 stops)"
        );
    }

    #[test]
    fn the_comparison_at_its_exposure_clips_nothing_though_chapter_6_alone_would() {
        let (w, h) = (80, 60);
        let whitted = whitted_image(w, h);
        let path = path_render(&with(size_flags(w, h, 16), &["--caustics"]), true).unwrap();
        assert!(
            clipped_channels(&path.image) > 0,
            "at ×1 the lit ground clips"
        );
        let e = exposure_without_clipping(&[&whitted, &path.image]);
        assert_eq!(clipped_channels(&exposed(&whitted, e)), 0);
        assert_eq!(clipped_channels(&exposed(&path.image, e)), 0);
        assert!(
            e >= 0.5,
            "the exposure is not made dark by a stray bright pixel: {e}"
        );
    }
}
