//! Planes: the ground, and its checkerboard.

use crate::Vec3;
use crate::ray::Ray;

/// An infinite plane through `point` with unit `normal`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Plane {
    /// Any point on the plane (`p0`).
    pub point: Vec3,
    /// Its unit normal (`n`).
    pub normal: Vec3,
}

impl Plane {
    // ANCHOR: intersect
    /// The distance `t > 0` at which the ray crosses the plane, or `None`.
    ///
    /// Points on the plane satisfy `dot(p − p0, n) = 0`; with `p = o + t·d`
    /// that gives `t = dot(p0 − o, n) / dot(d, n)`.
    #[inline]
    pub fn intersect(&self, ray: &Ray) -> Option<f32> {
        // ANCHOR: todo_plane "No hit if |dot(d, n)| < 1e-8 (the ray runs parallel); else t = dot(p0 − o, n) / dot(d, n), a hit only if t > 0."
        let denom = ray.direction.dot(self.normal);
        if denom.abs() < 1e-8 {
            return None; // the ray runs parallel to the plane
        }
        let t = (self.point - ray.origin).dot(self.normal) / denom;
        (t > 0.0).then_some(t)
        // ANCHOR_END: todo_plane
    }
    // ANCHOR_END: intersect
}

/// The two colours of the ground's unit squares.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Checker {
    /// The albedo of the squares where `floor(x) + floor(z)` is even.
    pub even: Vec3,
    /// The albedo of the others.
    pub odd: Vec3,
}

impl Checker {
    // ANCHOR: checker
    /// The albedo at a point on the ground: squares of side 1 in x and z.
    #[inline]
    pub fn albedo_at(&self, point: Vec3) -> Vec3 {
        // ANCHOR: todo_checker "With s = floor(x) + floor(z), return the even colour where s is even and the odd colour where it is odd (mind the negative squares)."
        // `floor`, not `as i32`: truncation would merge the two squares
        // either side of x = 0 into one double-width stripe.
        let s = point.x.floor() + point.z.floor();
        // `s` is a whole number; its lowest bit is its parity (two's
        // complement keeps that right for negative numbers too).
        if (s as i64) & 1 == 0 {
            self.even
        } else {
            self.odd
        }
        // ANCHOR_END: todo_checker
    }
    // ANCHOR_END: checker
}

// ANCHOR: tests
#[cfg(test)]
mod tests {
    use super::*;

    fn ground() -> Plane {
        Plane {
            point: Vec3::ZERO,
            normal: Vec3::Y,
        }
    }

    #[test]
    fn a_ray_parallel_to_the_plane_never_meets_it() {
        let ray = Ray::new(Vec3::new(0.0, 1.0, 0.0), Vec3::X);
        assert_eq!(ground().intersect(&ray), None);
    }

    #[test]
    fn a_plane_behind_the_ray_is_not_hit() {
        let ray = Ray::new(Vec3::new(0.0, 1.0, 0.0), Vec3::Y);
        assert_eq!(ground().intersect(&ray), None);
    }

    /// a ray falling at 45° from height 2 lands at t = 2√2
    #[test]
    fn a_ray_falling_at_45_degrees_from_height_2_lands_at_t_2_sqrt_2() {
        let d = Vec3::new(1.0, -1.0, 0.0).normalize();
        let ray = Ray::new(Vec3::new(0.0, 2.0, 0.0), d);
        let t = ground().intersect(&ray).unwrap();
        assert!((t - 2.0 * 2f32.sqrt()).abs() < 1e-6, "t = {t}");
        assert!(ray.at(t).abs_diff_eq(Vec3::new(2.0, 0.0, 0.0), 1e-6));
    }

    #[test]
    fn checker_parity_flips_across_negative_coordinates() {
        let checker = Checker {
            even: Vec3::ONE,
            odd: Vec3::ZERO,
        };
        // floor(0.5) + floor(0.5) = 0: even.
        assert_eq!(checker.albedo_at(Vec3::new(0.5, 0.0, 0.5)), Vec3::ONE);
        // floor(-0.5) + floor(0.5) = -1: odd, not merged with the square at +0.5.
        assert_eq!(checker.albedo_at(Vec3::new(-0.5, 0.0, 0.5)), Vec3::ZERO);
        // floor(-0.5) + floor(-0.5) = -2: even again.
        assert_eq!(checker.albedo_at(Vec3::new(-0.5, 0.0, -0.5)), Vec3::ONE);
        // floor(-1.5) + floor(0.2) = -2: even.
        assert_eq!(checker.albedo_at(Vec3::new(-1.5, 0.0, 0.2)), Vec3::ONE);
    }

    #[test]
    fn a_ray_from_below_the_ground_meets_it_from_underneath() {
        // Both sides of a plane count: dot(p0 − o, n) = 1 and dot(d, n) = 1.
        let ray = Ray::new(Vec3::new(0.0, -1.0, 0.0), Vec3::Y);
        assert_eq!(ground().intersect(&ray), Some(1.0));
    }

    #[test]
    fn a_ray_straight_down_from_height_3_lands_at_t_3() {
        let ray = Ray::new(Vec3::new(0.5, 3.0, -7.0), Vec3::NEG_Y);
        assert_eq!(ground().intersect(&ray), Some(3.0));
    }

    #[test]
    fn the_checker_squares_either_side_of_the_origin_differ() {
        let checker = Checker {
            even: Vec3::ONE,
            odd: Vec3::ZERO,
        };
        // floor(0.5) + floor(-0.5) = −1: odd. Truncating (`as i32`) would give
        // 0 + 0 = 0, even, and merge the squares either side of z = 0.
        assert_eq!(checker.albedo_at(Vec3::new(0.5, 0.0, -0.5)), Vec3::ZERO);
        // floor(1.5) + floor(0.5) = 1: odd; floor(1.5) + floor(1.5) = 2: even.
        assert_eq!(checker.albedo_at(Vec3::new(1.5, 0.0, 0.5)), Vec3::ZERO);
        assert_eq!(checker.albedo_at(Vec3::new(1.5, 0.0, 1.5)), Vec3::ONE);
    }
}
// ANCHOR_END: tests
