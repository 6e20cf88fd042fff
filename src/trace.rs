//! The tracer: the ray-stack loop of the lab model, and the seam where a chapter
//! plugs in what happens when a ray hits something.

mod record;

use crate::Vec3;
use crate::ray::{Ray, RayKind};
use crate::scene::{Hit, Scene, SceneQuery};
use crate::stack::{MAX_DEPTH_LIMIT, MAX_SECONDARIES, PendingRay, RayStack};

pub use record::{RayCounts, TracedRay};
use record::{Record, ShadowLog};

// ANCHOR: step
/// What a chapter adds: how a surface that a ray has hit is shaded.
///
/// `shade` returns the surface's *local* light — what it sends towards the
/// ray's origin by itself, from the sun and the ambient term. Along the way
/// it may ask `surface` whether a shadow ray is blocked, and hand it rays to
/// send on (reflected, refracted) with the share of the light each carries.
/// The tracer does the rest: it weights the local light by the share that
/// is left, and pushes the rays sent on while the depth allows.
pub trait Step: Sync {
    /// The local light the surface `hit` sends back along `ray`; shadow
    /// rays and the rays sent on go through `surface`.
    fn shade(&self, ray: &Ray, hit: &Hit, surface: &mut Surface) -> Vec3;

    /// Where the five rays of `--spp 5` go in a pixel, as offsets in
    /// [0,1)²: by default [`LAB_FIVE`](crate::sampling::LAB_FIVE). Chapter 5,
    /// whose step they are, gives its own.
    fn lab_five(&self) -> [(f32, f32); 5] {
        crate::sampling::LAB_FIVE
    }
}
// ANCHOR_END: step

/// A ray a step sends on from a surface, and its share of the light.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Secondary {
    /// Reflection or refraction: how the ray left the surface.
    pub kind: RayKind,
    /// Where it starts (already off the surface by `epsilon`) and where it goes.
    pub ray: Ray,
    /// The share of the light arriving at the hit that it carries on.
    pub share: f32,
}

/// What a step can do at a hit: look at the scene, cast shadow rays, and
/// send rays on. One `Surface` is reused for every hit.
pub struct Surface<'s> {
    scene: &'s Scene,
    /// Who answers the shadow rays (see [`Tracer::with_query`]). A `dyn`,
    /// not the tracer's `Q`, so that `Surface` has no type parameter and
    /// [`Step::shade`] stays the signature a learner writes.
    objects: &'s dyn SceneQuery,
    epsilon: f32,
    sent: [Secondary; MAX_SECONDARIES],
    sent_len: usize,
    kept: f32,
    shadow_rays: u32,
    /// The shadow rays of this hit, noted only for a probe.
    shadow_log: ShadowLog,
}

impl<'s> Surface<'s> {
    fn new(scene: &'s Scene, objects: &'s dyn SceneQuery, epsilon: f32) -> Self {
        let unsent = Secondary {
            kind: RayKind::Reflection,
            ray: Ray::new(Vec3::ZERO, Vec3::Z),
            share: 0.0,
        };
        Surface {
            scene,
            objects,
            epsilon,
            sent: [unsent; MAX_SECONDARIES],
            sent_len: 0,
            kept: 1.0,
            shadow_rays: 0,
            shadow_log: ShadowLog::off(),
        }
    }

    fn reset(&mut self) {
        self.sent_len = 0;
        self.kept = 1.0;
        self.shadow_rays = 0;
        self.shadow_log.clear();
    }

    /// The scene being rendered (for the sun, say).
    pub fn scene(&self) -> &'s Scene {
        self.scene
    }

    /// How far a new ray starts from the surface it leaves, so that it
    /// does not hit that same surface again through rounding (`--epsilon`).
    pub fn epsilon(&self) -> f32 {
        self.epsilon
    }

    /// Trace a shadow ray: `true` if anything at all lies in its way.
    pub fn trace_shadow_ray(&mut self, ray: Ray) -> bool {
        self.shadow_rays += 1;
        let blocked = self.objects.any_hit(&ray);
        self.shadow_log.note(ray, blocked);
        blocked
    }

    /// Send `share` of the light arriving here on along `ray`.
    ///
    /// The share is taken from the local light at once, even if the ray is
    /// too deep to be traced: at the maximum depth that light is lost,
    /// which is what a depth limit means.
    ///
    /// # Panics
    /// If a step sends on more than [`MAX_SECONDARIES`] rays from one hit.
    pub fn send(&mut self, kind: RayKind, ray: Ray, share: f32) {
        assert!(
            self.sent_len < MAX_SECONDARIES,
            "a step may send at most {MAX_SECONDARIES} rays on from one hit"
        );
        self.sent[self.sent_len] = Secondary { kind, ray, share };
        self.sent_len += 1;
        // Subtracted one share at a time, as the lab model writes `1 - r - t`.
        self.kept -= share;
    }

    /// The share of the light left for local shading: `1 − r − t`.
    pub fn kept(&self) -> f32 {
        self.kept
    }

    /// The rays sent on so far, in the order they were sent.
    pub fn sent(&self) -> &[Secondary] {
        &self.sent[..self.sent_len]
    }
}

/// The most rays (shadow rays included) traced for one primary ray.
///
/// With the default `--epsilon` even `--max-depth 64` stays far below it.
/// With `--epsilon 0` a ray can re-hit the surface it leaves and split in
/// two there, again and again: the tree doubles every level or two, and at
/// depth 64 it would never finish. Past the budget no new ray is sent on,
/// and the render reports how many samples that cut short.
pub const RAY_BUDGET: u32 = 4096;

/// What tracing one primary ray gave.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Traced {
    /// The light the ray tree brought to the pixel: every ray's weighted
    /// sky or local light, summed in the order the rays were traced.
    pub colour: Vec3,
    /// The depth of the deepest ray traced (shadow rays do not count).
    pub deepest: u32,
    /// Every ray traced, shadow rays included.
    pub rays: u32,
    /// Whether the tree was cut short by [`RAY_BUDGET`].
    pub over_budget: bool,
}

/// Traces rays through one scene with one step; one per thread.
///
/// `Q` is what answers "which object does this ray hit first?" — the scene
/// itself unless a chapter hands the tracer a faster way to the same
/// answers. It is a type parameter, not a `&dyn SceneQuery`, so that the
/// scene's own search is compiled into the trace loop: through a `dyn`,
/// every ray of chapters 1–5 would pay a call and a copy of its `Hit`.
pub struct Tracer<'s, S: Step + ?Sized, Q: SceneQuery = Scene> {
    scene: &'s Scene,
    /// What answers "which object does this ray hit first?": the scene
    /// itself, testing every object, unless [`Tracer::with_query`] hands
    /// it a faster way to the same answers.
    objects: &'s Q,
    step: &'s S,
    max_depth: u32,
    stack: RayStack,
    surface: Surface<'s>,
    /// The bench's bookkeeping: rays counted by kind, and a probe's log
    /// and the per-depth colours when asked for (`record.rs`).
    record: Record,
}

impl<'s, S: Step + ?Sized> Tracer<'s, S> {
    /// A tracer for rays up to `max_depth` deep (1 to [`MAX_DEPTH_LIMIT`]).
    pub fn new(scene: &'s Scene, step: &'s S, max_depth: u32, epsilon: f32) -> Self {
        Tracer::with_query(scene, scene, step, max_depth, epsilon)
    }
}

impl<'s, S: Step + ?Sized, Q: SceneQuery> Tracer<'s, S, Q> {
    /// A tracer whose rays ask `objects`, not the scene's list, what they
    /// hit: a [`SceneQuery`] that gives the same answers faster (a tree of
    /// boxes around the objects, say). The scene still gives the sky and
    /// the sun.
    pub fn with_query(
        scene: &'s Scene,
        objects: &'s Q,
        step: &'s S,
        max_depth: u32,
        epsilon: f32,
    ) -> Self {
        assert!(
            (1..=MAX_DEPTH_LIMIT).contains(&max_depth),
            "max_depth must be 1 to {MAX_DEPTH_LIMIT}"
        );
        Tracer {
            scene,
            objects,
            step,
            max_depth,
            stack: RayStack::default(),
            surface: Surface::new(scene, objects, epsilon),
            record: Record::default(),
        }
    }

    // ANCHOR: trace
    /// The colour seen along a primary ray: the lab model's ray-stack loop.
    pub fn trace(&mut self, primary: Ray) -> Traced {
        let mut traced = self.start();
        // ANCHOR: todo_trace "The ray-stack loop of the lab model: push the primary ray (weight 1, depth 1); pop until empty, counting each ray (self.count) and, after shading, its feelers (self.count_shadow_rays); a ray that hits nothing adds weight · sky; one that hits adds weight · kept · local and, below max_depth and within RAY_BUDGET, pushes each ray sent on with weight × share and depth + 1."
        self.stack.push(PendingRay {
            ray: primary,
            kind: RayKind::Primary,
            weight: 1.0,
            depth: 1,
            parent: None,
        });
        while let Some(pending) = self.stack.pop() {
            self.count(&mut traced, &pending);
            let Some(hit) = self.objects.nearest_hit(&pending.ray) else {
                // Nothing in the way: the ray sees the sky.
                let sky = pending.weight * self.scene.sky.radiance(pending.ray.direction);
                self.add(&mut traced, &pending, None, sky);
                continue;
            };

            self.surface.reset();
            let local = self.step.shade(&pending.ray, &hit, &mut self.surface);
            let added = pending.weight * self.surface.kept() * local;
            let me = self.add(&mut traced, &pending, Some(&hit), added);
            self.count_shadow_rays(&mut traced);

            if pending.depth < self.max_depth && self.surface.sent_len > 0 {
                if traced.rays >= RAY_BUDGET {
                    traced.over_budget = true;
                    continue;
                }
                for secondary in self.surface.sent() {
                    self.stack.push(PendingRay {
                        ray: secondary.ray,
                        kind: secondary.kind,
                        weight: pending.weight * secondary.share,
                        depth: pending.depth + 1,
                        parent: me,
                    });
                }
            }
        }
        traced
        // ANCHOR_END: todo_trace
    }
    // ANCHOR_END: trace

    /// A new pixel's tally.
    fn start(&mut self) -> Traced {
        self.record.start();
        Traced::default()
    }

    /// Count a ray taken off the stack, and how deep the tree has gone.
    fn count(&mut self, traced: &mut Traced, pending: &PendingRay) {
        self.record.count(pending.kind, 1);
        traced.rays += 1;
        traced.deepest = traced.deepest.max(pending.depth);
    }

    /// Count the feelers the step just cast.
    fn count_shadow_rays(&mut self, traced: &mut Traced) {
        let shadow_rays = self.surface.shadow_rays;
        self.record.count(RayKind::Shadow, u64::from(shadow_rays));
        traced.rays += shadow_rays;
    }

    /// Add a ray's contribution to the pixel. Returns the ray's index in
    /// the probe's log, if one is kept: the parent of the rays it sends on.
    fn add(
        &mut self,
        traced: &mut Traced,
        pending: &PendingRay,
        hit: Option<&Hit>,
        added: Vec3,
    ) -> Option<u32> {
        traced.colour += added;
        let shadows = &self.surface.shadow_log;
        self.record
            .add(pending, hit, added, self.max_depth, shadows, self.objects)
    }
}

// ANCHOR: tests
#[cfg(test)]
mod tests {
    use super::*;
    use crate::light::{Sky, Sun};
    use crate::material::Material;
    use crate::plane::{Checker, Plane};
    use crate::scene::Ground;
    use crate::sphere::Sphere;

    /// Two perfect mirrors facing each other along the x axis, the ground
    /// far below: a ray between them bounces for ever.
    fn facing_mirrors() -> Scene {
        let mut scene = Scene::new(
            Ground {
                plane: Plane {
                    point: Vec3::new(0.0, -100.0, 0.0),
                    normal: Vec3::Y,
                },
                checker: Checker {
                    even: Vec3::ONE,
                    odd: Vec3::ZERO,
                },
            },
            Sky {
                horizon: Vec3::ONE,
                zenith: Vec3::ONE,
            },
            Sun {
                direction: Vec3::Y,
                brightness: 1.0,
            },
        )
        .unwrap();
        let mirror = Material::new(Vec3::splat(0.5), 1.0, 0.0, 1.0).unwrap();
        for x in [-2.0, 2.0] {
            let shape = Sphere {
                centre: Vec3::new(x, 0.0, 0.0),
                radius: 1.0,
            };
            scene.add_sphere("mirror", shape, mirror).unwrap();
        }
        scene
    }

    /// A step that mirrors all the light it is given and casts one shadow ray.
    struct MirrorWithShadow;

    impl Step for MirrorWithShadow {
        fn shade(&self, ray: &Ray, hit: &Hit, surface: &mut Surface) -> Vec3 {
            let sun = surface.scene().sun.direction;
            surface.trace_shadow_ray(Ray::new(hit.point + sun * 1e-4, sun));
            let r = crate::optics::reflect(ray.direction, hit.facing_normal).normalize();
            let origin = hit.point + r * surface.epsilon();
            surface.send(
                RayKind::Reflection,
                Ray::new(origin, r),
                hit.material.reflection(),
            );
            hit.material.albedo()
        }
    }

    #[test]
    fn two_facing_mirrors_stop_after_max_depth_bounces() {
        // Every ray hits a mirror, casts one shadow ray and sends one ray on:
        // depth D traces D mirror rays (1 primary, D − 1 reflections) and D shadow rays.
        let scene = facing_mirrors();
        for max_depth in [1, 2, 10, 64] {
            let mut tracer = Tracer::new(&scene, &MirrorWithShadow, max_depth, 1e-4);
            let traced = tracer.trace(Ray::new(Vec3::ZERO, Vec3::X));
            let counts = tracer.counts();
            assert_eq!(counts.get(RayKind::Primary), 1, "primary rays");
            assert_eq!(
                counts.get(RayKind::Reflection),
                u64::from(max_depth - 1),
                "reflections at max depth {max_depth}"
            );
            assert_eq!(
                counts.get(RayKind::Shadow),
                u64::from(max_depth),
                "shadow rays at max depth {max_depth}"
            );
            assert_eq!(
                traced.rays,
                2 * max_depth,
                "rays traced at max depth {max_depth}"
            );
            assert_eq!(
                traced.deepest, max_depth,
                "the deepest ray at max depth {max_depth}"
            );
        }
    }

    #[test]
    fn no_ray_is_deeper_than_max_depth() {
        let scene = facing_mirrors();
        let mut tracer = Tracer::new(&scene, &MirrorWithShadow, 5, 1e-4).with_log();
        tracer.trace(Ray::new(Vec3::ZERO, Vec3::X));
        let log = tracer.log();
        assert_eq!(
            log.iter().map(|r| r.depth).max(),
            Some(5),
            "the deepest ray at max depth 5"
        );
        // Each mirror ray's parent is the one before it, one level up.
        for ray in log.iter().filter(|r| r.kind == RayKind::Reflection) {
            let parent = &log[ray.parent.unwrap()];
            assert_eq!(parent.depth + 1, ray.depth);
        }
    }

    #[test]
    fn a_tree_that_doubles_every_level_stops_at_the_ray_budget() {
        // Two rays sent on from every hit between two mirrors: 2^64 rays
        // at depth 64, were it not for the budget.
        struct Splitting;
        impl Step for Splitting {
            fn shade(&self, ray: &Ray, hit: &Hit, surface: &mut Surface) -> Vec3 {
                let r = crate::optics::reflect(ray.direction, hit.facing_normal).normalize();
                let next = Ray::new(hit.point + r * 1e-4, r);
                surface.send(RayKind::Reflection, next, 0.5);
                surface.send(RayKind::Reflection, next, 0.5);
                Vec3::ZERO
            }
        }
        let scene = facing_mirrors();
        let mut tracer = Tracer::new(&scene, &Splitting, 64, 1e-4);
        let traced = tracer.trace(Ray::new(Vec3::ZERO, Vec3::X));
        assert!(traced.over_budget);
        assert!(
            traced.rays >= RAY_BUDGET && traced.rays < 2 * RAY_BUDGET,
            "{}",
            traced.rays
        );
        // Within budget nothing is cut.
        let mut shallow = Tracer::new(&scene, &Splitting, 8, 1e-4);
        let traced = shallow.trace(Ray::new(Vec3::ZERO, Vec3::X));
        assert_eq!(
            (traced.rays, traced.over_budget),
            (255, false),
            "(rays traced, over budget) at max depth 8, a whole tree of 1 + 2 + … + 128 rays"
        );
    }

    #[test]
    fn at_the_maximum_depth_the_mirrored_share_is_lost() {
        // With r = 1 nothing is kept for local shading and, at depth 1,
        // nothing is traced further: the pixel is black.
        let scene = facing_mirrors();
        let mut tracer = Tracer::new(&scene, &MirrorWithShadow, 1, 1e-4);
        assert_eq!(
            tracer.trace(Ray::new(Vec3::ZERO, Vec3::X)).colour,
            Vec3::ZERO
        );
    }

    #[test]
    fn per_depth_colours_match_separate_renders() {
        let scene = Scene::lab();
        let glass = Vec3::new(1.0, 0.6, 0.8);
        let eye = Vec3::new(0.0, 1.2, 4.5);
        let ray = Ray::new(eye, (glass - eye).normalize());
        let mut all = Tracer::new(&scene, &MirrorWithShadow, 6, 1e-4).with_depth_colours();
        all.trace(ray);
        for depth in 1..=6 {
            let mut one = Tracer::new(&scene, &MirrorWithShadow, depth, 1e-4);
            assert_eq!(all.colour_at_depth(depth), Some(one.trace(ray).colour));
        }
    }

    /// Local light 1 everywhere, half of it sent on along the mirror direction.
    struct HalfMirror;

    impl Step for HalfMirror {
        fn shade(&self, ray: &Ray, hit: &Hit, surface: &mut Surface) -> Vec3 {
            let r = crate::optics::reflect(ray.direction, hit.facing_normal).normalize();
            let next = Ray::new(hit.point + r * surface.epsilon(), r);
            surface.send(RayKind::Reflection, next, 0.5);
            Vec3::ONE
        }
    }

    #[test]
    fn a_primary_ray_that_meets_nothing_sees_the_sky_with_weight_1() {
        // Straight up from between the mirrors: the sky, which is 1 everywhere here.
        let scene = facing_mirrors();
        let mut tracer = Tracer::new(&scene, &HalfMirror, 10, 1e-4);
        let traced = tracer.trace(Ray::new(Vec3::ZERO, Vec3::Y));
        assert_eq!(
            traced.colour,
            Vec3::ONE,
            "push the primary ray with weight 1 before the first pop"
        );
        assert_eq!((traced.rays, traced.deepest), (1, 1));
        assert_eq!(tracer.counts().get(RayKind::Primary), 1);
    }

    /// each bounce carries its parent's weight times its share
    #[test]
    fn each_bounce_carries_its_parents_weight_times_its_share() {
        // Every hit keeps half (local 1 · kept ½) and sends half on. Weights
        // 1, ½, ¼ at depths 1, 2, 3 add ½ + ¼ + ⅛ = 0.875; a weight that is
        // the share alone (½, ½) would add up to 1.
        let scene = facing_mirrors();
        let mut tracer = Tracer::new(&scene, &HalfMirror, 3, 1e-4);
        let traced = tracer.trace(Ray::new(Vec3::ZERO, Vec3::X));
        assert_eq!(traced.colour, Vec3::splat(0.875));
        assert_eq!((traced.rays, traced.deepest), (3, 3));
    }

    #[test]
    fn the_ray_sent_last_is_traced_first() {
        // A reflection then a refraction sent from the first hit: the lab model
        // pushes them in that order, so the refraction is popped first.
        struct ReflectThenRefract;
        impl Step for ReflectThenRefract {
            fn shade(&self, ray: &Ray, hit: &Hit, surface: &mut Surface) -> Vec3 {
                let r = crate::optics::reflect(ray.direction, hit.facing_normal).normalize();
                let next = Ray::new(hit.point + r * 1e-4, r);
                surface.send(RayKind::Reflection, next, 0.25);
                surface.send(RayKind::Refraction, next, 0.25);
                Vec3::ONE
            }
        }
        let scene = facing_mirrors();
        let mut tracer = Tracer::new(&scene, &ReflectThenRefract, 2, 1e-4).with_log();
        tracer.trace(Ray::new(Vec3::ZERO, Vec3::X));
        let kinds: Vec<RayKind> = tracer.log().iter().map(|r| r.kind).collect();
        assert_eq!(
            kinds,
            [RayKind::Primary, RayKind::Refraction, RayKind::Reflection],
            "the rays traced at max depth 2, in order, when the first hit sends a reflection \
             and then a refraction"
        );
        let weights: Vec<f32> = tracer.log().iter().map(|r| r.weight).collect();
        assert_eq!(weights, [1.0, 0.25, 0.25]);
    }
}
// ANCHOR_END: tests
