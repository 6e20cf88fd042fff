//! Chapter 3: reflection.
//!
//! A mirror-like surface sends a share `r` of the light it receives on
//! along the mirror direction. That ray goes on the ray stack, and what it
//! sees is added to the pixel with its weight — through as many bounces as
//! `--max-depth` allows.

use ch02_shadows::Shadows;
use raylab::optics::reflect;
use raylab::probe::ProbeTarget;
use raylab::{Hit, Ray, RayKind, Step, Surface, Vec3};
use raylab_cli::Chapter;

// ANCHOR: reflection
/// Send the reflected share of the light on along the mirror direction.
pub fn send_reflection(ray: &Ray, hit: &Hit, surface: &mut Surface) {
    // ANCHOR: todo_send_reflection "If the material reflects (r > 0), send a Reflection ray of share r along the mirror direction, started epsilon off the surface."
    let r = hit.material.reflection();
    if r > 0.0 {
        // Normalised again: rounding would otherwise shorten or lengthen
        // the direction a little at every bounce.
        let direction = reflect(ray.direction, hit.facing_normal).normalize();
        let origin = hit.point + direction * surface.epsilon();
        surface.send(RayKind::Reflection, Ray::new(origin, direction), r);
    }
    // ANCHOR_END: todo_send_reflection
}
// ANCHOR_END: reflection

// ANCHOR: step
/// Chapter 2's shading for the share `1 − r` the surface keeps, and a
/// reflected ray for the share `r` it mirrors.
pub struct Reflection;

impl Step for Reflection {
    fn shade(&self, ray: &Ray, hit: &Hit, surface: &mut Surface) -> Vec3 {
        send_reflection(ray, hit, surface);
        Shadows.shade(ray, hit, surface)
    }
}
// ANCHOR_END: step

/// Chapter 3's program: reflection on, rays up to depth 10.
pub const CHAPTER: Chapter<Reflection> = Chapter {
    binary: "ch03-reflection",
    about: "Chapter 3, reflection: mirrors send rays on through a ray stack, up to --max-depth.",
    max_depth: 10,
    spp: 1,
    // Near the mirror's right edge, where it reflects the red ball: the
    // reflected ray turns well away from the primary ray (at the centre it
    // would go straight back along it).
    probe: ProbeTarget::OnSphere {
        name: "mirror",
        right: 0.85,
        up: 0.4,
    },
    step: Reflection,
    render: raylab::render,
};

#[cfg(test)]
mod tests {
    use super::*;
    use raylab::scene::Object;
    use raylab::{Camera, Scene, Tracer};

    const MIRROR: Vec3 = Vec3::new(-1.25, 0.5, 0.5);

    /// a mirror hit sends one ray of weight 0.6 in the mirror direction
    #[test]
    fn a_mirror_hit_sends_one_ray_of_weight_0_6_in_the_mirror_direction() {
        let scene = Scene::lab();
        let eye = Camera::lab().eye;
        let primary = Ray::new(eye, (MIRROR - eye).normalize());
        let mut tracer = Tracer::new(&scene, &Reflection, 2, 1e-4).with_log();
        tracer.trace(primary);
        let log = tracer.log();
        assert_eq!(log[0].hit.map(|h| h.0), Some(Object::Sphere(0)));
        let children: Vec<_> = log.iter().filter(|r| r.parent == Some(0)).collect();
        let reflections: Vec<_> = children
            .iter()
            .filter(|r| r.kind == RayKind::Reflection)
            .collect();
        assert_eq!(reflections.len(), 1);
        let reflected = reflections[0];
        assert_eq!(reflected.weight, 0.6);
        assert_eq!(reflected.depth, 2);
        // Aimed at the centre, the ray hits head-on and comes straight back.
        let t = log[0].hit.unwrap().1;
        let normal = (primary.at(t) - MIRROR).normalize();
        let expected = reflect(primary.direction, normal).normalize();
        assert!(reflected.ray.direction.abs_diff_eq(expected, 1e-6));
        assert!(
            reflected
                .ray
                .direction
                .abs_diff_eq(-primary.direction, 1e-4)
        );
    }

    #[test]
    fn the_ground_and_matte_spheres_send_nothing_on() {
        let scene = Scene::lab();
        let mut tracer = Tracer::new(&scene, &Reflection, 10, 1e-4);
        tracer.trace(Ray::new(Vec3::new(0.0, 1.0, 4.0), Vec3::NEG_Y));
        assert_eq!(tracer.counts().get(RayKind::Reflection), 0);
    }
}
