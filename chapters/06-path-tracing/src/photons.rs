//! Caustics, traced from the sun.
//!
//! With the sun a single direction, no path from the eye finds the light
//! the glass ball focuses onto the ground: the ground's shadow ray hits the
//! glass, and a random bounce never lands exactly on the sun. So these rays
//! start at the other end. Light rays ("photons") leave the sun towards
//! each sphere that mirrors or refracts, as a parallel beam just wide
//! enough to cover it (pbrt's `DistantLight::SampleLe` does the same with a
//! disc facing the scene), follow the mirror and glass bounces, and leave
//! their power where they land on the ground, in a [`CausticMap`].

use rayon::prelude::*;

use raylab::optics::{reflect, refract};
use raylab::sampling::{Stream, sample_rng};
use raylab::scene::Object;
use raylab::{Ray, SceneQuery};

use crate::caustics::{CausticMap, Photon, ground_axes};
use crate::integrator::{Lobe, PathTracer};
use crate::random::Random;

/// Trace `per_sphere` photons towards every sphere that mirrors or
/// refracts. Paths are limited as eye paths are: at most `max_depth`
/// surface hits, of which the ground is one.
pub fn trace_caustics(
    tracer: &PathTracer<'_, impl SceneQuery + ?Sized>,
    per_sphere: u32,
    seed: u64,
) -> CausticMap {
    let scene = tracer.scene;
    let mut photons = Vec::new();
    let (mut sent, mut rays) = (0u64, 0u64);
    for (index, sphere) in scene.spheres().iter().enumerate() {
        let m = sphere.material;
        if m.reflection() + m.transmission() <= 0.0 {
            continue;
        }
        let (landed, traced) = (0..per_sphere)
            .into_par_iter()
            .fold(
                || (Vec::new(), 0u64),
                |(mut landed, mut traced), n| {
                    // Photon generators are keyed by an impossible pixel
                    // (no image is 2³² wide), so they never share
                    // numbers with the eye's paths.
                    let rng = sample_rng(seed, (u32::MAX, index as u32), n, Stream::Path);
                    let mut random = Random(rng);
                    let mut count = 0;
                    if let Some(p) = photon(tracer, index, per_sphere, &mut random, &mut count) {
                        landed.push(p);
                    }
                    traced += u64::from(count);
                    (landed, traced)
                },
            )
            .reduce(
                || (Vec::new(), 0),
                |(mut a, x), (b, y)| {
                    a.extend(b);
                    (a, x + y)
                },
            );
        photons.extend(landed);
        sent += u64::from(per_sphere);
        rays += traced;
    }
    CausticMap::from_photons(scene, photons, sent, rays)
}

// ANCHOR: photon
/// One photon towards sphere `index`: where it lands on the ground after
/// at least one mirror or glass bounce, or `None` (it was absorbed by a
/// diffuse share, hit a diffuse object first, or escaped).
fn photon(
    tracer: &PathTracer<'_, impl SceneQuery + ?Sized>,
    index: usize,
    per_sphere: u32,
    random: &mut Random,
    rays: &mut u32,
) -> Option<Photon> {
    let scene = tracer.scene;
    let sphere = &scene.spheres()[index].shape;
    // A direction towards the sun, and a point on the disc, facing it,
    // that just covers the sphere; the beam starts beyond every object.
    let to_sun = tracer.sun.sample(random.uniform(), random.uniform());
    let (t, b) = to_sun.any_orthonormal_pair();
    let r = sphere.radius * random.uniform().sqrt();
    let (sin, cos) = (2.0 * std::f32::consts::PI * random.uniform()).sin_cos();
    let far = scene
        .spheres()
        .iter()
        .map(|s| (s.shape.centre - sphere.centre).length() + s.shape.radius)
        .fold(0.0, f32::max)
        + 1.0;
    let origin = sphere.centre + to_sun * far + r * (cos * t + sin * b);
    // Each photon carries an equal part of the power crossing the disc:
    // irradiance E_sun times the disc's area, shared by the photons.
    let power =
        tracer.sun.irradiance * std::f32::consts::PI * sphere.radius.powi(2) / per_sphere as f32;
    let mut ray = Ray::new(origin, -to_sun);
    // `bounces`: the mirror and glass bounces before this hit.
    for bounces in 0..tracer.max_depth {
        *rays += 1;
        let hit = tracer.objects.nearest_hit(&ray)?;
        // The beam is for this sphere: light that meets something else
        // first is some other sphere's beam, or plain direct light.
        if bounces == 0 && hit.object != Object::Sphere(index) {
            return None;
        }
        let d = ray.direction;
        let direction = match tracer.choose_lobe(d, &hit, random.uniform()) {
            Lobe::Diffuse if hit.object == Object::Ground && bounces > 0 => {
                return Some(Photon {
                    u: (hit.point - scene.ground.plane.point).dot(ground_axes(scene).0),
                    v: (hit.point - scene.ground.plane.point).dot(ground_axes(scene).1),
                    power,
                    bounces,
                });
            }
            // Diffuse light is the eye paths' to find.
            Lobe::Diffuse => return None,
            Lobe::Mirror => reflect(d, hit.facing_normal),
            Lobe::Refraction => {
                let ior = hit.material.ior();
                let eta = if hit.entering { 1.0 / ior } else { ior };
                refract(d, hit.facing_normal, eta).unwrap_or_else(|| reflect(d, hit.facing_normal))
            }
        }
        .normalize();
        ray = Ray::new(hit.point + direction * tracer.epsilon, direction);
    }
    None
}
// ANCHOR_END: photon
