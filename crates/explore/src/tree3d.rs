//! A clicked pixel's ray trees drawn into the scene in 3D: each ray a
//! segment projected through the current camera, in the ray-tree
//! diagram's colours (`raylab_cli::diagrams::kind_colour`), as wide as its
//! weight, so that orbiting shows the tree from the side.

use raylab::trace::TracedRay;
use raylab::{Camera, RayKind, Vec3};
use raylab_cli::diagrams::kind_colour;
use raylab_plot::Canvas;

use crate::probe::Probe;

/// How far a ray that escapes to the sky is drawn, in scene units (the
/// ray-tree diagram's stub).
const SKY_STUB: f32 = 1.5;
/// Segments are cut where they pass this close to the eye's plane, so
/// that nothing behind the camera is projected.
const NEAR: f32 = 0.05;
/// The most trees drawn: past a few they are a tangle (as in the diagram).
const DRAWN_TREES: usize = raylab_cli::probe_text::SHOWN_TREES;

/// Draw `probe`'s trees as seen through `camera`.
pub fn draw(canvas: &mut Canvas, camera: &Camera, probe: &Probe) {
    let (width, height) = (canvas.width(), canvas.height());
    for tree in probe.trees.iter().take(DRAWN_TREES) {
        for ray in &tree.rays {
            draw_ray(canvas, camera, (width, height), ray);
        }
    }
    // The clicked pixel where it was, as long as the camera has not moved.
    if *camera == probe.camera {
        let (x, y) = (probe.pixel.0 as f32 + 0.5, probe.pixel.1 as f32 + 0.5);
        canvas.circle((x, y), 5.0, None, Some(([255, 255, 255], 2.0)));
    }
}

/// The mean x on screen of the drawn rays' ends, or `None` when none is
/// in front of the camera: where the tree is, for the text to keep clear of.
pub fn mean_x(camera: &Camera, size: (u32, u32), probe: &Probe) -> Option<f32> {
    let (mut sum, mut n) = (0.0, 0.0);
    for tree in probe.trees.iter().take(DRAWN_TREES) {
        for ray in &tree.rays {
            let length = ray.hit.map_or(SKY_STUB, |(_, t)| t);
            if let Some((from, to)) =
                project_segment(camera, size, ray.ray.origin, ray.ray.at(length))
            {
                sum += from.0 + to.0;
                n += 2.0;
            }
        }
    }
    (n > 0.0).then(|| sum / n)
}

fn draw_ray(canvas: &mut Canvas, camera: &Camera, size: (u32, u32), ray: &TracedRay) {
    let length = ray.hit.map_or(SKY_STUB, |(_, t)| t);
    let Some((from, to)) = project_segment(camera, size, ray.ray.origin, ray.ray.at(length)) else {
        return;
    };
    let colour = kind_colour(ray.kind);
    let halo = [255, 255, 255];
    if ray.kind == RayKind::Shadow {
        canvas.dashed_line(from, to, halo, 3.5, 6.0, 4.0);
        canvas.dashed_line(from, to, colour, 1.5, 6.0, 4.0);
        if ray.hit.is_some() {
            canvas.circle(to, 3.5, Some([204, 51, 51]), Some((halo, 1.0)));
        }
        return;
    }
    let width = 1.0 + 3.0 * ray.weight;
    // A pale halo keeps the dark primary ray visible on dark ground.
    canvas.stroke_line(from.0, from.1, to.0, to.1, halo, width + 2.0);
    canvas.arrow(from, to, colour, width, 8.0 + width);
}

/// The segment `a`–`b` on screen, cut at the near plane; `None` when it
/// lies wholly behind the camera.
pub fn project_segment(
    camera: &Camera,
    (width, height): (u32, u32),
    a: Vec3,
    b: Vec3,
) -> Option<((f32, f32), (f32, f32))> {
    let depth = |p: Vec3| (p - camera.eye).dot(camera.forward());
    let (za, zb) = (depth(a), depth(b));
    if za < NEAR && zb < NEAR {
        return None;
    }
    let cut = |p: Vec3, zp: f32, q: Vec3, zq: f32| {
        if zp >= NEAR {
            p
        } else {
            p + (q - p) * ((NEAR - zp) / (zq - zp))
        }
    };
    let (a, b) = (cut(a, za, b, zb), cut(b, zb, a, za));
    let pa = camera.project(a, width, height)?;
    let pb = camera.project(b, width, height)?;
    let finite = |p: (f32, f32)| p.0.is_finite() && p.1.is_finite();
    (finite(pa) && finite(pb)).then_some((pa, pb))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_segment_behind_the_camera_is_not_drawn() {
        let camera = Camera::lab();
        let behind = camera.eye - camera.forward();
        assert!(project_segment(&camera, (640, 480), behind, behind - camera.forward()).is_none());
    }

    #[test]
    fn a_segment_through_the_eye_plane_is_cut_not_dropped() {
        let camera = Camera::lab();
        let behind = camera.eye - camera.forward() + camera.right() * 0.1;
        let ahead = camera.eye + camera.forward() * 3.0;
        let (from, to) = project_segment(&camera, (640, 480), behind, ahead).unwrap();
        assert!(from.0.is_finite() && to.0.is_finite());
        // The far end is the image's centre.
        assert!((to.0 - 320.0).abs() < 1.0 && (to.1 - 240.0).abs() < 1.0);
    }
}
