//! Chapter 2: shadow rays.
//!
//! Before a surface counts the sun's light, it asks whether the sun can see
//! it: a *feeler* ray from the surface towards the sun. If anything at all
//! is in the way, the surface is in shadow and gets a tenth of the light.

use ch01_ray_cast::{SUN_LIT, local_light};
use raylab::probe::ProbeTarget;
use raylab::{Hit, Ray, Step, Surface, Vec3};
use raylab_cli::Chapter;

// ANCHOR: constants
/// The share of the sun's brightness that reaches a surface in shadow. Not
/// zero: a real shadow is lit by the sky and by other surfaces, light this
/// tracer does not follow, so a constant stands in for it.
pub const SUN_IN_SHADOW: f32 = 0.01;
// ANCHOR_END: constants

// ANCHOR: shadow_ray
/// `k` for this hit: [`SUN_LIT`] if a feeler ray towards the sun escapes,
/// [`SUN_IN_SHADOW`] if it hits anything.
pub fn sun_factor(hit: &Hit, surface: &mut Surface) -> f32 {
    // ANCHOR: todo_sun_factor "Cast a feeler ray from the hit point towards the sun: SUN_IN_SHADOW if anything blocks it, SUN_LIT if not."
    let to_sun = surface.scene().sun.direction;
    // Start the feeler a little way towards the sun: from the hit point
    // itself, rounding puts it just inside the surface half of the time,
    // and it would hit the very surface it leaves ("shadow acne").
    let feeler = Ray::new(hit.point + to_sun * surface.epsilon(), to_sun);
    if surface.trace_shadow_ray(feeler) {
        SUN_IN_SHADOW
    } else {
        SUN_LIT
    }
    // ANCHOR_END: todo_sun_factor
}
// ANCHOR_END: shadow_ray

// ANCHOR: step
/// Chapter 1's shading, with the sun's share decided by a shadow ray.
pub struct Shadows;

impl Step for Shadows {
    fn shade(&self, _ray: &Ray, hit: &Hit, surface: &mut Surface) -> Vec3 {
        let k = sun_factor(hit, surface);
        local_light(hit, &surface.scene().sun, k)
    }
}
// ANCHOR_END: step

/// Chapter 2's program: shadows on, still one ray per pixel and depth 1.
pub const CHAPTER: Chapter<Shadows> = Chapter {
    binary: "ch02-shadows",
    about: "Chapter 2, shadow rays: a feeler ray towards the sun decides whether a point is lit.",
    max_depth: 1,
    spp: 1,
    // A ground point in the yellow ball's shadow, where the line towards
    // the sun crosses the ball high up: the feeler is about a unit long,
    // long enough to see in the ray tree (right under a ball it is a few
    // hundredths).
    probe: ProbeTarget::ShadowOf {
        name: "yellow",
        above: 0.9,
    },
    step: Shadows,
    render: raylab::render,
};

#[cfg(test)]
mod tests {
    use super::*;
    use raylab::scene::Object;
    use raylab::{RayKind, Scene, Tracer};

    /// Trace one ray with a log, and return the shadow rays it cast.
    fn shadow_rays_from(origin: Vec3, target: Vec3) -> Vec<raylab::trace::TracedRay> {
        let scene = Scene::lab();
        let mut tracer = Tracer::new(&scene, &Shadows, 1, 1e-4).with_log();
        tracer.trace(Ray::new(origin, (target - origin).normalize()));
        tracer
            .log()
            .iter()
            .filter(|r| r.kind == RayKind::Shadow)
            .copied()
            .collect()
    }

    #[test]
    fn the_ground_behind_a_sphere_from_the_sun_is_shadowed() {
        // The sun is up and to the left (L = (-1, 1.2, 0.8)/|…|): the red
        // sphere at (0, 1, -1.5) shadows the ground on its right and behind.
        let scene = Scene::lab();
        let l = scene.sun.direction;
        let centre = Vec3::new(0.0, 1.0, -1.5);
        // The ground point whose line towards the sun passes the centre.
        let ground = centre - l * (centre.y / l.y);
        let shadows = shadow_rays_from(ground + Vec3::new(0.0, 3.0, 3.0), ground);
        assert_eq!(shadows.len(), 1);
        let (object, _) = shadows[0].hit.expect("the feeler is blocked");
        assert_eq!(scene.object_name(object), "red");
    }

    #[test]
    fn the_lit_side_of_a_sphere_is_not_shadowed() {
        // The point of the red sphere that faces the sun.
        let scene = Scene::lab();
        let centre = Vec3::new(0.0, 1.0, -1.5);
        let lit = centre + scene.sun.direction;
        let shadows = shadow_rays_from(lit + scene.sun.direction * 2.0, lit);
        assert_eq!(shadows.len(), 1);
        assert_eq!(shadows[0].hit, None, "the feeler reaches the sky");
    }

    #[test]
    fn the_plane_does_not_shadow_itself() {
        // Open ground far from every sphere: the feeler leaves upwards.
        let shadows = shadow_rays_from(Vec3::new(5.0, 2.0, 8.0), Vec3::new(5.0, 0.0, 6.0));
        assert_eq!(shadows[0].hit, None);
        assert!(shadows[0].ray.origin.y > 0.0, "it starts above the ground");
    }

    #[test]
    fn a_feeler_with_no_offset_can_hit_its_own_surface() {
        // With epsilon 0 the feeler starts exactly on the surface; on the
        // side of a sphere, rounding puts many such starts inside it.
        let scene = Scene::lab();
        let centre = Vec3::new(0.0, 1.0, -1.5);
        let mut acne = 0;
        for i in 0..200 {
            let a = i as f32 * 0.01;
            let normal = Vec3::new(a.cos(), 0.3, a.sin()).normalize();
            let point = centre + normal; // on the red sphere
            let mut tracer = Tracer::new(&scene, &Shadows, 1, 0.0).with_log();
            tracer.trace(Ray::new(point + normal * 3.0, -normal));
            let log = tracer.log();
            if log
                .iter()
                .any(|r| r.kind == RayKind::Shadow && r.hit.map(|h| h.0) == Some(Object::Sphere(2)))
            {
                acne += 1;
            }
        }
        assert!(acne > 0, "epsilon 0 shows shadow acne");
    }
}
