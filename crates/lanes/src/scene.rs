//! The scene as eight rays see it: the ground and every sphere against
//! eight rays at once, and the hit records of eight hits.
//!
//! The scalar tracer asks "does this ray hit this sphere?" and branches on
//! the answer. Eight lanes cannot all take the same branch, so every lane
//! computes everything, and a *mask* (a lane of all ones or all zeros)
//! records which lanes' answers count. `blend` then keeps, lane by lane,
//! the new answer where the mask is set and the old one elsewhere. The
//! arithmetic is the scalar code's, operation for operation, so every `t`,
//! point and normal is the same to the bit.

use std::f32::consts::PI;

use raylab::scene::{Object, SceneQuery};
use raylab::{Hit, Ray, Scene, Vec3};
use wide::{CmpEq, CmpGe, CmpLt, CmpNe, f32x8};

use crate::shapes::{plane_hits, sphere_hits};
use crate::vec3x8::Vec3x8;

/// The object number of a lane whose ray hit nothing (sphere `k` is `k + 1`).
pub const NOTHING: f32 = -1.0;
/// The object number of a lane whose ray hit the ground.
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
    /// Set in every lane if the material has a mirror or a glass share
    /// (`r + t > 0`), which a path tracer chooses between.
    chooses: f32x8,
}

/// The scene as the eight-lane tracers read it, made once per image.
#[derive(Clone, Debug)]
pub struct SceneX8<'s> {
    scene: &'s Scene,
    plane_point: Vec3x8,
    plane_normal: Vec3x8,
    /// The checker's colours, and each divided by π.
    checker_even: (Vec3x8, Vec3x8),
    checker_odd: (Vec3x8, Vec3x8),
    spheres: Vec<SphereX8>,
    /// Where the rays' hits are found, if not by testing every sphere in
    /// turn ([`SceneX8::with_query`]).
    query: Option<&'s dyn SceneQueryX8>,
}

// ANCHOR: query
/// Another way for eight rays to find what [`SceneX8::nearest_in_list`]
/// and [`SceneX8::any_in_list`] find, lane for lane and to the bit:
/// chapter 9's tree of boxes. It answers one ray's questions too (a
/// [`SceneQuery`]), for the rare ray a tracer follows alone.
pub trait SceneQueryX8: SceneQuery + std::fmt::Debug {
    /// The nearest hit of eight rays, as [`SceneX8::nearest_in_list`].
    fn nearest(&self, o: Vec3x8, d: Vec3x8) -> Hits;
    /// Whether eight shadow rays are blocked, in the lanes of `asked`, as
    /// [`SceneX8::any_in_list`].
    fn any(&self, o: Vec3x8, d: Vec3x8, asked: f32x8) -> f32x8;
}
// ANCHOR_END: query

/// What eight rays hit, lane by lane.
#[derive(Clone, Copy, Debug)]
pub struct Hits {
    /// The distance along each ray to its hit (unread where there is none).
    pub t: f32x8,
    /// [`NOTHING`], [`GROUND`] or a sphere's number plus one.
    pub object: f32x8,
    /// Set where the ray has a nearest hit (`Scene::nearest_hit` is `Some`).
    pub hit: f32x8,
    /// Set where the ray meets anything at all (`Scene::any_hit`).
    pub any: f32x8,
}

impl Hits {
    /// The result of a nearest-hit search: each lane's distance and object
    /// ([`NOTHING`] where it found none), and whether it met anything.
    #[inline]
    pub fn found(t: f32x8, object: f32x8, any: f32x8) -> Hits {
        Hits {
            t,
            object,
            hit: object.cmp_ne(f32x8::splat(NOTHING)),
            any,
        }
    }
}

/// Everything the shading needs about eight hits (the lab model's hit record).
/// Lanes without a hit hold numbers too, which the caller's masks leave
/// unread.
#[derive(Clone, Copy, Debug)]
pub struct Surfaces {
    /// Where each ray meets its surface.
    pub point: Vec3x8,
    /// The unit normal out of the object hit (`n`).
    pub normal: Vec3x8,
    /// The unit normal on the side the ray comes from (`nf`).
    pub facing_normal: Vec3x8,
    /// Set where the ray arrives from outside (`dot(d, n) < 0`).
    pub entering: f32x8,
    /// Set where the ray hit the ground, whose albedo is the checker's.
    pub on_ground: f32x8,
    /// The surface's albedo (the checker's colour on the ground).
    pub albedo: Vec3x8,
    /// `albedo / π`, divided as the scalar code divides it.
    pub albedo_over_pi: Vec3x8,
    /// The material's mirror share `r`.
    pub reflection: f32x8,
    /// The material's glass share `t`.
    pub transmission: f32x8,
    /// The material's index of refraction.
    pub ior: f32x8,
    /// Set where the material has a mirror or glass share to choose.
    pub chooses: f32x8,
}

impl<'s> SceneX8<'s> {
    /// The scene's numbers splatted across the lanes.
    pub fn new(scene: &'s Scene) -> Self {
        let spheres = scene
            .spheres()
            .iter()
            .map(|s| {
                let m = &s.material;
                let chooses = m.reflection() + m.transmission() > 0.0;
                SphereX8 {
                    centre: Vec3x8::splat(s.shape.centre),
                    radius_squared: f32x8::splat(s.shape.radius * s.shape.radius),
                    albedo: Vec3x8::splat(m.albedo()),
                    albedo_over_pi: Vec3x8::splat(m.albedo() / PI),
                    reflection: f32x8::splat(m.reflection()),
                    transmission: f32x8::splat(m.transmission()),
                    ior: f32x8::splat(m.ior()),
                    chooses: if chooses { all_set() } else { f32x8::ZERO },
                }
            })
            .collect();
        SceneX8 {
            scene,
            plane_point: Vec3x8::splat(scene.ground.plane.point),
            plane_normal: Vec3x8::splat(scene.ground.plane.normal),
            checker_even: with_over_pi(scene.ground.checker.even),
            checker_odd: with_over_pi(scene.ground.checker.odd),
            spheres,
            query: None,
        }
    }

    /// The same scene, with every ray's hits found by `query` (chapter 9's
    /// tree) instead of by testing every sphere: the same answers, faster
    /// when there are many spheres.
    pub fn with_query(mut self, query: &'s dyn SceneQueryX8) -> Self {
        self.query = Some(query);
        self
    }

    /// What a tracer that follows one ray at a time should ask: the
    /// query, if the scene was given one, else the scene's own list.
    pub fn one_ray(&self) -> &'s dyn SceneQuery {
        match self.query {
            Some(query) => query,
            None => self.scene,
        }
    }

    /// The same scene with the mirror share (`reflection`) or the glass
    /// share (`transmission`) of every sphere set to 0 where they are
    /// `false`: for a tracer of a chapter that has not come to them yet.
    pub fn with_optics(mut self, reflection: bool, transmission: bool) -> Self {
        for s in &mut self.spheres {
            if !reflection {
                s.reflection = f32x8::ZERO;
            }
            if !transmission {
                s.transmission = f32x8::ZERO;
            }
        }
        self
    }

    /// The scene the lanes were made from.
    pub fn scene(&self) -> &'s Scene {
        self.scene
    }

    /// The plane's `t` in every lane, and a mask of the lanes it counts in.
    #[inline]
    fn plane(&self, o: Vec3x8, d: Vec3x8) -> (f32x8, f32x8) {
        plane_hits(self.plane_point, self.plane_normal, o, d)
    }

    /// A sphere's nearest `t > 0` in every lane, and the lanes that hit it.
    #[inline]
    fn sphere(s: &SphereX8, o: Vec3x8, d: Vec3x8) -> (f32x8, f32x8) {
        sphere_hits(s.centre, s.radius_squared, o, d)
    }

    /// The nearest hit of eight rays, and whether each meets anything at
    /// all: through the query if the scene has one, else
    /// [`SceneX8::nearest_in_list`].
    #[inline]
    pub fn nearest(&self, o: Vec3x8, d: Vec3x8) -> Hits {
        match self.query {
            Some(query) => query.nearest(o, d),
            None => self.nearest_in_list(o, d),
        }
    }

    // ANCHOR: nearest
    /// The nearest hit of eight rays: the plane, then every sphere in
    /// order, a strictly nearer hit replacing the best so far (ties go to
    /// the earlier object, as in `Scene::nearest_hit`); and whether each
    /// ray meets anything at all, as `Scene::any_hit` asks.
    #[inline]
    pub fn nearest_in_list(&self, o: Vec3x8, d: Vec3x8) -> Hits {
        let (t_plane, on_plane) = self.plane(o, d);
        let mut t = on_plane.blend(t_plane, f32x8::splat(f32::INFINITY));
        let mut object = on_plane.blend(f32x8::splat(GROUND), f32x8::splat(NOTHING));
        let mut any = on_plane;
        for (k, sphere) in self.spheres.iter().enumerate() {
            let (t_sphere, hit) = SceneX8::sphere(sphere, o, d);
            any |= hit;
            // Mask: this sphere is hit, and nearer than what each lane has.
            let nearer = hit & t_sphere.cmp_lt(t);
            t = nearer.blend(t_sphere, t);
            object = nearer.blend(f32x8::splat(k as f32 + 1.0), object);
        }
        Hits::found(t, object, any)
    }
    // ANCHOR_END: nearest

    /// Whether each of eight shadow rays meets anything at all, in the
    /// lanes of `asked`: through the query if the scene has one, else
    /// [`SceneX8::any_in_list`].
    #[inline]
    pub fn any(&self, o: Vec3x8, d: Vec3x8, asked: f32x8) -> f32x8 {
        match self.query {
            Some(query) => query.any(o, d, asked),
            None => self.any_in_list(o, d, asked),
        }
    }

    /// Whether each of eight shadow rays meets anything at all, in the
    /// lanes of `asked` (the others' answers may be wrong): it stops as
    /// soon as every lane asked about is known to be blocked.
    #[inline]
    pub fn any_in_list(&self, o: Vec3x8, d: Vec3x8, asked: f32x8) -> f32x8 {
        let mut blocked = self.plane(o, d).1;
        for sphere in &self.spheres {
            if (asked & !blocked).none() {
                break;
            }
            blocked |= SceneX8::sphere(sphere, o, d).1;
        }
        blocked
    }

    /// The hit records of eight hits, as `Scene::hit_record` makes one.
    #[inline]
    pub fn surfaces(&self, o: Vec3x8, d: Vec3x8, hits: &Hits) -> Surfaces {
        let point = o + d.scale(hits.t);
        let on_ground = hits.object.cmp_eq(f32x8::splat(GROUND));
        let mut centre = Vec3x8::ZERO;
        // Divergence: groups with no lane on the ground skip the checker.
        let (mut albedo, mut albedo_over_pi) = if on_ground.any() {
            self.checker(point)
        } else {
            (Vec3x8::ZERO, Vec3x8::ZERO)
        };
        let (mut reflection, mut transmission) = (f32x8::ZERO, f32x8::ZERO);
        let (mut ior, mut chooses) = (f32x8::ONE, f32x8::ZERO);
        // Each lane picks its own sphere's numbers: one blend per sphere
        // hit, where a scalar tracer would index an array. The spheres are
        // taken from the lanes themselves (the lowest lane not yet served
        // names the next), so the work grows with the spheres these eight
        // rays hit, one or two in most groups, not with the scene's.
        let mut unserved = (hits.hit & !on_ground).move_mask() as u32;
        while unserved != 0 {
            let lane = unserved.trailing_zeros() as usize;
            let number = hits.object.as_array_ref()[lane];
            let mine = hits.object.cmp_eq(f32x8::splat(number));
            unserved &= !(mine.move_mask() as u32);
            let s = &self.spheres[number as usize - 1];
            centre = Vec3x8::select(mine, s.centre, centre);
            albedo = Vec3x8::select(mine, s.albedo, albedo);
            albedo_over_pi = Vec3x8::select(mine, s.albedo_over_pi, albedo_over_pi);
            reflection = mine.blend(s.reflection, reflection);
            transmission = mine.blend(s.transmission, transmission);
            ior = mine.blend(s.ior, ior);
            chooses = mine.blend(s.chooses, chooses);
        }
        // Divergence: a group whose hits are all on the ground (or nowhere)
        // has no sphere normal to normalise, and skips the division.
        let normal = if (hits.hit & !on_ground).none() {
            self.plane_normal
        } else {
            let sphere_normal = (point - centre).normalize();
            Vec3x8::select(on_ground, self.plane_normal, sphere_normal)
        };
        let entering = d.dot(normal).cmp_lt(f32x8::ZERO);
        let facing_normal = Vec3x8::select(entering, normal, -normal);
        Surfaces {
            point,
            normal,
            facing_normal,
            entering,
            on_ground,
            albedo,
            albedo_over_pi,
            reflection,
            transmission,
            ior,
            chooses,
        }
    }

    /// Lane `lane`'s hit as the scalar `Hit`, for code that takes one (a
    /// learner's step): `Scene::hit_record` of that lane's ray, whose
    /// numbers the lanes hold to the bit.
    pub fn hit(&self, o: Vec3x8, d: Vec3x8, hits: &Hits, lane: usize) -> Hit {
        let object = match hits.object.as_array_ref()[lane] {
            GROUND => Object::Ground,
            k => Object::Sphere(k as usize - 1),
        };
        let ray = Ray {
            origin: o.lane(lane),
            direction: d.lane(lane),
        };
        self.scene
            .hit_record(&ray, hits.t.as_array_ref()[lane], object)
    }

    /// [`SceneX8::hit`] of a sphere's hit, read from the hit records the
    /// lanes made already (`s`, from [`SceneX8::surfaces`] of the same rays
    /// and `hits`), which hold `Scene::hit_record`'s numbers to the bit: a
    /// copy of eight numbers, where `hit` works the point and the normal out
    /// again. A ground hit, whose material the checker colours, is `hit`'s.
    pub fn hit_of(&self, o: Vec3x8, d: Vec3x8, hits: &Hits, s: &Surfaces, lane: usize) -> Hit {
        let number = hits.object.as_array_ref()[lane];
        if number == GROUND {
            return self.hit(o, d, hits, lane);
        }
        let k = number as usize - 1;
        Hit {
            t: hits.t.as_array_ref()[lane],
            point: s.point.lane(lane),
            normal: s.normal.lane(lane),
            facing_normal: s.facing_normal.lane(lane),
            entering: s.entering.as_array_ref()[lane] != 0.0,
            object: Object::Sphere(k),
            material: self.scene.spheres()[k].material,
        }
    }

    // ANCHOR: checker
    /// The ground's checker colour at eight points, as `Checker::albedo_at`
    /// decides it: the parity of `floor(x) + floor(z)` as an `i64`. With
    /// it, the colour divided by π.
    #[inline]
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

/// A mask with every lane set.
fn all_set() -> f32x8 {
    f32x8::ZERO.cmp_eq(f32x8::ZERO)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::vec3x8::{lanes_of, mask_from_bits};
    use raylab::Camera;

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
        let wide = SceneX8::new(&scene);
        for j in 0..30 {
            let (o, d, rays) = eight_rays(j);
            let hits = wide.nearest(o, d);
            let surfaces = wide.surfaces(o, d, &hits);
            for (lane, ray) in rays.iter().enumerate() {
                let object = hits.object.as_array_ref()[lane];
                let any = hits.any.as_array_ref()[lane] != 0.0;
                assert_eq!(any, scene.any_hit(ray), "row {j}, lane {lane}");
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
                        assert_eq!(wide.hit(o, d, &hits, lane), hit);
                        assert_eq!(wide.hit_of(o, d, &hits, &surfaces, lane), hit);
                    }
                }
            }
        }
    }

    #[test]
    fn a_shadow_ray_is_blocked_in_exactly_the_lanes_the_scalar_scene_says() {
        let scene = Scene::lab();
        let wide = SceneX8::new(&scene);
        for j in 0..30 {
            let (o, d, rays) = eight_rays(j);
            let blocked = wide.any(o, d, mask_from_bits(0xff));
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
        let wide = SceneX8::new(&scene);
        for j in (0..30).step_by(3) {
            let (o, d, rays) = eight_rays(j);
            for asked in (1..0xffu32).step_by(7) {
                let blocked = wide.any(o, d, mask_from_bits(asked));
                for lane in lanes_of(asked) {
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
        let wide = SceneX8::new(&scene);
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
