//! `--like chNN-…`: which of chapters 1–5 the shader traces as
//! ([`raylab_like`], shared with chapters 7 and 9, which imitate the same
//! chapters on the CPU).
//!
//! The shader holds every feature of chapters 1–5; three bits of its
//! uniforms switch them on (`features` in `tracer.wgsl`). With `--like
//! ch03-reflection` it has chapter 3's features (shadows and mirrors, no
//! glass) and its defaults (depth 10, one ray per pixel).

pub use raylab_like::{Features, Like};

/// The shader's `params.features`: bit 0 shadows, bit 1 reflection, bit 2
/// transmission.
pub fn feature_bits(features: Features) -> u32 {
    u32::from(features.shadows)
        | u32::from(features.reflection) << 1
        | u32::from(features.transmission) << 2
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_chapter_switches_on_one_more_feature_bit() {
        let bits: Vec<u32> = Like::ALL
            .iter()
            .map(|l| feature_bits(l.features()))
            .collect();
        assert_eq!(bits, [0b000, 0b001, 0b011, 0b111, 0b111]);
    }
}
