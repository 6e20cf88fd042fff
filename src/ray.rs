//! Rays: a point that moves along a unit direction.

use crate::Vec3;

/// A half-line `origin + t · direction`, `t > 0`.
///
/// The direction is always of unit length (the lab model): `t` is then a distance,
/// and the intersection formulas can skip the `dot(d, d)` term.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ray {
    /// Where the ray starts (`o`).
    pub origin: Vec3,
    /// Which way it goes (`d`), of unit length.
    pub direction: Vec3,
}

impl Ray {
    /// A ray from `origin` along `direction`, which must already be normalised.
    #[inline]
    pub fn new(origin: Vec3, direction: Vec3) -> Self {
        debug_assert!(
            (direction.length() - 1.0).abs() < 1e-4,
            "ray directions must be unit length, got {direction}"
        );
        Ray { origin, direction }
    }

    // ANCHOR: at
    /// The point at distance `t` along the ray.
    #[inline]
    pub fn at(&self, t: f32) -> Vec3 {
        // ANCHOR: todo_ray_at "Return the point at distance t along the ray: origin + t · direction."
        self.origin + t * self.direction
        // ANCHOR_END: todo_ray_at
    }
    // ANCHOR_END: at
}

/// Why a ray was traced. The statistics, the heat maps and the ray-tree
/// diagrams all tell rays apart by kind.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum RayKind {
    /// From the eye through a pixel.
    Primary,
    /// A feeler towards the sun: is anything in the way?
    Shadow,
    /// The mirror direction at a reflective surface.
    Reflection,
    /// Bent by Snell's law into or out of a transparent surface.
    Refraction,
    /// The transmitted share sent along the mirror direction because no
    /// refracted direction exists.
    TotalInternalReflection,
}

impl RayKind {
    /// Every kind, in the order the statistics print them.
    pub const ALL: [RayKind; 5] = [
        RayKind::Primary,
        RayKind::Shadow,
        RayKind::Reflection,
        RayKind::Refraction,
        RayKind::TotalInternalReflection,
    ];

    /// The kind's name in summaries, diagrams and probe listings.
    pub fn name(self) -> &'static str {
        match self {
            RayKind::Primary => "primary",
            RayKind::Shadow => "shadow",
            RayKind::Reflection => "reflection",
            RayKind::Refraction => "refraction",
            RayKind::TotalInternalReflection => "total internal reflection",
        }
    }

    /// A dense index, for per-kind counters.
    pub fn index(self) -> usize {
        self as usize
    }
}

// ANCHOR: tests
#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_point_along_a_ray_is_origin_plus_t_times_direction() {
        let ray = Ray::new(Vec3::new(1.0, 2.0, 3.0), Vec3::X);
        assert_eq!(ray.at(2.5), Vec3::new(3.5, 2.0, 3.0));
    }

    #[test]
    fn the_point_at_distance_zero_is_the_origin() {
        let ray = Ray::new(Vec3::new(1.0, 2.0, 3.0), Vec3::Y);
        assert_eq!(ray.at(0.0), Vec3::new(1.0, 2.0, 3.0));
    }

    #[test]
    fn a_point_at_distance_3_along_a_slanted_ray_is_3_units_away() {
        // d = (0.6, 0.8, 0): 3 · d = (1.8, 2.4, 0).
        let ray = Ray::new(Vec3::new(-1.0, 0.0, 2.0), Vec3::new(0.6, 0.8, 0.0));
        assert!(
            ray.at(3.0).abs_diff_eq(Vec3::new(0.8, 2.4, 2.0), 1e-6),
            "{}",
            ray.at(3.0)
        );
    }
}
// ANCHOR_END: tests
