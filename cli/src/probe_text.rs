//! A probe's ray trees as text: what `--probe` prints and writes to `probe.txt`.

use std::fmt::Write;

use raylab::Vec3;
use raylab::probe::SampleTree;
use raylab::ray::RayKind;
use raylab::scene::Scene;
use raylab::trace::TracedRay;

/// The trees as indented text, one ray a line: kind, depth, weight,
/// origin, direction, what it hit and where, and what it added.
pub fn format_tree(scene: &Scene, pixel: (u32, u32), trees: &[SampleTree]) -> String {
    let mut out = String::new();
    let count: usize = trees.iter().map(|t| t.rays.len()).sum();
    let sum: Vec3 = trees.iter().flat_map(|t| &t.rays).map(|r| r.added).sum();
    let _ = writeln!(
        out,
        "ray tree{} of pixel ({}, {}): {count} rays, colour {} (linear RGB, the average of {} sample{})",
        if trees.len() == 1 { "" } else { "s" },
        pixel.0,
        pixel.1,
        fmt_vec(sum / trees.len().max(1) as f32),
        trees.len(),
        if trees.len() == 1 { "" } else { "s" },
    );
    for (n, tree) in trees.iter().enumerate() {
        if trees.len() > 1 {
            let _ = writeln!(
                out,
                "sample {} at ({}, {}) in the pixel:",
                n + 1,
                tree.offset.0,
                tree.offset.1
            );
        }
        format_rays(&mut out, scene, &tree.rays);
    }
    out
}

fn format_rays(out: &mut String, scene: &Scene, log: &[TracedRay]) {
    for (i, ray) in log.iter().enumerate() {
        let indent = "  ".repeat(level(log, i));
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
            "{indent}{} (depth {}, weight {:.4}) from {} along {}: {hit}; {added}",
            ray.kind.name(),
            ray.depth,
            ray.weight,
            fmt_vec(ray.ray.origin),
            fmt_vec(ray.ray.direction),
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

fn fmt_vec(v: Vec3) -> String {
    format!("({:.4}, {:.4}, {:.4})", v.x, v.y, v.z)
}
