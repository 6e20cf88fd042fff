//! Chapter 1: ray casting.
//!
//! One ray from the eye through each pixel; where it meets a surface, the
//! surface is shaded by the sun (Lambert's cosine law) and a little ambient
//! light; where it meets nothing, the pixel shows the sky. No shadows, no
//! reflections: every ray is a primary ray.

use std::f32::consts::PI;

use raylab::light::Sun;
use raylab::probe::ProbeTarget;
use raylab::{Hit, Ray, Step, Surface, Vec3};
use raylab_cli::Chapter;

// ANCHOR: constants
/// The share of the sun's brightness that reaches a lit surface (`k`).
pub const SUN_LIT: f32 = 0.1;
/// Light from everywhere at once, as a fraction of the albedo: the
/// stand-in for all the light bounced around the scene that we do not trace.
pub const AMBIENT: f32 = 0.04;
// ANCHOR_END: constants

// ANCHOR: local_light
/// The light a surface sends back by itself: a Lambertian (perfectly
/// matte) surface lit by the sun with factor `k`, plus the ambient term.
pub fn local_light(hit: &Hit, sun: &Sun, k: f32) -> Vec3 {
    // ANCHOR: todo_local_light "Return the Lambert term albedo/π · k · brightness · max(cos θ, 0) plus the ambient term albedo · AMBIENT."
    // Lambert: a surface tilted away from the sun catches its light over a
    // larger area, so each point receives less, in proportion to cos θ.
    let cos = hit.facing_normal.dot(sun.direction).max(0.0);
    let irradiance = k * sun.brightness * cos;
    // A Lambertian surface spreads what it reflects evenly over the
    // hemisphere: albedo / π of the irradiance leaves in every direction.
    let albedo = hit.material.albedo();
    albedo / PI * irradiance + albedo * AMBIENT
    // ANCHOR_END: todo_local_light
}
// ANCHOR_END: local_light

// ANCHOR: step
/// Ray casting: shade the first surface a ray hits, as if the sun
/// reached every point.
pub struct RayCast;

impl Step for RayCast {
    fn shade(&self, _ray: &Ray, hit: &Hit, surface: &mut Surface) -> Vec3 {
        local_light(hit, &surface.scene().sun, SUN_LIT)
    }
}
// ANCHOR_END: step

/// Chapter 1's program: the lab model's table gives depth 1, one ray per pixel.
pub const CHAPTER: Chapter<RayCast> = Chapter {
    binary: "ch01-ray-cast",
    about: "Chapter 1, ray casting: one ray per pixel, shaded by the sun and the sky.",
    max_depth: 1,
    spp: 1,
    probe: ProbeTarget::centre_of("red"),
    step: RayCast,
    render: raylab::render,
};

#[cfg(test)]
mod tests {
    use super::*;
    use raylab::material::Material;
    use raylab::scene::Object;

    fn hit_facing(normal: Vec3, albedo: Vec3) -> Hit {
        Hit {
            t: 1.0,
            point: Vec3::ZERO,
            normal,
            facing_normal: normal,
            entering: true,
            object: Object::Ground,
            material: Material::diffuse(albedo).unwrap(),
        }
    }

    #[test]
    fn a_surface_facing_the_sun_gets_the_full_lambert_term() {
        let sun = Sun {
            direction: Vec3::Y,
            brightness: 25.0,
        };
        let hit = hit_facing(Vec3::Y, Vec3::ONE);
        // 1/π · 0.1 · 25 · 1 + 0.04 = 0.795775 + 0.04 = 0.835775
        let c = local_light(&hit, &sun, SUN_LIT);
        assert!((c.x - 0.835_774_9).abs() < 1e-6, "{c}");
    }

    /// a surface at 60° to the sun gets half
    #[test]
    fn a_surface_at_60_degrees_to_the_sun_gets_half() {
        let sun = Sun {
            direction: Vec3::new(60f32.to_radians().sin(), 0.5, 0.0),
            brightness: 25.0,
        };
        let hit = hit_facing(Vec3::Y, Vec3::splat(0.5));
        // 0.5/π · 2.5 · 0.5 + 0.5 · 0.04 = 0.198944 + 0.02 = 0.218944
        let c = local_light(&hit, &sun, SUN_LIT);
        assert!((c.y - 0.218_944).abs() < 1e-6, "{c}");
    }

    #[test]
    fn a_surface_facing_away_from_the_sun_gets_only_ambient() {
        let sun = Sun {
            direction: Vec3::NEG_Y,
            brightness: 25.0,
        };
        let hit = hit_facing(Vec3::Y, Vec3::new(0.5, 0.2, 0.6));
        assert_eq!(
            local_light(&hit, &sun, SUN_LIT),
            Vec3::new(0.5, 0.2, 0.6) * 0.04
        );
    }

    #[test]
    fn a_shadowed_surface_gets_a_tenth_of_the_sunlight() {
        // With k = 0.01 instead of 0.1 (chapter 2's shadow factor).
        let sun = Sun {
            direction: Vec3::Y,
            brightness: 25.0,
        };
        let hit = hit_facing(Vec3::Y, Vec3::ONE);
        // 1/π · 0.01 · 25 + 0.04 = 0.0795775 + 0.04
        let c = local_light(&hit, &sun, 0.01);
        assert!((c.z - 0.119_577_5).abs() < 1e-6, "{c}");
    }
}
