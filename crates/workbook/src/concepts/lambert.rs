//! Lambert's cosine law as a footprint: a beam of width w that meets a
//! surface at θ from its normal spreads over w / cos θ, so each unit of
//! surface gets cos θ of the light. The middle panel is the lab's own sun
//! on the ground, its angle read from `Scene::lab().sun.direction`.

use image::RgbImage;
use raylab::Scene;
use raylab_plot::colour::{AXIS, TEXT};
use raylab_plot::{Anchor, Rgb};

use super::{LABEL, P, Sheet, along};

/// The angle between the lab's sun and the ground's normal (y), in
/// degrees: 90° less the sun's elevation.
pub fn lab_sun_angle() -> f32 {
    Scene::lab().sun.direction.y.acos().to_degrees()
}

const BEAM: Rgb = [230, 159, 0];
const FOOT: Rgb = [0, 114, 178];
const N: Rgb = [0, 158, 115];

pub fn figure() -> RgbImage {
    let lab = lab_sun_angle();
    let angles = [
        (0.0, "sun overhead"),
        (lab, "the lab's sun on the ground"),
        (70.0, "a low sun"),
    ];
    let mut sheet = Sheet::new(
        1200.0,
        560.0,
        "Lambert's law: a beam of width w covers w / cos θ, so each unit of surface gets cos θ of it",
    );
    let w = 72.0;
    let ground = 370.0;
    for (n, &(theta, title)) in angles.iter().enumerate() {
        let panel = 200.0 + 400.0 * n as f32;
        sheet.text((panel, 64.0), title, LABEL, TEXT, Anchor::TOP_CENTRE);
        sheet.fill_rect((panel - 185.0, ground), (370.0, 58.0), [238, 238, 238]);
        sheet.line((panel - 185.0, ground), (panel + 185.0, ground), AXIS, 2.0);
        let (s, c) = theta.to_radians().sin_cos();
        // Shorter beams where they slant, and the footprint moved right so
        // that beam and footprint together sit in the middle of the panel.
        let length = 231.0 - 1.2 * theta;
        let cx = panel + s * length / 2.0 - 24.0 * s;
        // Towards the sun, and across the beam.
        let to_sun = (-s, -c);
        let across = (c, -s);
        let foot = w / c;
        // The beam: parallel rays that start on a line across it, w wide,
        // and run on to the ground.
        let a = along((cx - foot / 2.0, ground), to_sun, length);
        for m in 0..5 {
            let start = along(a, across, w * m as f32 / 4.0);
            let f = along(start, (s, c), (ground - start.1) / c);
            sheet.arrow(start, f, BEAM, 1.8);
        }
        // Its width w, measured across it just behind the starts.
        let bar = along(a, to_sun, 12.0);
        let bar_end = along(bar, across, w);
        sheet.line(bar, bar_end, TEXT, 1.5);
        sheet.label(
            along(along(bar, across, w / 2.0), to_sun, 20.0),
            "w",
            LABEL,
            TEXT,
            Anchor::MIDDLE_CENTRE,
        );
        // Its footprint on the ground.
        let (l, r): (P, P) = (
            (cx - foot / 2.0, ground + 14.0),
            (cx + foot / 2.0, ground + 14.0),
        );
        sheet.line(l, r, FOOT, 3.0);
        sheet.line((l.0, l.1 - 6.0), (l.0, l.1 + 6.0), FOOT, 2.0);
        sheet.line((r.0, r.1 - 6.0), (r.0, r.1 + 6.0), FOOT, 2.0);
        sheet.text(
            (panel, ground + 24.0),
            &format!("w / cos θ = {:.2} w", 1.0 / c),
            LABEL,
            FOOT,
            Anchor::TOP_CENTRE,
        );
        // The normal, and the angle.
        let normal_at = (cx + foot / 2.0 + 16.0, ground);
        sheet.arrow(normal_at, (normal_at.0, ground - 100.0), N, 2.0);
        sheet.text(
            (normal_at.0 + 4.0, ground - 100.0),
            "n",
            LABEL,
            N,
            Anchor::TOP_LEFT,
        );
        sheet.text(
            (panel, ground + 70.0),
            &format!("θ = {theta:.1}°: E = {c:.3} × E head-on"),
            LABEL,
            TEXT,
            Anchor::TOP_CENTRE,
        );
    }
    sheet.legend(
        (40.0, ground + 120.0),
        &[(
            BEAM,
            "the sun's light, a beam of width w (θ from the normal n)",
        )],
    );
    sheet.legend(
        (660.0, ground + 120.0),
        &[(FOOT, "where the same light lands: spread thinner")],
    );
    sheet.note(
        0,
        &format!(
            "The lab sun: L = normalize(−1, 1.2, 0.8), elevation {:.1}°, so the ground gets cos θ = L·n = {:.3} of it.",
            90.0 - lab,
            lab.to_radians().cos()
        ),
    );
    sheet.finish()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_lab_sun_is_46_9_degrees_from_the_ground_normal() {
        // L·y = 1.2 / √(1 + 1.44 + 0.64) = 1.2 / 1.75499 = 0.68376: θ = 46.86°.
        let theta = lab_sun_angle();
        assert!((theta - 46.86).abs() < 0.01, "{theta}");
        assert!((theta.to_radians().cos() - 0.683_76).abs() < 1e-4);
    }
}
