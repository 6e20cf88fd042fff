//! A probe's ray trees as text: what `--probe` prints and writes to `probe.txt`.

use std::fmt::Write;

use raylab::Vec3;
use raylab::probe::SampleTree;
use raylab::ray::RayKind;
use raylab::scene::Scene;
use raylab::trace::TracedRay;

/// How much of a ray tree the text shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Listing {
    /// Every ray that can change the pixel; each deeper subtree that adds
    /// too little to show in an 8-bit pixel is one line saying so.
    Folded,
    /// Every ray traced (`--probe-full`).
    Full,
}

/// The most sample trees the text lists (and the ray-tree figure draws)
/// unless `--probe-full` asks for all: at `--spp 4096` a pixel has 4096
/// trees, more than anyone reads, and their colour is in the first line.
pub const SHOWN_TREES: usize = 16;

/// Light below this, in every channel, cannot move a pixel off black:
/// half of the darkest step of 8-bit sRGB, (0.5/255)/12.92 in linear light.
/// A subtree that adds less than this to the pixel is folded.
pub const INVISIBLE: f32 = 0.5 / 255.0 / 12.92;

/// The trees as indented text, one ray a line: kind, depth, weight,
/// origin, direction, what it hit and where, and what it added.
pub fn format_tree(
    scene: &Scene,
    pixel: (u32, u32),
    trees: &[SampleTree],
    listing: Listing,
) -> String {
    let mut out = String::new();
    let count: usize = trees.iter().map(|t| t.rays.len()).sum();
    let sum: Vec3 = trees.iter().flat_map(|t| &t.rays).map(|r| r.added).sum();
    let samples = trees.len().max(1);
    let _ = writeln!(
        out,
        "ray tree{} of pixel ({}, {}): {count} ray{}, colour {} (linear RGB, the average of {} sample{})",
        if trees.len() == 1 { "" } else { "s" },
        pixel.0,
        pixel.1,
        if count == 1 { "" } else { "s" },
        fmt_vec(sum / samples as f32),
        trees.len(),
        if trees.len() == 1 { "" } else { "s" },
    );
    let shown = match listing {
        Listing::Folded => trees.len().min(SHOWN_TREES),
        Listing::Full => trees.len(),
    };
    for (n, tree) in trees.iter().enumerate().take(shown) {
        if trees.len() > 1 {
            let _ = writeln!(
                out,
                "sample {} at ({}, {}) in the pixel:",
                n + 1,
                tree.offset.0,
                tree.offset.1
            );
        }
        format_rays(&mut out, scene, &tree.rays, fold_below(listing, samples));
    }
    if shown < trees.len() {
        let rest = trees.len() - shown;
        let rays: usize = trees[shown..].iter().map(|t| t.rays.len()).sum();
        let _ = writeln!(
            out,
            "… and {rest} more sample{} ({rays} rays), counted in the colour above but not listed (--probe-full lists every one)",
            if rest == 1 { "" } else { "s" },
        );
    }
    out
}

/// A ray and everything traced below it.
#[derive(Clone, Copy)]
struct Subtree {
    rays: usize,
    added: Vec3,
    deepest: u32,
}

/// The subtree of each ray of a log. Children come after their parent, so
/// one pass from the end gathers every subtree.
fn subtrees(log: &[TracedRay]) -> Vec<Subtree> {
    let mut totals: Vec<Subtree> = log
        .iter()
        .map(|r| Subtree {
            rays: 1,
            added: r.added,
            deepest: r.depth,
        })
        .collect();
    for i in (0..log.len()).rev() {
        if let Some(parent) = log[i].parent {
            let child = totals[i];
            let total = &mut totals[parent];
            total.rays += child.rays;
            total.added += child.added;
            total.deepest = total.deepest.max(child.deepest);
        }
    }
    totals
}

/// How much light a subtree must add to be listed: what a sample adds
/// reaches the pixel divided by the sample count.
pub fn fold_below(listing: Listing, samples: usize) -> f32 {
    match listing {
        Listing::Folded => INVISIBLE * samples as f32,
        Listing::Full => 0.0,
    }
}

/// How one tree is listed: each ray is listed in full, folded (one line
/// for it and everything below it), or hidden under a folded ray.
pub struct Folding {
    pub folded: Vec<bool>,
    pub hidden: Vec<bool>,
}

impl Folding {
    /// A ray is folded when it has rays below it and all of them together
    /// add less than `fold_below`; the rays under a folded one are hidden.
    pub fn of(log: &[TracedRay], fold_below: f32) -> Folding {
        let totals = subtrees(log);
        let folded: Vec<bool> = log
            .iter()
            .zip(&totals)
            .map(|(ray, sub)| {
                ray.parent.is_some() && sub.rays > 1 && sub.added.max_element() < fold_below
            })
            .collect();
        let mut hidden = vec![false; log.len()];
        for (i, ray) in log.iter().enumerate() {
            if let Some(parent) = ray.parent {
                hidden[i] = hidden[parent] || folded[parent];
            }
        }
        Folding { folded, hidden }
    }

    /// Whether ray `i` is listed in full: neither folded nor under a fold.
    pub fn listed(&self, i: usize) -> bool {
        !self.folded[i] && !self.hidden[i]
    }
}

fn format_rays(out: &mut String, scene: &Scene, log: &[TracedRay], fold_below: f32) {
    let totals = subtrees(log);
    let Folding { folded, hidden } = Folding::of(log, fold_below);
    for (i, ray) in log.iter().enumerate() {
        if hidden[i] {
            continue;
        }
        let indent = "  ".repeat(level(log, i));
        if folded[i] {
            let sub = totals[i];
            let below = sub.rays - 1;
            let _ = writeln!(
                out,
                "{indent}{} (depth {}, weight {}) and {below} ray{} below it, to depth {}: \
                 add {} in all, under half the darkest 8-bit step (--probe-full lists them)",
                ray.kind.name(),
                ray.depth,
                fmt_num(ray.weight),
                if below == 1 { "" } else { "s" },
                sub.deepest,
                fmt_vec(sub.added),
            );
            continue;
        }
        let hit = match ray.hit {
            Some((object, t)) => format!("hits {} at t = {t:.4}", scene.object_name(object)),
            None if ray.kind == RayKind::Shadow => "escapes: the sun is visible".to_owned(),
            None => "escapes to the sky".to_owned(),
        };
        let added = if ray.kind == RayKind::Shadow {
            if ray.hit.is_some() {
                "in shadow: k = 0.01".to_owned()
            } else {
                "lit: k = 0.1".to_owned()
            }
        } else {
            format!("adds {}", fmt_vec(ray.added))
        };
        let _ = writeln!(
            out,
            "{indent}{} (depth {}, weight {}) from {} along {}: {hit}; {added}",
            ray.kind.name(),
            ray.depth,
            fmt_num(ray.weight),
            fmt_point(ray.ray.origin),
            fmt_point(ray.ray.direction),
        );
    }
}

/// How many ancestors a ray has in the log.
fn level(log: &[TracedRay], mut i: usize) -> usize {
    let mut level = 0;
    while let Some(parent) = log[i].parent {
        level += 1;
        i = parent;
    }
    level
}

/// A weight or an amount of light, legible at every size: four decimals
/// down to 0.001, then two significant digits (`7.0e-5`), and `0` for none.
fn fmt_num(x: f32) -> String {
    if x == 0.0 {
        "0".to_owned()
    } else if x.abs() >= 1e-3 {
        format!("{x:.4}")
    } else {
        format!("{x:.1e}")
    }
}

fn fmt_vec(v: Vec3) -> String {
    format!("({}, {}, {})", fmt_num(v.x), fmt_num(v.y), fmt_num(v.z))
}

/// A position or a direction: scene units, four decimals.
fn fmt_point(v: Vec3) -> String {
    format!("({:.4}, {:.4}, {:.4})", v.x, v.y, v.z)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn small_numbers_keep_two_significant_digits() {
        assert_eq!(fmt_num(0.7), "0.7000");
        assert_eq!(fmt_num(0.0049), "0.0049");
        assert_eq!(fmt_num(7.0e-5), "7.0e-5");
        assert_eq!(fmt_num(3.43e-7), "3.4e-7");
        assert_eq!(fmt_num(0.0), "0");
    }

    #[test]
    fn the_invisible_threshold_rounds_to_black_in_8_bit() {
        assert_eq!(raylab::srgb::encode_channel(INVISIBLE * 0.999), 0);
        assert_eq!(raylab::srgb::encode_channel(INVISIBLE * 1.001), 1);
    }
}
