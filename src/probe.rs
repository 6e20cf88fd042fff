//! Following one pixel's rays: the ray tree behind a single colour.

use crate::camera::Camera;
use crate::frame::Settings;
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
