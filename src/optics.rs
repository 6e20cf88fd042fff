//! The two laws of geometric optics a Whitted ray tracer needs.

use crate::Vec3;

// ANCHOR: reflect
/// Mirror `d` about the normal `n` (GLSL `reflect`): `d − 2·dot(d, n)·n`.
///
/// `n` must be unit length; the result is as long as `d`.
pub fn reflect(d: Vec3, n: Vec3) -> Vec3 {
    d - 2.0 * d.dot(n) * n
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
pub fn refract(i: Vec3, n: Vec3, eta: f32) -> Option<Vec3> {
    let cos_i = n.dot(i); // negative: `i` points into the surface
    let k = 1.0 - eta * eta * (1.0 - cos_i * cos_i); // = cos² θ₂
    if k < 0.0 {
        return None;
    }
    Some(eta * i - (eta * cos_i + k.sqrt()) * n)
}
// ANCHOR_END: refract

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reflecting_at_45_degrees_turns_down_into_up() {
        let d = Vec3::new(1.0, -1.0, 0.0);
        assert_eq!(reflect(d, Vec3::Y), Vec3::new(1.0, 1.0, 0.0));
    }

    #[test]
    fn reflecting_head_on_sends_the_ray_back() {
        assert_eq!(reflect(Vec3::NEG_Z, Vec3::Z), Vec3::Z);
    }

    #[test]
    fn refracting_head_on_does_not_bend() {
        let t = refract(Vec3::NEG_Y, Vec3::Y, 1.0 / 1.5).unwrap();
        assert!(t.abs_diff_eq(Vec3::NEG_Y, 1e-6), "{t}");
    }

    #[test]
    fn entering_glass_at_45_degrees_bends_towards_the_normal() {
        // sin θ₂ = sin 45° / 1.5 = 0.4714: θ₂ = 28.13°.
        let i = Vec3::new(1.0, -1.0, 0.0).normalize();
        let t = refract(i, Vec3::Y, 1.0 / 1.5).unwrap();
        assert!((t.length() - 1.0).abs() < 1e-6);
        assert!((t.x - 0.471_404_5).abs() < 1e-6, "sin θ₂ = {}", t.x);
        assert!((t.y + 0.881_917_1).abs() < 1e-6, "cos θ₂ = {}", -t.y);
    }

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
}
