//! Chapter 6's figures, 7: the depth limit, for light that bounces.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use ch06_path_tracing::PathRender;
use image::RgbImage;
use raylab_plot::montage;

use super::{DEPTHS, SPP, magnified_crop, path_render, percent, save_all, size_flags, with};
use crate::measure::luminance;
use crate::{JobError, Size};

pub(super) fn depth_figures(dir: &Path, size: Size, quiet: bool) -> Result<Vec<PathBuf>, JobError> {
    let (w, h) = ((size.width / 5).max(8), (size.height / 5).max(6));
    let mut renders = Vec::new();
    for depth in DEPTHS {
        let flags = with(size_flags(w, h, SPP), &[&format!("--max-depth={depth}")]);
        renders.push(path_render(&flags, quiet)?);
    }
    let images: Vec<RgbImage> = renders.iter().map(|r| r.image.to_srgb8()).collect();
    let scale = (320 / w).max(1);
    let magnify = |image: &RgbImage| magnified_crop(image, (0.0, 0.0), (w, h), scale);
    let big: Vec<RgbImage> = images.iter().map(magnify).collect();
    let labels: Vec<String> = DEPTHS.iter().map(|d| format!("max depth {d}")).collect();
    let refs: Vec<(&str, &RgbImage)> = labels.iter().map(String::as_str).zip(&big).collect();
    let sweep = montage(
        &format!(
            "Chapter 6 at max depth 1, 2, 3, 5 and 10: {w}×{h}, {SPP} paths per pixel, the same seed"
        ),
        &refs,
        5,
    );
    let mut diffs = Vec::new();
    let mut text = String::from(
        "| depth | pixels changed (8-bit, by more than 1 level) | largest change (levels) | light \
         added (share of depth 10's) |\n|---|---:|---:|---:|\n",
    );
    let total = |r: &PathRender| -> f64 {
        r.image
            .pixels()
            .iter()
            .map(|&c| f64::from(luminance(c)))
            .sum()
    };
    let last = total(&renders[renders.len() - 1]);
    for k in 1..DEPTHS.len() {
        let (a, b) = (&images[k - 1], &images[k]);
        let changed = raylab_plot::changed_pixels(a, b, 1);
        let largest = raylab_plot::max_change(a, b);
        let added = (total(&renders[k]) - total(&renders[k - 1])) / last;
        let _ = writeln!(
            text,
            "| {} → {} | {changed} of {} | {largest} | {} |",
            DEPTHS[k - 1],
            DEPTHS[k],
            w * h,
            percent(added)
        );
        diffs.push((
            format!("{} → {}: {changed} pixels", DEPTHS[k - 1], DEPTHS[k]),
            magnify(&raylab_plot::magnified_difference(a, b, 8.0)),
        ));
    }
    let _ = writeln!(
        text,
        "\nEvery render uses seed 0, so a path follows the same random choices at every \
         depth limit and the images differ only by the light of the longer paths, not by \
         noise. Depth 1 ({:.1} % of depth 10's light) already has the sun and the sky seen \
         from the first surface.",
        100.0 * total(&renders[0]) / last
    );
    let refs: Vec<(&str, &RgbImage)> = diffs.iter().map(|(l, i)| (l.as_str(), i)).collect();
    let changes = raylab_plot::with_change_scale(
        &montage(
            "What each deeper limit adds (each change magnified 8 times; black: unchanged)",
            &refs,
            4,
        ),
        8.0,
    );
    save_all(
        dir,
        &[("depth.png", &sweep), ("changes.png", &changes)],
        &[("depth.md", &text)],
    )
}
