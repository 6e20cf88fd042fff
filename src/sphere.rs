//! Spheres: the ray–sphere quadratic.

use crate::Vec3;
use crate::ray::Ray;

/// A sphere with centre `c` and radius `R`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sphere {
    /// The centre `c`.
    pub centre: Vec3,
    /// The radius `R`, above 0.
    pub radius: f32,
}

impl Sphere {
    // ANCHOR: intersect
    /// The distance `t > 0` to the nearest point where the ray meets the
    /// sphere, or `None`.
    ///
    /// Points on the ray are `o + t·d`, points on the sphere satisfy
    /// `|p − c|² = R²`. Substituting gives `t² + 2bt + q = 0` with
    /// `b = dot(o − c, d)` and `q = |o − c|² − R²` (because `|d| = 1`).
    #[inline]
    pub fn intersect(&self, ray: &Ray) -> Option<f32> {
        // ANCHOR: todo_sphere "Solve t² + 2bt + q = 0 with b = dot(o − c, d), q = |o − c|² − R²: no hit if b² − q < 0, else the nearer root t0 = −b − √(b² − q) if it is > 0, else the far root t1 = −b + √(b² − q) if it is > 0 (the ray starts inside), else no hit."
        let oc = ray.origin - self.centre;
        let b = oc.dot(ray.direction);
        let q = oc.dot(oc) - self.radius * self.radius;
        let disc = b * b - q;
        if disc < 0.0 {
            return None; // the line misses the sphere
        }
        let root = disc.sqrt();
        let t0 = -b - root; // where the ray enters
        if t0 > 0.0 {
            return Some(t0);
        }
        let t1 = -b + root; // where it leaves: the origin is inside
        (t1 > 0.0).then_some(t1)
        // ANCHOR_END: todo_sphere
    }
    // ANCHOR_END: intersect

    /// The outward unit normal at a point on the sphere.
    #[inline]
    pub fn normal_at(&self, point: Vec3) -> Vec3 {
        (point - self.centre).normalize()
    }
}

// ANCHOR: tests
#[cfg(test)]
mod tests {
    use super::*;

    fn unit_sphere_at_origin() -> Sphere {
        Sphere {
            centre: Vec3::ZERO,
            radius: 1.0,
        }
    }

    #[test]
    fn a_ray_through_the_centre_hits_the_near_side_first() {
        // From z = 5 towards -z: roots at t = 4 and t = 6.
        let ray = Ray::new(Vec3::new(0.0, 0.0, 5.0), Vec3::NEG_Z);
        assert_eq!(unit_sphere_at_origin().intersect(&ray), Some(4.0));
    }

    #[test]
    fn a_tangent_ray_touches_the_sphere_once() {
        // Grazes the top at (0, 1, 0): the discriminant is exactly 0.
        let ray = Ray::new(Vec3::new(0.0, 1.0, 5.0), Vec3::NEG_Z);
        assert_eq!(unit_sphere_at_origin().intersect(&ray), Some(5.0));
    }

    #[test]
    fn a_ray_that_passes_above_misses() {
        let ray = Ray::new(Vec3::new(0.0, 1.5, 5.0), Vec3::NEG_Z);
        assert_eq!(unit_sphere_at_origin().intersect(&ray), None);
    }

    #[test]
    fn a_ray_from_inside_hits_the_far_side() {
        // t0 = -1 lies behind the origin, so the far root t1 = 1 wins.
        let ray = Ray::new(Vec3::ZERO, Vec3::X);
        assert_eq!(unit_sphere_at_origin().intersect(&ray), Some(1.0));
    }

    #[test]
    fn a_sphere_behind_the_ray_is_not_hit() {
        let ray = Ray::new(Vec3::new(0.0, 0.0, 5.0), Vec3::Z);
        assert_eq!(unit_sphere_at_origin().intersect(&ray), None);
    }

    #[test]
    fn the_normal_points_out_of_the_sphere() {
        let sphere = Sphere {
            centre: Vec3::new(1.0, 0.0, 0.0),
            radius: 2.0,
        };
        assert_eq!(sphere.normal_at(Vec3::new(1.0, 2.0, 0.0)), Vec3::Y);
    }

    #[test]
    fn a_ray_from_inside_an_off_centre_point_hits_the_far_side_1_away() {
        // Radius 2, from (1, 0, 0) along +x: b = 1, q = 1 − 4 = −3, √(b² − q) = 2,
        // so t0 = −3 (behind) and t1 = 1.
        let sphere = Sphere {
            centre: Vec3::ZERO,
            radius: 2.0,
        };
        let ray = Ray::new(Vec3::new(1.0, 0.0, 0.0), Vec3::X);
        assert_eq!(sphere.intersect(&ray), Some(1.0));
    }

    #[test]
    fn a_ray_off_centre_enters_where_the_quadratic_says() {
        // From (0, 0.6, 5) along −z: b = −5, q = 0.36 + 25 − 1 = 24.36,
        // b² − q = 0.64, so t0 = 5 − 0.8 = 4.2.
        let ray = Ray::new(Vec3::new(0.0, 0.6, 5.0), Vec3::NEG_Z);
        let t = unit_sphere_at_origin().intersect(&ray).unwrap();
        assert!((t - 4.2).abs() < 1e-5, "t = {t}");
    }
}
// ANCHOR_END: tests
