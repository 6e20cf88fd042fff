//! One ray in a panel: its arrow, its depth in a badge, and, seen from
//! above, where it passes over or under a ball it does not meet.

use glam::Vec2;

use super::SKY_STUB;
use super::view::View;
use crate::diagrams::kind_colour;
use raylab::ray::RayKind;
use raylab::scene::{Object, Scene};
use raylab::trace::TracedRay;
use raylab_plot::LabelBox;
use raylab_plot::colour::WHITE;
use raylab_plot::{Anchor, Canvas};

/// A stretch of a ray, from `t0` to `t1` along it, where seen from above
/// it lies over a ball's disc without meeting the ball.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Crossing {
    pub(super) t0: f32,
    pub(super) t1: f32,
    /// Over the ball (`true`) or under it.
    pub(super) over: bool,
    /// Which ball, by its index in the scene.
    pub(super) sphere: usize,
}

/// Where `ray`, seen from above, crosses the disc of a ball it neither
/// starts on nor hits. Within a ball's disc the ball fills a column of
/// heights, so a ray that does not meet it stays over it or under it all
/// the way across: its height at the middle of the stretch tells which.
pub(super) fn crossings(scene: &Scene, ray: &TracedRay) -> Vec<Crossing> {
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

pub(super) fn draw_ray(canvas: &mut Canvas, view: &View, ray: &TracedRay, crossings: &[Crossing]) {
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
pub(super) fn label_crossing(
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
pub(super) fn draw_badge(
    canvas: &mut Canvas,
    view: &View,
    ray: &TracedRay,
    taken: &mut Vec<LabelBox>,
) {
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

#[cfg(test)]
mod tests {
    use super::*;
    use raylab::Vec3;
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
