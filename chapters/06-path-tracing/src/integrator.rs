//! The rendering equation, as a path tracer.
//!
//! The light leaving a surface towards the eye is the integral, over every
//! direction, of the light arriving from there times the surface's BSDF
//! times the cosine. A path tracer estimates that integral with one random
//! direction per surface, and estimates the light arriving along that
//! direction the same way, recursively: one random *path* per sample, whose
//! average over many samples converges to the equation's answer.

use std::f32::consts::FRAC_1_PI;

use raylab::optics::{fresnel, reflect, refract};
use raylab::scene::Object;
use raylab::{Hit, Ray, Scene, SceneQuery, Vec3};

use crate::caustics::CausticMap;
use crate::random::Random;
use crate::sun::Sunlight;

/// What the lab's three shares mean physically (`--materials`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Materials {
    /// The lab's shares as a mixture of three BSDFs, whatever the angle.
    Lab,
    /// A transmitting material splits its specular share by exact Fresnel.
    Fresnel,
}

impl Materials {
    /// Both meanings, in the order `--help` lists them.
    pub const ALL: [Materials; 2] = [Materials::Lab, Materials::Fresnel];

    /// The name `--materials` takes and the reports print.
    pub fn name(self) -> &'static str {
        match self {
            Materials::Lab => "lab",
            Materials::Fresnel => "fresnel",
        }
    }
}

/// A pixel's light, split by where it came from and how many diffuse
/// scatterings `k` it took (the lab model, "Contributions by term").
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Terms {
    /// `k = 0`: the sky or the sun's disc, seen directly or through mirrors and glass.
    pub seen: Vec3,
    /// `k = 1`, from the sun.
    pub sun_direct: Vec3,
    /// `k = 1`, from the sky.
    pub sky_direct: Vec3,
    /// `k ≥ 2`, from either.
    pub indirect: Vec3,
    /// From the sun through mirrors and glass onto the ground, traced from the sun.
    pub caustics: Vec3,
}

impl Terms {
    /// The names of the terms, in the order of [`Terms::as_array`].
    pub const NAMES: [&'static str; 5] =
        ["seen", "sun direct", "sky direct", "indirect", "caustics"];

    pub fn as_array(&self) -> [Vec3; 5] {
        [
            self.seen,
            self.sun_direct,
            self.sky_direct,
            self.indirect,
            self.caustics,
        ]
    }

    /// The whole radiance: the terms' sum.
    pub fn total(&self) -> Vec3 {
        self.seen + self.sun_direct + self.sky_direct + self.indirect + self.caustics
    }

    /// Add light from the sky (or the sun's disc seen along a path) that
    /// took `k` diffuse scatterings.
    fn add_sky(&mut self, k: u32, light: Vec3) {
        match k {
            0 => self.seen += light,
            1 => self.sky_direct += light,
            _ => self.indirect += light,
        }
    }

    /// Add sunlight that took `k ≥ 1` diffuse scatterings.
    fn add_sun(&mut self, k: u32, light: Vec3) {
        match k {
            0 => self.seen += light,
            1 => self.sun_direct += light,
            _ => self.indirect += light,
        }
    }
}

impl std::ops::AddAssign for Terms {
    fn add_assign(&mut self, other: Terms) {
        self.seen += other.seen;
        self.sun_direct += other.sun_direct;
        self.sky_direct += other.sky_direct;
        self.indirect += other.indirect;
        self.caustics += other.caustics;
    }
}

/// Which of a material's three BSDFs a path follows from a surface.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Lobe {
    Diffuse,
    Mirror,
    Refraction,
}

/// What it takes to trace paths through one scene.
pub struct PathTracer<'s, Q: SceneQuery + ?Sized = Scene> {
    pub scene: &'s Scene,
    /// Who answers "what does this ray hit?": the scene itself, testing
    /// every object in turn, or any faster [`SceneQuery`] with the same
    /// answers.
    pub objects: &'s Q,
    pub sun: Sunlight,
    pub materials: Materials,
    /// The most surface hits on a path, the first one included.
    pub max_depth: u32,
    pub epsilon: f32,
    /// With `--caustics`: the sunlight focused onto the ground, traced from the sun.
    pub caustics: Option<&'s CausticMap>,
}

// Copied by hand rather than derived: a derive would ask `Q: Copy` too,
// and the tracer only holds a reference to it.
impl<Q: SceneQuery + ?Sized> Clone for PathTracer<'_, Q> {
    fn clone(&self) -> Self {
        *self
    }
}

impl<Q: SceneQuery + ?Sized> Copy for PathTracer<'_, Q> {}

impl<Q: SceneQuery + ?Sized> PathTracer<'_, Q> {
    // ANCHOR: lobe
    /// Choose the BSDF a path follows from `hit`, each with the
    /// probability of its share: the diffuse `1 − r − t`, the mirror `r`,
    /// the refraction `t` (or, with `--materials fresnel` on a material
    /// that transmits, `s·F` and `s·(1 − F)` for `s = r + t`). Because each
    /// lobe is chosen as often as it weighs, the weights cancel from the
    /// estimate: the mirror and refraction carry the light unchanged, the
    /// diffuse lobe multiplies it by the albedo.
    pub fn choose_lobe(&self, d: Vec3, hit: &Hit, u: f32) -> Lobe {
        // ANCHOR: todo_choose_lobe "Cut [0, 1) into the three shares, in any order (e.g. u below the mirror's share is Lobe::Mirror, below mirror + refraction Lobe::Refraction, the rest Lobe::Diffuse); with Fresnel the specular share s = r + t splits as s·F and s·(1 − F)."
        let (r, t) = (hit.material.reflection(), hit.material.transmission());
        if r + t <= 0.0 {
            return Lobe::Diffuse;
        }
        let (mirror, refraction) = match self.materials {
            Materials::Fresnel if t > 0.0 => {
                let s = r + t;
                let f = fresnel(d.dot(hit.facing_normal), eta(hit));
                (s * f, s * (1.0 - f))
            }
            _ => (r, t),
        };
        if u < mirror {
            Lobe::Mirror
        } else if u < mirror + refraction {
            Lobe::Refraction
        } else {
            Lobe::Diffuse
        }
        // ANCHOR_END: todo_choose_lobe
    }

    /// [`PathTracer::choose_lobe`] with the path's random number, drawn
    /// only where there is a choice: a matte surface has one lobe.
    pub(crate) fn draw_lobe(&self, d: Vec3, hit: &Hit, random: &mut Random) -> Lobe {
        let m = hit.material;
        if m.reflection() + m.transmission() <= 0.0 {
            return Lobe::Diffuse;
        }
        self.choose_lobe(d, hit, random.uniform())
    }
    // ANCHOR_END: lobe

    // ANCHOR: path
    /// One random path from the eye along `ray`: its light, by term.
    /// `rays` counts every segment and shadow ray traced.
    pub fn trace(&self, mut ray: Ray, random: &mut Random, rays: &mut u32) -> Terms {
        let mut terms = Terms::default();
        // The share of the light found further along that reaches the eye:
        // a colour, since every diffuse bounce tints it by an albedo.
        let mut throughput = Vec3::ONE;
        // Diffuse scatterings so far (`k`), and whether the last vertex was
        // one (then the sun was counted there already, by its shadow ray).
        let mut diffuse_bounces = 0;
        let mut after_diffuse = false;
        for hits in 1..=self.max_depth + 1 {
            *rays += 1;
            // One hit more than the depth allows: only whether it escapes matters.
            let hit = if hits > self.max_depth {
                if self.objects.any_hit(&ray) {
                    break;
                }
                None
            } else {
                self.objects.nearest_hit(&ray)
            };
            let Some(hit) = hit else {
                // Escaped: the sky's light, and the sun's disc if the path
                // reaches it through mirrors and glass only (after a diffuse
                // vertex the shadow ray has counted it; with --caustics the
                // photons from the sun count what mirrors and glass bring
                // to a diffuse surface).
                let d = ray.direction;
                terms.add_sky(diffuse_bounces, throughput * self.scene.sky.radiance(d));
                let sun_counted_elsewhere =
                    after_diffuse || (diffuse_bounces > 0 && self.caustics.is_some());
                if !sun_counted_elsewhere {
                    let sun = self.sun.radiance_along(d);
                    if sun > 0.0 {
                        terms.add_sun(diffuse_bounces, throughput * sun);
                    }
                }
                break;
            };
            let d = ray.direction;
            let lobe = self.draw_lobe(d, &hit, random);
            let direction = match lobe {
                Lobe::Diffuse => {
                    let albedo = hit.material.albedo();
                    let nf = hit.facing_normal;
                    // The sun, by next-event estimation (nothing, in its
                    // shadow: adding zero leaves every sum as it was).
                    let sun = self.sun_next_event(&hit, random, rays);
                    terms.add_sun(diffuse_bounces + 1, throughput * sun);
                    // The caustic light the photons left here, if any path
                    // that short may bring it.
                    if let Some(map) = self.caustics
                        && hit.object == Object::Ground
                    {
                        let irradiance = map.irradiance(hit.point, self.max_depth - hits);
                        terms.caustics += throughput * albedo * FRAC_1_PI * irradiance;
                    }
                    // Everything else, the sky and the other surfaces: one
                    // new direction drawn in proportion to cos θ. Its
                    // estimate f·cos/pdf = (albedo/π)·cos/(cos/π) = albedo.
                    throughput *= albedo;
                    diffuse_bounces += 1;
                    after_diffuse = true;
                    let dir = cosine_direction(nf, random);
                    ray = Ray::new(hit.point + nf * self.epsilon, dir);
                    continue;
                }
                Lobe::Mirror => reflect(d, hit.facing_normal),
                Lobe::Refraction => refract(d, hit.facing_normal, eta(&hit))
                    // Total internal reflection: the light goes along the mirror.
                    .unwrap_or_else(|| reflect(d, hit.facing_normal)),
            };
            let direction = direction.normalize();
            after_diffuse = false;
            ray = Ray::new(hit.point + direction * self.epsilon, direction);
        }
        terms
    }
    // ANCHOR_END: path

    // ANCHOR: nee
    /// The sun's light that a diffuse `hit` sends back, by next-event
    /// estimation: one shadow ray towards the sun (towards a random point
    /// of its disc, drawn with [`Sunlight::draw`]), started `epsilon` along
    /// it so that the surface cannot shadow itself. Unblocked, the light is
    /// `albedo/π · E_sun · cos θ`; blocked, or from behind the surface,
    /// nothing. `rays` counts the shadow ray, when one is traced.
    pub fn sun_next_event(&self, hit: &Hit, random: &mut Random, rays: &mut u32) -> Vec3 {
        // ANCHOR: todo_sun_next_event "Draw a direction to the sun (self.sun.draw(random)); if it is above the surface (cos θ = facing normal · it > 0), count and trace a shadow ray from hit.point + epsilon along it, and return albedo/π · self.sun.irradiance · cos θ if nothing blocks it, else Vec3::ZERO."
        let to_sun = self.sun.draw(random);
        let cos = hit.facing_normal.dot(to_sun);
        if cos > 0.0 {
            *rays += 1;
            let shadow = Ray::new(hit.point + to_sun * self.epsilon, to_sun);
            if !self.objects.any_hit(&shadow) {
                return hit.material.albedo() * FRAC_1_PI * self.sun.irradiance * cos;
            }
        }
        Vec3::ZERO
        // ANCHOR_END: todo_sun_next_event
    }
    // ANCHOR_END: nee
}

/// `n₁/n₂` across the surface, as in chapter 4.
fn eta(hit: &Hit) -> f32 {
    let ior = hit.material.ior();
    if hit.entering { 1.0 / ior } else { ior }
}

// ANCHOR: cosine
/// A unit direction around the unit normal `n`, with probability density
/// `cos θ / π` (Malley's method: a uniform point on the unit disc, lifted
/// onto the hemisphere). The point on the disc is found by rejection from
/// the square around it (on average 4/π ≈ 1.27 tries), which needs no
/// sine or cosine: the random numbers are cheaper than the trigonometry.
/// With `t`, `b`, `n` orthonormal and `x² + y² + z² = 1` the direction is
/// of unit length already, to rounding: it needs no normalisation.
pub fn cosine_direction(n: Vec3, random: &mut Random) -> Vec3 {
    // ANCHOR: todo_cosine_direction "Return a unit direction about the unit normal n with density cos θ / π, from random.uniform() numbers: e.g. a uniform point on the unit disc, lifted onto the hemisphere around n (n.any_orthonormal_pair() gives the two other axes)."
    let (x, y, r2) = loop {
        let x = 2.0 * random.uniform() - 1.0;
        let y = 2.0 * random.uniform() - 1.0;
        let r2 = x * x + y * y;
        if r2 < 1.0 {
            break (x, y, r2);
        }
    };
    let (t, b) = n.any_orthonormal_pair();
    let z = (1.0 - r2).max(0.0).sqrt();
    x * t + y * b + z * n
    // ANCHOR_END: todo_cosine_direction
}
// ANCHOR_END: cosine

#[cfg(test)]
mod tests {
    use super::*;
    use raylab::Material;

    // ANCHOR: cosine_tests
    /// `k` cosine-weighted directions about `n`, from a fixed seed.
    fn cosine_directions(n: Vec3, k: u32) -> Vec<Vec3> {
        let mut random = Random(raylab::sampling::sample_rng(
            7,
            (0, 0),
            0,
            raylab::sampling::Stream::Path,
        ));
        (0..k).map(|_| cosine_direction(n, &mut random)).collect()
    }

    /// Normals up, down, along x and slanted: a sampler that ignores `n`
    /// and always works about +y fails for the other three.
    fn normals() -> [Vec3; 4] {
        [
            Vec3::Y,
            Vec3::NEG_Y,
            Vec3::X,
            Vec3::new(0.3, 0.9, -0.2).normalize(),
        ]
    }

    /// `(mean − expected) / (σ/√k)`: how many standard errors off a mean
    /// of `k` draws is, for draws whose standard deviation is `sigma`.
    fn z(mean: f64, expected: f64, sigma: f64, k: usize) -> f64 {
        (mean - expected) / (sigma / (k as f64).sqrt())
    }

    #[test]
    fn a_cosine_weighted_direction_is_a_unit_vector_on_the_normals_side() {
        for n in normals() {
            for d in cosine_directions(n, 10_000) {
                assert!((d.length() - 1.0).abs() < 1e-5, "|{d}| about {n}");
                assert!(d.dot(n) >= 0.0, "{d} is below the surface of normal {n}");
            }
        }
    }

    #[test]
    fn cosine_directions_have_the_mean_cosine_of_two_thirds() {
        // E[cos θ] under cos θ/π is ∫cos²θ dω/π = 2/3; its variance is
        // E[cos²] − (2/3)² = 1/2 − 4/9 = 1/18. (Uniform directions on the
        // hemisphere have the mean cosine 1/2.)
        for n in normals() {
            let d = cosine_directions(n, 100_000);
            let mean = d.iter().map(|d| f64::from(d.dot(n))).sum::<f64>() / d.len() as f64;
            let z = z(mean, 2.0 / 3.0, (1.0f64 / 18.0).sqrt(), d.len());
            assert!(
                z.abs() < 4.0,
                "about {n}: mean cosine {mean:.4}, z = {z:.1}"
            );
        }
    }

    /// three quarters of cosine directions are within 60° of the normal
    #[test]
    fn three_quarters_of_cosine_directions_are_within_60_degrees_of_the_normal() {
        // P(θ < α) = sin²α under cos θ/π: sin²60° = 3/4 (uniform
        // directions: 1 − cos 60° = 1/2).
        for n in normals() {
            let d = cosine_directions(n, 100_000);
            let share = d.iter().filter(|d| d.dot(n) > 0.5).count() as f64 / d.len() as f64;
            let z = z(share, 0.75, (0.75f64 * 0.25).sqrt(), d.len());
            assert!(
                z.abs() < 4.0,
                "about {n}: {share:.4} within 60°, z = {z:.1}"
            );
        }
    }

    #[test]
    fn cosine_directions_are_spread_evenly_around_the_normal() {
        // Their mean is 2/3 · n: the parts across n cancel, each of
        // variance E[sin²θ]/2 = 1/4, a standard deviation of 1/2.
        for n in normals() {
            let d = cosine_directions(n, 100_000);
            let mean = d.iter().copied().sum::<Vec3>() / d.len() as f32;
            let across = mean - mean.dot(n) * n;
            for (axis, part) in [("x", across.x), ("y", across.y), ("z", across.z)] {
                let z = z(f64::from(part), 0.0, 0.5, d.len());
                assert!(
                    z.abs() < 4.0,
                    "about {n}: the mean direction {mean} leans along {axis} (z = {z:.1})"
                );
            }
        }
    }

    // ANCHOR_END: cosine_tests

    /// The lab's tracer with lab materials and a point sun.
    fn lab_tracer(scene: &Scene) -> PathTracer<'_> {
        PathTracer {
            scene,
            objects: scene,
            sun: Sunlight::new(&scene.sun, None),
            materials: Materials::Lab,
            max_depth: 10,
            epsilon: 1e-4,
            caustics: None,
        }
    }

    /// A ray straight down onto the top of the lab's glass (r 0.1, t 0.7).
    fn glass_hit_head_on() -> Hit {
        Hit {
            t: 1.0,
            point: Vec3::ZERO,
            normal: Vec3::Y,
            facing_normal: Vec3::Y,
            entering: true,
            object: Object::Sphere(1),
            material: Material::new(Vec3::ONE, 0.1, 0.7, 1.5).unwrap(),
        }
    }

    // ANCHOR: lobe_tests
    #[test]
    fn a_matte_surface_always_takes_the_diffuse_lobe() {
        let scene = Scene::lab();
        let tracer = lab_tracer(&scene);
        let hit = Hit {
            material: Material::new(Vec3::ONE, 0.0, 0.0, 1.0).unwrap(),
            ..glass_hit_head_on()
        };
        for u in [0.0, 0.3, 0.999] {
            assert_eq!(tracer.choose_lobe(Vec3::NEG_Y, &hit, u), Lobe::Diffuse);
        }
    }

    #[test]
    fn a_perfect_mirror_always_takes_the_mirror_lobe() {
        let scene = Scene::lab();
        let tracer = lab_tracer(&scene);
        let hit = Hit {
            material: Material::new(Vec3::ONE, 1.0, 0.0, 1.0).unwrap(),
            ..glass_hit_head_on()
        };
        for u in [0.0, 0.3, 0.999] {
            assert_eq!(tracer.choose_lobe(Vec3::NEG_Y, &hit, u), Lobe::Mirror);
        }
    }

    #[test]
    fn each_lobe_is_chosen_as_often_as_its_share() {
        let scene = Scene::lab();
        let tracer = lab_tracer(&scene);
        let hit = glass_hit_head_on();
        let mut counts = [0; 3];
        for i in 0..1000 {
            let lobe = tracer.choose_lobe(Vec3::NEG_Y, &hit, (i as f32 + 0.5) / 1000.0);
            counts[lobe as usize] += 1;
        }
        assert_eq!(
            counts,
            [200, 100, 700],
            "(diffuse, mirror, refraction) of 1000 evenly spread u on the lab's glass"
        );
        // With Fresnel, head on: s·F = 0.8 · 0.04 = 0.032 mirrors.
        let fresnel = PathTracer {
            materials: Materials::Fresnel,
            ..tracer
        };
        let mut counts = [0; 3];
        for i in 0..1000 {
            let lobe = fresnel.choose_lobe(Vec3::NEG_Y, &hit, (i as f32 + 0.5) / 1000.0);
            counts[lobe as usize] += 1;
        }
        assert_eq!(
            counts,
            [200, 32, 768],
            "(diffuse, mirror, refraction) with Fresnel, head on"
        );
    }

    // ANCHOR_END: lobe_tests

    // ANCHOR: nee_tests
    /// A diffuse hit of albedo `albedo` at `point`, facing `normal`.
    fn matte_hit(point: Vec3, normal: Vec3, albedo: f32) -> Hit {
        Hit {
            t: 1.0,
            point,
            normal,
            facing_normal: normal,
            entering: true,
            object: Object::Ground,
            material: Material::new(Vec3::splat(albedo), 0.0, 0.0, 1.0).unwrap(),
        }
    }

    /// The sun's light at `hit` by next-event estimation, and the rays it traced.
    fn next_event(tracer: &PathTracer<'_>, hit: &Hit) -> (Vec3, u32) {
        let mut random = Random(raylab::sampling::sample_rng(
            5,
            (0, 0),
            0,
            raylab::sampling::Stream::Path,
        ));
        let mut rays = 0;
        let light = tracer.sun_next_event(hit, &mut random, &mut rays);
        (light, rays)
    }

    /// next-event estimation of open ground is albedo/π · 2.5 · cos θ
    #[test]
    fn next_event_estimation_of_open_ground_is_albedo_over_pi_times_2_5_times_cos() {
        // L = (−1, 1.2, 0.8)/√3.08, so cos θ = L.y = 0.683763 on the
        // ground, and 0.75/π · 2.5 · 0.683763 = 0.408091. Far out on the
        // sun's side, nothing is in the way.
        let scene = Scene::lab();
        let hit = matte_hit(Vec3::new(-20.5, 0.0, 19.5), Vec3::Y, 0.75);
        let (light, rays) = next_event(&lab_tracer(&scene), &hit);
        assert!(
            light.abs_diff_eq(Vec3::splat(0.408091), 1e-5),
            "{light}, not 0.408091 in each channel"
        );
        assert_eq!(rays, 1, "one shadow ray, counted");
    }

    /// next-event estimation of a surface in the sun's shadow adds nothing
    #[test]
    fn next_event_estimation_of_a_surface_in_the_suns_shadow_adds_nothing() {
        // The red sphere's centre (0, 1, −1.5) seen from the ground along
        // L: (0, 1, −1.5) − L/L.y = (5/6, 0, −13/6).
        let scene = Scene::lab();
        let hit = matte_hit(Vec3::new(5.0 / 6.0, 0.0, -13.0 / 6.0), Vec3::Y, 0.75);
        let (light, rays) = next_event(&lab_tracer(&scene), &hit);
        assert_eq!(light, Vec3::ZERO, "the red sphere is in the way");
        assert_eq!(rays, 1, "the shadow ray is traced, and counted");
    }

    /// next-event estimation of a surface facing away from the sun adds nothing and traces no ray
    #[test]
    fn next_event_estimation_of_a_surface_facing_away_from_the_sun_adds_nothing_and_traces_no_ray()
    {
        let scene = Scene::lab();
        let hit = matte_hit(Vec3::new(-20.5, 0.0, 19.5), Vec3::NEG_Y, 0.75);
        let (light, rays) = next_event(&lab_tracer(&scene), &hit);
        assert_eq!(light, Vec3::ZERO, "the sun is behind the surface");
        assert_eq!(rays, 0, "no shadow ray for a sun behind the surface");
    }

    #[test]
    fn the_shadow_ray_starts_off_the_surface_so_a_point_rounded_below_the_ground_is_still_lit() {
        // A hit point rounded 1e-6 below the ground: a shadow ray from it
        // meets the ground at once ("shadow acne"); one started
        // epsilon = 1e-4 along L is 6.8e-5 above it.
        let scene = Scene::lab();
        let hit = matte_hit(Vec3::new(-20.5, -1e-6, 19.5), Vec3::Y, 0.75);
        let (light, _) = next_event(&lab_tracer(&scene), &hit);
        assert!(
            light.abs_diff_eq(Vec3::splat(0.408091), 1e-5),
            "{light}, not 0.408091 in each channel, at a point rounded 1e-6 below open ground \
             (0 here while open ground gets 0.408091 is the ground shadowing itself)"
        );
    }

    /// with a disc sun, next-event estimation averages the cosine over the disc
    #[test]
    fn with_a_disc_sun_next_event_estimation_averages_the_cosine_over_the_disc() {
        // A surface facing L under a disc 60° across, α = 30°: directions
        // uniform over the disc have the mean cosine (1 + cos α)/2 =
        // 0.9330 with L, so the light is 1/π · 2.5 · 0.9330 = 0.74246 on
        // average, not the point sun's 0.79577.
        let scene = Scene::lab();
        let tracer = PathTracer {
            sun: Sunlight::new(&scene.sun, Some(60.0)),
            ..lab_tracer(&scene)
        };
        let hit = matte_hit(Vec3::new(0.0, 100.0, 0.0), scene.sun.direction, 1.0);
        let mut random = Random(raylab::sampling::sample_rng(
            5,
            (0, 0),
            0,
            raylab::sampling::Stream::Path,
        ));
        let (mut sum, mut rays, k) = (0.0f64, 0, 10_000);
        for _ in 0..k {
            sum += f64::from(tracer.sun_next_event(&hit, &mut random, &mut rays).x);
        }
        let mean = sum / f64::from(k);
        assert!(
            (mean - 0.74246).abs() < 0.002,
            "mean {mean:.5} over {k} draws under a sun 60° across, not 0.74246 ± 0.002 \
             (a point sun gives 0.79577)"
        );
        assert_eq!(rays, k, "one shadow ray per draw");
    }
    // ANCHOR_END: nee_tests
}
