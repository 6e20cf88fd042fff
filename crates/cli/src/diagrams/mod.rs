//! The figures every chapter writes beside its render: where the rays go.
//!
//! - [`heatmaps`]: per pixel, how deep its ray tree went and how many rays it took;
//! - [`ray_tree`]: one pixel's ray tree, seen from above and from the side;
//! - [`sweep`]: the image at every max depth, and when it stops changing.

pub mod heatmaps;
pub mod ray_tree;
pub mod sweep;

use raylab::ray::RayKind;
use raylab_plot::Rgb;

/// The colour of each kind of ray, the same in every diagram.
pub fn kind_colour(kind: RayKind) -> Rgb {
    match kind {
        RayKind::Primary => [40, 40, 40],
        RayKind::Shadow => [230, 159, 0],
        RayKind::Reflection => [0, 114, 178],
        RayKind::Refraction => [0, 158, 115],
        RayKind::TotalInternalReflection => [204, 51, 153],
    }
}
