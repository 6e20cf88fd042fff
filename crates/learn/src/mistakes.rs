//! The catalogue of mistakes: for each exercise, the wrong answers
//! learners make again and again (acne, a swapped ratio, a forgotten 1/π),
//! each written as a small replacement in the reference's region, and what
//! the check sees when it is made.
//!
//! The checker (`learn-check`, the program `check` builds on first use)
//! learns each mistake's fingerprint itself, by building and checking it
//! in a lab of its own ([`mistake_lab`], never the learner's crate): which
//! of the exercise's tests fail, and, when they all pass, its render. The
//! fingerprints are kept there with a key made from the wrong source, so a
//! chapter that changes is learnt again, and `learn mistakes` shows what
//! they say. A failed check is then matched against them: the same
//! failing tests (or, where the tests pass, the same picture) name the
//! mistake; anything else is said to match none. A correct answer passes
//! its check and is never matched at all.

use std::path::{Path, PathBuf};

use crate::lab::Lab;
use crate::path::Item;

/// One known wrong answer to an exercise.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Mistake {
    /// The exercise, by the name `check` takes.
    pub exercise: &'static str,
    /// Its short name: `no-offset`.
    pub slug: &'static str,
    /// What it is, in one line.
    pub what: &'static str,
    /// What it does to the picture (or to the tests), in one line.
    pub picture: &'static str,
    /// The book's section that explains it.
    pub section: &'static str,
    /// The region it is made in, by its marker name.
    pub region: &'static str,
    /// The wrong code: every `from` in the reference's region becomes `to`.
    pub from: &'static str,
    pub to: &'static str,
}

/// The catalogue, by exercise in the path's order.
pub const MISTAKES: [Mistake; 19] = [
    Mistake {
        exercise: "refract",
        slug: "eta-inverted",
        what: "the ratio of the indices upside down (n₂/n₁ for n₁/n₂)",
        picture: "rays entering glass bend away from the normal; many find no refraction at all",
        section: "book/src/ch04-refraction.md, \"Snell's law\"",
        region: "refract",
        from: "let cos_i = n.dot(i);",
        to: "let eta = 1.0 / eta;\n    let cos_i = n.dot(i);",
    },
    Mistake {
        exercise: "refract",
        slug: "no-tir",
        what: "a direction (NaN from the square root of a negative k) where Snell's law has none",
        picture: "NaN where total internal reflection should be, black pixels inside the glass",
        section: "book/src/ch04-refraction.md, \"Total internal reflection\"",
        region: "refract",
        from: "    if k < 0.0 {\n        return None;\n    }\n",
        to: "",
    },
    Mistake {
        exercise: "refract",
        slug: "not-unit",
        what: "the refracted direction is right but not of unit length",
        picture: "Ray::new refuses it, or distances along it come out wrong",
        section: "book/src/ch04-refraction.md, \"The refract formula\"",
        region: "refract",
        from: "Some(eta * i - (eta * cos_i + k.sqrt()) * n)",
        to: "Some((eta * i - (eta * cos_i + k.sqrt()) * n) / eta)",
    },
    Mistake {
        exercise: "2",
        slug: "no-offset",
        what: "the feeler starts on the surface itself, not epsilon off it",
        picture: "dark speckles over lit surfaces (shadow acne)",
        section: "book/src/ch02-shadows.md, \"Why epsilon\"",
        region: "sun_factor",
        from: "hit.point + to_sun * surface.epsilon()",
        to: "hit.point",
    },
    Mistake {
        exercise: "2",
        slug: "away-from-sun",
        what: "the feeler goes away from the sun, not towards it",
        picture: "shadows where the ground faces the sun's side of a sphere, and none behind it",
        section: "book/src/ch02-shadows.md, \"The shadow ray\"",
        region: "sun_factor",
        from: "let to_sun = surface.scene().sun.direction;",
        to: "let to_sun = -surface.scene().sun.direction;",
    },
    Mistake {
        exercise: "2",
        slug: "factors-swapped",
        what: "the lit and shadowed factors exchanged",
        picture: "the lit ground dark and the shadows lit",
        section: "book/src/ch02-shadows.md, \"The shadow ray\"",
        region: "sun_factor",
        from: "SUN_IN_SHADOW\n    } else {\n        SUN_LIT",
        to: "SUN_LIT\n    } else {\n        SUN_IN_SHADOW",
    },
    Mistake {
        exercise: "3",
        slug: "no-offset",
        what: "the mirror ray starts on the mirror itself, not epsilon off it",
        picture: "speckles in the mirror, where a reflection meets the mirror again",
        section: "book/src/ch02-shadows.md, \"Why epsilon\"",
        region: "send_reflection",
        from: "let origin = hit.point + direction * surface.epsilon();",
        to: "let origin = hit.point;",
    },
    Mistake {
        exercise: "3",
        slug: "share-not-r",
        what: "the reflection sent with a weight other than r",
        picture: "the mirror too bright: it reflects all the light and keeps its own colour too",
        section: "book/src/ch03-reflection.md, \"The ray stack\"",
        region: "send_reflection",
        from: "Ray::new(origin, direction), r);",
        to: "Ray::new(origin, direction), 1.0);",
    },
    Mistake {
        exercise: "4",
        slug: "eta-inverted",
        what: "eta = ior going in and 1/ior coming out: the ratio n₁/n₂ upside down",
        picture: "the glass ball bends light the wrong way; rays inside find total internal reflection where there is none",
        section: "book/src/ch04-refraction.md, \"Snell's law\"",
        region: "send_refraction",
        from: "let eta = if hit.entering { 1.0 / ior } else { ior };",
        to: "let eta = if hit.entering { ior } else { 1.0 / ior };",
    },
    Mistake {
        exercise: "4",
        slug: "tir-dropped",
        what: "no ray where refract finds none: the totally internally reflected share is lost",
        picture: "none in the lab scene, where no ray is totally reflected inside a sphere; under water (scenes/total-internal-reflection.toml) the sky outside Snell's window goes black",
        section: "book/src/ch04-refraction.md, \"Total internal reflection\"",
        region: "send_refraction",
        from: "            surface.send(\n                RayKind::TotalInternalReflection,\n                Ray::new(origin, direction),\n                t,\n            );",
        to: "            let _ = (origin, t);",
    },
    Mistake {
        exercise: "4",
        slug: "no-offset",
        what: "the refracted (or reflected) ray starts on the glass itself, not epsilon off it",
        picture: "speckles and dark patches in the glass ball",
        section: "book/src/ch02-shadows.md, \"Why epsilon\"",
        region: "send_refraction",
        from: "let origin = hit.point + direction * surface.epsilon();",
        to: "let origin = hit.point;",
    },
    Mistake {
        exercise: "stack",
        slug: "fifo",
        what: "pop takes the oldest ray, not the last one pushed (a queue, not a stack)",
        picture: "the same light in another order: the ray log, the depth colours and the budget differ",
        section: "book/src/ch03-reflection.md, \"The ray stack\"",
        region: "stack_pop",
        from: "        Some(self.rays[self.len])",
        to: "        let oldest = self.rays[0];\n        self.rays.copy_within(1..=self.len, 0);\n        Some(oldest)",
    },
    Mistake {
        exercise: "stack",
        slug: "weight-not-multiplied",
        what: "a ray's weight is its share alone, not its parent's weight times its share",
        picture: "mirror and glass too bright after two bounces or more",
        section: "book/src/ch03-reflection.md, \"The ray stack\"",
        region: "trace",
        from: "weight: pending.weight * secondary.share,",
        to: "weight: secondary.share,",
    },
    Mistake {
        exercise: "stack",
        slug: "depth-off-by-one",
        what: "rays pushed at max depth too (<= for <): one bounce more than asked",
        picture: "one level of reflection more than the reference",
        section: "book/src/ch03-reflection.md, \"How deep is deep enough?\"",
        region: "trace",
        from: "if pending.depth < self.max_depth",
        to: "if pending.depth <= self.max_depth",
    },
    Mistake {
        exercise: "cosine",
        slug: "uniform",
        what: "directions uniform over the hemisphere, not cosine-weighted",
        picture: "diffuse surfaces too dark: a uniform sampler needs a weight of 2 cos θ it does not get",
        section: "book/src/ch06-path-tracing.md, \"The equation, and the one path that estimates it\"",
        region: "cosine_direction",
        from: "    let z = (1.0 - r2).max(0.0).sqrt();\n    x * t + y * b + z * n",
        to: "    let z = random.uniform();\n    let s = ((1.0 - z * z) / r2).max(0.0).sqrt();\n    s * x * t + s * y * b + z * n",
    },
    Mistake {
        exercise: "cosine",
        slug: "one-random-number",
        what: "one random number for both the radius and the angle of the disc point",
        picture: "diffuse light leans to one side: the angle grows with the radius, so the directions spiral",
        section: "book/src/ch06-path-tracing.md, \"The equation, and the one path that estimates it\"",
        region: "cosine_direction",
        from: "    let (x, y, r2) = loop {\n        let x = 2.0 * random.uniform() - 1.0;\n        let y = 2.0 * random.uniform() - 1.0;\n        let r2 = x * x + y * y;\n        if r2 < 1.0 {\n            break (x, y, r2);\n        }\n    };",
        to: "    let u = random.uniform();\n    let (s, c) = (2.0 * std::f32::consts::PI * u).sin_cos();\n    let (x, y, r2) = (u.sqrt() * c, u.sqrt() * s, u);",
    },
    Mistake {
        exercise: "nee",
        slug: "missing-pi",
        what: "the BRDF's 1/π left out: albedo · irradiance · cos θ",
        picture: "sunlit surfaces π times too bright",
        section: "book/src/ch06-path-tracing.md, \"The equation, and the one path that estimates it\"",
        region: "sun_next_event",
        from: "hit.material.albedo() * FRAC_1_PI * self.sun.irradiance",
        to: "hit.material.albedo() * self.sun.irradiance",
    },
    Mistake {
        exercise: "nee",
        slug: "missing-cosine",
        what: "the cos θ of the sun's angle left out",
        picture: "surfaces tilted from the sun as bright as those facing it",
        section: "book/src/ch06-path-tracing.md, \"The equation, and the one path that estimates it\"",
        region: "sun_next_event",
        from: "self.sun.irradiance * cos;",
        to: "self.sun.irradiance;",
    },
    Mistake {
        exercise: "nee",
        slug: "no-shadow-ray",
        what: "the sun's light added without asking whether anything blocks it",
        picture: "no shadows from the sun",
        section: "book/src/ch06-path-tracing.md, \"The equation, and the one path that estimates it\"",
        region: "sun_next_event",
        from: "            *rays += 1;\n            let shadow = Ray::new(hit.point + to_sun * self.epsilon, to_sun);\n            if !self.objects.any_hit(&shadow) {",
        to: "            {",
    },
];

/// The mistakes catalogued for the exercise `name`.
pub fn of(name: &str) -> impl Iterator<Item = &'static Mistake> {
    MISTAKES.iter().filter(move |m| m.exercise == name)
}

/// The reference file that holds `mistake`'s region, from the root.
pub fn source_file(root: &Path, mistake: &Mistake) -> Option<PathBuf> {
    match crate::path::find(mistake.exercise)? {
        Item::Core(core) => {
            let file = core.files.iter().find(|file| {
                std::fs::read_to_string(root.join("src").join(file))
                    .is_ok_and(|text| text.contains(&marker(mistake.region)))
            })?;
            Some(Path::new("src").join(file))
        }
        Item::Chapter(chapter) => Some(Path::new(chapter.dir).join(chapter.step)),
        Item::Shader => None,
    }
}

fn marker(region: &str) -> String {
    format!("// ANCHOR: todo_{region} ")
}

/// The reference source `text` with `mistake` made in its region (markers
/// kept): `None` if the region, or `from` inside it, is not there.
pub fn made_in(text: &str, mistake: &Mistake) -> Option<String> {
    let start = text.find(&marker(mistake.region))?;
    let end_marker = format!("// ANCHOR_END: todo_{}", mistake.region);
    let end = start + text[start..].find(&end_marker)?;
    let region = &text[start..end];
    if !region.contains(mistake.from) {
        return None;
    }
    Some(format!(
        "{}{}{}",
        &text[..start],
        region.replace(mistake.from, mistake.to),
        &text[end..]
    ))
}

/// What the check saw when it checked a mistake.
#[derive(Clone, Debug, Default, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Fingerprint {
    /// Made from the wrong source: a changed chapter is learnt again.
    pub key: String,
    /// The tests that failed, by their full names.
    pub failing: Vec<String>,
    /// Their messages, in the same order: the values they print tell
    /// apart mistakes that fail the same tests.
    #[serde(default)]
    pub messages: Vec<String>,
    /// Where its tests all pass: its render (a PNG beside the
    /// fingerprint), when it differs from the reference's.
    pub image: Option<PathBuf>,
    /// Where its tests fail: whether its picture, checked alone, matches
    /// the reference (a mistake the lab scene does not show).
    #[serde(default)]
    pub picture_passes: bool,
    /// The verdict, in words, for `learn mistakes`.
    pub verdict: String,
}

/// The lab the mistakes are built in: beside the learner's builds, in the
/// target folder, with a package version of its own.
pub fn mistake_lab(lab: &Lab) -> Lab {
    Lab {
        dir: lab.target.join("learn-mistakes"),
        version: "0.1.0-mistakes".to_owned(),
        ..lab.clone()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn root() -> &'static Path {
        Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/../.."))
    }

    #[test]
    fn every_mistake_is_a_replacement_found_in_its_exercises_region() {
        for m in &MISTAKES {
            let item = crate::path::find(m.exercise).unwrap_or_else(|| panic!("{}", m.exercise));
            let file =
                source_file(root(), m).unwrap_or_else(|| panic!("{}: {}", m.exercise, m.region));
            let text = std::fs::read_to_string(root().join(&file)).unwrap();
            let wrong = made_in(&text, m)
                .unwrap_or_else(|| panic!("{} {}: no `{}`", m.exercise, m.slug, m.from));
            assert_ne!(wrong, text);
            assert!(
                item.name() == m.exercise && !m.what.contains('\n') && !m.picture.contains('\n'),
                "{}",
                m.slug
            );
        }
    }

    #[test]
    fn the_slugs_of_one_exercise_differ() {
        for m in &MISTAKES {
            assert_eq!(
                of(m.exercise).filter(|o| o.slug == m.slug).count(),
                1,
                "{}",
                m.slug
            );
        }
    }
}
