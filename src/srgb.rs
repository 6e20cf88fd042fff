//! From linear light to the 8-bit numbers in a PNG.

// ANCHOR: encode
/// The sRGB transfer function: linear light in [0, 1] to the non-linear
/// value a display expects. Brightness perception is roughly logarithmic,
/// so the curve spends more of the 256 levels on dark tones.
pub fn linear_to_srgb(c: f32) -> f32 {
    if c <= 0.003_130_8 {
        12.92 * c
    } else {
        1.055 * c.powf(1.0 / 2.4) - 0.055
    }
}

/// One linear channel to an 8-bit sRGB value: clamp, encode, round
/// (halves away from zero). Light brighter than white clips to 255.
pub fn encode_channel(c: f32) -> u8 {
    // A NaN never reaches here (the renderer checks every pixel), but if it
    // did it must not become an arbitrary byte: it encodes as black.
    let c = if c.is_nan() { 0.0 } else { c.clamp(0.0, 1.0) };
    quantise(linear_to_srgb(c))
}

/// An encoded value in [0, 1] to the nearest of 256 levels, halves away
/// from zero (`f32::round`, not round-half-to-even).
pub fn quantise(v: f32) -> u8 {
    (255.0 * v).round() as u8
}
// ANCHOR_END: encode

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn black_and_white_stay_black_and_white() {
        assert_eq!(encode_channel(0.0), 0);
        assert_eq!(encode_channel(1.0), 255);
    }

    #[test]
    fn light_beyond_white_and_below_black_is_clamped() {
        assert_eq!(encode_channel(7.5), 255);
        assert_eq!(encode_channel(-0.2), 0);
        assert_eq!(encode_channel(f32::INFINITY), 255);
    }

    #[test]
    fn the_dark_end_is_the_linear_segment() {
        // 0.001 · 12.92 · 255 = 3.2946: rounds to 3.
        assert!((linear_to_srgb(0.001) - 0.012_92).abs() < 1e-9);
        assert_eq!(encode_channel(0.001), 3);
    }

    #[test]
    fn mid_grey_encodes_to_188() {
        // 1.055 · 0.5^(1/2.4) − 0.055 = 0.735357; · 255 = 187.52.
        assert!((linear_to_srgb(0.5) - 0.735_357).abs() < 1e-6);
        assert_eq!(encode_channel(0.5), 188);
    }

    #[test]
    fn a_level_exactly_half_way_rounds_away_from_zero() {
        // Find the f32 with 255 · v = 2.5 exactly; round-half-to-even would give 2.
        let near = (5.0f32 / 510.0).to_bits();
        let v = (-8..=8)
            .map(|i| f32::from_bits(near.wrapping_add_signed(i)))
            .find(|v| 255.0 * v == 2.5)
            .expect("an f32 with 255 · v = 2.5");
        assert_eq!(quantise(v), 3);
    }
}
