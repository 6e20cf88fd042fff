//! The lab's shading for eight hits at once: the same formulas as chapters
//! 1–4, in the same order of operations, so that every lane rounds as the
//! scalar code does.

use ch01_ray_cast::{AMBIENT, SUN_LIT};
use ch02_shadows::SUN_IN_SHADOW;
use raylab::Scene;
use raylab_lanes::{Hits, SkyX8, Surfaces};
use wide::{CmpGt, f32x8};

use crate::Features;
use crate::soa::Vec3x8;

/// What eight rays' shading computed: the light they add, and the rays
/// they send on (for lanes whose masks are set).
pub(crate) struct Shaded {
    pub added: Vec3x8,
    pub hit: f32x8,
    pub reflects: f32x8,
    pub transmits: f32x8,
    pub reflected: Option<(Vec3x8, Vec3x8)>,
    /// The transmitted direction and origin, and the mask of total
    /// internal reflection (where the mirror direction is used instead).
    pub transmitted: Option<(Vec3x8, Vec3x8, f32x8)>,
    pub reflection: f32x8,
    pub transmission: f32x8,
    /// Set where the ray arrived from outside its surface.
    pub entering: f32x8,
}

/// The sky and the sun as eight-lane constants.
#[derive(Clone, Copy, Debug)]
pub struct Light {
    pub sky: SkyX8,
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
            sky: SkyX8::new(&scene.sky),
            to_sun: Vec3x8::splat(sun.direction),
            lit: f32x8::splat(SUN_LIT * sun.brightness),
            shadowed: f32x8::splat(SUN_IN_SHADOW * sun.brightness),
        }
    }

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

/// Which lanes of eight rays send on a reflected and a transmitted ray:
/// the ones that hit a surface with that share, in a chapter that has come
/// to it.
pub fn senders(surfaces: &Surfaces, hits: &Hits, features: Features) -> (f32x8, f32x8) {
    let zero = f32x8::ZERO;
    let reflects = if features.reflection {
        hits.hit & surfaces.reflection.cmp_gt(zero)
    } else {
        zero
    };
    let transmits = if features.transmission {
        hits.hit & surfaces.transmission.cmp_gt(zero)
    } else {
        zero
    };
    (reflects, transmits)
}
