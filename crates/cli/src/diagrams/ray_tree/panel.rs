//! One panel: its grid and axes, the ground, the spheres (whole from
//! above, their cross-sections from the side), the sun's direction, and
//! the rays.

use glam::Vec2;

use super::SKY_STUB;
use super::rays::{crossings, draw_badge, draw_ray, label_crossing};
use super::view::View;
use crate::diagrams::kind_colour;
use raylab::camera::Camera;
use raylab::ray::RayKind;
use raylab::scene::{Object, Scene};
use raylab::srgb::encode_channel;
use raylab::trace::TracedRay;
use raylab_plot::LabelBox;
use raylab_plot::colour::{AXIS, FRAME, GRID, TEXT, TEXT_MUTED, WHITE, mix};
use raylab_plot::{Anchor, Canvas, Rgb};

pub(super) fn draw_panel(
    canvas: &mut Canvas,
    scene: &Scene,
    camera: &Camera,
    view: &View,
    log: &[TracedRay],
) {
    let s = view.scale();
    let (x0, y1) = view.plane_to_canvas(view.min);
    let (x1, y0) = view.plane_to_canvas(view.max);
    canvas.text(
        (x0 + x1) / 2.0,
        y0 - 8.0,
        view.name,
        15.0,
        TEXT,
        Anchor::BASELINE_CENTRE,
    );
    draw_grid(canvas, view, (x0, y0, x1, y1));
    canvas.set_clip_rect(x0, y0, x1 - x0, y1 - y0);

    // The ground: a line at y = 0 seen from the side.
    if view.up_label == "y" {
        let (gx0, gy) = view.plane_to_canvas(Vec2::new(view.min.x, 0.0));
        let (gx1, _) = view.plane_to_canvas(Vec2::new(view.max.x, 0.0));
        canvas.stroke_line(gx0, gy, gx1, gy, AXIS, 2.0);
        canvas.text(
            gx1 - 6.0,
            gy + 4.0,
            "ground",
            12.0,
            TEXT_MUTED,
            Anchor::TOP_RIGHT,
        );
    }
    // Spheres a ray of the tree hits, so that no ray ends in empty space.
    let hit: Vec<usize> = log
        .iter()
        .filter_map(|r| match r.hit {
            Some((Object::Sphere(index), _)) => Some(index),
            _ => None,
        })
        .collect();
    let mut taken = Vec::new();
    for (index, sphere) in scene.spheres().iter().enumerate() {
        let albedo = sphere.material.albedo().to_array().map(encode_channel);
        let centre = view.to_canvas(sphere.shape.centre);
        let mut radius = sphere.shape.radius;
        let mut cut = true;
        if let Some((point, normal)) = view.plane {
            // Only the circle where the plane cuts the sphere lies in it; a
            // sphere it misses is drawn, dashed, as its shadow on the
            // plane, if a ray hits it.
            let off = (sphere.shape.centre - point).dot(normal);
            if off.abs() < radius {
                radius = (radius * radius - off * off).sqrt();
            } else if hit.contains(&index) {
                cut = false;
            } else {
                continue;
            }
        }
        let radius = radius * s;
        if cut {
            canvas.circle(
                centre,
                radius,
                Some(mix(albedo, WHITE, 0.55)),
                Some((albedo, 1.5)),
            );
        } else {
            dashed_circle(canvas, centre, radius, albedo);
        }
        let name = if cut {
            sphere.name.clone()
        } else {
            format!("{} (off the plane)", sphere.name)
        };
        canvas.text(
            centre.0,
            centre.1,
            &name,
            12.0,
            TEXT_MUTED,
            Anchor::MIDDLE_CENTRE,
        );
        let w = canvas.text_width(&name, 12.0);
        taken.push(LabelBox::around(centre, w + 6.0, 18.0));
    }
    // Seen from above, a ray that passes over or under a ball would seem
    // to go through it: the stretch over a ball is drawn on a white edge
    // (a bridge), the stretch under one dashed (hidden), as a map draws a
    // road that crosses another, and each is labelled.
    let mut labels = Vec::new();
    for ray in log {
        let crossings = match view.plane {
            None if ray.kind != RayKind::Shadow => crossings(scene, ray),
            _ => Vec::new(),
        };
        draw_ray(canvas, view, ray, &crossings);
        labels.extend(crossings.iter().map(|c| (ray, *c)));
    }
    for (ray, crossing) in labels {
        label_crossing(canvas, scene, view, ray, crossing, &mut taken);
    }
    // The depths last, each on a leader line beside its ray, where it hides
    // no name and no other depth.
    // Rays of several samples that run together share one badge.
    let mut badged: Vec<(RayKind, u32, (f32, f32))> = Vec::new();
    for ray in log.iter().filter(|r| r.kind != RayKind::Shadow) {
        let length = ray.hit.map_or(SKY_STUB, |(_, t)| t);
        let (a, b) = (
            view.to_canvas(ray.ray.origin),
            view.to_canvas(ray.ray.at(length)),
        );
        let middle = ((a.0 + b.0) / 2.0, (a.1 + b.1) / 2.0);
        let twin = badged.iter().any(|&(kind, depth, m)| {
            kind == ray.kind && depth == ray.depth && (m.0 - middle.0).hypot(m.1 - middle.1) < 24.0
        });
        if !twin {
            draw_badge(canvas, view, ray, &mut taken);
            badged.push((ray.kind, ray.depth, middle));
        }
    }
    // The camera, and the direction of the sun from the panel's corner.
    let eye = view.to_canvas(camera.eye);
    canvas.circle(eye, 5.0, Some(TEXT), None);
    canvas.text(
        eye.0 + 8.0,
        eye.1 - 6.0,
        "camera",
        12.0,
        TEXT,
        Anchor::BASELINE_LEFT,
    );
    canvas.clear_clip();
    let sun =
        view.flatten.as_ref()(camera.eye + scene.sun.direction) - view.flatten.as_ref()(camera.eye);
    if let Some(sun) = sun.try_normalize() {
        let from = if view.sun_at_top {
            (x1 - 70.0, y0 + 60.0)
        } else {
            (x1 - 70.0, y1 - 60.0)
        };
        let to = (from.0 + sun.x * 45.0, from.1 - sun.y * 45.0);
        canvas.arrow(from, to, kind_colour(RayKind::Shadow), 2.5, 10.0);
        // The label goes on the side of the start the arrow does not point to.
        let (y, anchor) = if sun.y > 0.0 {
            (from.1 + 8.0, Anchor::TOP_CENTRE)
        } else {
            (from.1 - 8.0, Anchor::BASELINE_CENTRE)
        };
        canvas.text(from.0, y, "to the sun", 12.0, TEXT, anchor);
    }
}

pub(super) fn draw_grid(canvas: &mut Canvas, view: &View, (x0, y0, x1, y1): (f32, f32, f32, f32)) {
    let (lo, hi) = (view.min.ceil(), view.max.floor());
    for i in lo.x as i32..=hi.x as i32 {
        let (x, _) = view.plane_to_canvas(Vec2::new(i as f32, view.min.y));
        canvas.stroke_line(x, y0, x, y1, GRID, 1.0);
        canvas.text(
            x,
            y1 + 6.0,
            &i.to_string(),
            12.0,
            TEXT_MUTED,
            Anchor::TOP_CENTRE,
        );
    }
    for j in lo.y as i32..=hi.y as i32 {
        let (_, y) = view.plane_to_canvas(Vec2::new(view.min.x, j as f32));
        canvas.stroke_line(x0, y, x1, y, GRID, 1.0);
        canvas.text(
            x0 - 6.0,
            y,
            &j.to_string(),
            12.0,
            TEXT_MUTED,
            Anchor::MIDDLE_RIGHT,
        );
    }
    canvas.stroke_rect(x0, y0, x1 - x0, y1 - y0, FRAME, 1.0);
    canvas.text(
        (x0 + x1) / 2.0,
        y1 + 24.0,
        view.across_label,
        13.0,
        TEXT,
        Anchor::TOP_CENTRE,
    );
    canvas.text_vertical(
        x0 - 30.0,
        (y0 + y1) / 2.0,
        view.up_label,
        13.0,
        TEXT,
        Anchor::MIDDLE_CENTRE,
    );
}

/// A circle drawn as dashes: a sphere the plane of the view does not cut.
pub(super) fn dashed_circle(canvas: &mut Canvas, centre: (f32, f32), radius: f32, colour: Rgb) {
    let segments = ((radius * 0.6).ceil() as usize).clamp(12, 96) * 2;
    let point = |k: usize| {
        let a = std::f32::consts::TAU * k as f32 / segments as f32;
        (centre.0 + radius * a.cos(), centre.1 + radius * a.sin())
    };
    for k in (0..segments).step_by(2) {
        let (a, b) = (point(k), point(k + 1));
        canvas.stroke_line(a.0, a.1, b.0, b.1, colour, 1.5);
    }
}
