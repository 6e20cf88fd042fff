//! How a panel flattens the scene: from above, or in the vertical plane
//! of the primary ray.

use glam::Vec2;
use raylab::Vec3;

use super::{PANEL_HEIGHT, PANEL_TOP};

/// How a panel flattens the scene: a map from 3-D to (across, up) in scene
/// units, and the window of the plane it shows.
pub(super) struct View {
    pub(super) name: &'static str,
    pub(super) across_label: &'static str,
    pub(super) up_label: &'static str,
    pub(super) flatten: Box<dyn Fn(Vec3) -> Vec2>,
    /// Lower-left and upper-right corners of the window, scene units.
    pub(super) min: Vec2,
    pub(super) max: Vec2,
    /// Where the panel sits on the canvas, pixels.
    pub(super) left: f32,
    pub(super) width: f32,
    /// Where the sun's direction is drawn: in a corner rays rarely cross
    /// (`true` for the top-right corner, `false` for the bottom-right).
    pub(super) sun_at_top: bool,
    /// For a side view, the vertical plane shown (a point on it and its
    /// normal): spheres are drawn as their cross-section with it.
    pub(super) plane: Option<(Vec3, Vec3)>,
}

impl View {
    /// Pixels per scene unit: the same along both axes, so circles stay round.
    pub(super) fn scale(&self) -> f32 {
        let size = self.max - self.min;
        (self.width / size.x).min(PANEL_HEIGHT / size.y)
    }

    pub(super) fn to_canvas(&self, p: Vec3) -> (f32, f32) {
        self.plane_to_canvas(self.flatten.as_ref()(p))
    }

    pub(super) fn plane_to_canvas(&self, q: Vec2) -> (f32, f32) {
        let s = self.scale();
        (
            self.left + (q.x - self.min.x) * s,
            PANEL_TOP + (self.max.y - q.y) * s,
        )
    }
}

/// Looking down on the scene: x to the right, z towards the bottom of the
/// page (where the camera is).
pub(super) fn top_view() -> View {
    View {
        name: "From above (the x–z plane)",
        across_label: "x",
        up_label: "−z",
        flatten: Box::new(|p| Vec2::new(p.x, -p.z)),
        min: Vec2::new(-3.5, -5.2),
        max: Vec2::new(3.5, 3.5),
        left: 50.0,
        width: 440.0,
        sun_at_top: false,
        plane: None,
    }
}

/// The vertical plane that holds the primary ray: across is the distance
/// from the eye along the ray's horizontal heading, up is height.
pub(super) fn side_view(eye: Vec3, primary: Vec3) -> View {
    let heading = Vec3::new(primary.x, 0.0, primary.z).normalize_or(Vec3::NEG_Z);
    View {
        name: "From the side (the vertical plane of the primary ray; dashed: a sphere off it)",
        across_label: "distance from the eye along the view",
        up_label: "y",
        flatten: Box::new(move |p| Vec2::new((p - eye).dot(heading), p.y)),
        min: Vec2::new(-0.5, -0.7),
        max: Vec2::new(9.0, 3.3),
        left: 560.0,
        width: 650.0,
        sun_at_top: true,
        plane: Some((eye, heading.cross(Vec3::Y))),
    }
}
