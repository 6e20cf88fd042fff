//! Chapter 4: refraction.
//!
//! A transparent surface lets a share `t` of the light through, bent by
//! Snell's law. Inside the glass the ray meets the surface again from
//! within and bends once more on the way out — unless it arrives too
//! steeply, when no light gets out and all of it is reflected back inside
//! (total internal reflection).

use ch03_reflection::Reflection;
use raylab::optics::{reflect, refract};
use raylab::probe::ProbeTarget;
use raylab::{Hit, Ray, RayKind, Step, Surface, Vec3};
use raylab_cli::Chapter;

// ANCHOR: refraction
/// Send the transmitted share of the light on through the surface.
pub fn send_refraction(ray: &Ray, hit: &Hit, surface: &mut Surface) {
    // ANCHOR: todo_send_refraction "If the material transmits (t > 0), send a Refraction ray of share t bent by Snell's law (eta = 1/ior going in, ior coming out), or a TotalInternalReflection ray when refract finds none."
    let t = hit.material.transmission();
    if t <= 0.0 {
        return;
    }
    // Going from air into the material the ratio n₁/n₂ is 1/ior; coming out
    // of it, ior/1. `hit.entering` is the sign of dot(d, n).
    let ior = hit.material.ior();
    let eta = if hit.entering { 1.0 / ior } else { ior };
    // Every new direction is normalised: inside the glass a ray can bounce
    // many times, and the rounding of each bounce would compound until the
    // refract formula saw a false total internal reflection.
    match refract(ray.direction, hit.facing_normal, eta) {
        Some(bent) => {
            let direction = bent.normalize();
            let origin = hit.point + direction * surface.epsilon();
            surface.send(RayKind::Refraction, Ray::new(origin, direction), t);
        }
        None => {
            // Total internal reflection: no refracted direction exists, so
            // the transmitted share goes along the mirror direction instead.
            // (The original GLSL lab pushed a ray with the zero direction
            // here, and that light was lost.)
            let direction = reflect(ray.direction, hit.facing_normal).normalize();
            let origin = hit.point + direction * surface.epsilon();
            surface.send(
                RayKind::TotalInternalReflection,
                Ray::new(origin, direction),
                t,
            );
        }
    }
    // ANCHOR_END: todo_send_refraction
}
// ANCHOR_END: refraction

// ANCHOR: step
/// Chapter 3's shading and reflection, then a transmitted ray for the
/// share `t`: the reflected ray is pushed first, so the transmitted one is
/// traced first.
pub struct Refraction;

impl Step for Refraction {
    fn shade(&self, ray: &Ray, hit: &Hit, surface: &mut Surface) -> Vec3 {
        let local = Reflection.shade(ray, hit, surface);
        send_refraction(ray, hit, surface);
        local
    }
}
// ANCHOR_END: step

/// Chapter 4's program: refraction on, rays up to depth 10.
pub const CHAPTER: Chapter<Refraction> = Chapter {
    binary: "ch04-refraction",
    about: "Chapter 4, refraction: glass bends rays by Snell's law, or reflects them all inside.",
    max_depth: 10,
    spp: 1,
    // Off the glass ball's centre, about 60 % of the way to its outline,
    // where the refracted rays visibly bend (through the centre they run
    // straight).
    probe: ProbeTarget::OnSphere {
        name: "glass",
        right: 0.5,
        up: 0.3,
    },
    step: Refraction,
    render: raylab::render,
};

#[cfg(test)]
mod tests {
    use super::*;
    use raylab::scene::Object;
    use raylab::{Camera, Scene, Tracer};

    const GLASS: Vec3 = Vec3::new(1.0, 0.6, 0.8);

    #[test]
    fn a_ray_through_the_glass_centre_leaves_undeviated() {
        let scene = Scene::lab();
        let eye = Camera::lab().eye;
        let primary = Ray::new(eye, (GLASS - eye).normalize());
        let mut tracer = Tracer::new(&scene, &Refraction, 3, 1e-4).with_log();
        tracer.trace(primary);
        let log = tracer.log();
        let inside = log
            .iter()
            .find(|r| r.kind == RayKind::Refraction && r.depth == 2)
            .expect("a refracted ray into the glass");
        let out = log
            .iter()
            .find(|r| r.kind == RayKind::Refraction && r.depth == 3)
            .expect("a refracted ray out of the glass");
        assert_eq!(inside.hit.map(|h| h.0), Some(Object::Sphere(1)));
        assert!((inside.weight - 0.7).abs() < 1e-7);
        assert!((out.weight - 0.49).abs() < 1e-6);
        for ray in [inside, out] {
            assert!(
                ray.ray.direction.abs_diff_eq(primary.direction, 1e-4),
                "{:?}",
                ray.ray
            );
        }
        // It crossed a whole diameter, 1.2, inside the glass.
        assert!((inside.hit.unwrap().1 - 1.2).abs() < 1e-3);
    }

    #[test]
    fn a_grazing_ray_inside_the_glass_is_totally_internally_reflected() {
        // From near the centre of the glass, almost along the surface at the
        // point it reaches: 80° from the normal, beyond the critical 41.8°.
        let scene = Scene::lab();
        let normal = Vec3::X;
        let exit = GLASS + normal * 0.6;
        let along = Vec3::Y;
        let (s, c) = 80f32.to_radians().sin_cos();
        let direction = (normal * c + along * s).normalize();
        let start = exit - direction * 0.2;
        let mut tracer = Tracer::new(&scene, &Refraction, 2, 1e-4).with_log();
        tracer.trace(Ray::new(start, direction));
        let log = tracer.log();
        assert!(!log.is_empty());
        let tir: Vec<_> = log
            .iter()
            .filter(|r| r.kind == RayKind::TotalInternalReflection)
            .collect();
        let traced: Vec<String> = log
            .iter()
            .map(|r| format!("{:?} at depth {}", r.kind, r.depth))
            .collect();
        assert_eq!(
            tir.len(),
            1,
            "totally internally reflected rays, of those traced: {}",
            traced.join(", ")
        );
        assert!((tir[0].weight - 0.7).abs() < 1e-7);
        assert!(
            !log.iter().any(|r| r.kind == RayKind::Refraction),
            "a refracted ray past the critical angle, of those traced: {}",
            traced.join(", ")
        );
        // The reflected ray stays inside: it heads back towards the centre side.
        assert!(tir[0].ray.direction.dot(normal) < 0.0);
    }
}
