//! Eight rays against the ground and every sphere at once, and the hit
//! records of eight hits (chapter 7's intersection, with chapter 6's
//! materials). Every lane computes everything; a *mask* (a lane of all ones
//! or all zeros) records which lanes' answers count, and `blend` keeps the
//! new answer where it is set. The arithmetic is the scalar code's,
//! operation for operation, so every `t`, point and normal is the same to
//! the bit.

use raylab::scene::Object;
use raylab::{Hit, Material, Scene};
use wide::{CmpEq, CmpGe, CmpLt, CmpNe, f32x8};

use raylab::lanes::{Vec3x8, plane_hits, sphere_hits};

/// Object numbers in a lane: nothing hit, the ground, sphere `k` is `k + 1`.
const NOTHING: f32 = -1.0;
const GROUND: f32 = 0.0;

/// A sphere and what the path tracer reads of its material, each number
/// in all eight lanes.
#[derive(Clone, Copy, Debug)]
struct SphereX8 {
    centre: Vec3x8,
    radius_squared: f32x8,
    albedo: Vec3x8,
    ior: f32x8,
    /// Set in every lane if the material has a mirror or a glass share
    /// (`r + t > 0`): then a path there chooses its lobe.
    chooses: f32x8,
}

/// The scene as the eight-lane tracer reads it, made once per image.
#[derive(Clone, Debug)]
pub struct SceneX8<'s> {
    scene: &'s Scene,
    plane_point: Vec3x8,
    plane_normal: Vec3x8,
    checker_even: Vec3x8,
    checker_odd: Vec3x8,
    spheres: Vec<SphereX8>,
}

/// What eight rays hit, lane by lane.
#[derive(Clone, Copy, Debug)]
pub struct Hits {
    pub t: f32x8,
    /// `NOTHING`, `GROUND` or a sphere's number plus one.
    object: f32x8,
    /// Set where the ray has a nearest hit (`Scene::nearest_hit` is `Some`).
    pub nearest: f32x8,
    /// Set where the ray meets anything at all (`Scene::any_hit`).
    pub any: f32x8,
}

/// The hit records of eight hits (lanes without one hold numbers too,
/// which the caller's masks leave unread).
#[derive(Clone, Copy, Debug)]
pub struct Surfaces {
    pub point: Vec3x8,
    pub normal: Vec3x8,
    pub facing_normal: Vec3x8,
    /// Set where the ray arrives from outside (`dot(d, n) < 0`).
    pub entering: f32x8,
    pub albedo: Vec3x8,
    pub ior: f32x8,
    /// Set where the material has a mirror or glass share to choose.
    pub chooses: f32x8,
    pub on_ground: f32x8,
}

impl<'s> SceneX8<'s> {
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
                    ior: f32x8::splat(m.ior()),
                    chooses: if chooses { all_set() } else { f32x8::ZERO },
                }
            })
            .collect();
        SceneX8 {
            scene,
            plane_point: Vec3x8::splat(scene.ground.plane.point),
            plane_normal: Vec3x8::splat(scene.ground.plane.normal),
            checker_even: Vec3x8::splat(scene.ground.checker.even),
            checker_odd: Vec3x8::splat(scene.ground.checker.odd),
            spheres,
        }
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

    /// The nearest hit of eight rays: the ground, then every sphere in
    /// order, only a strictly nearer hit replacing the best so far (ties
    /// go to the earlier object, as in `Scene::nearest_hit`); and whether
    /// each ray meets anything at all, as `Scene::any_hit` asks.
    #[inline]
    pub fn nearest(&self, o: Vec3x8, d: Vec3x8) -> Hits {
        let (t_plane, on_plane) = self.plane(o, d);
        let mut t = on_plane.blend(t_plane, f32x8::splat(f32::INFINITY));
        let mut object = on_plane.blend(f32x8::splat(GROUND), f32x8::splat(NOTHING));
        let mut any = on_plane;
        for (k, sphere) in self.spheres.iter().enumerate() {
            let (t_sphere, hit) = SceneX8::sphere(sphere, o, d);
            any |= hit;
            // Mask: this sphere is hit, and nearer than what the lane has.
            let nearer = hit & t_sphere.cmp_lt(t);
            t = nearer.blend(t_sphere, t);
            object = nearer.blend(f32x8::splat(k as f32 + 1.0), object);
        }
        let nearest = object.cmp_ne(f32x8::splat(NOTHING));
        Hits {
            t,
            object,
            nearest,
            any,
        }
    }

    /// Whether each of eight shadow rays meets anything, in the lanes of
    /// `asked`; stops as soon as every lane asked is known to be blocked.
    #[inline]
    pub fn any(&self, o: Vec3x8, d: Vec3x8, asked: f32x8) -> f32x8 {
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
        let mut albedo = self.checker(point);
        let (mut ior, mut chooses) = (f32x8::ONE, f32x8::ZERO);
        // Each lane picks its own sphere's numbers: one blend per sphere,
        // where scalar code indexes an array.
        for (k, s) in self.spheres.iter().enumerate() {
            let mine = hits.object.cmp_eq(f32x8::splat(k as f32 + 1.0));
            // Most groups hit one or two objects: nothing to hand over
            // from the spheres no lane hit.
            if mine.none() {
                continue;
            }
            centre = Vec3x8::select(mine, s.centre, centre);
            albedo = Vec3x8::select(mine, s.albedo, albedo);
            ior = mine.blend(s.ior, ior);
            chooses = mine.blend(s.chooses, chooses);
        }
        let sphere_normal = (point - centre).normalize();
        let normal = Vec3x8::select(on_ground, self.plane_normal, sphere_normal);
        let entering = d.dot(normal).cmp_lt(f32x8::ZERO);
        let facing_normal = Vec3x8::select(entering, normal, -normal);
        Surfaces {
            point,
            normal,
            facing_normal,
            entering,
            albedo,
            ior,
            chooses,
            on_ground,
        }
    }

    /// Lane `lane`'s hit as the scalar `Hit`, for the per-lane code that
    /// takes one (the learner's `choose_lobe`): `Scene::hit_record`'s
    /// numbers, which the lanes hold to the bit.
    pub fn hit(&self, hits: &Hits, s: &Surfaces, lane: usize) -> Hit {
        let (object, material) = match hits.object.as_array_ref()[lane] {
            GROUND => {
                let albedo = s.albedo.lane(lane);
                let matte = Material::diffuse(albedo).expect("Scene::new checked the checker");
                (Object::Ground, matte)
            }
            k => {
                let k = k as usize - 1;
                (Object::Sphere(k), self.scene.spheres()[k].material)
            }
        };
        Hit {
            t: hits.t.as_array_ref()[lane],
            point: s.point.lane(lane),
            normal: s.normal.lane(lane),
            facing_normal: s.facing_normal.lane(lane),
            entering: s.entering.as_array_ref()[lane] != 0.0,
            object,
            material,
        }
    }

    // ANCHOR: checker
    /// The ground's checker colour at eight points, as `Checker::albedo_at`
    /// decides it: the parity of `floor(x) + floor(z)` as an `i64`.
    #[inline]
    fn checker(&self, p: Vec3x8) -> Vec3x8 {
        let s = p.x.floor() + p.z.floor();
        // `s` is whole. Below 2^24 halving it is exact, and it is odd where
        // the half is not whole; above, every f32 is even. Two masks copy
        // what the scalar `as i64` does at the edges: NaN becomes 0 (even),
        // and 2^63 or more saturates to i64::MAX (odd).
        let half = s * f32x8::splat(0.5);
        let not_nan = s.cmp_eq(s);
        let saturated = s.cmp_ge(f32x8::splat(9.223_372e18));
        let odd = (half.floor().cmp_ne(half) & not_nan) | saturated;
        Vec3x8::select(odd, self.checker_odd, self.checker_even)
    }
    // ANCHOR_END: checker
}

/// A mask with every lane set.
fn all_set() -> f32x8 {
    f32x8::ZERO.cmp_eq(f32x8::ZERO)
}
