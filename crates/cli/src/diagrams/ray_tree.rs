//! One pixel's ray tree drawn in the scene: from above, and from the side.

use glam::Vec2;
use image::RgbImage;

use super::kind_colour;
use raylab::Vec3;
use raylab::camera::Camera;
use raylab::ray::RayKind;
use raylab::scene::{Object, Scene};
use raylab::srgb::encode_channel;
use raylab::trace::TracedRay;
use raylab_plot::LabelBox;
use raylab_plot::colour::{AXIS, FRAME, GRID, TEXT, TEXT_MUTED, WHITE, mix};
use raylab_plot::{Anchor, Canvas, Rgb};

const WIDTH: u32 = 1240;
const HEIGHT: u32 = 700;
const PANEL_TOP: f32 = 92.0;
const PANEL_HEIGHT: f32 = 500.0;
/// How far a ray that escapes to the sky is drawn, in scene units.
const SKY_STUB: f32 = 1.5;

/// How a panel flattens the scene: a map from 3-D to (across, up) in scene
/// units, and the window of the plane it shows.
struct View {
    name: &'static str,
    across_label: &'static str,
    up_label: &'static str,
    flatten: Box<dyn Fn(Vec3) -> Vec2>,
    /// Lower-left and upper-right corners of the window, scene units.
    min: Vec2,
    max: Vec2,
    /// Where the panel sits on the canvas, pixels.
    left: f32,
    width: f32,
    /// Where the sun's direction is drawn: in a corner rays rarely cross
    /// (`true` for the top-right corner, `false` for the bottom-right).
    sun_at_top: bool,
    /// For a side view, the vertical plane shown (a point on it and its
    /// normal): spheres are drawn as their cross-section with it.
    plane: Option<(Vec3, Vec3)>,
}

impl View {
    /// Pixels per scene unit: the same along both axes, so circles stay round.
    fn scale(&self) -> f32 {
        let size = self.max - self.min;
        (self.width / size.x).min(PANEL_HEIGHT / size.y)
    }

    fn to_canvas(&self, p: Vec3) -> (f32, f32) {
        self.plane_to_canvas(self.flatten.as_ref()(p))
    }

    fn plane_to_canvas(&self, q: Vec2) -> (f32, f32) {
        let s = self.scale();
        (
            self.left + (q.x - self.min.x) * s,
            PANEL_TOP + (self.max.y - q.y) * s,
        )
    }
}

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

/// Looking down on the scene: x to the right, z towards the bottom of the
/// page (where the camera is).
fn top_view() -> View {
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
fn side_view(eye: Vec3, primary: Vec3) -> View {
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

fn draw_panel(canvas: &mut Canvas, scene: &Scene, camera: &Camera, view: &View, log: &[TracedRay]) {
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
    for ray in log {
        draw_ray(canvas, view, ray);
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

fn draw_grid(canvas: &mut Canvas, view: &View, (x0, y0, x1, y1): (f32, f32, f32, f32)) {
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

fn draw_ray(canvas: &mut Canvas, view: &View, ray: &TracedRay) {
    let length = ray.hit.map_or(SKY_STUB, |(_, t)| t);
    let from = view.to_canvas(ray.ray.origin);
    let to = view.to_canvas(ray.ray.at(length));
    let colour = kind_colour(ray.kind);
    if ray.kind == RayKind::Shadow {
        canvas.dashed_line(from, to, colour, 1.5, 6.0, 4.0);
        if ray.hit.is_some() {
            // Blocked: a cross where the feeler meets the object in the
            // way, which may be too close to the start to see the line.
            let blocked = [204, 51, 51];
            canvas.stroke_line(to.0 - 6.0, to.1 - 6.0, to.0 + 6.0, to.1 + 6.0, blocked, 2.5);
            canvas.stroke_line(to.0 - 6.0, to.1 + 6.0, to.0 + 6.0, to.1 - 6.0, blocked, 2.5);
        }
        return;
    }
    let width = 1.0 + 3.0 * ray.weight;
    canvas.arrow(from, to, colour, width, 9.0);
}

/// The ray's depth in a badge, on a short leader line from a point of the
/// arrow: the first spot, nearest the arrow's middle, that covers no name
/// and no badge already placed. A ray too short to see gets none.
fn draw_badge(canvas: &mut Canvas, view: &View, ray: &TracedRay, taken: &mut Vec<LabelBox>) {
    let length = ray.hit.map_or(SKY_STUB, |(_, t)| t);
    let from = view.to_canvas(ray.ray.origin);
    let to = view.to_canvas(ray.ray.at(length));
    let (dx, dy) = (to.0 - from.0, to.1 - from.1);
    let span = dx.hypot(dy);
    if span < 40.0 {
        return;
    }
    let normal = (-dy / span, dx / span);
    let spots = [0.5, 0.35, 0.65, 0.2, 0.8]
        .into_iter()
        .flat_map(|along| [22.0, -22.0, 36.0, -36.0].map(move |away: f32| (along, away)));
    let mut chosen = None;
    for (along, away) in spots {
        let foot = (from.0 + dx * along, from.1 + dy * along);
        let centre = (foot.0 + normal.0 * away, foot.1 + normal.1 * away);
        let spot = LabelBox::around(centre, 18.0, 18.0);
        if !taken.iter().any(|t| t.overlaps(&spot)) {
            chosen = Some((foot, centre, spot));
            break;
        }
    }
    // Crowded everywhere: the nearest spot, even if it overlaps.
    let (foot, centre, spot) = chosen.unwrap_or_else(|| {
        let foot = (from.0 + dx * 0.5, from.1 + dy * 0.5);
        let centre = (foot.0 + normal.0 * 22.0, foot.1 + normal.1 * 22.0);
        (foot, centre, LabelBox::around(centre, 18.0, 18.0))
    });
    let colour = kind_colour(ray.kind);
    canvas.stroke_line(foot.0, foot.1, centre.0, centre.1, colour, 1.0);
    canvas.circle(centre, 8.0, Some(WHITE), Some((colour, 1.0)));
    canvas.text(
        centre.0,
        centre.1,
        &ray.depth.to_string(),
        11.0,
        colour,
        Anchor::MIDDLE_CENTRE,
    );
    taken.push(spot);
}

/// A circle drawn as dashes: a sphere the plane of the view does not cut.
fn dashed_circle(canvas: &mut Canvas, centre: (f32, f32), radius: f32, colour: Rgb) {
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
