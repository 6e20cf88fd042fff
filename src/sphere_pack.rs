//! Four spheres tested against one ray at once.
//!
//! [`Sphere::intersect`] is the formula the book explains. A render asks it
//! of every sphere for every ray, which takes about 40 % of chapter 4's
//! time, so the scene also keeps its spheres in packs of four, coordinate by coordinate
//! (`x` of all four, then `y` …), and runs the same formula on four lanes of
//! one SIMD register (glam's `Vec4`: SSE2 on x86-64, NEON on ARM). Each lane
//! does exactly the arithmetic of `Sphere::intersect`, in the same order, so
//! the distances are the same to the last bit; the tests below check that
//! on random spheres and rays.

use glam::{BVec4A, Vec4};

use crate::ray::Ray;
use crate::sphere::Sphere;

/// Up to four spheres, stored coordinate by coordinate.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SpherePack {
    centre_x: Vec4,
    centre_y: Vec4,
    centre_z: Vec4,
    radius_squared: Vec4,
    len: usize,
}

impl SpherePack {
    /// Lanes per pack.
    pub const LANES: usize = 4;

    /// An empty pack. Its free lanes hold a sphere no ray can hit: with
    /// `R² = −∞` the discriminant `b² − (|oc|² − R²)` is `−∞` (or NaN), never
    /// `≥ 0`.
    pub fn new() -> Self {
        SpherePack {
            centre_x: Vec4::ZERO,
            centre_y: Vec4::ZERO,
            centre_z: Vec4::ZERO,
            radius_squared: Vec4::NEG_INFINITY,
            len: 0,
        }
    }

    /// How many lanes hold a sphere.
    pub fn len(&self) -> usize {
        self.len
    }

    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    pub fn is_full(&self) -> bool {
        self.len == Self::LANES
    }

    /// Put `sphere` in the next free lane.
    ///
    /// # Panics
    /// If the pack is full.
    pub fn push(&mut self, sphere: &Sphere) {
        assert!(!self.is_full(), "a sphere pack holds four spheres");
        let lane = self.len;
        self.centre_x[lane] = sphere.centre.x;
        self.centre_y[lane] = sphere.centre.y;
        self.centre_z[lane] = sphere.centre.z;
        self.radius_squared[lane] = sphere.radius * sphere.radius;
        self.len += 1;
    }

    /// For each lane, the distance at which the ray hits that sphere, as
    /// [`Sphere::intersect`] gives it, with `f32::INFINITY` for a miss.
    pub fn distances(&self, ray: &Ray) -> Vec4 {
        let (hit, t) = self.hits(ray);
        Vec4::select(hit, t, Vec4::INFINITY)
    }

    /// Whether the ray hits any sphere of the pack.
    pub fn any_hit(&self, ray: &Ray) -> bool {
        self.hits(ray).0.any()
    }

    /// Which lanes the ray hits, and at what distance (meaningless where it
    /// misses).
    fn hits(&self, ray: &Ray) -> (BVec4A, Vec4) {
        let (o, d) = (ray.origin, ray.direction);
        let oc_x = Vec4::splat(o.x) - self.centre_x;
        let oc_y = Vec4::splat(o.y) - self.centre_y;
        let oc_z = Vec4::splat(o.z) - self.centre_z;
        // The same sums as `Vec3::dot`, term by term, left to right.
        let b = oc_x * d.x + oc_y * d.y + oc_z * d.z;
        let q = (oc_x * oc_x + oc_y * oc_y + oc_z * oc_z) - self.radius_squared;
        let disc = b * b - q;
        let root = disc.sqrt(); // NaN in lanes that miss; masked below
        let t0 = -b - root;
        let t1 = -b + root;
        let zero = Vec4::ZERO;
        let t = Vec4::select(t0.cmpgt(zero), t0, t1);
        (disc.cmpge(zero) & t.cmpgt(zero), t)
    }
}

impl Default for SpherePack {
    fn default() -> Self {
        Self::new()
    }
}

/// Spheres in packs of four, in the order they were added.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SpherePacks(Vec<SpherePack>);

impl SpherePacks {
    pub fn push(&mut self, sphere: &Sphere) {
        match self.0.last_mut() {
            Some(pack) if !pack.is_full() => pack.push(sphere),
            _ => {
                let mut pack = SpherePack::new();
                pack.push(sphere);
                self.0.push(pack);
            }
        }
    }

    /// The nearest sphere hit closer than `limit`, and its distance: the
    /// earlier sphere wins a tie, as in a loop over the spheres in order.
    pub fn nearest(&self, ray: &Ray, limit: f32) -> Option<(usize, f32)> {
        let mut nearest = None;
        let mut limit = limit;
        for (p, pack) in self.0.iter().enumerate() {
            let t = pack.distances(ray);
            let best = t.min_element();
            if best < limit {
                // The first lane at that distance: the earlier sphere wins a tie.
                let lane = t.cmpeq(Vec4::splat(best)).bitmask().trailing_zeros() as usize;
                limit = best;
                nearest = Some((p * SpherePack::LANES + lane, best));
            }
        }
        nearest
    }

    /// Whether the ray hits any sphere at all.
    pub fn any(&self, ray: &Ray) -> bool {
        self.0.iter().any(|pack| pack.any_hit(ray))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Vec3;
    use proptest::prelude::*;

    fn sphere(x: f32, y: f32, z: f32, radius: f32) -> Sphere {
        Sphere {
            centre: Vec3::new(x, y, z),
            radius,
        }
    }

    /// What the scene did before it had packs: each sphere in turn, a
    /// strictly nearer hit replacing the best so far.
    fn nearest_one_by_one(spheres: &[Sphere], ray: &Ray, limit: f32) -> Option<(usize, f32)> {
        let mut nearest = None;
        let mut limit = limit;
        for (i, s) in spheres.iter().enumerate() {
            if let Some(t) = s.intersect(ray)
                && t < limit
            {
                (limit, nearest) = (t, Some((i, t)));
            }
        }
        nearest
    }

    fn packed(spheres: &[Sphere]) -> SpherePacks {
        let mut packs = SpherePacks::default();
        for s in spheres {
            packs.push(s);
        }
        packs
    }

    #[test]
    fn five_spheres_fill_one_pack_and_one_lane_of_the_next() {
        let spheres = [sphere(0.0, 0.0, 0.0, 1.0); 5];
        let packs = packed(&spheres);
        assert_eq!(packs.0.len(), 2);
        assert!(packs.0[0].is_full());
        assert_eq!(packs.0[1].len(), 1);
    }

    #[test]
    fn free_lanes_are_never_hit() {
        // One sphere far away; the free lanes' zero centres lie on the ray.
        let pack = packed(&[sphere(10.0, 10.0, 10.0, 1.0)]).0[0];
        let ray = Ray::new(Vec3::new(0.0, 0.0, -5.0), Vec3::Z);
        assert_eq!(pack.distances(&ray), Vec4::INFINITY);
        assert!(!pack.any_hit(&ray));
    }

    #[test]
    fn a_ray_through_two_spheres_reports_both_distances() {
        // From z = 5 towards -z through unit spheres at z = 0 and z = -3.
        let pack = packed(&[sphere(0.0, 0.0, 0.0, 1.0), sphere(0.0, 0.0, -3.0, 1.0)]).0[0];
        let ray = Ray::new(Vec3::new(0.0, 0.0, 5.0), Vec3::NEG_Z);
        let t = pack.distances(&ray);
        assert_eq!(
            (t.x, t.y, t.z, t.w),
            (4.0, 7.0, f32::INFINITY, f32::INFINITY)
        );
        let nearest = packed(&[sphere(0.0, 0.0, -3.0, 1.0), sphere(0.0, 0.0, 0.0, 1.0)])
            .nearest(&ray, f32::INFINITY);
        assert_eq!(nearest, Some((1, 4.0)));
    }

    #[test]
    fn a_tie_goes_to_the_earlier_sphere_in_a_pack_and_across_packs() {
        let ray = Ray::new(Vec3::new(0.0, 0.0, 5.0), Vec3::NEG_Z);
        let same = sphere(0.0, 0.0, 0.0, 1.0);
        let far = sphere(0.0, 0.0, -10.0, 1.0);
        // Lanes 1 and 2 of the first pack.
        assert_eq!(
            packed(&[far, same, same, far]).nearest(&ray, f32::INFINITY),
            Some((1, 4.0))
        );
        // Lane 3 of the first pack and lane 0 of the second.
        assert_eq!(
            packed(&[far, far, far, same, same]).nearest(&ray, f32::INFINITY),
            Some((3, 4.0))
        );
    }

    #[test]
    fn only_a_strictly_nearer_sphere_beats_the_limit() {
        // The ground, say, was hit at exactly the sphere's distance: it stays.
        let ray = Ray::new(Vec3::new(0.0, 0.0, 5.0), Vec3::NEG_Z);
        let packs = packed(&[sphere(0.0, 0.0, 0.0, 1.0)]);
        assert_eq!(packs.nearest(&ray, 4.0), None);
        assert_eq!(packs.nearest(&ray, 4.5), Some((0, 4.0)));
    }

    fn coordinate() -> impl Strategy<Value = f32> {
        -8.0f32..8.0
    }

    fn any_sphere() -> impl Strategy<Value = Sphere> {
        (coordinate(), coordinate(), coordinate(), 0.01f32..4.0)
            .prop_map(|(x, y, z, r)| sphere(x, y, z, r))
    }

    fn any_ray() -> impl Strategy<Value = Ray> {
        let point = (coordinate(), coordinate(), coordinate());
        let direction = (-1.0f32..1.0, -1.0f32..1.0, -1.0f32..1.0)
            .prop_filter("a direction", |&(x, y, z)| x * x + y * y + z * z > 1e-4);
        (point, direction).prop_map(|((x, y, z), (dx, dy, dz))| {
            Ray::new(Vec3::new(x, y, z), Vec3::new(dx, dy, dz).normalize())
        })
    }

    proptest! {
        #[test]
        fn every_lane_gives_sphere_intersect_to_the_last_bit(
            spheres in prop::collection::vec(any_sphere(), 1..=4),
            ray in any_ray(),
        ) {
            let pack = packed(&spheres).0[0];
            let t = pack.distances(&ray).to_array();
            for (lane, s) in spheres.iter().enumerate() {
                let expected = s.intersect(&ray).unwrap_or(f32::INFINITY);
                prop_assert_eq!(t[lane].to_bits(), expected.to_bits(), "lane {}", lane);
            }
        }

        #[test]
        fn packs_answer_as_the_one_by_one_loop_does(
            spheres in prop::collection::vec(any_sphere(), 1..=9),
            ray in any_ray(),
            limit in prop_oneof![Just(f32::INFINITY), 0.0f32..20.0],
        ) {
            let packs = packed(&spheres);
            prop_assert_eq!(packs.nearest(&ray, limit), nearest_one_by_one(&spheres, &ray, limit));
            let any = spheres.iter().any(|s| s.intersect(&ray).is_some());
            prop_assert_eq!(packs.any(&ray), any);
        }
    }
}
