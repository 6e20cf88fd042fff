//! `--like chNN-…`: which of chapters 1–5 chapter 7 traces as.
//!
//! Chapter 7 changes how the rays are traced, not what they compute, so
//! it can stand in for any of the Whitted chapters: with `--like
//! ch03-reflection` it has chapter 3's features (shadows and mirrors, no
//! glass) and its defaults (depth 10, one ray per pixel), and its image is
//! chapter 3's, to the byte.

use std::ffi::OsString;

use raylab::probe::ProbeTarget;

/// One of the Whitted chapters, as chapter 7 imitates it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Like {
    RayCast,
    Shadows,
    Reflection,
    Refraction,
    AntiAliasing,
}

/// What a chapter has switched on (the lab model's chapter table).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Features {
    pub shadows: bool,
    pub reflection: bool,
    pub transmission: bool,
}

impl Like {
    pub const ALL: [Like; 5] = [
        Like::RayCast,
        Like::Shadows,
        Like::Reflection,
        Like::Refraction,
        Like::AntiAliasing,
    ];

    /// The program this imitates, e.g. `ch04-refraction`.
    pub fn binary(self) -> &'static str {
        match self {
            Like::RayCast => ch01_ray_cast::CHAPTER.binary,
            Like::Shadows => ch02_shadows::CHAPTER.binary,
            Like::Reflection => ch03_reflection::CHAPTER.binary,
            Like::Refraction => ch04_refraction::CHAPTER.binary,
            Like::AntiAliasing => ch05_antialiasing::CHAPTER.binary,
        }
    }

    pub fn features(self) -> Features {
        let on = |first: Like| self as usize >= first as usize;
        Features {
            shadows: on(Like::Shadows),
            reflection: on(Like::Reflection),
            transmission: on(Like::Refraction),
        }
    }

    /// The chapter's default `--max-depth`, `--spp` and probed pixel.
    pub fn defaults(self) -> (u32, u32, ProbeTarget) {
        macro_rules! of {
            ($chapter:expr) => {
                ($chapter.max_depth, $chapter.spp, $chapter.probe)
            };
        }
        match self {
            Like::RayCast => of!(ch01_ray_cast::CHAPTER),
            Like::Shadows => of!(ch02_shadows::CHAPTER),
            Like::Reflection => of!(ch03_reflection::CHAPTER),
            Like::Refraction => of!(ch04_refraction::CHAPTER),
            Like::AntiAliasing => of!(ch05_antialiasing::CHAPTER),
        }
    }

    /// `ch04-refraction`, or just `ch04`.
    pub fn parse(text: &str) -> Result<Like, String> {
        Like::ALL
            .into_iter()
            .find(|like| like.binary() == text || like.binary().split('-').next() == Some(text))
            .ok_or_else(|| {
                let names: Vec<_> = Like::ALL.iter().map(|l| l.binary()).collect();
                format!(
                    "--like '{text}' is not a chapter that chapter 7 can imitate: use one of {}",
                    names.join(", ")
                )
            })
    }
}

/// Take `--like NAME` (or `--like=NAME`) out of a program's arguments and
/// return the rest for the shared command line. Chapter 5 when absent.
pub fn take_like(args: Vec<OsString>) -> Result<(Like, Vec<OsString>), String> {
    let mut like = None;
    let mut rest = Vec::with_capacity(args.len());
    let mut args = args.into_iter();
    while let Some(arg) = args.next() {
        let text = arg.to_string_lossy();
        let value = if text == "--like" {
            let value = args
                .next()
                .ok_or("--like needs a chapter, e.g. --like ch04-refraction")?;
            value.to_string_lossy().into_owned()
        } else if let Some(value) = text.strip_prefix("--like=") {
            value.to_owned()
        } else {
            rest.push(arg);
            continue;
        };
        if like.is_some() {
            return Err("--like was given twice: give it once".into());
        }
        like = Some(Like::parse(&value)?);
    }
    Ok((like.unwrap_or(Like::AntiAliasing), rest))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn args(list: &[&str]) -> Vec<OsString> {
        list.iter().map(OsString::from).collect()
    }

    #[test]
    fn chapter_3_has_shadows_and_mirrors_but_no_glass() {
        let f = Like::Reflection.features();
        assert!(f.shadows && f.reflection && !f.transmission);
        assert!(!Like::RayCast.features().shadows);
        assert_eq!(Like::Reflection.defaults().0, 10);
        assert_eq!(Like::AntiAliasing.defaults().1, 5);
    }

    #[test]
    fn like_is_taken_out_of_the_arguments_in_either_spelling() {
        let (like, rest) =
            take_like(args(&["ch07", "--like", "ch02-shadows", "--spp", "1"])).unwrap();
        assert_eq!(like, Like::Shadows);
        assert_eq!(rest, args(&["ch07", "--spp", "1"]));
        let (like, _) = take_like(args(&["ch07", "--like=ch04"])).unwrap();
        assert_eq!(like, Like::Refraction);
        assert_eq!(take_like(args(&["ch07"])).unwrap().0, Like::AntiAliasing);
    }

    #[test]
    fn an_unknown_or_missing_chapter_is_one_clear_line() {
        let err = take_like(args(&["ch07", "--like", "ch06"])).unwrap_err();
        assert!(err.contains("use one of ch01-ray-cast"), "{err}");
        assert!(take_like(args(&["ch07", "--like"])).is_err());
        assert!(take_like(args(&["ch07", "--like=ch01", "--like=ch02"])).is_err());
    }
}
