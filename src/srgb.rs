//! From linear light to the 8-bit numbers in a PNG.

// ANCHOR: encode
/// The sRGB transfer function: linear light in [0, 1] to the non-linear
/// value a display expects. Brightness perception is roughly logarithmic,
/// so the curve spends more of the 256 levels on dark tones.
pub fn linear_to_srgb(c: f32) -> f32 {
    // ANCHOR: todo_srgb_curve "The sRGB transfer function: 12.92 · c for c ≤ 0.0031308, else 1.055 · c^(1/2.4) − 0.055."
    if c <= 0.003_130_8 {
        12.92 * c
    } else {
        1.055 * c.powf(1.0 / 2.4) - 0.055
    }
    // ANCHOR_END: todo_srgb_curve
}

/// One linear channel to an 8-bit sRGB value: clamp, encode, round
/// (halves away from zero). Light brighter than white clips to 255.
pub fn encode_channel(c: f32) -> u8 {
    // ANCHOR: todo_srgb_encode "Clamp c to [0, 1] (a NaN becomes 0), apply linear_to_srgb, then quantise."
    // A NaN never reaches here (the renderer checks every pixel), but if it
    // did it must not become an arbitrary byte: it encodes as black.
    let c = if c.is_nan() { 0.0 } else { c.clamp(0.0, 1.0) };
    quantise(linear_to_srgb(c))
    // ANCHOR_END: todo_srgb_encode
}

/// An encoded value in [0, 1] to the nearest of 256 levels, halves away
/// from zero (`f32::round`, not round-half-to-even).
pub fn quantise(v: f32) -> u8 {
    // ANCHOR: todo_srgb_quantise "Round 255 · v to the nearest whole number, halves away from zero, as a byte."
    (255.0 * v).round() as u8
    // ANCHOR_END: todo_srgb_quantise
}
// ANCHOR_END: encode

// ANCHOR: table
/// [`encode_channel`] without a `powf` per channel: a table that gives the
/// same byte for every `f32`, made once from `encode_channel` itself.
///
/// The encoding only ever goes up as `c` does, so it is fixed by the 255
/// *thresholds*, the smallest `c` that encodes to each level 1 to 255. A
/// second table, indexed by the top 16 bits of `c` (its exponent and 7
/// bits of mantissa, so 128 slots per octave), gives the level at the
/// bottom of each slot. The levels climb slowly enough that at most one
/// threshold lies inside a slot (`new` checks it), so one comparison with
/// it finds the byte.
pub struct EncodeTable {
    /// `thresholds[v]`: the smallest `c` that encodes to `v`; level 256,
    /// which no `c` reaches, is infinitely far.
    thresholds: [f32; 257],
    slots: Vec<u8>,
}

/// The smallest `c` in [0, 1] that `encode_channel` takes to `level` (1 to
/// 255) or above. The inverse of the sRGB curve at the level's lower edge
/// (`level − ½` of 255) lands within a few `f32` steps of it; from there,
/// stepping one `f32` at a time (consecutive bit patterns of positive
/// floats are consecutive floats) finds the exact edge, asking
/// `encode_channel` itself, so the answer does not depend on how good the
/// first guess was.
fn smallest_encoding_to(level: u8) -> f32 {
    let v = (f64::from(level) - 0.5) / 255.0;
    let guess = if v <= 12.92 * 0.003_130_8 {
        v / 12.92
    } else {
        ((v + 0.055) / 1.055).powf(2.4)
    };
    let reaches = |bits: u32| encode_channel(f32::from_bits(bits)) >= level;
    let mut bits = (guess as f32).to_bits();
    while !reaches(bits) {
        bits += 1;
    }
    while bits > 0 && reaches(bits - 1) {
        bits -= 1;
    }
    f32::from_bits(bits)
}

/// The slot of a `c` in (0, 1): its top 16 bits.
fn slot(c: f32) -> usize {
    (c.to_bits() >> 16) as usize
}

impl EncodeTable {
    fn new() -> Self {
        let mut thresholds = [f32::INFINITY; 257];
        thresholds[0] = 0.0;
        for (level, threshold) in thresholds.iter_mut().enumerate().take(256).skip(1) {
            *threshold = smallest_encoding_to(level as u8);
        }
        // The level at each slot's bottom: how many thresholds lie at or
        // below it (the encoding only goes up, so that is the byte
        // `encode_channel` gives there), counted in one walk up the slots.
        let mut level = 0;
        let slots: Vec<u8> = (0..=slot(1.0))
            .map(|s| {
                let bottom = f32::from_bits((s as u32) << 16);
                while level < 255 && thresholds[level + 1] <= bottom {
                    level += 1;
                }
                level as u8
            })
            .collect();
        // The level at a slot's bottom and the next slot's bottom differ
        // by at most 1: no slot holds two thresholds.
        assert!(slots.windows(2).all(|w| w[1] - w[0] <= 1));
        EncodeTable { thresholds, slots }
    }

    /// The table, made the first time it is asked for (about a thousand
    /// calls of `encode_channel`).
    pub fn get() -> &'static EncodeTable {
        static TABLE: std::sync::LazyLock<EncodeTable> = std::sync::LazyLock::new(EncodeTable::new);
        &TABLE
    }

    /// A pixel's three bytes: [`EncodeTable::encode`] of each channel.
    pub fn encode_rgb(&self, colour: crate::Vec3) -> [u8; 3] {
        colour.to_array().map(|c| self.encode(c))
    }

    /// The same byte as [`encode_channel`], for every `f32`.
    pub fn encode(&self, c: f32) -> u8 {
        // NaN, negatives and zero are black, and 1 and above white, as the
        // clamp in `encode_channel` makes them (`c > 0` is false for NaN).
        // 1 has a slot of its own, whose level is 255.
        let c = if c > 0.0 { c.min(1.0) } else { 0.0 };
        let level = self.slots[slot(c)];
        // Past the slot's one threshold or not, added without a branch:
        // in a noisy image that is a coin toss, and a branch on it would
        // be mispredicted half the time.
        level + u8::from(c >= self.thresholds[usize::from(level) + 1])
    }
}
// ANCHOR_END: table

// ANCHOR: tests
#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_table_encodes_a_million_spread_values_as_encode_channel_does() {
        // Every 1021st f32 in [0, 1] (a prime stride, so that every slot
        // and every mantissa pattern is visited), and each threshold with
        // its neighbours. `encode_table_matches_for_every_f32` checks all.
        let table = EncodeTable::get();
        for bits in (0..=1.0f32.to_bits()).step_by(1021) {
            let c = f32::from_bits(bits);
            assert_eq!(table.encode(c), encode_channel(c), "{c:e}");
        }
        for &t in &table.thresholds[1..256] {
            for c in [
                f32::from_bits(t.to_bits() - 1),
                t,
                f32::from_bits(t.to_bits() + 1),
            ] {
                assert_eq!(table.encode(c), encode_channel(c), "{c:e}");
            }
        }
    }

    #[test]
    fn each_threshold_is_the_first_f32_that_encodes_to_its_level() {
        let table = EncodeTable::get();
        for level in 1..=255u8 {
            let t = table.thresholds[usize::from(level)];
            let below = f32::from_bits(t.to_bits() - 1);
            assert_eq!(encode_channel(t), level, "level {level}");
            assert_eq!(encode_channel(below), level - 1, "level {level}");
        }
    }

    #[test]
    fn the_table_clamps_nan_infinities_negatives_and_values_above_one() {
        let table = EncodeTable::get();
        for c in [
            f32::NAN,
            -f32::NAN,
            f32::INFINITY,
            f32::NEG_INFINITY,
            -0.0,
            -1e-30,
            -0.5,
            1.0,
            1.000_001,
            7.5,
            f32::MAX,
            f32::MIN_POSITIVE,
            1e-45,
        ] {
            assert_eq!(table.encode(c), encode_channel(c), "{c:e}");
        }
    }

    /// All 1,065,353,217 f32 values in [0, 1]: about two seconds in a release
    /// build. `cargo test --release -p raylab --lib -- --ignored encode_table`
    #[test]
    #[ignore = "exhaustive: run in release with --ignored"]
    fn encode_table_matches_for_every_f32_in_zero_to_one() {
        let table = EncodeTable::get();
        let wrong = (0..=1.0f32.to_bits())
            .filter(|&bits| {
                let c = f32::from_bits(bits);
                table.encode(c) != encode_channel(c)
            })
            .count();
        assert_eq!(wrong, 0);
    }

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
// ANCHOR_END: tests
