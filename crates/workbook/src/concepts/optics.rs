//! Reflection and refraction at a surface: `raylab::optics::reflect`'s
//! decomposition d − 2(d·n)n, and `refract`'s fan of rays into and out of
//! the lab's glass (ior read from the scene), with the critical angle
//! found where `refract` starts to return `None`.

use image::RgbImage;
use raylab::optics::{reflect, refract};
use raylab::{RayKind, Scene, Vec3};
use raylab_cli::diagrams::kind_colour;
use raylab_plot::colour::{AXIS, TEXT, TEXT_MUTED, series_colour};
use raylab_plot::{Anchor, Rgb};

use super::{LABEL, LINE, P, SMALL, Sheet, along, degrees};

/// The index of refraction of the lab's glass sphere.
pub fn glass_ior() -> f32 {
    let scene = Scene::lab();
    let glass = scene
        .sphere_named("glass")
        .expect("the lab has a glass sphere");
    scene.spheres()[glass].material.ior()
}

/// A unit direction `degrees` from the normal `y`, travelling in +x and
/// towards the surface from `side` (+1 above it, going down; −1 below it,
/// going up).
fn incoming(degrees: f32, side: f32) -> Vec3 {
    let (s, c) = degrees.to_radians().sin_cos();
    Vec3::new(s, -side * c, 0.0)
}

/// The smallest angle of incidence, from inside a medium of index `ior`
/// into air, at which `refract` returns `None`: found by halving, on the
/// code's own test, not by the formula asin(1/ior).
pub fn critical_angle(ior: f32) -> f32 {
    let leaves = |degrees: f32| refract(incoming(degrees, -1.0), Vec3::NEG_Y, ior).is_some();
    let (mut lo, mut hi) = (0.0f32, 90.0f32);
    for _ in 0..40 {
        let mid = 0.5 * (lo + hi);
        if leaves(mid) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

const D: Rgb = [40, 40, 40];
const N: Rgb = [0, 158, 115];
const R: Rgb = [0, 114, 178];
const PART: Rgb = [213, 94, 0];

pub fn reflection_figure() -> RgbImage {
    let mut sheet = Sheet::new(1000.0, 600.0, "Reflection: r = d − 2(d·n)n");
    let (p, k): (P, f32) = ((440.0, 290.0), 215.0);
    let to = |v: Vec3| -> P { (p.0 + v.x * k, p.1 - v.y * k) };
    let n = Vec3::Y;
    let d = incoming(40.0, 1.0);
    let r = reflect(d, n);
    let dn = d.dot(n);
    // The surface, and the glass-free side under it.
    sheet.fill_rect((80.0, p.1), (840.0, 220.0), [242, 242, 242]);
    sheet.line((80.0, p.1), (920.0, p.1), AXIS, 2.5);
    sheet.text(
        (910.0, p.1 + 10.0),
        "surface",
        SMALL,
        TEXT_MUTED,
        Anchor::TOP_RIGHT,
    );
    // d arrives at p; drawn again from p (dashed) to build r from it.
    sheet.arrow(to(-d), p, D, 2.5);
    sheet.label(
        along(to(-d * 0.55), (-22.0, 0.0), 1.0),
        "d",
        LABEL,
        D,
        Anchor::MIDDLE_RIGHT,
    );
    sheet.dashed(p, to(d), D, 1.5);
    sheet.text(
        along(to(d), (0.0, 12.0), 1.0),
        "d, moved to p",
        SMALL,
        TEXT_MUTED,
        Anchor::TOP_CENTRE,
    );
    // −2(d·n)n: from the tip of d straight up, twice d's normal part.
    sheet.arrow(to(d), to(d - 2.0 * dn * n), PART, 2.5);
    sheet.label(
        along(to(d - 0.5 * dn * n), (10.0, 0.0), 1.0),
        &format!("−2(d·n)n, with d·n = {dn:.3}"),
        LABEL,
        PART,
        Anchor::MIDDLE_LEFT,
    );
    // (d·n)n, the part of d along the normal, under the surface.
    sheet.dashed(to(Vec3::ZERO), to(dn * n), PART, 1.5);
    sheet.text(
        along(to(dn * n), (-8.0, 0.0), 1.0),
        "(d·n)n",
        SMALL,
        PART,
        Anchor::MIDDLE_RIGHT,
    );
    sheet.arrow(p, to(r), R, 3.0);
    // Level with r's tip, beyond the arrow that ends there with it.
    sheet.label(
        (to(d).0 + 16.0, to(r * 0.92).1),
        "r = d − 2(d·n)n",
        LABEL,
        R,
        Anchor::MIDDLE_LEFT,
    );
    sheet.arrow(p, to(n * 0.85), N, 2.5);
    sheet.label(
        along(to(n * 0.85), (0.0, -6.0), 1.0),
        "n",
        LABEL,
        N,
        Anchor::BOTTOM_CENTRE,
    );
    sheet.dot(p, TEXT);
    sheet.text((p.0 - 8.0, p.1 + 8.0), "p", LABEL, TEXT, Anchor::TOP_RIGHT);
    let angle_in = (-d).dot(n).acos();
    let angle_out = r.dot(n).acos();
    sheet.text(
        along(p, (-54.0, -134.0), 1.0),
        &degrees(angle_in),
        SMALL,
        TEXT_MUTED,
        Anchor::MIDDLE_RIGHT,
    );
    sheet.text(
        along(p, (54.0, -134.0), 1.0),
        &degrees(angle_out),
        SMALL,
        TEXT_MUTED,
        Anchor::MIDDLE_LEFT,
    );
    sheet.note(
        1,
        "Subtracting d's normal part twice flips it and keeps the part along the surface:",
    );
    sheet.note(
        0,
        "the angle out equals the angle in. r computed by raylab::optics::reflect.",
    );
    sheet.finish()
}

/// The angles of incidence drawn into the glass, and out of it.
const INTO: [f32; 5] = [0.0, 20.0, 40.0, 60.0, 80.0];
const OUT_OF: [f32; 6] = [0.0, 20.0, 35.0, 45.0, 55.0, 70.0];

pub fn snell_figure() -> RgbImage {
    let ior = glass_ior();
    let critical = critical_angle(ior);
    let mut sheet = Sheet::new(
        1200.0,
        664.0,
        &format!("Snell's law at the lab's glass (ior {ior}): n1 sin θ1 = n2 sin θ2"),
    );
    let length = 200.0;
    let glass_fill: Rgb = [226, 238, 246];
    let tir = kind_colour(RayKind::TotalInternalReflection);
    for panel in 0..2 {
        let p: P = (295.0 + 610.0 * panel as f32, 330.0);
        let to = |v: Vec3| -> P { (p.0 + v.x * length, p.1 - v.y * length) };
        // Air above, glass below, in both panels.
        sheet.fill_rect((p.0 - 265.0, p.1), (530.0, 240.0), glass_fill);
        sheet.line((p.0 - 265.0, p.1), (p.0 + 265.0, p.1), AXIS, 2.0);
        sheet.text(
            (p.0 + 258.0, p.1 - 8.0),
            "air, n = 1",
            SMALL,
            TEXT_MUTED,
            Anchor::BASELINE_RIGHT,
        );
        sheet.text(
            (p.0 + 258.0, p.1 + 8.0),
            &format!("glass, n = {ior}"),
            SMALL,
            TEXT_MUTED,
            Anchor::TOP_RIGHT,
        );
        sheet.dashed(to(Vec3::Y * 1.05), to(Vec3::NEG_Y * 1.05), AXIS, 1.0);
        if panel == 0 {
            sheet.text(
                (p.0, 64.0),
                &format!("into the glass: refract(d, n, 1/{ior}) bends towards n"),
                LABEL,
                TEXT,
                Anchor::TOP_CENTRE,
            );
            for (m, &angle) in INTO.iter().enumerate() {
                let colour = series_colour(m);
                let d = incoming(angle, 1.0);
                let t = refract(d, Vec3::Y, 1.0 / ior).expect("light always enters");
                sheet.line(to(-d), p, colour, 2.0);
                sheet.arrow(p, to(t * 0.95), colour, 2.0);
                let bent = t.x.asin();
                sheet.label(
                    along(to(-d * 1.02), (0.0, -4.0), 1.0),
                    &format!("{angle:.0}°"),
                    SMALL,
                    colour,
                    Anchor::BOTTOM_CENTRE,
                );
                sheet.text(
                    (p.0 - 255.0, p.1 + 44.0 + LINE * m as f32),
                    &format!("{angle:.0}° in air → {} in glass", degrees(bent)),
                    SMALL,
                    colour,
                    Anchor::BASELINE_LEFT,
                );
            }
        } else {
            sheet.text(
                (p.0, 64.0),
                &format!("out of the glass: refract(d, n, {ior}) bends away from n"),
                LABEL,
                TEXT,
                Anchor::TOP_CENTRE,
            );
            for (m, &angle) in OUT_OF.iter().enumerate() {
                let d = incoming(angle, -1.0);
                let out = refract(d, Vec3::NEG_Y, ior);
                let colour = if out.is_some() { series_colour(m) } else { tir };
                sheet.line(to(-d), p, colour, 2.0);
                // Beyond the ray's start, turned a little away from the
                // critical angle's line, which runs between 35° and 45°.
                let turn = if angle < critical { -4.0 } else { 4.0 };
                sheet.label(
                    to(-incoming(angle + turn, -1.0) * 1.1),
                    &format!("{angle:.0}°"),
                    SMALL,
                    colour,
                    Anchor::MIDDLE_CENTRE,
                );
                let line = match out {
                    Some(t) => {
                        sheet.arrow(p, to(t * 0.95), colour, 2.0);
                        format!("{angle:.0}° in glass → {} in air", degrees(t.x.asin()))
                    }
                    None => {
                        let r = reflect(d, Vec3::NEG_Y);
                        sheet.arrow(p, to(r * 0.8), tir, 2.0);
                        format!("{angle:.0}° in glass → None: reflected")
                    }
                };
                // In the air on the left, ending short of the normal.
                let widest = sheet.text_width("45° in glass → None: reflected", SMALL);
                sheet.text(
                    (p.0 - 16.0 - widest, p.1 - 190.0 + LINE * m as f32),
                    &line,
                    SMALL,
                    colour,
                    Anchor::BASELINE_LEFT,
                );
            }
            // The critical angle, dashed, inside the glass.
            let c = incoming(critical, -1.0);
            // Longer than the rays, so that its label clears theirs.
            sheet.dashed(to(-c * 1.25), p, TEXT, 1.5);
            sheet.label(
                along(to(-c * 1.25), (-2.0, 4.0), 1.0),
                &format!("critical {critical:.2}°"),
                SMALL,
                TEXT,
                Anchor::TOP_RIGHT,
            );
            // Ending at the panel's right edge.
            let text = "past the critical angle: refract returns None, all of it reflects";
            let width = 32.0 + sheet.text_width(text, SMALL);
            sheet.legend((p.0 + 265.0 - width, p.1 + 256.0), &[(tir, text)]);
        }
        sheet.dot(p, TEXT);
    }
    sheet.note(
        0,
        &format!(
            "The critical angle is where refract starts returning None, found by halving: \
             {critical:.2}° (asin(1/{ior}) = {:.2}°).",
            (1.0 / ior).asin().to_degrees()
        ),
    );
    sheet.finish()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_lab_glass_has_ior_1_5_and_a_critical_angle_of_41_81_degrees() {
        assert_eq!(glass_ior(), 1.5);
        // asin(1/1.5) = asin(0.6667) = 41.810°.
        let critical = critical_angle(1.5);
        assert!((critical - 41.81).abs() < 0.005, "{critical}");
    }

    #[test]
    fn reflecting_at_40_degrees_leaves_at_40_degrees() {
        let d = incoming(40.0, 1.0);
        let r = reflect(d, Vec3::Y);
        assert!((r.dot(Vec3::Y).acos().to_degrees() - 40.0).abs() < 1e-3);
        // d·n = −cos 40° = −0.766.
        assert!((d.dot(Vec3::Y) + 0.766_04).abs() < 1e-4);
    }

    #[test]
    fn sixty_degrees_into_glass_bends_to_35_26_degrees() {
        // sin θ₂ = sin 60° / 1.5 = 0.57735: θ₂ = 35.26°.
        let t = refract(incoming(60.0, 1.0), Vec3::Y, 1.0 / 1.5).unwrap();
        assert!((t.x.asin().to_degrees() - 35.26).abs() < 0.01);
    }
}
