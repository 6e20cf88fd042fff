//! Why the depth sweep settles, and why it settles later in dark pixels.
//!
//! Raising the max depth from d − 1 to d adds the light of the rays at
//! depth d, each scaled by its weight. What carries light out of the glass
//! are the rays that leave it: in through its transmission (0.7), k
//! reflections inside (0.1 each), out through its transmission again, so
//! `0.7 · 0.1ᵏ · 0.7` at depth k + 3; and the same seen in the mirror,
//! `0.6 · 0.7 · 0.1ᵏ · 0.7` at depth k + 4. All shares are read from the
//! lab scene. A ray stops mattering once its weight times its light is
//! below half an 8-bit level, which in linear light is smallest near black,
//! where sRGB is steepest: `0.5 / (255 · 12.92) ≈ 1.5 · 10⁻⁴`.

use std::path::Path;

use image::RgbImage;
use raylab::Scene;
use raylab_cli::diagrams::sweep::{changes_from_csv, settles_at};
use raylab_plot::colour::{TEXT_MUTED, series_colour};
use raylab_plot::{Corner, LinePlot, Series};

use crate::JobError;

/// The deepest depth drawn: the chapters' max depth.
pub const DEEPEST: u32 = 10;
/// The smallest weight drawn: the log axis's floor.
const FLOOR: f64 = 1e-9;
/// The chapters whose depth sweeps the figure marks, as the main job
/// names their folders.
pub const SWEPT: [&str; 3] = ["ch03-reflection", "ch04-refraction", "ch05-antialiasing"];

/// `(reflection, transmission)` of a lab sphere.
pub fn shares(name: &str) -> (f32, f32) {
    let scene = Scene::lab();
    let index = scene.sphere_named(name).expect("a lab sphere");
    let m = scene.spheres()[index].material;
    (m.reflection(), m.transmission())
}

/// The weight of the ray at `depth` (1 = the ray from the eye) that leaves
/// the glass after `depth − 3` reflections inside it; `None` above depth 3,
/// where no ray has left it yet.
pub fn leaving_glass(depth: u32) -> Option<f64> {
    let (r, t) = shares("glass");
    let k = depth.checked_sub(3)?;
    Some(f64::from(t) * f64::from(r).powi(k as i32) * f64::from(t))
}

/// The same, for the glass seen in the mirror: one depth later, and
/// scaled by the mirror's reflection.
pub fn leaving_glass_in_mirror(depth: u32) -> Option<f64> {
    let (mirror, _) = shares("mirror");
    Some(f64::from(mirror) * leaving_glass(depth.checked_sub(1)?)?)
}

/// sRGB's decoding, from an encoded value in [0, 1] to linear light.
fn decode(v: f64) -> f64 {
    if v <= 0.04045 {
        v / 12.92
    } else {
        ((v + 0.055) / 1.055).powf(2.4)
    }
}

/// Half an 8-bit level at `level`, in linear light: how much light it
/// takes to round a pixel of that level to the next one.
pub fn half_a_level(level: u8) -> f64 {
    let v = f64::from(level) / 255.0;
    decode(v + 0.5 / 255.0) - decode(v)
}

/// The first depth whose ray weighs less than `threshold`.
pub fn first_below(weight: fn(u32) -> Option<f64>, threshold: f64) -> Option<u32> {
    (1..=DEEPEST).find(|&d| weight(d).is_some_and(|w| w < threshold))
}

/// Where each swept chapter settled, read from the `changes.csv` its
/// depth sweep wrote under `figures`.
pub fn measured(figures: &Path) -> Result<Vec<(&'static str, u32)>, JobError> {
    SWEPT
        .iter()
        .map(|&binary| {
            let path = figures.join(binary).join("depth-sweep/changes.csv");
            let text = std::fs::read_to_string(&path)
                .map_err(|e| JobError::Measured(format!("{}: {e}", path.display())))?;
            let changes = changes_from_csv(&text)
                .map_err(|e| JobError::Measured(format!("{}: {e}", path.display())))?;
            Ok((binary, settles_at(&changes)))
        })
        .collect()
}

/// The figure, with a dashed line at each depth a sweep settled at.
pub fn figure(settled: &[(&str, u32)]) -> RgbImage {
    let (mirror_r, _) = shares("mirror");
    let (glass_r, glass_t) = shares("glass");
    let black = half_a_level(0);
    let grey = half_a_level(128);
    let points = |weight: fn(u32) -> Option<f64>| {
        (1..=DEEPEST)
            .filter_map(move |d| weight(d).map(|w| (f64::from(d), w)))
            .filter(|&(_, w)| w >= FLOOR)
    };
    let line = |label: String, colour, y: f64| {
        Series::new(label, colour, [(1.0, y), (f64::from(DEEPEST), y)]).without_markers()
    };
    let mut plot = LinePlot::new("Why it settles later in dark pixels")
        .x_label("depth of the ray (1 = the ray from the eye)")
        .y_label("weight: its share of the pixel")
        .integer_x_ticks()
        .x_range(1.0, f64::from(DEEPEST))
        .log_y(FLOOR)
        .y_range(FLOOR, 1.0)
        .series(Series::new(
            format!("leaving the glass: {glass_t} · {glass_r}^k · {glass_t}, k = depth − 3"),
            series_colour(2),
            points(leaving_glass),
        ))
        .series(Series::new(
            format!(
                "the same, seen in the mirror: {mirror_r} · {glass_t} · {glass_r}^k · {glass_t}"
            ),
            series_colour(0),
            points(leaving_glass_in_mirror),
        ))
        .series(line(
            format!("half a level near black: 0.5/(255 · 12.92) = {black:.1e}"),
            series_colour(3),
            black,
        ))
        .series(line(
            format!("half a level at mid-grey (level 128): {grey:.1e}"),
            series_colour(1),
            grey,
        ))
        .legend(Corner::BottomLeft);
    // One line per depth, naming every chapter that settled there.
    let mut depths: Vec<u32> = settled.iter().map(|&(_, d)| d).collect();
    depths.sort_unstable();
    depths.dedup();
    for depth in depths {
        let names: Vec<&str> = settled
            .iter()
            .filter(|&&(_, d)| d == depth)
            .map(|&(name, _)| name.split('-').next().unwrap_or(name))
            .collect();
        plot = plot.vertical_marker(
            f64::from(depth),
            format!(
                "measured: {} {} at {depth}",
                names.join(", "),
                if names.len() == 1 {
                    "settles"
                } else {
                    "settle"
                }
            ),
            TEXT_MUTED,
        );
    }
    // The size of the other line plots: at a page's width its type stays legible.
    plot.render(900, 540)
}

/// The figure's line for the book, naming the measured depths.
pub fn caption(settled: &[(&str, u32)]) -> String {
    let black = half_a_level(0);
    let at = |name: &str| {
        settled
            .iter()
            .find(|&&(n, _)| n == name)
            .map_or("?".to_owned(), |&(_, d)| d.to_string())
    };
    let glass_at = first_below(leaving_glass, black).map_or("—".into(), |d| d.to_string());
    let mirror_at =
        first_below(leaving_glass_in_mirror, black).map_or("—".into(), |d| d.to_string());
    format!(
        "![The weight of the rays that leave the glass against their depth, on a log axis, \
         with half an 8-bit level near black and at mid-grey: the glass's rays fall below \
         {black:.1e} at depth {glass_at}, the glass's in the mirror at {mirror_at}; the sweeps \
         settled at {} (chapter 4) and {} (chapter 5)](figures/concepts/weights.png)\n",
        at("ch04-refraction"),
        at("ch05-antialiasing")
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_rays_that_leave_the_glass_weigh_0_49_then_a_tenth_less_per_depth() {
        assert_eq!(leaving_glass(2), None);
        assert!((leaving_glass(3).unwrap() - 0.49).abs() < 1e-6);
        assert!((leaving_glass(6).unwrap() - 4.9e-4).abs() < 1e-9);
        // Seen in the mirror: 0.6 · 0.7 · 0.1² · 0.7 = 0.00294 at depth 6.
        assert_eq!(leaving_glass_in_mirror(3), None);
        assert!((leaving_glass_in_mirror(6).unwrap() - 0.00294).abs() < 1e-8);
    }

    #[test]
    fn half_a_level_is_1_5e_minus_4_near_black_and_ten_times_more_at_mid_grey() {
        // 0.5 / (255 · 12.92) = 1.5177e-4.
        assert!((half_a_level(0) - 1.5177e-4).abs() < 1e-8);
        // At level 128 sRGB's slope is 1.08 per unit of light: 0.5/(255 · 1.08).
        let grey = half_a_level(128);
        assert!((grey - 1.82e-3).abs() < 2e-5, "{grey}");
    }

    #[test]
    fn near_black_the_glass_stops_mattering_after_depth_6_and_in_the_mirror_after_7() {
        // 0.7 · 0.1³ · 0.7 = 4.9e-4 > 1.5e-4 > 4.9e-5 at depth 7.
        assert_eq!(first_below(leaving_glass, half_a_level(0)), Some(7));
        assert_eq!(
            first_below(leaving_glass_in_mirror, half_a_level(0)),
            Some(8)
        );
        // At mid-grey a depth earlier each.
        assert_eq!(first_below(leaving_glass, half_a_level(128)), Some(6));
    }

    #[test]
    fn the_caption_names_the_depths_the_sweeps_measured() {
        let settled = [
            ("ch03-reflection", 5),
            ("ch04-refraction", 6),
            ("ch05-antialiasing", 7),
        ];
        let text = caption(&settled);
        assert!(
            text.contains("settled at 6 (chapter 4) and 7 (chapter 5)"),
            "{text}"
        );
        assert!(text.contains("below 1.5e-4 at depth 7"), "{text}");
    }
}
