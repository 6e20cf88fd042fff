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

/// A stretch of a ray, from `t0` to `t1` along it, where seen from above
/// it lies over a ball's disc without meeting the ball.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Crossing {
    t0: f32,
    t1: f32,
    /// Over the ball (`true`) or under it.
    over: bool,
    /// Which ball, by its index in the scene.
    sphere: usize,
}

/// Where `ray`, seen from above, crosses the disc of a ball it neither
/// starts on nor hits. Within a ball's disc the ball fills a column of
/// heights, so a ray that does not meet it stays over it or under it all
/// the way across: its height at the middle of the stretch tells which.
fn crossings(scene: &Scene, ray: &TracedRay) -> Vec<Crossing> {
    let length = ray.hit.map_or(SKY_STUB, |(_, t)| t);
    let (origin, direction) = (ray.ray.origin, ray.ray.direction);
    let mut found = Vec::new();
    for (index, sphere) in scene.spheres().iter().enumerate() {
        let (centre, radius) = (sphere.shape.centre, sphere.shape.radius);
        let hit_here = matches!(ray.hit, Some((Object::Sphere(i), _)) if i == index);
        let starts_here = ((origin - centre).length() - radius).abs() < 1e-3;
        if hit_here || starts_here {
            continue;
        }
        // |(o + t d − c) in x–z|² = r²: a quadratic in t.
        let (o, d) = (
            Vec2::new(origin.x - centre.x, origin.z - centre.z),
            Vec2::new(direction.x, direction.z),
        );
        let a = d.dot(d);
        let b = 2.0 * o.dot(d);
        let c = o.dot(o) - radius * radius;
        let discriminant = b * b - 4.0 * a * c;
        if a < 1e-12 || discriminant <= 0.0 {
            continue;
        }
        let root = discriminant.sqrt();
        let t0 = ((-b - root) / (2.0 * a)).max(0.0);
        let t1 = ((-b + root) / (2.0 * a)).min(length);
        if t1 <= t0 {
            continue;
        }
        let middle = origin + direction * (0.5 * (t0 + t1));
        found.push(Crossing {
            t0,
            t1,
            over: middle.y > centre.y,
            sphere: index,
        });
    }
    found
}

fn draw_ray(canvas: &mut Canvas, view: &View, ray: &TracedRay, crossings: &[Crossing]) {
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
    if crossings.is_empty() {
        canvas.arrow(from, to, colour, width, 9.0);
        return;
    }
    let at = |t: f32| view.to_canvas(ray.ray.at(t));
    for crossing in crossings.iter().filter(|c| c.over) {
        let (a, b) = (at(crossing.t0), at(crossing.t1));
        canvas.stroke_line(a.0, a.1, b.0, b.1, WHITE, width + 4.0);
    }
    // The arrow in pieces between the crossings' ends, each piece dashed
    // if it lies under a ball.
    let mut cuts: Vec<f32> = crossings.iter().flat_map(|c| [c.t0, c.t1]).collect();
    cuts.extend([0.0, length]);
    cuts.sort_by(f32::total_cmp);
    cuts.dedup();
    for pair in cuts.windows(2) {
        let (t0, t1) = (pair[0], pair[1]);
        let middle = 0.5 * (t0 + t1);
        let under = crossings
            .iter()
            .any(|c| !c.over && c.t0 <= middle && middle <= c.t1);
        let (a, b) = (at(t0), at(t1));
        let last = t1 >= length;
        if under {
            canvas.dashed_line(a, b, colour, width, 7.0, 5.0);
        } else if !last {
            canvas.stroke_line(a.0, a.1, b.0, b.1, colour, width);
        }
        if last {
            if under {
                let (dx, dy) = (b.0 - a.0, b.1 - a.1);
                let span = dx.hypot(dy).max(1e-3);
                let back = (b.0 - dx / span * 9.0, b.1 - dy / span * 9.0);
                canvas.arrow(back, b, colour, width, 9.0);
            } else {
                canvas.arrow(a, b, colour, width, 9.0);
            }
        }
    }
}

/// "over the blue ball" (or "under"), on a white patch beside the middle
/// of the crossing, on whichever side covers no name or badge.
fn label_crossing(
    canvas: &mut Canvas,
    scene: &Scene,
    view: &View,
    ray: &TracedRay,
    crossing: Crossing,
    taken: &mut Vec<LabelBox>,
) {
    let name = &scene.spheres()[crossing.sphere].name;
    let text = format!(
        "{} the {name} ball",
        if crossing.over { "over" } else { "under" }
    );
    let (a, b) = (
        view.to_canvas(ray.ray.at(crossing.t0)),
        view.to_canvas(ray.ray.at(crossing.t1)),
    );
    let middle = ((a.0 + b.0) / 2.0, (a.1 + b.1) / 2.0);
    let span = (b.0 - a.0).hypot(b.1 - a.1).max(1e-3);
    let normal = (-(b.1 - a.1) / span, (b.0 - a.0) / span);
    let (w, h) = (canvas.text_width(&text, 12.0) + 8.0, 18.0);
    // Far enough along the normal that the box clears the line.
    let away = 0.5 * (w * normal.0.abs() + h * normal.1.abs()) + 6.0;
    let spots = [away, -away, away + 20.0, -away - 20.0]
        .map(|d| LabelBox::around((middle.0 + normal.0 * d, middle.1 + normal.1 * d), w, h));
    let spot = spots
        .iter()
        .find(|spot| !taken.iter().any(|t| t.overlaps(spot)))
        .unwrap_or(&spots[0]);
    canvas.fill_rect(spot.x, spot.y, spot.w, spot.h, WHITE);
    canvas.text(
        spot.x + spot.w / 2.0,
        spot.y + spot.h / 2.0,
        &text,
        12.0,
        kind_colour(ray.kind),
        Anchor::MIDDLE_CENTRE,
    );
    taken.push(*spot);
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

#[cfg(test)]
mod tests {
    use super::*;
    use raylab::ray::Ray;

    /// A ray of the lab scene towards -z along x = 0.1, through the blue
    /// ball's column (centre (0.1, 0.25, 1.2), radius 0.25), at `height`.
    fn level_ray(height: f32) -> TracedRay {
        TracedRay {
            kind: RayKind::Primary,
            depth: 1,
            weight: 1.0,
            ray: Ray::new(Vec3::new(0.1, height, 3.0), Vec3::NEG_Z),
            hit: None,
            added: Vec3::ZERO,
            parent: None,
        }
    }

    #[test]
    fn a_ray_above_a_ball_crosses_its_disc_over_it_and_one_below_under_it() {
        let scene = Scene::lab();
        // A ray to the sky is drawn for 1.5 units only, short of the blue
        // ball's disc (z from 1.45 to 0.95): a far hit takes it there.
        let mut over = level_ray(0.7);
        over.hit = Some((Object::Ground, 10.0));
        let found = crossings(&scene, &over);
        let blue = found
            .iter()
            .find(|c| (c.t0 - 1.55).abs() < 1e-4)
            .expect("crosses the blue ball's disc from z = 1.45");
        assert!((blue.t1 - 2.05).abs() < 1e-4, "to z = 0.95: {blue:?}");
        assert!(blue.over);
        let mut under = level_ray(-0.1);
        under.hit = Some((Object::Ground, 10.0));
        assert!(crossings(&scene, &under).iter().all(|c| !c.over));
    }

    #[test]
    fn a_ray_does_not_cross_the_ball_it_hits_or_starts_on() {
        let scene = Scene::lab();
        let blue = scene.sphere_named("blue").expect("the lab has a blue ball");
        let mut hits_blue = level_ray(0.25);
        hits_blue.hit = Some((Object::Sphere(blue), 1.55));
        assert!(crossings(&scene, &hits_blue).is_empty());
        // From the top of the blue ball, straight up: on it, not over it.
        let mut leaves = level_ray(0.0);
        leaves.ray = Ray::new(Vec3::new(0.1, 0.5, 1.2), Vec3::Y);
        assert!(crossings(&scene, &leaves).is_empty());
    }
}
