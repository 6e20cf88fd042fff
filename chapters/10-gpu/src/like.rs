//! `--like chNN-…`: which of chapters 1–5 the shader traces as: chapter
//! 7's [`Like`], which imitates the same chapters on the CPU, with this
//! chapter's name in its messages.
//!
//! The shader holds every feature of chapters 1–5; three bits of its
//! uniforms switch them on (`features` in `tracer.wgsl`). With `--like
//! ch03-reflection` it has chapter 3's features (shadows and mirrors, no
//! glass) and its defaults (depth 10, one ray per pixel).

use std::ffi::OsString;

pub use ch07_eight_rays::like::{Features, Like};

/// The shader's `params.features`: bit 0 shadows, bit 1 reflection, bit 2
/// transmission.
pub fn feature_bits(features: Features) -> u32 {
    u32::from(features.shadows)
        | u32::from(features.reflection) << 1
        | u32::from(features.transmission) << 2
}

/// Take `--like NAME` (or `--like=NAME`) out of the arguments; chapter 5
/// when absent. It is read before the rest because it decides the
/// defaults the rest are parsed with (`--max-depth`, `--spp`).
pub fn take_like(args: Vec<OsString>) -> Result<(Like, Vec<OsString>), String> {
    ch07_eight_rays::like::take_like(args)
        .map_err(|message| message.replace("that chapter 7 can", "that chapter 10 can"))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn args(list: &[&str]) -> Vec<OsString> {
        list.iter().map(OsString::from).collect()
    }

    #[test]
    fn each_chapter_switches_on_one_more_feature_bit() {
        let bits: Vec<u32> = Like::ALL
            .iter()
            .map(|l| feature_bits(l.features()))
            .collect();
        assert_eq!(bits, [0b000, 0b001, 0b011, 0b111, 0b111]);
    }

    #[test]
    fn like_is_taken_out_of_the_arguments_in_either_spelling() {
        let (like, rest) =
            take_like(args(&["ch10", "--like", "ch02-shadows", "--spp", "1"])).unwrap();
        assert_eq!(like, Like::Shadows);
        assert_eq!(rest, args(&["ch10", "--spp", "1"]));
        let (like, _) = take_like(args(&["ch10", "--like=ch04"])).unwrap();
        assert_eq!(like, Like::Refraction);
        assert_eq!(take_like(args(&["ch10"])).unwrap().0, Like::AntiAliasing);
    }

    #[test]
    fn an_unknown_or_missing_chapter_is_one_clear_line_that_names_this_chapter() {
        let err = take_like(args(&["ch10", "--like", "ch06"])).unwrap_err();
        assert!(err.contains("use one of ch01-ray-cast"), "{err}");
        assert!(err.contains("chapter 10"), "{err}");
        assert!(take_like(args(&["ch10", "--like"])).is_err());
        assert!(take_like(args(&["ch10", "--like=ch01", "--like=ch02"])).is_err());
    }
}
