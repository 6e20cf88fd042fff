//! Following one pixel's rays: the ray tree behind a single colour.

use std::fmt::Write;

use crate::camera::Camera;
use crate::ray::RayKind;
use crate::render::Settings;
use crate::scene::Scene;
use crate::trace::{Step, TracedRay, Tracer};

/// Which pixel a chapter probes when `--probe` is not given.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ProbeTarget {
    /// The pixel where the centre of the named sphere is seen.
    SphereCentre(&'static str),
    /// A ground pixel in the shadow of the named sphere: the point whose
    /// line towards the sun passes through the sphere's centre.
    ShadowOf(&'static str),
}

impl ProbeTarget {
    /// The pixel `(x, y)` this target is seen at in a `width` × `height`
    /// image, if it is on screen.
    pub fn pixel(
        &self,
        scene: &Scene,
        camera: &Camera,
        width: u32,
        height: u32,
    ) -> Option<(u32, u32)> {
        let point = match *self {
            ProbeTarget::SphereCentre(name) => {
                scene.spheres()[scene.sphere_named(name)?].shape.centre
            }
            ProbeTarget::ShadowOf(name) => {
                let centre = scene.spheres()[scene.sphere_named(name)?].shape.centre;
                let to_sun = scene.sun.direction;
                centre - to_sun * (centre.y / to_sun.y)
            }
        };
        let (x, y) = camera.project(point, width, height)?;
        let inside = (0.0..width as f32).contains(&x) && (0.0..height as f32).contains(&y);
        inside.then_some((x as u32, y as u32))
    }
}

/// One sample's ray tree: where in the pixel it started, and every ray in
/// the order it was traced (parents before children).
#[derive(Clone, Debug, PartialEq)]
pub struct SampleTree {
    pub offset: (f32, f32),
    pub rays: Vec<TracedRay>,
}

/// The ray trees of pixel `(x, y)`, one per sample of the pattern: one
/// tree with one sample per pixel, five with the lab's five rays, N with N.
pub fn probe<S: Step + ?Sized>(
    scene: &Scene,
    camera: &Camera,
    step: &S,
    settings: &Settings,
    (x, y): (u32, u32),
) -> Vec<SampleTree> {
    settings
        .sampling
        .offsets((x, y))
        .map(|offset| {
            let ray = camera.ray(x, y, offset, settings.width, settings.height);
            let mut tracer =
                Tracer::new(scene, step, settings.max_depth, settings.epsilon).with_log();
            tracer.trace(ray);
            SampleTree {
                offset,
                rays: tracer.log().to_vec(),
            }
        })
        .collect()
}

/// The trees as indented text, one ray a line: kind, depth, weight,
/// origin, direction, what it hit and where, and what it added.
pub fn format_tree(scene: &Scene, pixel: (u32, u32), trees: &[SampleTree]) -> String {
    let mut out = String::new();
    let count: usize = trees.iter().map(|t| t.rays.len()).sum();
    let sum: crate::Vec3 = trees.iter().flat_map(|t| &t.rays).map(|r| r.added).sum();
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

fn fmt_vec(v: crate::Vec3) -> String {
    format!("({:.4}, {:.4}, {:.4})", v.x, v.y, v.z)
}
