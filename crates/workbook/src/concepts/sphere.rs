//! The ray–sphere quadratic's roots: a ray that enters and leaves (t0 and
//! t1), one that misses (b² − q < 0), and one from inside (t0 ≤ 0, so t1
//! counts), each with the numbers `Sphere::intersect` works with.

use image::RgbImage;
use raylab::sphere::Sphere;
use raylab::{Ray, Vec3};
use raylab_plot::colour::{AXIS, TEXT, TEXT_MUTED};
use raylab_plot::{Anchor, Rgb};

use super::{LABEL, P, SMALL, Sheet, along};

/// The quadratic `t² + 2bt + q = 0` of a ray and a sphere, as
/// `Sphere::intersect` forms it, and what it returns.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Roots {
    pub b: f32,
    pub q: f32,
    pub discriminant: f32,
    /// `(t0, t1)` when the line meets the sphere.
    pub roots: Option<(f32, f32)>,
    /// What `Sphere::intersect` returns.
    pub returned: Option<f32>,
}

pub fn roots(sphere: &Sphere, ray: &Ray) -> Roots {
    let oc = ray.origin - sphere.centre;
    let b = oc.dot(ray.direction);
    let q = oc.dot(oc) - sphere.radius * sphere.radius;
    let discriminant = b * b - q;
    let roots = (discriminant >= 0.0).then(|| {
        let root = discriminant.sqrt();
        (-b - root, -b + root)
    });
    Roots {
        b,
        q,
        discriminant,
        roots,
        returned: sphere.intersect(ray),
    }
}

/// The three cases, in the plane z = 0 around a unit sphere at the origin.
pub fn cases() -> [(&'static str, Ray); 3] {
    [
        (
            "a hit: enters at t0, leaves at t1",
            Ray::new(Vec3::new(-2.0, 0.4, 0.0), Vec3::X),
        ),
        (
            "a miss: b² − q < 0",
            Ray::new(Vec3::new(-2.0, 1.3, 0.0), Vec3::X),
        ),
        (
            "from inside: t0 ≤ 0, t1 counts",
            Ray::new(
                Vec3::new(-0.4, -0.3, 0.0),
                Vec3::new(1.0, 0.25, 0.0).normalize(),
            ),
        ),
    ]
}

const RAY: Rgb = [40, 40, 40];
const ENTER: Rgb = [0, 114, 178];
const LEAVE: Rgb = [213, 94, 0];

pub fn figure() -> RgbImage {
    let sphere = Sphere {
        centre: Vec3::ZERO,
        radius: 1.0,
    };
    let mut sheet = Sheet::new(
        1200.0,
        560.0,
        "Ray meets sphere: the roots of t² + 2bt + q = 0",
    );
    let k = 92.0;
    for (n, (title, ray)) in cases().into_iter().enumerate() {
        let cx = 200.0 + 400.0 * n as f32;
        let cy = 255.0;
        let to = |p: Vec3| -> P { (cx + p.x * k, cy - p.y * k) };
        sheet.text((cx, 64.0), title, LABEL, TEXT, Anchor::TOP_CENTRE);
        sheet.circle((cx, cy), k, Some([232, 240, 248]), Some(AXIS));
        sheet.dot((cx, cy), AXIS);
        sheet.text(
            (cx - 4.0, cy - 4.0),
            "c",
            SMALL,
            TEXT_MUTED,
            Anchor::BASELINE_RIGHT,
        );
        let r = roots(&sphere, &ray);
        let end = ray.at(if r.q > 0.0 { 4.0 } else { 2.5 });
        // Behind the origin, dashed: the line goes on, the ray does not.
        if let Some((t0, _)) = r.roots
            && t0 <= 0.0
        {
            sheet.dashed(to(ray.at(t0 - 0.6)), to(ray.origin), TEXT_MUTED, 1.5);
        }
        sheet.arrow(to(ray.origin), to(end), RAY, 2.0);
        sheet.dot(to(ray.origin), RAY);
        sheet.text(
            along(to(ray.origin), (0.0, -10.0), 1.0),
            "o",
            LABEL,
            TEXT,
            Anchor::BASELINE_CENTRE,
        );
        match r.roots {
            Some((t0, t1)) => {
                let (p0, p1) = (to(ray.at(t0)), to(ray.at(t1)));
                sheet.circle(p0, 6.0, Some(ENTER), None);
                sheet.circle(p1, 6.0, Some(LEAVE), None);
                let behind = if t0 <= 0.0 { " (behind o)" } else { "" };
                sheet.label(
                    (p0.0, p0.1 + 12.0),
                    &format!("t0 = {t0:.2}{behind}"),
                    SMALL,
                    ENTER,
                    Anchor::TOP_CENTRE,
                );
                sheet.label(
                    (p1.0, p1.1 - 12.0),
                    &format!("t1 = {t1:.2}"),
                    SMALL,
                    LEAVE,
                    Anchor::BASELINE_CENTRE,
                );
            }
            None => {
                // The closest the line comes to the centre: farther than R.
                let t = -r.b;
                let near = ray.at(t);
                sheet.dashed((cx, cy), to(near), LEAVE, 1.5);
                sheet.label(
                    along(to(near), (8.0, 16.0), 1.0),
                    &format!("closest {:.2} > R = 1", near.length()),
                    SMALL,
                    LEAVE,
                    Anchor::TOP_LEFT,
                );
            }
        }
        let verdict = match r.returned {
            Some(t) => format!("intersect returns t = {t:.2}"),
            None => "intersect returns None".to_owned(),
        };
        let lines = [
            format!("b = (o − c)·d = {:.2}", r.b),
            format!("q = |o − c|² − R² = {:.2}", r.q),
            format!("b² − q = {:.2}", r.discriminant),
            verdict,
        ];
        for (m, line) in lines.iter().enumerate() {
            let colour = if m == 3 { TEXT } else { TEXT_MUTED };
            sheet.text(
                (cx, cy + k + 42.0 + 26.0 * m as f32),
                line,
                LABEL,
                colour,
                Anchor::BASELINE_CENTRE,
            );
        }
    }
    sheet.legend(
        (60.0, 498.0),
        &[(ENTER, "t0 = −b − √(b² − q): where the line enters")],
    );
    sheet.legend(
        (660.0, 498.0),
        &[(LEAVE, "t1 = −b + √(b² − q): where it leaves")],
    );
    sheet.note(
        0,
        "A unit sphere (R = 1) and unit directions d; the numbers are Sphere::intersect's own.",
    );
    sheet.finish()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn unit() -> Sphere {
        Sphere {
            centre: Vec3::ZERO,
            radius: 1.0,
        }
    }

    #[test]
    fn the_hit_has_the_roots_worked_by_hand() {
        // o = (−2, 0.4), d = x: b = −2, q = 4 + 0.16 − 1 = 3.16,
        // b² − q = 0.84, t = 2 ∓ 0.9165.
        let r = roots(&unit(), &cases()[0].1);
        let (t0, t1) = r.roots.unwrap();
        assert!((r.discriminant - 0.84).abs() < 1e-5);
        assert!((t0 - 1.083_48).abs() < 1e-4 && (t1 - 2.916_52).abs() < 1e-4);
        assert_eq!(r.returned, Some(t0));
    }

    #[test]
    fn the_miss_has_a_negative_discriminant_and_the_inside_ray_returns_t1() {
        let miss = roots(&unit(), &cases()[1].1);
        // b² − q = 4 − (4 + 1.69 − 1) = −0.69.
        assert!((miss.discriminant + 0.69).abs() < 1e-5);
        assert_eq!((miss.roots, miss.returned), (None, None));
        let inside = roots(&unit(), &cases()[2].1);
        let (t0, t1) = inside.roots.unwrap();
        assert!(t0 <= 0.0 && inside.q < 0.0);
        assert_eq!(inside.returned, Some(t1));
    }
}
