//! Why the depth sweep settles: the weight a ray carries falls
//! geometrically with its depth, the mirror's reflection (0.6) at every
//! bounce, or inside the glass its transmission (0.7) once and then its
//! reflection (0.1) at every bounce within, both read from the lab scene.
//! Once a ray's weight is below 1/255 it cannot move an 8-bit pixel by a
//! level (for light no brighter than white).

use image::RgbImage;
use raylab::Scene;
use raylab_plot::colour::{TEXT_MUTED, series_colour};
use raylab_plot::{Corner, LinePlot, Series};

/// The deepest depth drawn.
pub const DEEPEST: u32 = 13;
/// The smallest weight drawn: the log axis's floor.
const FLOOR: f64 = 1e-9;

/// `(reflection, transmission)` of a lab sphere.
pub fn shares(name: &str) -> (f32, f32) {
    let scene = Scene::lab();
    let index = scene.sphere_named(name).expect("a lab sphere");
    let m = scene.spheres()[index].material;
    (m.reflection(), m.transmission())
}

/// The weight of the ray at `depth` (1 = the ray from the eye) on a path
/// that bounces off the mirror at every depth.
pub fn mirror_weight(depth: u32) -> f64 {
    let (r, _) = shares("mirror");
    f64::from(r).powi(depth as i32 - 1)
}

/// The weight of the ray at `depth` on a path that enters the glass at
/// depth 1 and then reflects inside it at every depth.
pub fn glass_weight(depth: u32) -> f64 {
    let (r, t) = shares("glass");
    match depth {
        0 | 1 => 1.0,
        d => f64::from(t) * f64::from(r).powi(d as i32 - 2),
    }
}

/// The first depth at which `weight` is below one 8-bit level.
pub fn first_below_a_level(weight: fn(u32) -> f64) -> u32 {
    (1..).find(|&d| weight(d) < 1.0 / 255.0).unwrap_or(u32::MAX)
}

pub fn figure() -> RgbImage {
    let depths = 1..=DEEPEST;
    let (mirror_r, _) = shares("mirror");
    let (glass_r, glass_t) = shares("glass");
    let level = 1.0 / 255.0;
    let mirror_at = first_below_a_level(mirror_weight);
    let glass_at = first_below_a_level(glass_weight);
    LinePlot::new("The weight of the deepest ray against its depth")
        .x_label("depth of the ray (1 = the ray from the eye)")
        .y_label("weight: its share of the pixel")
        .integer_x_ticks()
        .x_range(1.0, f64::from(DEEPEST))
        .log_y(FLOOR)
        .y_range(FLOOR, 1.0)
        .series(Series::new(
            format!("mirror path: {mirror_r}^(depth − 1)"),
            series_colour(0),
            depths.clone().map(|d| (f64::from(d), mirror_weight(d))),
        ))
        .series(Series::new(
            format!("inside the glass: {glass_t} · {glass_r}^(depth − 2)"),
            series_colour(2),
            depths
                .map(|d| (f64::from(d), glass_weight(d)))
                .filter(|&(_, w)| w >= FLOOR),
        ))
        .series(
            Series::new(
                "1/255: below it, an 8-bit pixel no longer changes",
                series_colour(3),
                [(1.0, level), (f64::from(DEEPEST), level)],
            )
            .without_markers(),
        )
        .vertical_marker(
            f64::from(glass_at),
            format!("glass below 1/255 at depth {glass_at}"),
            series_colour(2),
        )
        .vertical_marker(
            f64::from(mirror_at),
            format!("mirror at depth {mirror_at}"),
            series_colour(0),
        )
        .vertical_marker(10.0, "the chapters' max depth, 10", TEXT_MUTED)
        .legend(Corner::BottomLeft)
        .render(900, 520)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_weights_fall_below_one_level_at_depths_12_and_5() {
        // 0.6^10 = 0.00605 > 1/255 = 0.00392 > 0.6^11 = 0.00363: depth 12.
        assert_eq!(first_below_a_level(mirror_weight), 12);
        // 0.7 · 0.1² = 0.007 > 1/255 > 0.7 · 0.1³ = 0.0007: depth 5.
        assert_eq!(first_below_a_level(glass_weight), 5);
        assert!((mirror_weight(3) - 0.36).abs() < 1e-6);
        assert!((glass_weight(3) - 0.07).abs() < 1e-6);
    }
}
