//! Eight rays against the ground and every sphere at once.
//!
//! The scalar tracer asks "does this ray hit this sphere?" and branches on
//! the answer. Eight lanes cannot all take the same branch, so every lane
//! computes everything, and a *mask* (a lane of all ones or all zeros)
//! records which lanes' answers count. `blend` then keeps, lane by lane,
//! the new answer where the mask is set and the old one elsewhere.

use std::f32::consts::PI;

use raylab::{Scene, Vec3};
use wide::{CmpEq, CmpGe, CmpGt, CmpLt, CmpNe, f32x8};

use crate::like::Features;
use crate::soa::Vec3x8;
use raylab::lanes::{plane_hits, sphere_hits};

/// Object numbers in a lane: nothing hit, the ground, sphere `k` is `k + 1`.
pub const NOTHING: f32 = -1.0;
pub const GROUND: f32 = 0.0;

/// A sphere and its material, each number in all eight lanes.
#[derive(Clone, Copy, Debug)]
struct SphereX8 {
    centre: Vec3x8,
    radius_squared: f32x8,
    albedo: Vec3x8,
    /// `albedo / π`, divided once here as the scalar code divides it per hit.
    albedo_over_pi: Vec3x8,
    reflection: f32x8,
    transmission: f32x8,
    ior: f32x8,
}

/// The scene as the eight-lane tracer reads it, made once per image.
#[derive(Clone, Debug)]
pub struct SceneX8 {
    plane_point: Vec3x8,
    plane_normal: Vec3,
    /// The checker's colours, and each divided by π.
    checker_even: (Vec3x8, Vec3x8),
    checker_odd: (Vec3x8, Vec3x8),
    spheres: Vec<SphereX8>,
}

/// What eight rays hit, lane by lane.
#[derive(Clone, Copy, Debug)]
pub struct Hits {
    pub t: f32x8,
    /// [`NOTHING`], [`GROUND`] or a sphere's number plus one.
    pub object: f32x8,
    /// Set in lanes whose ray hit something.
    pub hit: f32x8,
}

/// Everything the shading needs about eight hits (LAB.md's hit record).
#[derive(Clone, Copy, Debug)]
pub struct Surfaces {
    pub point: Vec3x8,
    pub normal: Vec3x8,
    pub facing_normal: Vec3x8,
    /// Set where the ray arrives from outside (`dot(d, n) < 0`).
    pub entering: f32x8,
    pub albedo: Vec3x8,
    pub albedo_over_pi: Vec3x8,
    /// The shares the chapter's features let through (0 when switched off).
    pub reflection: f32x8,
    pub transmission: f32x8,
    pub ior: f32x8,
}

impl SceneX8 {
    /// The scene's numbers splatted across the lanes; the reflection and
    /// transmission of a feature the chapter has not switched on are 0.
    pub fn new(scene: &Scene, features: Features) -> Self {
        let spheres = scene
            .spheres()
            .iter()
            .map(|s| {
                let m = &s.material;
                let on = |enabled: bool, share: f32| if enabled { share } else { 0.0 };
                SphereX8 {
                    centre: Vec3x8::splat(s.shape.centre),
                    radius_squared: f32x8::splat(s.shape.radius * s.shape.radius),
                    albedo: Vec3x8::splat(m.albedo()),
                    albedo_over_pi: Vec3x8::splat(m.albedo() / PI),
                    reflection: f32x8::splat(on(features.reflection, m.reflection())),
                    transmission: f32x8::splat(on(features.transmission, m.transmission())),
                    ior: f32x8::splat(m.ior()),
                }
            })
            .collect();
        SceneX8 {
            plane_point: Vec3x8::splat(scene.ground.plane.point),
            plane_normal: scene.ground.plane.normal,
            checker_even: with_over_pi(scene.ground.checker.even),
            checker_odd: with_over_pi(scene.ground.checker.odd),
            spheres,
        }
    }

    /// The plane's `t` in every lane, and a mask of the lanes it counts in.
    fn plane(&self, o: Vec3x8, d: Vec3x8) -> (f32x8, f32x8) {
        plane_hits(self.plane_point, Vec3x8::splat(self.plane_normal), o, d)
    }

    /// A sphere's nearest `t > 0` in every lane, and the lanes that hit it.
    fn sphere(s: &SphereX8, o: Vec3x8, d: Vec3x8) -> (f32x8, f32x8) {
        sphere_hits(s.centre, s.radius_squared, o, d)
    }

    // ANCHOR: nearest
    /// The nearest hit of eight rays: the plane, then every sphere in
    /// order, a strictly nearer hit replacing the best so far (ties go to
    /// the earlier object, as in `Scene::nearest_hit`).
    pub fn nearest(&self, o: Vec3x8, d: Vec3x8) -> Hits {
        let (t_plane, on_plane) = self.plane(o, d);
        let mut t = on_plane.blend(t_plane, f32x8::splat(f32::INFINITY));
        let mut object = on_plane.blend(f32x8::splat(GROUND), f32x8::splat(NOTHING));
        for (k, sphere) in self.spheres.iter().enumerate() {
            let (t_sphere, hit) = SceneX8::sphere(sphere, o, d);
            // Mask: this sphere is hit, and nearer than what each lane has.
            let nearer = hit & t_sphere.cmp_lt(t);
            t = nearer.blend(t_sphere, t);
            object = nearer.blend(f32x8::splat(k as f32 + 1.0), object);
        }
        let hit = object.cmp_ne(f32x8::splat(NOTHING));
        Hits { t, object, hit }
    }
    // ANCHOR_END: nearest

    /// Whether each of eight shadow rays meets anything at all, in the
    /// lanes of `asked` (the others' answers may be wrong).
    pub fn any(&self, o: Vec3x8, d: Vec3x8, asked: f32x8) -> f32x8 {
        let mut blocked = self.plane(o, d).1;
        for sphere in &self.spheres {
            if (blocked | !asked).all() {
                break; // every lane asked about is in shadow already
            }
            blocked |= SceneX8::sphere(sphere, o, d).1;
        }
        blocked
    }

    /// The hit record of eight hits. Lanes that hit nothing get numbers
    /// too; their `hit` mask is clear and the caller ignores them.
    pub fn surfaces(&self, o: Vec3x8, d: Vec3x8, hits: &Hits) -> Surfaces {
        let point = o + d.scale(hits.t);
        let on_ground = hits.object.cmp_eq(f32x8::splat(GROUND));
        let mut centre = Vec3x8::splat(Vec3::ZERO);
        // Divergence: groups with no lane on the ground skip the checker.
        let (mut albedo, mut albedo_over_pi) = if on_ground.any() {
            self.checker(point)
        } else {
            (Vec3x8::ZERO, Vec3x8::ZERO)
        };
        let (mut reflection, mut transmission, mut ior) = (f32x8::ZERO, f32x8::ZERO, f32x8::ONE);
        // Each lane picks its own sphere's numbers: one blend per sphere,
        // where a scalar tracer would index an array.
        for (k, s) in self.spheres.iter().enumerate() {
            let mine = hits.object.cmp_eq(f32x8::splat(k as f32 + 1.0));
            // Divergence: most groups hit one or two of the objects; the
            // spheres that no lane hit have nothing to hand over.
            if mine.none() {
                continue;
            }
            centre = Vec3x8::select(mine, s.centre, centre);
            albedo = Vec3x8::select(mine, s.albedo, albedo);
            albedo_over_pi = Vec3x8::select(mine, s.albedo_over_pi, albedo_over_pi);
            reflection = mine.blend(s.reflection, reflection);
            transmission = mine.blend(s.transmission, transmission);
            ior = mine.blend(s.ior, ior);
        }
        let ground_normal = Vec3x8::splat(self.plane_normal);
        // Divergence: a group whose hits are all on the ground (or nowhere)
        // has no sphere normal to normalise, and skips the division.
        let normal = if (hits.hit & !on_ground).none() {
            ground_normal
        } else {
            let sphere_normal = (point - centre).normalize();
            Vec3x8::select(on_ground, ground_normal, sphere_normal)
        };
        let entering = d.dot(normal).cmp_lt(f32x8::ZERO);
        let facing_normal = Vec3x8::select(entering, normal, -normal);
        Surfaces {
            point,
            normal,
            facing_normal,
            entering,
            albedo,
            albedo_over_pi,
            reflection,
            transmission,
            ior,
        }
    }

    // ANCHOR: checker
    /// The ground's checker colour at eight points, as `Checker::albedo_at`
    /// decides it: the parity of `floor(x) + floor(z)` as an `i64`. With
    /// it, the colour divided by π.
    fn checker(&self, p: Vec3x8) -> (Vec3x8, Vec3x8) {
        let s = p.x.floor() + p.z.floor();
        // `s` is a whole number. Below 2^24 halving it is exact, and it is
        // odd where the half is not whole; above, every f32 is even. Two
        // masks copy what the scalar `as i64` does at the edges: NaN
        // becomes 0 (even), and 2^63 or more saturates to i64::MAX (odd).
        let half = s * f32x8::splat(0.5);
        let not_nan = s.cmp_eq(s);
        let saturated = s.cmp_ge(f32x8::splat(9.223_372e18));
        let odd = (half.floor().cmp_ne(half) & not_nan) | saturated;
        let (even, odd_colour) = (self.checker_even, self.checker_odd);
        (
            Vec3x8::select(odd, odd_colour.0, even.0),
            Vec3x8::select(odd, odd_colour.1, even.1),
        )
    }
    // ANCHOR_END: checker
}

fn with_over_pi(colour: Vec3) -> (Vec3x8, Vec3x8) {
    (Vec3x8::splat(colour), Vec3x8::splat(colour / PI))
}

/// Which lanes of eight rays send on a reflected and a transmitted ray.
pub fn senders(surfaces: &Surfaces, hits: &Hits, features: Features) -> (f32x8, f32x8) {
    let zero = f32x8::ZERO;
    let reflects = if features.reflection {
        hits.hit & surfaces.reflection.cmp_gt(zero)
    } else {
        zero
    };
    let transmits = if features.transmission {
        hits.hit & surfaces.transmission.cmp_gt(zero)
    } else {
        zero
    };
    (reflects, transmits)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::like::Like;
    use raylab::scene::Object;
    use raylab::{Camera, Ray};

    /// Eight camera rays of a small image, as lanes and as scalar rays.
    fn eight_rays(j: u32) -> (Vec3x8, Vec3x8, Vec<Ray>) {
        let camera = Camera::lab();
        let rays: Vec<Ray> = (0..8)
            .map(|i| camera.ray(i * 5 + 2, j, (0.5, 0.5), 40, 30))
            .collect();
        let lanes = |f: fn(&Ray) -> Vec3| {
            let v: Vec<Vec3> = rays.iter().map(f).collect();
            Vec3x8 {
                x: f32x8::from(std::array::from_fn::<f32, 8, _>(|i| v[i].x)),
                y: f32x8::from(std::array::from_fn::<f32, 8, _>(|i| v[i].y)),
                z: f32x8::from(std::array::from_fn::<f32, 8, _>(|i| v[i].z)),
            }
        };
        (lanes(|r| r.origin), lanes(|r| r.direction), rays)
    }

    #[test]
    fn eight_rays_hit_what_the_scalar_scene_says_at_the_same_distance() {
        let scene = Scene::lab();
        let wide = SceneX8::new(&scene, Like::AntiAliasing.features());
        for j in 0..30 {
            let (o, d, rays) = eight_rays(j);
            let hits = wide.nearest(o, d);
            let surfaces = wide.surfaces(o, d, &hits);
            for (lane, ray) in rays.iter().enumerate() {
                let object = hits.object.as_array_ref()[lane];
                match scene.nearest_hit(ray) {
                    None => assert_eq!(object, NOTHING),
                    Some(hit) => {
                        let expected = match hit.object {
                            Object::Ground => GROUND,
                            Object::Sphere(k) => k as f32 + 1.0,
                        };
                        assert_eq!(object, expected);
                        assert_eq!(hits.t.as_array_ref()[lane], hit.t);
                        assert_eq!(surfaces.point.lane(lane), hit.point);
                        assert_eq!(surfaces.facing_normal.lane(lane), hit.facing_normal);
                        assert_eq!(surfaces.albedo.lane(lane), hit.material.albedo());
                    }
                }
            }
        }
    }

    #[test]
    fn a_shadow_ray_is_blocked_in_exactly_the_lanes_the_scalar_scene_says() {
        let scene = Scene::lab();
        let wide = SceneX8::new(&scene, Like::AntiAliasing.features());
        for j in 0..30 {
            let (o, d, rays) = eight_rays(j);
            let blocked = wide.any(o, d, raylab::lanes::mask_from_bits(0xff));
            for (lane, ray) in rays.iter().enumerate() {
                let lane_blocked = blocked.as_array_ref()[lane] != 0.0;
                assert_eq!(lane_blocked, scene.any_hit(ray), "row {j}, lane {lane}");
            }
        }
    }

    #[test]
    fn a_shadow_test_answers_every_lane_it_is_asked_about() {
        // Every mask of asked lanes that leaves some out: the lanes asked
        // get the scalar answer, whatever the others' rays meet.
        let scene = Scene::lab();
        let wide = SceneX8::new(&scene, Like::AntiAliasing.features());
        for j in (0..30).step_by(3) {
            let (o, d, rays) = eight_rays(j);
            for asked in (1..0xffu32).step_by(7) {
                let blocked = wide.any(o, d, raylab::lanes::mask_from_bits(asked));
                for lane in raylab::lanes::lanes_of(asked) {
                    let lane_blocked = blocked.as_array_ref()[lane] != 0.0;
                    assert_eq!(
                        lane_blocked,
                        scene.any_hit(&rays[lane]),
                        "row {j}, lane {lane}"
                    );
                }
            }
        }
    }

    #[test]
    fn the_checker_parity_matches_the_scalar_one_far_out_and_at_nan() {
        let scene = Scene::lab();
        let wide = SceneX8::new(&scene, Like::AntiAliasing.features());
        let xs = [
            -0.5,
            0.5,
            -3.5,
            1.0e7 + 1.0,
            3.0e9,
            1.0e19,
            f32::NAN,
            f32::INFINITY,
        ];
        let p = Vec3x8 {
            x: f32x8::from(xs),
            y: f32x8::ZERO,
            z: f32x8::splat(0.25),
        };
        let (albedo, _) = wide.checker(p);
        for (lane, &x) in xs.iter().enumerate() {
            let expected = scene.ground.checker.albedo_at(Vec3::new(x, 0.0, 0.25));
            assert_eq!(albedo.lane(lane), expected, "x = {x}");
        }
    }
}
