//! After a failed check: which mistake of the catalogue
//! ([`learn::mistakes`]) it matches, by the fingerprints
//! [`crate::fingerprints`] learnt (the same failing tests, or where the
//! tests pass, the same picture), or that none does; and for a picture
//! that differs, what it shows.

use std::io::Write;
use std::path::Path;

use image::RgbImage;
use learn::lab::Lab;
use learn::mistakes::{Fingerprint, Mistake};

use crate::verdict::Verdict;
use learn::limits::Limits;

/// After a failed check: the mistake of the catalogue it matches, or that
/// none does; and for a picture that differs, what it shows.
pub(crate) fn after_failure(
    lab: &Lab,
    name: &str,
    verdict: &Verdict,
    picture_dir: &Path,
    out: &mut dyn Write,
) {
    let matchable = matches!(
        verdict,
        Verdict::TestsFail { .. }
            | Verdict::Differs(_)
            | Verdict::NoisyDiffers(_)
            | Verdict::NonFinite(_)
    );
    // A region still a `todo!` is no mistake: nothing to match.
    let unwritten = matches!(
        verdict,
        Verdict::TestsFail { messages, .. }
            if !messages.is_empty() && messages.iter().all(|m| m.starts_with("not yet implemented"))
    );
    let Some(item) = learn::path::find(name).filter(|_| matchable && !unwritten) else {
        return;
    };
    // Only a picture this check wrote: an older learner.png says nothing.
    let read = |name: &str| {
        matches!(verdict, Verdict::Differs(_))
            .then(|| image::open(picture_dir.join(name)).ok())
            .flatten()
            .map(|image| image.to_rgb8())
    };
    let learner = read("learner.png");
    let prints = crate::fingerprints::fingerprints(lab, item, out);
    let shown = learner.as_ref().map_or(Picture::Unknown, Picture::Differs);
    let mut diagnosis = diagnose(&prints, verdict, shown);
    if diagnosis == Diagnosis::Tied
        && let learn::path::Item::Chapter(exercise) = item
    {
        // Mistakes that fail the same tests differ in their pictures:
        // render the learner's too, though its tests failed.
        let _ = std::fs::remove_file(picture_dir.join("learner.png"));
        let mut quiet = Vec::new();
        let picture =
            crate::chapter_stages::check_picture_with(lab, exercise, Limits::DEFAULT, &mut quiet);
        let image = matches!(picture, Verdict::Differs(_))
            .then(|| image::open(picture_dir.join("learner.png")).ok())
            .flatten()
            .map(|image| image.to_rgb8());
        let shown = match &image {
            Some(image) => Picture::Differs(image),
            None if picture.passed() => Picture::AsReference,
            None => Picture::Unknown,
        };
        diagnosis = diagnose(&prints, verdict, shown);
    }
    let src = match item {
        learn::path::Item::Core(_) => lab.core_build().join("raylab/src"),
        learn::path::Item::Chapter(exercise) => lab.folder(exercise).join("src"),
        learn::path::Item::Shader => lab.shader_folder().join("src"),
    };
    let titles = learn::run::test_titles(&src);
    let title = |name: &str| {
        learn::run::title_of(&titles, name).unwrap_or_else(|| learn::run::sentence(name))
    };
    report(&diagnosis, verdict, &title, out);
    if !matches!(diagnosis, Diagnosis::Likely(_))
        && let (Some(learner), Some(reference)) = (&learner, read("reference.png"))
        && let Some(symptom) = symptom(learner, &reference)
    {
        let _ = writeln!(
            out,
            "What the picture shows: {symptom}; probe its worst pixel with the commands above, \
             and read {}",
            item.page()
        );
    }
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
                learn::run::shortened(&what)
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
    use learn::mistakes::MISTAKES;

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
