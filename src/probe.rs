//! Following one pixel's rays: the ray tree behind a single colour.

use crate::Vec3;
use crate::camera::Camera;
use crate::frame::Settings;
use crate::scene::Scene;
use crate::trace::{Step, TracedRay, Tracer};

/// Which pixel a chapter probes when `--probe` is not given: a pixel
/// chosen to show the chapter's new rays, so not always a centre (the
/// mirror's centre reflects straight back along the primary ray; a
/// feeler from right under a ball is too short to see).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ProbeTarget {
    /// The pixel where the named sphere is seen `right` and `up` of its
    /// centre, in radii along the camera's right and up directions:
    /// `(0, 0)` is the centre, and a point at distance 1 is on its outline
    /// (near enough: perspective makes the outline a little larger).
    OnSphere {
        /// The sphere's name in the scene.
        name: &'static str,
        /// Radii to the right of the centre, as the camera sees it.
        right: f32,
        /// Radii up from the centre, as the camera sees it.
        up: f32,
    },
    /// A ground pixel in the shadow of the named sphere: the point whose
    /// line towards the sun passes `above` radii above the sphere's
    /// centre. The higher the line crosses the ball, the longer the
    /// feeler from the ground to it.
    ShadowOf {
        /// The name of the sphere casting the shadow.
        name: &'static str,
        /// Radii above the sphere's centre that the line to the sun passes.
        above: f32,
    },
}

impl ProbeTarget {
    /// The pixel where the centre of the named sphere is seen.
    pub const fn centre_of(name: &'static str) -> ProbeTarget {
        ProbeTarget::OnSphere {
            name,
            right: 0.0,
            up: 0.0,
        }
    }

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
            ProbeTarget::OnSphere { name, right, up } => {
                let sphere = scene.spheres()[scene.sphere_named(name)?].shape;
                sphere.centre + (camera.right() * right + camera.up() * up) * sphere.radius
            }
            ProbeTarget::ShadowOf { name, above } => {
                let sphere = scene.spheres()[scene.sphere_named(name)?].shape;
                let crossing = sphere.centre + Vec3::Y * (above * sphere.radius);
                let to_sun = scene.sun.direction;
                crossing - to_sun * (crossing.y / to_sun.y)
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
    /// Where in the pixel the sample's primary ray starts, in [0,1)².
    pub offset: (f32, f32),
    /// Every ray of its tree, shadow rays included.
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

#[cfg(test)]
mod tests {
    use super::*;

    fn lab_pixel(target: ProbeTarget) -> Option<(u32, u32)> {
        target.pixel(&Scene::lab(), &Camera::lab(), 800, 600)
    }

    #[test]
    fn the_red_balls_centre_is_seen_in_the_middle_column() {
        // The red ball's centre (0, 1, -1.5) is straight ahead in x: column
        // 400 exactly. It is 0.2404 of the half-height up from the middle
        // row: (1 - 0.2404) · 300 = 227.9, so row 227.
        assert_eq!(lab_pixel(ProbeTarget::centre_of("red")), Some((400, 227)));
    }

    #[test]
    fn a_point_off_a_spheres_centre_is_seen_to_the_right_and_above() {
        // The glass ball's centre is seen at (593.3, 320.4); half a radius
        // right and 0.3 of one up moves it 58 columns right, 35 rows up.
        let target = ProbeTarget::OnSphere {
            name: "glass",
            right: 0.5,
            up: 0.3,
        };
        assert_eq!(lab_pixel(target), Some((651, 285)));
    }

    #[test]
    fn a_shadow_target_is_the_ground_point_whose_feeler_crosses_the_ball() {
        // The line towards the sun through (-2, 1.425, -1.2), 0.9 radii
        // above the yellow ball's centre, meets the ground 1.425 / 0.6838
        // units further on, at (-0.8125, 0, -2.15): seen at (312.8, 333.3).
        let target = ProbeTarget::ShadowOf {
            name: "yellow",
            above: 0.9,
        };
        assert_eq!(lab_pixel(target), Some((312, 333)));
    }

    #[test]
    fn a_target_on_a_sphere_the_scene_does_not_have_is_not_probed() {
        assert_eq!(lab_pixel(ProbeTarget::centre_of("green")), None);
    }
}
