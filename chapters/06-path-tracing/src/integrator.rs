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

/// `--materials`: what the lab's three shares mean physically.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Materials {
    /// The lab's shares as a mixture of three BSDFs, whatever the angle.
    Lab,
    /// A transmitting material splits its specular share by exact Fresnel.
    Fresnel,
}

impl Materials {
    pub fn name(self) -> &'static str {
        match self {
            Materials::Lab => "lab",
            Materials::Fresnel => "fresnel",
        }
    }
}

/// A pixel's light, split by where it came from and how many diffuse
/// scatterings `k` it took (LAB.md "Contributions by term").
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
        // ANCHOR: todo_choose_lobe "Split [0, 1) by the shares, in this order: u below the mirror's share is Lobe::Mirror, below mirror + refraction Lobe::Refraction, the rest Lobe::Diffuse (with Fresnel, the specular share s = r + t splits as s·F and s·(1 − F))."
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
                    // The sun, by next-event estimation: one shadow ray
                    // towards a point of its disc, whose light is
                    // albedo/π · E_sun · cos θ when nothing is in the way.
                    let to_sun = self.sun.draw(random);
                    let cos = nf.dot(to_sun);
                    if cos > 0.0 {
                        *rays += 1;
                        let shadow = Ray::new(hit.point + to_sun * self.epsilon, to_sun);
                        if !self.objects.any_hit(&shadow) {
                            let light = albedo * FRAC_1_PI * self.sun.irradiance * cos;
                            terms.add_sun(diffuse_bounces + 1, throughput * light);
                        }
                    }
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
}
// ANCHOR_END: cosine

#[cfg(test)]
mod tests {
    use super::*;
    use raylab::Material;

    #[test]
    fn cosine_directions_have_the_mean_cosine_of_two_thirds() {
        // E[cos θ] under cos θ/π is ∫cos²θ dω/π = 2/3.
        let n = Vec3::new(0.3, 0.9, -0.2).normalize();
        // Its variance is E[cos²] − (2/3)² = 1/2 − 4/9 = 1/18.
        let mut random = Random(raylab::sampling::sample_rng(
            7,
            (0, 0),
            0,
            raylab::sampling::Stream::Path,
        ));
        let k = 100_000;
        let mut sum = 0.0f64;
        for _ in 0..k {
            let d = cosine_direction(n, &mut random);
            assert!((d.length() - 1.0).abs() < 1e-5);
            assert!(d.dot(n) >= 0.0);
            sum += f64::from(d.dot(n));
        }
        let mean = sum / f64::from(k);
        let z = (mean - 2.0 / 3.0) / (1.0f64 / 18.0 / f64::from(k)).sqrt();
        assert!(z.abs() < 4.0, "mean {mean}, z = {z}");
    }

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

    #[test]
    fn the_mirror_takes_the_lowest_numbers_then_the_refraction_then_the_diffuse() {
        // The order is part of the estimator's definition here: the same
        // random number must pick the same lobe as the reference does, or
        // an image correct on average has other noise than the reference.
        let scene = Scene::lab();
        let tracer = lab_tracer(&scene);
        let hit = glass_hit_head_on();
        let lobe = |u| tracer.choose_lobe(Vec3::NEG_Y, &hit, u);
        // Glass: [0, 0.1) mirror, [0.1, 0.8) refraction, [0.8, 1) diffuse.
        assert_eq!(lobe(0.05), Lobe::Mirror);
        assert_eq!(lobe(0.5), Lobe::Refraction);
        assert_eq!(lobe(0.9), Lobe::Diffuse);
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
        assert_eq!(counts, [200, 100, 700]);
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
        assert_eq!(counts, [200, 32, 768]);
    }
}
