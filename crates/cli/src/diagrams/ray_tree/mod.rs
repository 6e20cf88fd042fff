//! One pixel's ray tree drawn in the scene: from above, and from the side.
//!
//! The figure ([`ray_tree_figure`]) is two panels of the same rays: how
//! a panel flattens the scene (`view`), what a panel draws (`panel`: the
//! grid, the spheres, the sun), and how each ray is drawn (`rays`: its
//! arrow, its depth badge, and where it passes over or under a ball).

mod panel;
mod rays;
mod view;

use image::RgbImage;

use crate::diagrams::kind_colour;
use panel::draw_panel;
use raylab::camera::Camera;
use raylab::ray::RayKind;
use raylab::scene::Scene;
use raylab::trace::TracedRay;
use raylab_plot::colour::{TEXT, TEXT_MUTED, WHITE};
use raylab_plot::{Anchor, Canvas, Rgb};
use view::{side_view, top_view};

const WIDTH: u32 = 1240;
const HEIGHT: u32 = 700;
const PANEL_TOP: f32 = 92.0;
const PANEL_HEIGHT: f32 = 500.0;
/// How far a ray that escapes to the sky is drawn, in scene units.
const SKY_STUB: f32 = 1.5;

/// The diagram of one pixel's ray tree (or the trees of all its samples,
/// drawn together), as the renderer traced it.
pub fn ray_tree_figure(
    scene: &Scene,
    camera: &Camera,
    title: &str,
    pixel: (u32, u32),
    log: &[TracedRay],
    left_out: usize,
) -> RgbImage {
    let mut canvas = Canvas::new(WIDTH, HEIGHT, WHITE);
    canvas.text(
        WIDTH as f32 / 2.0,
        18.0,
        title,
        22.0,
        TEXT,
        Anchor::TOP_CENTRE,
    );
    let rays = log.iter().filter(|r| r.kind != RayKind::Shadow).count();
    let shadows = log.len() - rays;
    let subtitle = format!(
        "The rays traced for pixel ({}, {}): {rays} ray{} and {shadows} shadow ray{}. \
         Arrows run from each ray's origin to what it hits; line width shows its weight.",
        pixel.0,
        pixel.1,
        if rays == 1 { "" } else { "s" },
        if shadows == 1 { "" } else { "s" },
    );
    if left_out > 0 {
        // Under the side view, where the figure has room.
        canvas.text(
            WIDTH as f32 * 0.71,
            440.0,
            &format!(
                "Not drawn: {left_out} deeper ray{}, which together add under half an \
                 8-bit step (--probe-full draws them).",
                if left_out == 1 { "" } else { "s" }
            ),
            14.0,
            TEXT_MUTED,
            Anchor::TOP_CENTRE,
        );
    }
    canvas.text(
        WIDTH as f32 / 2.0,
        52.0,
        &subtitle,
        14.0,
        TEXT_MUTED,
        Anchor::TOP_CENTRE,
    );

    let primary = log.first().map_or(camera.forward(), |r| r.ray.direction);
    for view in [top_view(), side_view(camera.eye, primary)] {
        draw_panel(&mut canvas, scene, camera, &view, log);
    }
    draw_legend(&mut canvas);
    canvas.to_rgb_image()
}

fn draw_legend(canvas: &mut Canvas) {
    let y = HEIGHT as f32 - 34.0;
    let mut x = 60.0;
    let entries: [(RayKind, &str); 5] = [
        (RayKind::Primary, "primary"),
        (RayKind::Reflection, "reflection"),
        (RayKind::Refraction, "refraction"),
        (
            RayKind::TotalInternalReflection,
            "total internal reflection",
        ),
        (RayKind::Shadow, "shadow ray (dashed; × where blocked)"),
    ];
    for (kind, name) in entries {
        let colour: Rgb = kind_colour(kind);
        if kind == RayKind::Shadow {
            canvas.dashed_line((x, y), (x + 34.0, y), colour, 1.5, 6.0, 4.0);
        } else {
            canvas.arrow((x, y), (x + 34.0, y), colour, 2.5, 9.0);
        }
        canvas.text(x + 42.0, y, name, 14.0, TEXT, Anchor::MIDDLE_LEFT);
        x += 42.0 + canvas.text_width(name, 14.0) + 36.0;
    }
    canvas.circle((x + 8.0, y), 8.0, Some(WHITE), Some((TEXT, 1.0)));
    canvas.text(x + 8.0, y, "2", 11.0, TEXT, Anchor::MIDDLE_CENTRE);
    canvas.text(
        x + 22.0,
        y,
        "depth of the ray",
        14.0,
        TEXT,
        Anchor::MIDDLE_LEFT,
    );
}
