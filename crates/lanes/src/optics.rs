//! GLSL's `reflect` and `refract` for eight rays at once, with the
//! contract of the core's [`raylab::optics`]: neither normalises its
//! result (a tracer that wants a unit direction normalises it, as the
//! chapters do), and `refract` says with a mask, not an `Option`, where
//! there is no refracted direction.

use wide::{CmpLt, f32x8};

use crate::vec3x8::Vec3x8;

// ANCHOR: optics
/// `reflect(d, n) = d − 2·dot(d, n)·n` in every lane (`optics::reflect`).
#[inline]
pub fn reflect(d: Vec3x8, n: Vec3x8) -> Vec3x8 {
    d - n.scale(f32x8::splat(2.0) * d.dot(n))
}

/// `refract(i, n, eta)` in every lane (`optics::refract`), and the mask
/// of the lanes where there is no refracted direction (total internal
/// reflection, `k < 0`), where `optics::refract` gives `None`.
#[inline]
pub fn refract(i: Vec3x8, n: Vec3x8, eta: f32x8) -> (Vec3x8, f32x8) {
    let cos_i = n.dot(i);
    let k = f32x8::ONE - eta * eta * (f32x8::ONE - cos_i * cos_i);
    let total = k.cmp_lt(f32x8::ZERO);
    // The lanes with k < 0 take the root of a negative number (NaN); their
    // mask `total` tells the caller to send them along the mirror instead.
    let refracted = i.scale(eta) - n.scale(eta * cos_i + k.sqrt());
    (refracted, total)
}
// ANCHOR_END: optics

#[cfg(test)]
mod tests {
    use super::*;
    use raylab::{Vec3, optics};

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
        let wide_d = Vec3x8::from_lanes(d);
        let r = reflect(wide_d, Vec3x8::splat(n));
        let mut totals = 0;
        for eta in [1.0 / 1.5, 1.5, 2.4] {
            let (t, total) = refract(wide_d, Vec3x8::splat(n), f32x8::splat(eta));
            for (lane, &d) in d.iter().enumerate() {
                assert_eq!(r.lane(lane), optics::reflect(d, n));
                assert_eq!(r.normalize().lane(lane), optics::reflect(d, n).normalize());
                let is_total = total.as_array_ref()[lane] != 0.0;
                match optics::refract(d, n, eta) {
                    Some(bent) => {
                        assert!(!is_total, "lane {lane}, eta {eta}");
                        assert_eq!(t.lane(lane), bent);
                        assert_eq!(t.normalize().lane(lane), bent.normalize());
                    }
                    None => {
                        assert!(is_total, "lane {lane}, eta {eta}");
                        totals += 1;
                    }
                }
            }
        }
        assert!(totals > 0, "some lanes are totally internally reflected");
    }
}
