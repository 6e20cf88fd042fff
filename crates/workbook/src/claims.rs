//! The sentences of the book that describe a probe, checked against the
//! probe they describe.
//!
//! A chapter's ray-tree figure (`figures/<dir>/ray-tree.png`) is made from
//! the chapter's probe, whose text the program writes to
//! `figures/<dir>/probe.txt`. The paragraph that introduces the figure,
//! the figure's alt text and its caption are written by hand, so they can
//! go stale when the probe moves. This module reads them as a *passage*
//! and checks it against that text: the passage names the probe's pixel as
//! `(x, y)` and no other pixel, and every number it writes with two or more
//! decimals (a distance `t`, a weight, a colour) is one the probe prints,
//! at the precision the passage writes it. Like the depth sweep's sentence,
//! which its own test checks against the sweep's CSV, a passage that
//! disagrees with its file is an error, not a warning.

use std::path::Path;

use raylab::Step;
use raylab::probe;
use raylab_cli::probe_text::{self, Listing};
use raylab_cli::{Chapter, CliError};

use crate::Size;

/// One ray-tree figure of a page and the hand-written text around it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Passage {
    /// The figure's folder under `figures/`, e.g. `ch02-shadows`.
    pub dir: String,
    /// The paragraph before the figure, its alt text and its caption.
    pub text: String,
}

/// Every ray-tree figure in `markdown`, with its passage.
pub fn passages(markdown: &str) -> Vec<Passage> {
    let paragraphs: Vec<&str> = markdown.split("\n\n").map(str::trim).collect();
    let mut found = Vec::new();
    for (i, paragraph) in paragraphs.iter().enumerate() {
        let Some(start) = paragraph.find("](figures/") else {
            continue;
        };
        let target = &paragraph[start + "](figures/".len()..];
        let Some((dir, rest)) = target.split_once('/') else {
            continue;
        };
        if !paragraph.starts_with("![") || !rest.starts_with("ray-tree.png)") {
            continue;
        }
        let mut text = String::new();
        // The paragraph that introduces the figure, unless it is another
        // figure, a listing or a heading.
        if let Some(before) = i.checked_sub(1).map(|b| paragraphs[b])
            && !before.starts_with(['!', '#', '`', '<', '*', '|', '{'])
        {
            text.push_str(before);
            text.push('\n');
        }
        text.push_str(paragraph);
        // The caption: the italic line under the figure.
        if let Some(caption) = paragraphs.get(i + 1)
            && caption.starts_with('*')
            && !caption.starts_with("**")
        {
            text.push('\n');
            text.push_str(caption);
        }
        found.push(Passage {
            dir: dir.to_owned(),
            text,
        });
    }
    found
}

/// What in `passage` disagrees with `probe`, the text of `probe.txt`: one
/// line per disagreement, empty when the passage is right.
pub fn disagreements(passage: &str, probe: &str) -> Vec<String> {
    let mut wrong = Vec::new();
    let Some(pixel) = probe_pixel(probe) else {
        return vec![format!("the probe's text names no pixel: {probe:.60}")];
    };
    let pairs = pixel_pairs(passage);
    if !pairs.contains(&pixel) {
        wrong.push(format!(
            "it does not name the probe's pixel ({}, {})",
            pixel.0, pixel.1
        ));
    }
    for pair in pairs.iter().filter(|&&p| p != pixel) {
        wrong.push(format!(
            "it names pixel ({}, {}), but the probe is ({}, {})",
            pair.0, pair.1, pixel.0, pixel.1
        ));
    }
    let printed = decimals(probe);
    for (written, places) in decimals(passage) {
        if places < 2 {
            continue;
        }
        let text = format!("{written:.places$}");
        let found = printed
            .iter()
            .any(|&(value, _)| format!("{value:.places$}") == text);
        if !found {
            wrong.push(format!("it says {text}, which the probe does not print"));
        }
    }
    wrong
}

/// The pixel a probe's text is the tree of: its first line's `(x, y)`.
pub fn probe_pixel(probe: &str) -> Option<(u32, u32)> {
    pixel_pairs(probe.lines().next()?).first().copied()
}

/// Every `(x, y)` of two whole numbers in `text`.
fn pixel_pairs(text: &str) -> Vec<(u32, u32)> {
    text.split('(')
        .skip(1)
        .filter_map(|piece| {
            let inside = piece.split(')').next()?;
            let (x, y) = inside.split_once(',')?;
            Some((x.trim().parse().ok()?, y.trim().parse().ok()?))
        })
        .collect()
}

/// Every decimal number in `text` (a digit, a point, digits), with how
/// many places it is written to; a minus sign before it is kept.
fn decimals(text: &str) -> Vec<(f64, usize)> {
    let bytes = text.as_bytes();
    let mut found = Vec::new();
    let mut i = 0;
    while i < bytes.len() {
        let starts = bytes[i].is_ascii_digit() && (i == 0 || !bytes[i - 1].is_ascii_alphanumeric());
        if !starts {
            i += 1;
            continue;
        }
        let begin = i;
        while i < bytes.len() && bytes[i].is_ascii_digit() {
            i += 1;
        }
        if i + 1 < bytes.len() && bytes[i] == b'.' && bytes[i + 1].is_ascii_digit() {
            let point = i;
            i += 1;
            while i < bytes.len() && bytes[i].is_ascii_digit() {
                i += 1;
            }
            // A minus sign, ASCII or typeset (−), belongs to the number.
            let sign = if text[..begin].ends_with('-') || text[..begin].ends_with('−') {
                -1.0
            } else {
                1.0
            };
            if let Ok(value) = text[begin..i].parse::<f64>() {
                found.push((sign * value, i - point - 1));
            }
        }
    }
    found
}

/// Check every page under `src` whose ray-tree passages have a probe text
/// (`probe_of(dir)`); returns one line per disagreement, naming the page.
pub fn check_pages(src: &Path, probe_of: impl Fn(&str) -> Option<String>) -> Vec<String> {
    let mut wrong = Vec::new();
    for page in crate::book::pages(src) {
        let markdown = std::fs::read_to_string(&page).unwrap_or_default();
        let name = page.file_name().unwrap_or_default().to_string_lossy();
        for passage in passages(&markdown) {
            let Some(probe) = probe_of(&passage.dir) else {
                wrong.push(format!(
                    "{name}: figures/{}/ray-tree.png has no probe.txt beside it",
                    passage.dir
                ));
                continue;
            };
            for line in disagreements(&passage.text, &probe) {
                wrong.push(format!(
                    "{name}, the passage of figures/{}/ray-tree.png: {line}",
                    passage.dir
                ));
            }
        }
    }
    wrong
}

/// The text a chapter's program writes to `probe.txt` for its own probe
/// at `size`, without rendering the image: the tree of one pixel.
pub fn probe_text<S: Step>(chapter: &Chapter<S>, size: Size) -> Result<String, CliError> {
    let settings = crate::speed::settings_of(chapter, size)?;
    // The chapter's defaults render the lab scene.
    let (scene, camera) = (raylab::Scene::lab(), raylab::Camera::lab());
    let pixel = chapter
        .probe
        .pixel(&scene, &camera, size.width, size.height)
        .unwrap_or((size.width / 2, size.height / 2));
    let trees = probe::probe(&scene, &camera, &chapter.step, &settings, pixel);
    Ok(probe_text::format_tree(
        &scene,
        pixel,
        &trees,
        Listing::Folded,
    ))
}

/// The probe text of the chapter whose figures are in `figures/<dir>`, at
/// `size`, for the chapters that draw a ray tree (1 to 5).
pub fn chapter_probe_text(dir: &str, size: Size) -> Option<Result<String, CliError>> {
    Some(match dir {
        "ch01-ray-cast" => probe_text(&ch01_ray_cast::CHAPTER, size),
        "ch02-shadows" => probe_text(&ch02_shadows::CHAPTER, size),
        "ch03-reflection" => probe_text(&ch03_reflection::CHAPTER, size),
        "ch04-refraction" => probe_text(&ch04_refraction::CHAPTER, size),
        "ch05-antialiasing" => probe_text(&ch05_antialiasing::CHAPTER, size),
        _ => return None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    const PROBE: &str = "ray tree of pixel (312, 333): 2 rays, colour (0.0708, 0.0708, 0.0708) (linear RGB)\n\
        primary (depth 1, weight 1.0000) from (0.0000, 1.2000, 4.5000): hits ground at t = 6.7973\n  \
        shadow (depth 1, weight 1.0000) from (-0.8145, 0.0001, -2.1407): hits yellow at t = 1.0473; in shadow: k = 0.01\n";

    #[test]
    fn a_passage_that_names_the_probes_pixel_and_its_numbers_agrees() {
        let passage = "The probe pixel, (312, 333), is hit at t = 6.80; its feeler runs 1.05 \
                       units and the point gets 0.0708, with k = 0.01 and 75 in sRGB.";
        assert_eq!(disagreements(passage, PROBE), Vec::<String>::new());
    }

    #[test]
    fn a_passage_that_names_another_pixel_or_none_is_wrong() {
        let other = disagreements("The probe pixel, (400, 300), is on the ground.", PROBE);
        assert_eq!(other.len(), 2, "{other:?}");
        assert!(other[0].contains("does not name the probe's pixel (312, 333)"));
        assert!(other[1].contains("names pixel (400, 300)"));
        let none = disagreements("The ray tree of the centre pixel.", PROBE);
        assert_eq!(none.len(), 1, "{none:?}");
    }

    #[test]
    fn a_number_the_probe_does_not_print_at_that_precision_is_wrong() {
        let wrong = disagreements("Pixel (312, 333): t = 6.79, and 0.03 of ambient.", PROBE);
        assert_eq!(wrong.len(), 2, "{wrong:?}");
        assert!(wrong[0].contains("6.79"), "{wrong:?}");
        assert!(wrong[1].contains("0.03"), "{wrong:?}");
        // One decimal is a share (0.6, 0.7), not a printed number: not checked.
        assert!(disagreements("Pixel (312, 333), weight 0.6.", PROBE).is_empty());
        // A minus sign belongs to the number.
        assert!(!disagreements("Pixel (312, 333) at x = 0.8145.", PROBE).is_empty());
        assert!(disagreements("Pixel (312, 333) at x = -0.8145.", PROBE).is_empty());
        assert!(disagreements("Pixel (312, 333) at x = −0.8145.", PROBE).is_empty());
    }

    #[test]
    fn a_passage_is_the_paragraph_before_a_ray_tree_figure_its_alt_and_caption() {
        let page = "# Page\n\nThe probe pixel, (1, 2), says t = 0.50.\n\n\
                    ![The tree of (1, 2)](figures/ch09/ray-tree.png)\n\n\
                    *Its caption.*\n\n```text\n{{#include figures/ch09/probe.txt}}\n```\n\n\
                    ![Not a tree](figures/ch09/render.png)\n";
        let found = passages(page);
        assert_eq!(found.len(), 1, "{found:?}");
        assert_eq!(found[0].dir, "ch09");
        assert_eq!(
            found[0].text,
            "The probe pixel, (1, 2), says t = 0.50.\n\
             ![The tree of (1, 2)](figures/ch09/ray-tree.png)\n*Its caption.*"
        );
    }
}
