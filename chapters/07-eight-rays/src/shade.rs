//! The lab's shading for eight hits at once: the same formulas as chapters
//! 1–4, in the same order of operations, so that every lane rounds as the
//! scalar code does.

use ch01_ray_cast::{AMBIENT, SUN_LIT};
use ch02_shadows::SUN_IN_SHADOW;
use raylab::Scene;
use wide::{CmpLt, f32x8};

use crate::intersect::Surfaces;
use crate::soa::Vec3x8;

/// The sky and the sun as eight-lane constants.
#[derive(Clone, Copy, Debug)]
pub struct Light {
    horizon: Vec3x8,
    zenith: Vec3x8,
    /// `L`, from a surface towards the sun.
    pub to_sun: Vec3x8,
    /// `k · E` for a lit and a shadowed point, as `k * E` rounds in scalar code.
    lit: f32x8,
    shadowed: f32x8,
}

impl Light {
    pub fn new(scene: &Scene) -> Self {
        let sun = scene.sun;
        Light {
            horizon: Vec3x8::splat(scene.sky.horizon),
            zenith: Vec3x8::splat(scene.sky.zenith),
            to_sun: Vec3x8::splat(sun.direction),
            lit: f32x8::splat(SUN_LIT * sun.brightness),
            shadowed: f32x8::splat(SUN_IN_SHADOW * sun.brightness),
        }
    }

    // ANCHOR: sky
    /// The sky along eight unit directions (`Sky::radiance`).
    pub fn sky(&self, d: Vec3x8) -> Vec3x8 {
        let t = d.y.max(f32x8::ZERO).min(f32x8::ONE).sqrt();
        self.horizon.scale(f32x8::ONE - t) + self.zenith.scale(t)
    }
    // ANCHOR_END: sky

    // ANCHOR: local
    /// Lambert and ambient (chapter 1's `local_light`) at eight surfaces;
    /// `in_shadow` is the mask of lanes whose shadow ray was blocked.
    pub fn local(&self, s: &Surfaces, in_shadow: f32x8) -> Vec3x8 {
        // `ZERO.max(x)`, not `x.max(ZERO)`: wide's max keeps its first
        // argument when the second is NaN, and `f32::max(NaN, 0)` is 0.
        let cos = f32x8::ZERO.max(s.facing_normal.dot(self.to_sun));
        let irradiance = in_shadow.blend(self.shadowed, self.lit) * cos;
        // `albedo / π · irradiance + albedo · ambient`, with `albedo / π`
        // divided once per material (the same division, the same result).
        let lambert =
            |a: f32x8, a_over_pi: f32x8| a_over_pi * irradiance + a * f32x8::splat(AMBIENT);
        let (a, a_pi) = (s.albedo, s.albedo_over_pi);
        Vec3x8 {
            x: lambert(a.x, a_pi.x),
            y: lambert(a.y, a_pi.y),
            z: lambert(a.z, a_pi.z),
        }
    }
    // ANCHOR_END: local
}

// ANCHOR: optics
/// GLSL's `reflect(d, n) = d − 2·dot(d, n)·n`, normalised as chapter 3 does.
pub fn reflect(d: Vec3x8, n: Vec3x8) -> Vec3x8 {
    let twice = f32x8::splat(2.0) * d.dot(n);
    (d - n.scale(twice)).normalize()
}

/// GLSL's `refract(d, n, eta)`, normalised as chapter 4 does, and the mask
/// of lanes where it does not exist (total internal reflection, `k < 0`).
pub fn refract(d: Vec3x8, n: Vec3x8, eta: f32x8) -> (Vec3x8, f32x8) {
    let cos_i = n.dot(d);
    let k = f32x8::ONE - eta * eta * (f32x8::ONE - cos_i * cos_i);
    // Lanes with k < 0 take the square root of a negative number; the mask
    // sends their light along the mirror direction instead.
    let total = k.cmp_lt(f32x8::ZERO);
    let bent = d.scale(eta) - n.scale(eta * cos_i + k.sqrt());
    (bent.normalize(), total)
}
// ANCHOR_END: optics

#[cfg(test)]
mod tests {
    use super::*;
    use raylab::Vec3;
    use raylab::optics;

    fn lanes(v: [Vec3; 8]) -> Vec3x8 {
        Vec3x8 {
            x: f32x8::from(v.map(|v| v.x)),
            y: f32x8::from(v.map(|v| v.y)),
            z: f32x8::from(v.map(|v| v.z)),
        }
    }

    fn directions() -> [Vec3; 8] {
        std::array::from_fn(|i| {
            let a = i as f32 * 0.37;
            Vec3::new(a.sin(), -0.2 - 0.1 * i as f32, a.cos()).normalize()
        })
    }

    #[test]
    fn eight_reflections_and_refractions_equal_the_scalar_ones_to_the_bit() {
        let d = directions();
        let n = Vec3::new(0.2, 0.9, -0.1).normalize();
        let r = reflect(lanes(d), Vec3x8::splat(n));
        for eta in [1.0 / 1.5, 1.5] {
            let (t, total) = refract(lanes(d), Vec3x8::splat(n), f32x8::splat(eta));
            for (lane, &d) in d.iter().enumerate() {
                assert_eq!(r.lane(lane), optics::reflect(d, n).normalize());
                match optics::refract(d, n, eta) {
                    Some(bent) => assert_eq!(t.lane(lane), bent.normalize()),
                    None => assert_ne!(total.as_array_ref()[lane], 0.0),
                }
            }
        }
    }

    #[test]
    fn the_sky_of_eight_directions_is_the_scalar_sky() {
        let scene = Scene::lab();
        let d = directions().map(|d| Vec3::new(d.x, -d.y, d.z));
        let sky = Light::new(&scene).sky(lanes(d));
        for (lane, &d) in d.iter().enumerate() {
            assert_eq!(sky.lane(lane), scene.sky.radiance(d));
        }
    }
}
