//! Caustics, traced from the sun.
//!
//! With the sun a single direction, no path from the eye finds the light
//! the glass ball focuses onto the ground: the ground's shadow ray hits the
//! glass, and a random bounce never lands exactly on the sun. So these rays
//! start at the other end. Light rays ("photons") leave the sun towards
//! each sphere that mirrors or refracts, as a parallel beam just wide
//! enough to cover it (pbrt's `DistantLight::SampleLe` does the same with a
//! disc facing the scene), follow the mirror and glass bounces, and leave
//! their power where they land on the ground. The irradiance at a ground
//! point is then estimated from the photons near it: a density estimate.

use rayon::prelude::*;

use raylab::optics::{reflect, refract};
use raylab::scene::Object;
use raylab::{Ray, Scene, Vec3};

use crate::integrator::{Lobe, PathTracer};
use crate::random::Random;
use raylab::sampling::{Stream, sample_rng};

/// The density estimate's kernel radius on the ground, in scene units
/// (the checker squares are 1 across).
pub const KERNEL_RADIUS: f32 = 0.025;
/// Photons sent towards each mirror or glass sphere.
pub const PHOTONS_PER_SPHERE: u32 = 2_000_000;
/// Photons are kept where they land within this distance of the ground's
/// point, along either axis: the part of the ground the lab camera sees
/// in any detail.
const EXTENT: f32 = 16.0;

/// One photon on the ground.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Photon {
    /// Position in the ground's own two axes.
    u: f32,
    v: f32,
    /// Its power (irradiance × area), per colour channel.
    power: Vec3,
    /// Mirror and glass bounces it took from the sun.
    bounces: u32,
}

/// The photons on the ground, bucketed in a grid of cells one kernel
/// radius across, so that a lookup reads only the 3 × 3 cells around it.
pub struct CausticMap {
    origin: Vec3,
    axis_u: Vec3,
    axis_v: Vec3,
    cells: usize,
    /// Where each cell's photons start in `photons` (one more entry at the end).
    cell_start: Vec<u32>,
    photons: Vec<Photon>,
    /// Light rays sent, and rays traced for them.
    pub sent: u64,
    pub rays: u64,
}

impl CausticMap {
    /// Trace `per_sphere` photons towards every sphere that mirrors or
    /// refracts. Paths are limited as eye paths are: at most `max_depth`
    /// surface hits, of which the ground is one.
    pub fn trace(tracer: &PathTracer, per_sphere: u32, seed: u64) -> CausticMap {
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
                        if let Some(p) = photon(tracer, index, per_sphere, &mut random, &mut count)
                        {
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

    fn from_photons(scene: &Scene, photons: Vec<Photon>, sent: u64, rays: u64) -> CausticMap {
        let plane = scene.ground.plane;
        let (axis_u, axis_v) = plane.normal.any_orthonormal_pair();
        let cells = (2.0 * EXTENT / KERNEL_RADIUS).ceil() as usize;
        let cell_of = |p: &Photon| -> Option<usize> {
            let x = ((p.u + EXTENT) / KERNEL_RADIUS).floor();
            let y = ((p.v + EXTENT) / KERNEL_RADIUS).floor();
            let inside = (0.0..cells as f32).contains(&x) && (0.0..cells as f32).contains(&y);
            inside.then(|| y as usize * cells + x as usize)
        };
        // A counting sort by cell.
        let mut cell_start = vec![0u32; cells * cells + 1];
        for p in &photons {
            if let Some(c) = cell_of(p) {
                cell_start[c + 1] += 1;
            }
        }
        for c in 0..cells * cells {
            cell_start[c + 1] += cell_start[c];
        }
        let mut next = cell_start.clone();
        let kept = cell_start[cells * cells] as usize;
        let none = Photon {
            u: 0.0,
            v: 0.0,
            power: Vec3::ZERO,
            bounces: 0,
        };
        let mut sorted = vec![none; kept];
        for p in &photons {
            if let Some(c) = cell_of(p) {
                sorted[next[c] as usize] = *p;
                next[c] += 1;
            }
        }
        CausticMap {
            origin: plane.point,
            axis_u,
            axis_v,
            cells,
            cell_start,
            photons: sorted,
            sent,
            rays,
        }
    }

    /// How many photons landed on the kept part of the ground.
    pub fn len(&self) -> usize {
        self.photons.len()
    }

    pub fn is_empty(&self) -> bool {
        self.photons.is_empty()
    }

    // ANCHOR: density
    /// The caustic irradiance at ground point `p` from photons that took
    /// at most `max_bounces` mirror and glass bounces: their power, spread
    /// by the Epanechnikov kernel `K(d) = 2/(πh²) · (1 − d²/h²)` of radius
    /// `h` ([`KERNEL_RADIUS`]), which integrates to 1 over the plane.
    pub fn irradiance(&self, p: Vec3, max_bounces: u32) -> Vec3 {
        if max_bounces == 0 {
            return Vec3::ZERO;
        }
        let local = p - self.origin;
        let (u, v) = (local.dot(self.axis_u), local.dot(self.axis_v));
        let h = KERNEL_RADIUS;
        let cx = ((u + EXTENT) / h).floor() as i64;
        let cy = ((v + EXTENT) / h).floor() as i64;
        let last = self.cells as i64 - 1;
        let mut sum = Vec3::ZERO;
        for y in (cy - 1).max(0)..=(cy + 1).min(last) {
            for x in (cx - 1).max(0)..=(cx + 1).min(last) {
                let cell = (y * self.cells as i64 + x) as usize;
                let range = self.cell_start[cell] as usize..self.cell_start[cell + 1] as usize;
                for photon in &self.photons[range] {
                    let d2 = (photon.u - u).powi(2) + (photon.v - v).powi(2);
                    if d2 < h * h && photon.bounces <= max_bounces {
                        sum += photon.power * (1.0 - d2 / (h * h));
                    }
                }
            }
        }
        sum * (2.0 / (std::f32::consts::PI * h * h))
    }
    // ANCHOR_END: density
}

// ANCHOR: photon
/// One photon towards sphere `index`: where it lands on the ground after
/// at least one mirror or glass bounce, or `None` (it was absorbed by a
/// diffuse share, hit a diffuse object first, or escaped).
fn photon(
    tracer: &PathTracer,
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
        let hit = scene.nearest_hit(&ray)?;
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
                    power: Vec3::splat(power),
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

fn ground_axes(scene: &Scene) -> (Vec3, Vec3) {
    scene.ground.plane.normal.any_orthonormal_pair()
}
