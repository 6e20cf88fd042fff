//! The shadow feeler's offset, magnified. Chapter 2 starts the feeler at
//! p + ε·L (along the ray it casts, as `sun_factor` does), not p + ε·n, so
//! it starts only ε·cos θ above the surface: plenty where the sun is high,
//! little near the terminator, where cos θ → 0 and the rounding error of
//! the computed p (measured here on the lab's glass sphere) can exceed it.

use image::RgbImage;
use raylab::{Camera, RayKind, Scene};
use raylab_cli::diagrams::kind_colour;
use raylab_plot::colour::{AXIS, TEXT, TEXT_MUTED};
use raylab_plot::{Anchor, Rgb};

use super::{LABEL, P, SMALL, Sheet, along};

/// The offset every chapter uses by default (`--epsilon`).
pub const EPSILON: f32 = 1e-4;

/// The largest distance from the surface of the lab's glass sphere of a
/// hit point the camera's rays compute (160 × 120 pixel centres): how far
/// rounding puts a computed p off its surface.
pub fn rounding_error() -> f32 {
    let (scene, camera) = (Scene::lab(), Camera::lab());
    let glass = scene
        .sphere_named("glass")
        .expect("the lab has a glass sphere");
    let sphere = scene.spheres()[glass].shape;
    let (w, h) = (160, 120);
    let mut worst = 0.0f32;
    for j in 0..h {
        for i in 0..w {
            let ray = camera.ray(i, j, (0.5, 0.5), w, h);
            if let Some(t) = sphere.intersect(&ray) {
                let off = ((ray.at(t) - sphere.centre).length() - sphere.radius).abs();
                worst = worst.max(off);
            }
        }
    }
    worst
}

/// The angle from the normal past which the feeler starts closer to the
/// surface than `error`: where ε·cos θ = error.
pub fn danger_angle(epsilon: f32, error: f32) -> f32 {
    (error / epsilon).clamp(0.0, 1.0).acos().to_degrees()
}

const N: Rgb = [0, 158, 115];
const HEIGHT: Rgb = [213, 94, 0];

pub fn figure() -> RgbImage {
    let shadow = kind_colour(RayKind::Shadow);
    let error = rounding_error();
    let danger = danger_angle(EPSILON, error);
    let mut sheet = Sheet::new(
        1200.0,
        660.0,
        "The shadow feeler starts at p + ε·L: only ε·cos θ above the surface",
    );
    let eps = 156.0; // ε, in pixels
    let surface = 430.0;
    for (n, theta) in [30.0f32, 80.0].into_iter().enumerate() {
        let p: P = (230.0 + 600.0 * n as f32, surface);
        let title = if n == 0 {
            "sun high: θ = 30°"
        } else {
            "near the terminator: θ = 80°"
        };
        sheet.text((p.0 + 80.0, 64.0), title, LABEL, TEXT, Anchor::TOP_CENTRE);
        sheet.fill_rect((p.0 - 170.0, surface), (500.0, 80.0), [238, 238, 238]);
        sheet.line((p.0 - 170.0, surface), (p.0 + 330.0, surface), AXIS, 2.5);
        sheet.text(
            (p.0 - 160.0, surface + 44.0),
            "inside the object",
            SMALL,
            TEXT_MUTED,
            Anchor::TOP_LEFT,
        );
        let (s, c) = theta.to_radians().sin_cos();
        let l = (s, -c);
        // The normal, and where an offset along it would start.
        sheet.arrow(p, (p.0, surface - eps * 1.5), N, 2.0);
        sheet.text(
            (p.0 - 6.0, surface - eps * 1.5),
            "n",
            LABEL,
            N,
            Anchor::MIDDLE_RIGHT,
        );
        let along_n = (p.0, surface - eps);
        sheet.circle(along_n, 5.0, None, Some(TEXT_MUTED));
        sheet.text(
            (p.0 - 10.0, surface - eps),
            "p + ε·n",
            SMALL,
            TEXT_MUTED,
            Anchor::MIDDLE_RIGHT,
        );
        // The feeler: from p + ε·L on towards the sun.
        let start = along(p, l, eps);
        sheet.dashed(p, start, shadow, 2.0);
        sheet.arrow(start, along(p, l, eps * 2.1), shadow, 2.5);
        sheet.label(
            along(along(p, l, eps * 2.1), (0.0, -12.0), 1.0),
            "L, towards the sun",
            SMALL,
            shadow,
            Anchor::new(raylab_plot::HAlign::Right, raylab_plot::VAlign::Bottom),
        );
        sheet.circle(start, 5.0, Some(shadow), None);
        // Beside a steep feeler, under it; above a shallow one.
        let (at, anchor) = if c > 0.5 {
            ((start.0 + 14.0, start.1 + 4.0), Anchor::MIDDLE_LEFT)
        } else {
            ((start.0 - 8.0, start.1 - 8.0), Anchor::BOTTOM_CENTRE)
        };
        sheet.label(at, "p + ε·L", LABEL, TEXT, anchor);
        // Its height above the surface.
        sheet.line(start, (start.0, surface), HEIGHT, 2.0);
        // A short bar leaves no room beside it: the label goes under the surface.
        let (at, anchor) = if surface - start.1 > 40.0 {
            (
                (start.0 + 8.0, (start.1 + surface) / 2.0 + 2.0),
                Anchor::MIDDLE_LEFT,
            )
        } else {
            ((start.0 + 8.0, surface + 10.0), Anchor::TOP_LEFT)
        };
        if anchor == Anchor::TOP_LEFT {
            sheet.line((start.0, surface), (start.0, surface + 16.0), HEIGHT, 1.0);
        }
        sheet.label(at, &format!("ε·cos θ = {c:.2} ε"), LABEL, HEIGHT, anchor);
        sheet.dot(p, TEXT);
        sheet.text((p.0, surface + 8.0), "p", LABEL, TEXT, Anchor::TOP_CENTRE);
        // The angle, on the line halfway between n and L.
        let (half_s, half_c) = (theta / 2.0).to_radians().sin_cos();
        sheet.text(
            along(p, (half_s, -half_c), 100.0),
            &format!("{theta:.0}°"),
            SMALL,
            TEXT_MUTED,
            Anchor::MIDDLE_CENTRE,
        );
    }
    sheet.legend(
        (60.0, surface + 104.0),
        &[
            (shadow, "the feeler ray, as chapter 2's sun_factor casts it"),
            (HEIGHT, "how far its start is above the surface"),
        ],
    );
    sheet.note(
        1,
        &format!(
            "Magnified: ε = {EPSILON} is drawn {eps:.0} pixels long. Rounding puts a computed p up to \
             {error:.1e} off the glass sphere's surface,"
        ),
    );
    sheet.note(
        0,
        &format!(
            "so the feeler can start inside it only where ε·cos θ < {error:.1e}: within {:.2}° of the terminator ({danger:.2}° from n).",
            90.0 - danger
        ),
    );
    sheet.finish()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rounding_is_far_below_epsilon_and_matters_only_at_the_terminator() {
        let error = rounding_error();
        // f32 has 24 bits: near |p| ≈ 2 one step is 2.4e-7; a hit point
        // is some steps off (more at the silhouette, where t is found by a
        // difference of near-equal squares), never near ε.
        assert!(error > 0.0 && error < 1e-5, "{error}");
        let danger = danger_angle(EPSILON, error);
        assert!(danger > 84.0 && danger < 90.0, "{danger}");
        // Hand-checked: error 1e-6 against ε 1e-4 is acos(0.01) = 89.427°.
        assert!((danger_angle(1e-4, 1e-6) - 89.427).abs() < 1e-3);
    }
}
