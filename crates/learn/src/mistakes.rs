//! The catalogue of mistakes: for each exercise, the wrong answers
//! learners make again and again (acne, a swapped ratio, a forgotten 1/π),
//! each written as a small replacement in the reference's region, and what
//! the check sees when it is made.
//!
//! The tool learns each mistake's fingerprint itself, by building and
//! checking it in a lab of its own (`learn-mistakes/` in the target
//! folder, never the learner's crate): which of the exercise's tests fail,
//! and, when they all pass, its render. The fingerprints are kept there
//! with a key made from the wrong source, so a chapter that changes is
//! learnt again. A failed check is then matched against them: the same
//! failing tests (or, where the tests pass, the same picture) name the
//! mistake; anything else is said to match none. A correct answer passes
//! its check and is never matched at all.

use std::collections::hash_map::DefaultHasher;
use std::hash::{Hash, Hasher};
use std::io::Write;
use std::path::{Path, PathBuf};

use image::RgbImage;

use crate::check::{Limits, Verdict};
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

/// The learner's picture, as a tie between mistakes needs it.
#[derive(Clone, Copy, Debug)]
pub enum Picture<'a> {
    /// Not rendered.
    Unknown,
    /// It matches the reference within the lab model's tolerance.
    AsReference,
    /// It differs: the render.
    Differs(&'a RgbImage),
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

const LIMITS: Limits = Limits {
    tests: std::time::Duration::from_secs(20),
    render: std::time::Duration::from_secs(30),
};

/// The fingerprints of every mistake of the exercise `item`, from the
/// cache or learnt now (saying so first: it builds the exercise).
pub fn fingerprints(lab: &Lab, item: Item, out: &mut dyn Write) -> Vec<(Mistake, Fingerprint)> {
    let name = item.name();
    let mistakes: Vec<&Mistake> = of(&name).collect();
    if mistakes.is_empty() {
        return Vec::new();
    }
    let cache = mistake_lab(lab);
    let dir = cache.dir.join("fingerprints");
    let mut known = Vec::new();
    let mut to_learn = Vec::new();
    for mistake in mistakes {
        let Some(file) = source_file(&lab.root, mistake) else {
            continue;
        };
        let Some(wrong) = std::fs::read_to_string(lab.root.join(&file))
            .ok()
            .and_then(|text| made_in(&text, mistake))
        else {
            continue;
        };
        let key = key_of(&wrong, mistake);
        let path = dir.join(format!("{}-{}.toml", mistake.exercise, mistake.slug));
        let cached: Option<Fingerprint> = std::fs::read_to_string(&path)
            .ok()
            .and_then(|text| toml::from_str(&text).ok());
        match cached {
            Some(print) if print.key == key => known.push((*mistake, print)),
            _ => to_learn.push((*mistake, file, wrong, key, path)),
        }
    }
    if !to_learn.is_empty() {
        let _ = writeln!(
            out,
            "  learning what {} known mistake{} of `{name}` look like, once (each built and checked \
             in {}; a few seconds each after the first build) …",
            to_learn.len(),
            if to_learn.len() == 1 { "" } else { "s" },
            crate::run::shown(&cache.dir, &lab.root),
        );
        let _ = out.flush();
    }
    for (mistake, file, wrong, key, path) in to_learn {
        let mut print = learn_one(&cache, item, &file, &wrong);
        print.key = key;
        if let Some(image) = &print.image {
            let keep = path.with_extension("png");
            if std::fs::create_dir_all(&dir).is_ok() && std::fs::copy(image, &keep).is_ok() {
                print.image = Some(keep);
            } else {
                print.image = None;
            }
        }
        if let Ok(text) = toml::to_string(&print) {
            let _ = std::fs::create_dir_all(&dir);
            let _ = std::fs::write(&path, text);
        }
        known.push((mistake, print));
    }
    known
}

fn key_of(wrong: &str, mistake: &Mistake) -> String {
    let mut hasher = DefaultHasher::new();
    (wrong, mistake.slug, env!("CARGO_PKG_VERSION")).hash(&mut hasher);
    format!("{:016x}", hasher.finish())
}

/// Build and check one mistake in the mistake lab.
fn learn_one(cache: &Lab, item: Item, file: &Path, wrong: &str) -> Fingerprint {
    let mut quiet = Vec::new();
    let (verdict, picture_dir) = match item {
        Item::Core(core) => {
            let src = cache.core_src();
            let _ = std::fs::remove_dir_all(&src);
            let _ = std::fs::remove_file(cache.progress_path());
            for exercise in &crate::core::CORE_EXERCISES {
                let _ = cache.start_core(exercise, true);
                let _ = cache.record_core_pass(exercise.name);
            }
            let name = file.file_name().unwrap_or_default();
            let _ = std::fs::write(src.join(name), wrong);
            let verdict = crate::check::check_core_quietly(cache, core, LIMITS, &mut quiet);
            (verdict, cache.core_check_dir(core))
        }
        Item::Chapter(chapter) => {
            let folder = cache.folder(chapter);
            let _ = std::fs::remove_dir_all(&folder);
            let _ = cache.start(chapter, true);
            if let Ok(solved) = crate::exercise::blank_only(wrong, |_| false) {
                let _ = std::fs::write(folder.join(chapter.step), solved.exercise);
            }
            let verdict = crate::check::check_quietly(cache, chapter, LIMITS, &mut quiet);
            if let Verdict::TestsFail {
                failing, messages, ..
            } = &verdict
            {
                // Its picture too, to tell apart mistakes that fail the
                // same tests.
                let image = folder.join("check/learner.png");
                let _ = std::fs::remove_file(&image);
                let picture = crate::check::check_picture_with(cache, chapter, LIMITS, &mut quiet);
                return Fingerprint {
                    verdict: format!("{verdict:?}").chars().take(120).collect(),
                    failing: failing.clone(),
                    messages: messages.clone(),
                    image: (matches!(picture, Verdict::Differs(_)) && image.is_file())
                        .then_some(image),
                    picture_passes: picture.passed(),
                    ..Fingerprint::default()
                };
            }
            (verdict, folder.join("check"))
        }
        Item::Shader => (Verdict::NoExercise, PathBuf::new()),
    };
    let mut print = Fingerprint {
        verdict: format!("{verdict:?}").chars().take(120).collect(),
        ..Fingerprint::default()
    };
    match verdict {
        Verdict::TestsFail {
            failing, messages, ..
        } => {
            print.failing = failing;
            print.messages = messages;
        }
        Verdict::Differs(_) => print.image = Some(picture_dir.join("learner.png")),
        _ => {}
    }
    print
}

/// How the learner's failed check compares with the catalogue.
#[derive(Clone, Debug, PartialEq)]
pub enum Diagnosis {
    Likely(Mistake),
    /// Several fail the same tests, and no picture was given to tell them
    /// apart.
    Tied,
    /// Some mistakes are catalogued, and none fits.
    NoMatch,
    /// None is catalogued for this exercise, or the verdict is not one a
    /// fingerprint can match (a compile error, a timeout).
    Nothing,
}

/// The numbers in a message, in order: `left: Vec3A(1.282, …)` → 1.282, ….
fn numbers(message: &str) -> Vec<f64> {
    message
        .split(|c: char| !(c.is_ascii_digit() || c == '.' || c == '-' || c == 'e'))
        .filter_map(|word| word.trim_matches(|c| c == '.' || c == 'e').parse().ok())
        .collect()
}

/// Whether every failing test the learner and a mistake share prints the
/// same numbers, within 2 %: the same wrong values (a statistical test's
/// mean and z move a little with the random numbers drawn; two mistakes'
/// values differ by far more).
fn same_values(failing: &[String], messages: &[String], print: &Fingerprint) -> bool {
    let mut compared = 0;
    for (test, message) in failing.iter().zip(messages) {
        let Some(at) = print.failing.iter().position(|t| t == test) else {
            continue;
        };
        let Some(theirs) = print.messages.get(at) else {
            continue;
        };
        let (a, b) = (numbers(message), numbers(theirs));
        if a.is_empty() && b.is_empty() {
            continue;
        }
        compared += 1;
        let close = |x: f64, y: f64| (x - y).abs() <= 0.02 * x.abs().max(y.abs()).max(1e-3);
        if a.len() != b.len() || a.iter().zip(&b).any(|(x, y)| !close(*x, *y)) {
            return false;
        }
    }
    compared > 0
}

/// The share of failing tests two sets have in common (Jaccard): 1 for
/// the same tests, 0 for none in common.
fn overlap(a: &[String], b: &[String]) -> f64 {
    let common = a.iter().filter(|t| b.contains(t)).count();
    let all = a.len() + b.len() - common;
    if all == 0 {
        0.0
    } else {
        common as f64 / all as f64
    }
}

/// How much of the failing tests must be the same for a mistake to be
/// named: most of them, so a learner's mistake that fails one test more
/// or less than the catalogue's own still matches, and one that fails
/// other tests does not.
pub const MIN_OVERLAP: f64 = 0.75;

/// The share of pixels within 3 of 255 a learner's render must have in
/// common with a mistake's for the picture to name it.
pub const MIN_PICTURE_AGREEMENT: f64 = 0.98;

/// The same where the failing tests are the same and the picture only
/// decides between the mistakes that fail them.
pub const MIN_TIED_PICTURE_AGREEMENT: f64 = 0.9;

/// Match a failed check with the exercise's mistakes: the best match,
/// when it fits well enough and no other fits as well.
pub fn diagnose(
    prints: &[(Mistake, Fingerprint)],
    verdict: &Verdict,
    picture: Picture,
) -> Diagnosis {
    if prints.is_empty() {
        return Diagnosis::Nothing;
    }
    let agreement = |p: &Fingerprint, learner: &RgbImage| {
        let image = image::open(p.image.as_ref()?).ok()?.to_rgb8();
        (image.dimensions() == learner.dimensions())
            .then(|| crate::compare::compare(learner, &image).within_3)
    };
    let scores: Vec<(f64, &Mistake)> = match verdict {
        Verdict::TestsFail {
            failing, messages, ..
        } if !failing.is_empty() => {
            let by_tests: Vec<(f64, &(Mistake, Fingerprint))> = prints
                .iter()
                .filter(|(_, p)| !p.failing.is_empty())
                .map(|pair| (overlap(failing, &pair.1.failing), pair))
                .filter(|(score, _)| *score >= MIN_OVERLAP)
                .collect();
            let best = by_tests.iter().map(|(s, _)| *s).fold(0.0, f64::max);
            let mut tied: Vec<&(Mistake, Fingerprint)> = by_tests
                .iter()
                .filter(|(s, _)| *s == best)
                .map(|(_, pair)| *pair)
                .collect();
            if tied.len() > 1 {
                // The same tests fail: the values their messages print
                // decide, where they differ between the mistakes.
                let agreeing: Vec<_> = tied
                    .iter()
                    .copied()
                    .filter(|(_, p)| same_values(failing, messages, p))
                    .collect();
                if !agreeing.is_empty() {
                    tied = agreeing;
                }
            }
            match (tied.as_slice(), picture) {
                ([], _) => return Diagnosis::NoMatch,
                ([(only, _)], _) => return Diagnosis::Likely(*only),
                (_, Picture::Unknown) => return Diagnosis::Tied,
                // The same tests fail: the picture decides, if it can.
                (_, Picture::AsReference) => tied
                    .iter()
                    .filter(|(_, p)| p.picture_passes)
                    .map(|(m, _)| (1.0, m))
                    .collect(),
                (_, Picture::Differs(learner)) => tied
                    .iter()
                    .filter_map(|(m, p)| Some((agreement(p, learner)?, m)))
                    .filter(|(score, _)| *score >= MIN_TIED_PICTURE_AGREEMENT)
                    .collect(),
            }
        }
        Verdict::Differs(_) => {
            let Picture::Differs(learner) = picture else {
                return Diagnosis::NoMatch;
            };
            prints
                .iter()
                .filter(|(_, p)| p.failing.is_empty())
                .filter_map(|(m, p)| Some((agreement(p, learner)?, m)))
                .filter(|(score, _)| *score >= MIN_PICTURE_AGREEMENT)
                .collect()
        }
        Verdict::TestsFail { .. } | Verdict::NoisyDiffers(_) | Verdict::NonFinite(_) => {
            return Diagnosis::NoMatch;
        }
        _ => return Diagnosis::Nothing,
    };
    let best = scores.iter().map(|(s, _)| *s).fold(0.0, f64::max);
    let at_best: Vec<&&Mistake> = scores
        .iter()
        .filter(|(s, _)| *s == best)
        .map(|(_, m)| m)
        .collect();
    match at_best.as_slice() {
        [only] => Diagnosis::Likely(***only),
        _ => Diagnosis::NoMatch,
    }
}

/// The line a failed check ends with, if it has one.
/// `title` gives a test's title from its full name.
pub fn report(
    diagnosis: &Diagnosis,
    verdict: &Verdict,
    title: &dyn Fn(&str) -> String,
    out: &mut dyn Write,
) {
    match diagnosis {
        Diagnosis::Likely(m) => {
            let _ = writeln!(
                out,
                "Likely mistake: {} — {}; see {}",
                m.slug, m.what, m.section
            );
        }
        Diagnosis::NoMatch | Diagnosis::Tied => {
            let what = match verdict {
                Verdict::TestsFail { failing, .. } if !failing.is_empty() => format!(
                    "{} failing test{} ({})",
                    failing.len(),
                    if failing.len() == 1 { "" } else { "s" },
                    failing
                        .iter()
                        .map(|t| title(t))
                        .collect::<Vec<_>>()
                        .join("; ")
                ),
                Verdict::NonFinite(n) => format!("{n} NaN or infinite pixels"),
                _ => "its picture differs from the reference (its tests pass)".to_owned(),
            };
            let _ = writeln!(
                out,
                "No known mistake matches: {}",
                crate::run::shortened(&what)
            );
        }
        Diagnosis::Nothing => {}
    }
}

/// What a picture that differs shows, in words, from where the learner's
/// pixels differ from the reference's: speckles (isolated pixels) darker
/// than the reference are acne; a darker region is light lost; a brighter
/// one, light added.
pub fn symptom(learner: &RgbImage, reference: &RgbImage) -> Option<&'static str> {
    if learner.dimensions() != reference.dimensions() {
        return None;
    }
    let (w, h) = learner.dimensions();
    let differs = |x: u32, y: u32| {
        let (a, b) = (learner.get_pixel(x, y).0, reference.get_pixel(x, y).0);
        (0..3).any(|c| a[c].abs_diff(b[c]) > 3)
    };
    let (mut count, mut darker, mut isolated) = (0usize, 0usize, 0usize);
    for y in 0..h {
        for x in 0..w {
            if !differs(x, y) {
                continue;
            }
            count += 1;
            let (a, b) = (learner.get_pixel(x, y).0, reference.get_pixel(x, y).0);
            let sum = |p: [u8; 3]| p.iter().map(|&v| u32::from(v)).sum::<u32>();
            if sum(a) < sum(b) {
                darker += 1;
            }
            let neighbours = [
                (x.wrapping_sub(1), y),
                (x + 1, y),
                (x, y.wrapping_sub(1)),
                (x, y + 1),
            ]
            .into_iter()
            .filter(|&(i, j)| i < w && j < h && differs(i, j))
            .count();
            if neighbours <= 1 {
                isolated += 1;
            }
        }
    }
    if count == 0 {
        return None;
    }
    let share = |n: usize| n as f64 / count as f64;
    if share(darker) >= 0.8 && share(isolated) >= 0.4 {
        Some(
            "dark speckles scattered over surfaces the reference lights: shadow acne, a ray \
             started on the surface it leaves (book/src/ch02-shadows.md, \"Why epsilon\")",
        )
    } else if share(darker) >= 0.8 {
        Some(
            "whole regions darker than the reference: light lost, a ray not sent or a share \
             dropped (a black glass ball is transmitted light lost)",
        )
    } else if share(darker) <= 0.2 {
        Some(
            "whole regions brighter than the reference: light added, a share too large or counted twice",
        )
    } else {
        None
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

    fn print(failing: &[&str]) -> Fingerprint {
        Fingerprint {
            failing: failing.iter().map(|t| (*t).to_owned()).collect(),
            ..Fingerprint::default()
        }
    }

    fn fails(failing: &[&str]) -> Verdict {
        Verdict::TestsFail {
            failed: failing.len(),
            of: 10,
            failing: failing.iter().map(|t| (*t).to_owned()).collect(),
            messages: failing.iter().map(|_| String::new()).collect(),
        }
    }

    #[test]
    fn mistakes_that_fail_the_same_tests_are_told_apart_by_the_values_printed() {
        let with = |message: &str| Fingerprint {
            failing: vec!["a".into()],
            messages: vec![message.into()],
            ..Fingerprint::default()
        };
        let prints = [
            (MISTAKES[0], with("[1.2820001, 1.282, 1.282], not 0.408091")),
            (MISTAKES[1], with("[0.5968, 0.5968, 0.5968], not 0.408091")),
        ];
        let learner = |message: &str| Verdict::TestsFail {
            failed: 1,
            of: 3,
            failing: vec!["a".into()],
            messages: vec![message.into()],
        };
        let told = |m: &str| diagnose(&prints, &learner(m), Picture::Unknown);
        assert_eq!(
            told("[1.282, 1.282, 1.282], not 0.408091"),
            Diagnosis::Likely(MISTAKES[0])
        );
        assert_eq!(
            told("[0.59680003, 0.5968, 0.5968], not 0.408091"),
            Diagnosis::Likely(MISTAKES[1])
        );
        assert_eq!(told("[3.75, 3.75, 3.75], not 0.408091"), Diagnosis::Tied);
    }

    #[test]
    fn a_failure_is_named_by_the_mistake_with_the_same_failing_tests_and_only_then() {
        let prints = [
            (MISTAKES[0], print(&["a", "b", "c", "d"])),
            (MISTAKES[1], print(&["e"])),
        ];
        assert_eq!(
            diagnose(&prints, &fails(&["a", "b", "c", "d"]), Picture::Unknown),
            Diagnosis::Likely(MISTAKES[0])
        );
        // One test fewer still fits (3 of 4); other tests do not.
        assert_eq!(
            diagnose(&prints, &fails(&["a", "b", "c"]), Picture::Unknown),
            Diagnosis::Likely(MISTAKES[0])
        );
        assert_eq!(
            diagnose(&prints, &fails(&["a", "e"]), Picture::Unknown),
            Diagnosis::NoMatch
        );
        assert_eq!(
            diagnose(&prints, &fails(&["x"]), Picture::Unknown),
            Diagnosis::NoMatch
        );
        assert_eq!(
            diagnose(&[], &fails(&["a"]), Picture::Unknown),
            Diagnosis::Nothing
        );
    }

    #[test]
    fn two_mistakes_that_fail_the_same_tests_name_neither_unless_the_picture_tells() {
        let mut passes = print(&["a"]);
        passes.picture_passes = true;
        let prints = [(MISTAKES[0], print(&["a"])), (MISTAKES[1], passes)];
        let told = |picture| diagnose(&prints, &fails(&["a"]), picture);
        assert_eq!(told(Picture::Unknown), Diagnosis::Tied);
        assert_eq!(told(Picture::AsReference), Diagnosis::Likely(MISTAKES[1]));
        let other = RgbImage::new(4, 4);
        assert_eq!(told(Picture::Differs(&other)), Diagnosis::NoMatch);
    }

    #[test]
    fn isolated_dark_pixels_are_acne_and_a_dark_patch_is_light_lost() {
        let reference = RgbImage::from_pixel(20, 20, image::Rgb([200, 200, 200]));
        let mut speckled = reference.clone();
        for (x, y) in [(2, 2), (7, 3), (12, 9), (15, 15), (4, 17)] {
            speckled.put_pixel(x, y, image::Rgb([40, 40, 40]));
        }
        assert!(symptom(&speckled, &reference).is_some_and(|s| s.contains("shadow acne")));
        let mut patch = reference.clone();
        for y in 5..12 {
            for x in 5..12 {
                patch.put_pixel(x, y, image::Rgb([0, 0, 0]));
            }
        }
        assert!(symptom(&patch, &reference).is_some_and(|s| s.contains("light lost")));
        assert_eq!(symptom(&reference, &reference), None);
    }
}
