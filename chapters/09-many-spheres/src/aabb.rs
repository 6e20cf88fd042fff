//! Axis-aligned boxes, and the slab test: where a ray is inside a box.

use glam::BVec3A;
use raylab::Vec3;
use raylab::sphere::Sphere;

/// A ray made ready for many slab tests: where it starts, `1/d` per axis,
/// and the axes it runs backwards along (`d < 0`, or `−0`).
#[derive(Clone, Copy, Debug)]
pub struct SlabRay {
    pub origin: Vec3,
    pub inverse: Vec3,
    pub backwards: BVec3A,
}

impl SlabRay {
    pub fn new(origin: Vec3, direction: Vec3) -> SlabRay {
        let inverse = direction.recip();
        SlabRay {
            origin,
            inverse,
            backwards: inverse.cmplt(Vec3::ZERO),
        }
    }
}

/// A box whose faces are perpendicular to the axes: every point `p` with
/// `min ≤ p ≤ max` in each coordinate. Boxes are closed (their faces belong
/// to them) and may be flat, or a single point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Aabb {
    pub min: Vec3,
    pub max: Vec3,
}

/// How much a sphere's box is wider than the sphere, as a share of its
/// radius. The ray–sphere test rounds `R²` and so may report a hit up to
/// about `√(2u)·R ≈ 3.5e-4·R` outside the sphere (`u = 2⁻²⁴`, one rounding);
/// `2⁻¹⁰ ≈ 9.8e-4` covers that with room to spare, so the box never loses
/// a hit the list of spheres would find.
pub const RADIUS_SLACK: f32 = 1.0 / 1024.0;

impl Aabb {
    /// The empty box: the union of nothing. Any box joined to it is itself.
    pub const EMPTY: Aabb = Aabb {
        min: Vec3::splat(f32::INFINITY),
        max: Vec3::splat(f32::NEG_INFINITY),
    };

    /// The box around a sphere, widened by [`RADIUS_SLACK`].
    pub fn around_sphere(sphere: &Sphere) -> Aabb {
        let r = Vec3::splat(sphere.radius + sphere.radius * RADIUS_SLACK);
        Aabb {
            min: sphere.centre - r,
            max: sphere.centre + r,
        }
    }

    /// The smallest box holding both. Exact: `min` and `max` never round.
    pub fn union(self, other: Aabb) -> Aabb {
        Aabb {
            min: self.min.min(other.min),
            max: self.max.max(other.max),
        }
    }

    /// The smallest box holding this one and a point.
    pub fn grow(self, point: Vec3) -> Aabb {
        self.union(Aabb {
            min: point,
            max: point,
        })
    }

    /// The box's centre.
    pub fn centre(&self) -> Vec3 {
        0.5 * (self.min + self.max)
    }

    // ANCHOR: surface_area
    /// The area of the box's six faces, `2(xy + yz + zx)`: the surface area
    /// heuristic's measure of how likely a ray is to pass through it. For a
    /// flat or point box it is 0; for the empty box, 0 as well.
    pub fn surface_area(&self) -> f32 {
        let e = (self.max - self.min).max(Vec3::ZERO);
        2.0 * (e.x * e.y + e.y * e.z + e.z * e.x)
    }
    // ANCHOR_END: surface_area

    // ANCHOR: slab
    /// Where the ray is inside the box widened by `pad` on every side,
    /// clipped to `t_min ≤ t ≤ t_max`: the entry distance, or `None` if that
    /// stretch of the ray misses it.
    ///
    /// A box is the overlap of three slabs (`min.x ≤ x ≤ max.x`, and so on);
    /// the ray is in a slab between the two distances where it crosses its
    /// planes, and in the box where it is in all three at once. Along an
    /// axis it runs backwards on, it crosses the `max` plane first.
    ///
    /// Two cases need care. Where `d.x = 0` the ray never crosses the x
    /// planes: `1/d.x` is ±∞ and the distances are ±∞, which says "always
    /// inside" or "never inside", as it should. But a ray that runs exactly
    /// *in* one of the planes gives `0 · ∞ = NaN`: that ray lies in the
    /// (closed) slab, so that distance must set no limit. `f32::max` and
    /// `f32::min` do just that: given a NaN, they return the other number.
    /// The same rule makes a NaN ray visit every box, which is slow but
    /// never wrong: the sphere tests then find nothing, as the list does.
    #[inline]
    pub fn slab_test(&self, ray: &SlabRay, pad: f32, t_min: f32, t_max: f32) -> Option<f32> {
        let low = (self.min - pad - ray.origin) * ray.inverse;
        let high = (self.max + pad - ray.origin) * ray.inverse;
        let near = Vec3::select(ray.backwards, high, low);
        let far = Vec3::select(ray.backwards, low, high);
        let enter = t_min.max(near.x).max(near.y).max(near.z);
        let leave = t_max.min(far.x).min(far.y).min(far.z);
        (enter <= leave).then_some(enter)
    }
    // ANCHOR_END: slab
}

#[cfg(test)]
mod tests {
    use super::*;

    fn unit_cube() -> Aabb {
        Aabb {
            min: Vec3::ZERO,
            max: Vec3::ONE,
        }
    }

    #[test]
    fn a_ray_along_x_enters_the_unit_cube_at_its_near_face() {
        // From x = -2 towards +x: enters at t = 2, leaves at t = 3.
        let (o, d) = (Vec3::new(-2.0, 0.5, 0.5), Vec3::X);
        let t = unit_cube().slab_test(&SlabRay::new(o, d), 0.0, 0.0, f32::INFINITY);
        assert_eq!(t, Some(2.0));
    }

    #[test]
    fn a_ray_from_inside_enters_at_its_own_start() {
        let (o, d) = (Vec3::splat(0.5), Vec3::Y);
        let t = unit_cube().slab_test(&SlabRay::new(o, d), 0.0, 0.0, f32::INFINITY);
        assert_eq!(t, Some(0.0));
    }

    #[test]
    fn a_box_beyond_the_nearest_hit_so_far_is_skipped() {
        let (o, d) = (Vec3::new(-2.0, 0.5, 0.5), Vec3::X);
        assert_eq!(
            unit_cube().slab_test(&SlabRay::new(o, d), 0.0, 0.0, 1.5),
            None
        );
        // A hit exactly at the entry distance keeps the box: ties must be seen.
        assert_eq!(
            unit_cube().slab_test(&SlabRay::new(o, d), 0.0, 0.0, 2.0),
            Some(2.0)
        );
    }

    #[test]
    fn a_ray_parallel_to_a_face_outside_the_box_misses() {
        // d.y = 0 and y = 2 is outside 0 ≤ y ≤ 1: 1/d.y = ∞ gives ±∞ distances.
        let (o, d) = (Vec3::new(-2.0, 2.0, 0.5), Vec3::X);
        assert_eq!(
            unit_cube().slab_test(&SlabRay::new(o, d), 0.0, 0.0, f32::INFINITY),
            None
        );
    }

    #[test]
    fn a_ray_running_in_a_face_plane_hits_the_box() {
        // y = 1 exactly and d.y = 0: (1 − 1)·∞ is NaN, and the ray is on the top face.
        let (o, d) = (Vec3::new(-2.0, 1.0, 0.5), Vec3::X);
        let t = unit_cube().slab_test(&SlabRay::new(o, d), 0.0, 0.0, f32::INFINITY);
        assert_eq!(t, Some(2.0));
    }

    #[test]
    fn a_nan_ray_visits_every_box() {
        let (o, d) = (Vec3::splat(f32::NAN), Vec3::X);
        let t = unit_cube().slab_test(&SlabRay::new(o, d), 0.0, 0.0, f32::INFINITY);
        assert_eq!(t, Some(0.0));
    }

    #[test]
    fn padding_widens_the_box_on_every_side() {
        // With pad 0.5 the cube spans -0.5..1.5: entered at t = 1.5, and
        // a ray at y = 1.25 now passes through.
        let (o, d) = (Vec3::new(-2.0, 1.25, 0.5), Vec3::X);
        assert_eq!(
            unit_cube().slab_test(&SlabRay::new(o, d), 0.0, 0.0, 9.0),
            None
        );
        assert_eq!(
            unit_cube().slab_test(&SlabRay::new(o, d), 0.5, 0.0, 9.0),
            Some(1.5)
        );
    }

    #[test]
    fn the_unit_cube_has_surface_area_six_and_a_flat_box_twice_its_face() {
        assert_eq!(unit_cube().surface_area(), 6.0);
        let flat = Aabb {
            min: Vec3::ZERO,
            max: Vec3::new(2.0, 3.0, 0.0),
        };
        assert_eq!(flat.surface_area(), 12.0);
        assert_eq!(Aabb::EMPTY.surface_area(), 0.0);
    }

    #[test]
    fn a_spheres_box_is_its_radius_and_a_little_more_each_way() {
        let sphere = Sphere {
            centre: Vec3::new(1.0, 2.0, 3.0),
            radius: 1024.0,
        };
        // 1024 · (1 + 1/1024) = 1025 each side.
        let b = Aabb::around_sphere(&sphere);
        assert_eq!(b.min, Vec3::new(-1024.0, -1023.0, -1022.0));
        assert_eq!(b.max, Vec3::new(1026.0, 1027.0, 1028.0));
        assert_eq!(Aabb::EMPTY.union(b), b);
    }
}
