//! The Halton sequence: points that fill the unit square evenly, one
//! digit-reversal at a time.

// ANCHOR: radical_inverse
/// The radical inverse of `index` in `base`: write `index` in that base
/// and mirror its digits about the point. In base 2, 1 = 1₂ → 0.1₂ = 1/2,
/// 2 = 10₂ → 0.01₂ = 1/4, 3 = 11₂ → 0.11₂ = 3/4; in base 3, 1/3, 2/3, 1/9 …
/// Each new point falls in the largest gap the earlier ones left.
pub fn radical_inverse(base: u32, mut index: u32) -> f32 {
    let inverse_base = 1.0 / f64::from(base);
    let (mut value, mut scale) = (0.0f64, inverse_base);
    while index > 0 {
        value += f64::from(index % base) * scale;
        index /= base;
        scale *= inverse_base;
    }
    // In f64 the value is below 1 by at least base⁻²⁰; rounding to f32
    // could still reach 1, which a pixel offset must never be.
    (value as f32).min(ONE_BELOW)
}
// ANCHOR_END: radical_inverse

/// The largest `f32` below 1.
pub const ONE_BELOW: f32 = 1.0 - f32::EPSILON / 2.0;

/// Point `k` (from 0) of the 2-D Halton sequence in bases 2 and 3. It
/// starts at index 1: index 0 would put the first point on the corner.
pub fn halton_2_3(k: u32) -> (f32, f32) {
    (radical_inverse(2, k + 1), radical_inverse(3, k + 1))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn halton_in_base_2_halves_the_gaps() {
        let firsts: Vec<f32> = (0..7).map(|k| halton_2_3(k).0).collect();
        assert_eq!(firsts, [0.5, 0.25, 0.75, 0.125, 0.625, 0.375, 0.875]);
    }

    #[test]
    fn halton_in_base_3_thirds_the_gaps() {
        let expected = [
            1.0 / 3.0,
            2.0 / 3.0,
            1.0 / 9.0,
            4.0 / 9.0,
            7.0 / 9.0,
            2.0 / 9.0,
        ];
        for (k, want) in expected.into_iter().enumerate() {
            let got = halton_2_3(k as u32).1;
            assert!((got - want).abs() < 1e-7, "point {k}: {got} vs {want}");
        }
    }

    #[test]
    fn the_radical_inverse_stays_below_one_for_every_index() {
        for base in [2, 3] {
            for index in (0..=u32::MAX).step_by(65_521) {
                assert!((0.0..1.0).contains(&radical_inverse(base, index)));
            }
            assert!(radical_inverse(base, u32::MAX) < 1.0);
        }
    }
}
