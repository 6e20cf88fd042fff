//! Heat maps of a render: the deepest ray per pixel, and rays per pixel.

use image::RgbImage;

use raylab::{PixelMaps, Rendered};
use raylab_plot::{Colormap, ColourScale, HeatmapFigure};

/// A short description of the settings, for captions.
pub fn settings_caption(binary: &str, rendered: &Rendered) -> String {
    format!("{binary}, {}.", rendered.settings)
}

/// For each pixel, the depth of the deepest ray its tree reached, from a
/// render that kept its maps.
pub fn depth_figure(binary: &str, rendered: &Rendered, maps: &PixelMaps) -> RgbImage {
    let max_depth = rendered.settings.max_depth;
    let values: Vec<f32> = maps.deepest.iter().map(|&d| f32::from(d)).collect();
    let deepest = maps.deepest.iter().copied().max().unwrap_or(1);
    let mut caption = settings_caption(binary, rendered);
    if deepest <= 1 {
        caption.push_str(
            " Every pixel is 1: no ray in this chapter makes another, so each \
             pixel's tree is its primary ray alone (shadow rays do not count as depth).",
        );
    } else {
        caption.push_str(&format!(
            " The deepest tree reached depth {deepest}: mirrors and glass send rays on, \
             everything else stops at depth 1."
        ));
    }
    HeatmapFigure {
        title: "Deepest ray per pixel",
        caption: &caption,
        values: &values,
        width: rendered.settings.width as usize,
        height: rendered.settings.height as usize,
        // One colour per depth, one legend entry each: on a smooth bar
        // depths 1, 2 and 3 would be three near-identical shades. Past ten
        // depths the distinct colours run out, and viridis steps take over.
        colour_scale: ColourScale::steps(1, max_depth.max(2)),
        colour_bar_label: "depth of the deepest ray",
        colormap: if max_depth <= 10 {
            Colormap::Distinct
        } else {
            Colormap::Viridis
        },
        pixel_scale: Some(1),
    }
    .render()
}

/// For each pixel, every ray traced for it, shadow rays included.
pub fn rays_figure(binary: &str, rendered: &Rendered, maps: &PixelMaps) -> RgbImage {
    let values: Vec<f32> = maps.rays.iter().map(|&n| n as f32).collect();
    let most = maps.rays.iter().copied().max().unwrap_or(1).max(1);
    let least = maps.rays.iter().copied().min().unwrap_or(1).max(1);
    let mut caption = settings_caption(binary, rendered);
    if most == least {
        caption.push_str(&format!(
            " Every pixel took {most} ray{}: the same work everywhere.",
            if most == 1 { "" } else { "s" }
        ));
    } else {
        let total = rendered.counts.total();
        caption.push_str(&format!(
            " From {least} to {most} rays a pixel, {} in all, {:.2} on average.",
            raylab::frame::thousands(total),
            total as f64 / maps.rays.len().max(1) as f64
        ));
    }
    HeatmapFigure {
        title: "Rays traced per pixel (log scale)",
        caption: &caption,
        values: &values,
        width: rendered.settings.width as usize,
        height: rendered.settings.height as usize,
        colour_scale: ColourScale::log(1.0, (most as f32).max(10.0)),
        colour_bar_label: "rays, shadow rays included",
        colormap: Colormap::Magma,
        pixel_scale: Some(1),
    }
    .render()
}
