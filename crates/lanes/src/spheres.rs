//! One ray against eight spheres at once.
//!
//! [`SceneX8`](crate::scene::SceneX8) puts eight *rays* in the lanes of an
//! `f32x8` and tests them against one sphere at a time. A tracer that
//! follows one ray at a time can use the transpose: the *spheres* go in the
//! lanes, eight to a group, and one ray meets a whole group in a handful of
//! instructions instead of a loop with a branch per sphere. The ground is a single object and is
//! tested the scalar way, first, as `Scene::nearest_hit` tests it.
//!
//! Every lane computes everything, and a *mask* (a lane of all ones or all
//! zeros) records which lanes' answers count. The arithmetic is the scalar
//! `Sphere::intersect`'s, operation for operation and in the same order, so
//! every `t` is the same to the bit and so is every image.

use raylab::scene::{Object, SceneQuery};
use raylab::{Hit, Ray, Scene};
use wide::{CmpGt, CmpLt, f32x8};

use crate::vec3x8::negate;

/// Up to eight spheres, one per lane: their centres and squared radii.
#[derive(Clone, Copy, Debug)]
struct Group {
    x: f32x8,
    y: f32x8,
    z: f32x8,
    radius_squared: f32x8,
}

/// A scene's spheres in groups of eight, made once per image, with the
/// scene itself for the ground and the hit record.
#[derive(Clone, Debug)]
pub struct SpheresX8 {
    /// A copy of the scene (a few hundred bytes for the lab's), for the
    /// ground and the hit record: the lanes then borrow nothing, and a
    /// tracer may hold them for as long as it likes.
    scene: Scene,
    groups: Vec<Group>,
}

impl SpheresX8 {
    /// The spheres of `scene`, in order: sphere `8g + l` is lane `l` of
    /// group `g`. A last group that is not full is padded with spheres of
    /// squared radius −∞: their `q` is +∞ and their discriminant −∞, so no
    /// ray ever meets one.
    pub fn new(scene: &Scene) -> Self {
        let groups = scene
            .spheres()
            .chunks(8)
            .map(|chunk| {
                let lane = |f: &dyn Fn(usize) -> f32, pad: f32| {
                    f32x8::from(std::array::from_fn(|l| {
                        if l < chunk.len() { f(l) } else { pad }
                    }))
                };
                Group {
                    x: lane(&|l| chunk[l].shape.centre.x, 0.0),
                    y: lane(&|l| chunk[l].shape.centre.y, 0.0),
                    z: lane(&|l| chunk[l].shape.centre.z, 0.0),
                    radius_squared: lane(
                        &|l| chunk[l].shape.radius * chunk[l].shape.radius,
                        f32::NEG_INFINITY,
                    ),
                }
            })
            .collect();
        SpheresX8 {
            scene: scene.clone(),
            groups,
        }
    }

    // ANCHOR: group
    /// Where the ray meets each sphere of a group (its nearest `t > 0`),
    /// and a mask of the lanes whose sphere it meets at all.
    #[inline]
    fn group(g: &Group, ray: &Ray) -> (f32x8, f32x8) {
        let (o, d) = (ray.origin, ray.direction);
        let ocx = f32x8::splat(o.x) - g.x;
        let ocy = f32x8::splat(o.y) - g.y;
        let ocz = f32x8::splat(o.z) - g.z;
        let (dx, dy, dz) = (f32x8::splat(d.x), f32x8::splat(d.y), f32x8::splat(d.z));
        let b = ocx * dx + ocy * dy + ocz * dz;
        let q = (ocx * ocx + ocy * ocy + ocz * ocz) - g.radius_squared;
        let disc = b * b - q;
        // Mask 1: the line meets the sphere. A lane that misses takes the
        // square root of a negative number below (NaN); this mask keeps
        // that NaN from counting.
        let meets = !disc.cmp_lt(f32x8::ZERO);
        let root = disc.sqrt();
        let minus_b = negate(b);
        let t0 = minus_b - root; // where the ray enters
        let t1 = minus_b + root; // where it leaves
        // Mask 2: the entry is in front of the origin, so `t0` counts;
        // elsewhere the origin is inside the sphere (or past it) and the
        // exit `t1` is the candidate.
        let front = t0.cmp_gt(f32x8::ZERO);
        // Mask 3: the sphere is not behind the ray. `t1 ≥ t0` (rounding
        // keeps the order), so `t1 > 0` holds wherever `t0 > 0` does.
        let ahead = t1.cmp_gt(f32x8::ZERO);
        (front.blend(t0, t1), meets & ahead)
    }
    // ANCHOR_END: group
}

impl SceneQuery for SpheresX8 {
    // ANCHOR: nearest_hit
    /// The first surface the ray meets, or `None` if it escapes to the
    /// sky: the same answer as [`Scene::nearest_hit`], with the same rule
    /// for ties (the ground first, then the spheres in order, and only a
    /// strictly nearer hit replaces the best so far).
    #[inline]
    fn nearest_hit(&self, ray: &Ray) -> Option<Hit> {
        let mut nearest = f32::INFINITY;
        let mut object = None;
        if let Some(t) = self.scene.ground.plane.intersect(ray) {
            (nearest, object) = (t, Some(Object::Ground));
        }
        for (g, group) in self.groups.iter().enumerate() {
            let (t, hit) = SpheresX8::group(group, ray);
            // Mask 4: the lanes hit and nearer than the best so far. Most
            // rays meet one sphere of a group or none, so the lanes are
            // looked at one by one only where this is set.
            let mut nearer = (hit & t.cmp_lt(f32x8::splat(nearest))).move_mask();
            if nearer == 0 {
                continue;
            }
            let t = t.to_array();
            // Lowest lane first, so that on a tie the earlier sphere wins.
            while nearer != 0 {
                let lane = nearer.trailing_zeros() as usize;
                nearer &= nearer - 1;
                if t[lane] < nearest {
                    (nearest, object) = (t[lane], Some(Object::Sphere(8 * g + lane)));
                }
            }
        }
        object.map(|object| self.scene.hit_record(ray, nearest, object))
    }
    // ANCHOR_END: nearest_hit

    /// Whether the ray meets any surface at all (the shadow-ray query): the
    /// same answer as [`Scene::any_hit`], stopping at the first group hit.
    #[inline]
    fn any_hit(&self, ray: &Ray) -> bool {
        self.scene.ground.plane.intersect(ray).is_some()
            || self
                .groups
                .iter()
                .any(|group| SpheresX8::group(group, ray).1.any())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use raylab::sampling::{Stream, sample_rng, unit_f32};
    use raylab::sphere::Sphere;
    use raylab::{Material, Vec3};

    /// Random rays from around and inside the scene: origins in a box
    /// that holds every sphere (some inside one), directions anywhere.
    fn random_rays(count: usize) -> Vec<Ray> {
        let mut rng = sample_rng(11, (0, 0), 0, Stream::Path);
        let mut uniform = |lo: f32, hi: f32| lo + (hi - lo) * unit_f32(&mut rng);
        (0..count)
            .map(|_| {
                let origin = Vec3::new(uniform(-4.0, 4.0), uniform(-0.5, 3.0), uniform(-4.0, 4.0));
                let direction = loop {
                    let v = Vec3::new(uniform(-1.0, 1.0), uniform(-1.0, 1.0), uniform(-1.0, 1.0));
                    if (0.01..1.0).contains(&v.length_squared()) {
                        break v.normalize();
                    }
                };
                Ray::new(origin, direction)
            })
            .collect()
    }

    /// The lab scene with `extra` more small spheres in a row behind it,
    /// and a copy of its first sphere last, which can only tie with it.
    fn crowded(extra: usize) -> Scene {
        let mut scene = Scene::lab();
        let material = Material::diffuse(Vec3::splat(0.5)).unwrap();
        for k in 0..extra {
            let shape = Sphere {
                centre: Vec3::new(-3.0 + 0.7 * k as f32, 0.3, 2.5 - 0.4 * k as f32),
                radius: 0.3,
            };
            scene
                .add_sphere(&format!("ball {k}"), shape, material)
                .unwrap();
        }
        let first = scene.spheres()[0].shape;
        scene.add_sphere("mirror's twin", first, material).unwrap();
        scene
    }

    fn assert_same_answers(scene: &Scene, rays: &[Ray]) -> usize {
        let lanes = SpheresX8::new(scene);
        let mut sphere_hits = 0;
        for ray in rays {
            let (scalar, simd) = (scene.nearest_hit(ray), lanes.nearest_hit(ray));
            // Bit for bit: the lanes do the scalar arithmetic in its order.
            assert_eq!(scalar, simd, "nearest hit of {ray:?}");
            assert_eq!(scene.any_hit(ray), lanes.any_hit(ray), "any hit of {ray:?}");
            sphere_hits += usize::from(matches!(scalar.map(|h| h.object), Some(Object::Sphere(_))));
        }
        sphere_hits
    }

    #[test]
    fn the_lanes_give_the_scalar_hits_of_the_lab_scene_to_the_bit() {
        let scene = Scene::lab();
        let rays = random_rays(50_000);
        let sphere_hits = assert_same_answers(&scene, &rays);
        // The rays are a real test: about one in ten meets a sphere.
        assert!(sphere_hits > 4_000, "only {sphere_hits} rays hit a sphere");
    }

    #[test]
    fn the_lanes_give_the_scalar_hits_of_a_scene_with_two_groups_of_spheres() {
        // 5 + 6 + 1 = 12 spheres: a full group of eight and a padded one.
        let scene = crowded(6);
        assert_eq!(scene.spheres().len(), 12);
        let rays = random_rays(50_000);
        let sphere_hits = assert_same_answers(&scene, &rays);
        assert!(sphere_hits > 4_000, "only {sphere_hits} rays hit a sphere");
        // Through the mirror and its twin: a tie, which the earlier sphere
        // (lane 0 of group 0, against lane 3 of group 1) wins.
        let centre = scene.spheres()[0].shape.centre;
        let ray = Ray::new(centre + Vec3::new(0.0, 0.0, 3.0), Vec3::NEG_Z);
        let hit = SpheresX8::new(&scene).nearest_hit(&ray).unwrap();
        assert_eq!(hit.object, Object::Sphere(0));
        assert_eq!(hit, scene.nearest_hit(&ray).unwrap());
    }

    #[test]
    fn a_ray_from_inside_a_sphere_hits_its_far_side_in_the_lanes_too() {
        let scene = Scene::lab();
        let lanes = SpheresX8::new(&scene);
        // From the glass sphere's centre: out through its far side at t = r.
        let glass = scene.spheres()[1].shape;
        let hit = lanes.nearest_hit(&Ray::new(glass.centre, Vec3::X)).unwrap();
        assert_eq!(hit.object, Object::Sphere(1));
        assert_eq!(hit.t, 0.6);
        assert!(!hit.entering);
        assert!(lanes.any_hit(&Ray::new(glass.centre, Vec3::Y)));
    }

    #[test]
    fn a_ray_parallel_to_the_ground_meets_only_the_spheres_in_its_way() {
        let scene = Scene::lab();
        let lanes = SpheresX8::new(&scene);
        // At the red sphere's centre height, towards it from the front:
        // the sphere at t = 4 - 1 = 3, the ground never.
        let ray = Ray::new(Vec3::new(0.0, 1.0, 2.5), Vec3::NEG_Z);
        let hit = lanes.nearest_hit(&ray).unwrap();
        assert_eq!(scene.object_name(hit.object), "red");
        assert_eq!(hit.t, 3.0);
        assert_eq!(Some(hit), scene.nearest_hit(&ray));
        // High above everything: it escapes.
        let over = Ray::new(Vec3::new(0.0, 5.0, 2.5), Vec3::NEG_Z);
        assert_eq!(lanes.nearest_hit(&over), None);
        assert!(!lanes.any_hit(&over));
    }

    #[test]
    fn padded_lanes_are_never_hit() {
        // One sphere: seven lanes of padding, and rays through the origin,
        // where the padding's centres sit.
        let lab = Scene::lab();
        let mut scene = Scene::new(lab.ground, lab.sky, lab.sun).unwrap();
        let red = &lab.spheres()[2];
        scene
            .add_sphere(&red.name, red.shape, red.material)
            .unwrap();
        let lanes = SpheresX8::new(&scene);
        for d in [
            Vec3::X,
            Vec3::NEG_X,
            Vec3::Z,
            Vec3::new(1.0, 0.0, 1.0).normalize(),
        ] {
            let ray = Ray::new(-5.0 * d, d);
            assert_eq!(lanes.nearest_hit(&ray), scene.nearest_hit(&ray));
            assert_eq!(lanes.any_hit(&ray), scene.any_hit(&ray));
        }
        assert_same_answers(&scene, &random_rays(5_000));
    }
}
