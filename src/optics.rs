//! The laws of geometric optics: the two a Whitted ray tracer needs, and
//! the Fresnel reflectance that chapter 6's `--materials fresnel` adds.

use crate::Vec3;

// ANCHOR: reflect
/// Mirror `d` about the normal `n` (GLSL `reflect`): `d − 2·dot(d, n)·n`.
///
/// `n` must be unit length; the result is as long as `d`.
#[inline]
pub fn reflect(d: Vec3, n: Vec3) -> Vec3 {
    // ANCHOR: todo_reflect "Mirror d about the unit normal n: d − 2 · dot(d, n) · n."
    d - 2.0 * d.dot(n) * n
    // ANCHOR_END: todo_reflect
}
// ANCHOR_END: reflect

// ANCHOR: refract
/// Bend the unit direction `i` through a surface with unit normal `n`
/// facing it (GLSL `refract`), where `eta` = n₁/n₂ is the ratio of the
/// indices of refraction on the incoming and the outgoing side.
///
/// Returns `None` on total internal reflection: when Snell's law asks for
/// `sin θ₂ = eta · sin θ₁ > 1`, no refracted direction exists (GLSL returns
/// the zero vector there).
#[inline]
pub fn refract(i: Vec3, n: Vec3, eta: f32) -> Option<Vec3> {
    // ANCHOR: todo_refract "GLSL refract: k = 1 − eta² (1 − dot(n, i)²); None if k < 0 (total internal reflection), else eta · i − (eta · dot(n, i) + √k) · n."
    let cos_i = n.dot(i); // negative: `i` points into the surface
    let k = 1.0 - eta * eta * (1.0 - cos_i * cos_i); // = cos² θ₂
    if k < 0.0 {
        return None;
    }
    Some(eta * i - (eta * cos_i + k.sqrt()) * n)
    // ANCHOR_END: todo_refract
}
// ANCHOR_END: refract

// ANCHOR: fresnel
/// The exact Fresnel reflectance of unpolarised light at a smooth
/// dielectric interface: the share of the light that is reflected, the rest
/// being refracted. `cos_i` is the cosine of the angle between the incoming
/// ray and the normal (either sign), `eta` = n₁/n₂ as for [`refract`].
///
/// `F = (R_s + R_p) / 2`, the mean of the two polarisations:
/// `R_s = ((η cos θᵢ − cos θₜ) / (η cos θᵢ + cos θₜ))²` and
/// `R_p = ((η cos θₜ − cos θᵢ) / (η cos θₜ + cos θᵢ))²`, with
/// `sin θₜ = η sin θᵢ` (Snell). Under total internal reflection it is 1.
pub fn fresnel(cos_i: f32, eta: f32) -> f32 {
    let cos_i = cos_i.abs().min(1.0);
    let sin2_t = eta * eta * (1.0 - cos_i * cos_i);
    if sin2_t >= 1.0 {
        return 1.0; // no refracted direction: everything is reflected
    }
    let cos_t = (1.0 - sin2_t).sqrt();
    let r_s = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    let r_p = (eta * cos_t - cos_i) / (eta * cos_t + cos_i);
    0.5 * (r_s * r_s + r_p * r_p)
}
// ANCHOR_END: fresnel

// ANCHOR: tests
#[cfg(test)]
mod tests {
    use super::*;

    // ANCHOR: reflect_tests
    /// reflecting at 45° turns down into up
    #[test]
    fn reflecting_at_45_degrees_turns_down_into_up() {
        let d = Vec3::new(1.0, -1.0, 0.0);
        assert_eq!(reflect(d, Vec3::Y), Vec3::new(1.0, 1.0, 0.0));
    }

    #[test]
    fn reflecting_head_on_sends_the_ray_back() {
        assert_eq!(reflect(Vec3::NEG_Z, Vec3::Z), Vec3::Z);
    }
    // ANCHOR_END: reflect_tests

    // ANCHOR: refract_tests

    #[test]
    fn refracting_head_on_does_not_bend() {
        let t = refract(Vec3::NEG_Y, Vec3::Y, 1.0 / 1.5).unwrap();
        assert!(t.abs_diff_eq(Vec3::NEG_Y, 1e-6), "{t}");
    }

    /// entering glass at 45° bends towards the normal
    #[test]
    fn entering_glass_at_45_degrees_bends_towards_the_normal() {
        // sin θ₂ = sin 45° / 1.5 = 0.4714: θ₂ = 28.13°.
        let i = Vec3::new(1.0, -1.0, 0.0).normalize();
        let t = refract(i, Vec3::Y, 1.0 / 1.5).unwrap();
        assert!((t.length() - 1.0).abs() < 1e-6);
        assert!((t.x - 0.471_404_5).abs() < 1e-6, "sin θ₂ = {}", t.x);
        assert!((t.y + 0.881_917_1).abs() < 1e-6, "cos θ₂ = {}", -t.y);
    }

    /// leaving glass at 20° bends away from the normal
    #[test]
    fn leaving_glass_at_20_degrees_bends_away_from_the_normal() {
        // Inside the glass, 20° from the normal: sin θ₂ = 1.5 · sin 20° = 0.5130.
        let (s, c) = 20f32.to_radians().sin_cos();
        let i = Vec3::new(s, c, 0.0); // going up, out through a surface facing down at it
        let t = refract(i, Vec3::NEG_Y, 1.5).unwrap();
        assert!((t.x - 0.513_030_1).abs() < 1e-6, "sin θ₂ = {}", t.x);
        assert!((t.length() - 1.0).abs() < 1e-6);
    }

    #[test]
    fn leaving_glass_beyond_the_critical_angle_is_total_internal_reflection() {
        // The critical angle of glass (1.5) is asin(1/1.5) = 41.81°; 45° is past it.
        let i = Vec3::new(1.0, 1.0, 0.0).normalize();
        assert_eq!(refract(i, Vec3::NEG_Y, 1.5), None);
        // Just below the critical angle the ray still gets out.
        let (s, c) = 41.5f32.to_radians().sin_cos();
        assert!(refract(Vec3::new(s, c, 0.0), Vec3::NEG_Y, 1.5).is_some());
    }
    // ANCHOR_END: refract_tests

    /// glass reflects 4 % head on
    #[test]
    fn glass_reflects_four_percent_head_on() {
        assert!((fresnel(1.0, 1.0 / 1.5) - 0.04).abs() < 1e-6);
        // The same from inside: reciprocity.
        assert!((fresnel(1.0, 1.5) - 0.04).abs() < 1e-6);
    }

    /// glass reflects 5.024 % at 45°
    #[test]
    fn glass_reflects_5_024_percent_at_45_degrees() {
        let f = fresnel(45f32.to_radians().cos(), 1.0 / 1.5);
        assert!((f - 0.05024).abs() < 1e-5, "{f}");
    }

    /// near grazing, glass reflects 45.931 %, where Schlick says 48.881 %
    #[test]
    fn near_grazing_glass_reflects_45_931_percent_where_schlick_says_48_881() {
        let f = fresnel(0.141_067, 1.0 / 1.5);
        assert!((f - 0.45931).abs() < 1e-5, "{f}");
        let schlick = 0.04 + 0.96 * (1.0f32 - 0.141_067).powi(5);
        assert!((schlick - 0.48881).abs() < 1e-5, "{schlick}");
    }

    #[test]
    fn fresnel_reflectance_is_one_under_total_internal_reflection() {
        // Inside glass at 45°, beyond the critical angle of 41.81°.
        assert_eq!(fresnel(45f32.to_radians().cos(), 1.5), 1.0);
        assert_eq!(
            refract(Vec3::new(1.0, 1.0, 0.0).normalize(), Vec3::NEG_Y, 1.5),
            None
        );
    }

    #[test]
    fn reflected_and_transmitted_shares_add_up_to_one_at_every_angle() {
        // T is what the interface does not reflect: check it by the energy
        // flux of the refracted beam, T = (cos θₜ / (η cos θᵢ)) · |t|²
        // averaged over the two polarisations, from the amplitude
        // coefficients t_s = 2η cos θᵢ / (η cos θᵢ + cos θₜ) and
        // t_p = 2η cos θᵢ / (η cos θₜ + cos θᵢ).
        for eta in [1.0 / 1.5, 1.5, 1.0 / 1.33] {
            for step in 0..=100 {
                let cos_i = step as f32 / 100.0;
                let sin2_t = eta * eta * (1.0 - cos_i * cos_i);
                let r = fresnel(cos_i, eta);
                assert!((0.0..=1.0).contains(&r), "eta {eta}, cos {cos_i}: {r}");
                if sin2_t >= 1.0 {
                    assert_eq!(r, 1.0);
                    continue;
                }
                let cos_t = (1.0 - sin2_t).sqrt();
                let t_s = 2.0 * eta * cos_i / (eta * cos_i + cos_t);
                let t_p = 2.0 * eta * cos_i / (eta * cos_t + cos_i);
                let t = cos_t / (eta * cos_i).max(1e-30) * 0.5 * (t_s * t_s + t_p * t_p);
                if cos_i > 0.0 {
                    assert!(
                        (r + t - 1.0).abs() < 1e-4,
                        "eta {eta}, cos {cos_i}: R {r} + T {t}"
                    );
                }
            }
        }
    }
}
// ANCHOR_END: tests
