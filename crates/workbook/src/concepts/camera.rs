//! The pinhole camera from the side: the lab camera's eye, its forward and
//! up vectors, the image plane at distance 1 with half-height tan(fov/2),
//! and one pixel's ray through its centre, all from `Camera::lab()`.

use image::RgbImage;
use raylab::{Camera, Vec3};
use raylab_plot::colour::{AXIS, FRAME, GRID, TEXT, TEXT_MUTED};
use raylab_plot::{Anchor, HAlign, VAlign};

use super::{LABEL, LINE, P, SMALL, Sheet};

/// The small image the figure divides the plane into, so that its pixels
/// can be seen: 8 columns, 6 rows (the lab's 4:3).
pub const COLUMNS: u32 = 8;
pub const ROWS: u32 = 6;
/// The pixel whose ray is drawn.
pub const PIXEL: (u32, u32) = (5, 4);

/// The lab camera's vertical field of view, in degrees, read back from
/// its half-height.
pub fn fov_degrees(camera: &Camera) -> f32 {
    2.0 * camera.half_height().atan().to_degrees()
}

/// Where pixel `(i, j)`'s centre ray crosses the image plane at distance 1,
/// as (right, up) coordinates on the plane: the camera's own ray, scaled
/// until its forward component is 1.
pub fn on_plane(camera: &Camera, (i, j): (u32, u32), width: u32, height: u32) -> (f32, f32) {
    let d = camera.ray(i, j, (0.5, 0.5), width, height).direction;
    let d = d / d.dot(camera.forward());
    (d.dot(camera.right()), d.dot(camera.up()))
}

const BLUE: [u8; 3] = [0, 114, 178];
const GREEN: [u8; 3] = [0, 158, 115];
const ORANGE: [u8; 3] = [213, 94, 0];

pub fn figure() -> RgbImage {
    let camera = Camera::lab();
    let (eye, forward, up, h) = (
        camera.eye,
        camera.forward(),
        camera.up(),
        camera.half_height(),
    );
    let fov = fov_degrees(&camera);
    let mut sheet = Sheet::new(
        1200.0,
        830.0,
        "The lab camera from the side, and the image plane from the front",
    );
    // Side view, across the top: -z to the right, y up; x (the camera's
    // right) points out of the page.
    let (k, left, ground) = (190.0, 240.0, 540.0);
    let map = |p: Vec3| -> P { (left + (eye.z - p.z) * k, ground - p.y * k) };
    // The ground and the target.
    sheet.line((20.0, ground), (1180.0, ground), AXIS, 2.0);
    sheet.text(
        (30.0, ground + 8.0),
        "ground, y = 0",
        SMALL,
        TEXT_MUTED,
        Anchor::TOP_LEFT,
    );
    // The frustum: the rays through the top and bottom edges of the image,
    // as far as the ground or the target's distance.
    let edge = |sign: f32| (forward + sign * h * up).normalize();
    for sign in [1.0, -1.0] {
        let d = edge(sign);
        let far = if d.y < 0.0 { -eye.y / d.y } else { 4.6 };
        sheet.dashed(map(eye), map(eye + d * far), FRAME, 1.5);
    }
    let target = Vec3::new(0.0, 0.6, 0.0);
    sheet.dashed(map(eye), map(target), GRID, 1.5);
    sheet.dot(map(target), AXIS);
    sheet.label(
        (map(target).0, map(target).1 - 12.0),
        "target (0, 0.6, 0)",
        SMALL,
        TEXT,
        Anchor::BASELINE_CENTRE,
    );
    // Ending where it meets the line, the label lies wholly above it.
    sheet.label(
        add_p(map(eye + edge(1.0) * 3.8), (-6.0, -10.0)),
        &format!("top edge of the view: forward + tan({:.1}°)·up", fov / 2.0),
        SMALL,
        TEXT_MUTED,
        Anchor::BASELINE_RIGHT,
    );

    // The image plane at distance 1, divided into ROWS rows.
    let centre = eye + forward;
    let (top, bottom) = (centre + up * h, centre - up * h);
    sheet.line(map(top), map(bottom), AXIS, 3.0);
    for row in 1..ROWS {
        let y = h * (1.0 - 2.0 * row as f32 / ROWS as f32);
        let p = centre + up * y;
        let across = forward * 0.04;
        sheet.line(map(p - across), map(p + across), AXIS, 1.5);
    }
    sheet.label(
        add_p(map(bottom), (-6.0, 12.0)),
        "image plane, distance 1",
        SMALL,
        TEXT,
        Anchor::TOP_RIGHT,
    );
    // Its half-height, beside it.
    let off = forward * 0.18;
    sheet.line(map(centre + off), map(top + off), ORANGE, 1.5);
    sheet.line(
        map(centre + off * 0.7),
        map(centre + off * 1.3),
        ORANGE,
        1.5,
    );
    sheet.line(map(top + off * 0.7), map(top + off * 1.3), ORANGE, 1.5);
    sheet.label(
        add_p(map(centre + up * (h * 0.5) + off * 1.4), (2.0, 0.0)),
        &format!("tan({:.1}°) = {h:.4}", fov / 2.0),
        LABEL,
        ORANGE,
        Anchor::MIDDLE_LEFT,
    );

    // The eye and its frame.
    sheet.arrow(map(eye), map(centre), BLUE, 2.5);
    sheet.label(
        add_p(map(eye + forward * 0.62), (0.0, -6.0)),
        "forward",
        LABEL,
        BLUE,
        Anchor::BOTTOM_CENTRE,
    );
    sheet.arrow(map(eye), map(eye + up * 0.6), GREEN, 2.5);
    sheet.text(
        add_p(map(eye + up * 0.6), (-8.0, 0.0)),
        "up",
        LABEL,
        GREEN,
        Anchor::MIDDLE_RIGHT,
    );
    // Right points out of the page: a dot in a circle.
    sheet.circle(map(eye), 9.0, None, Some(TEXT));
    sheet.dot(map(eye), TEXT);
    sheet.text(
        add_p(map(eye), (-18.0, 0.0)),
        "eye (0, 1.2, 4.5)",
        LABEL,
        TEXT,
        Anchor::MIDDLE_RIGHT,
    );
    sheet.text(
        add_p(map(eye), (-18.0, LINE)),
        "right: out of the page",
        SMALL,
        TEXT_MUTED,
        Anchor::MIDDLE_RIGHT,
    );

    // Pixel PIXEL's ray, through the plane and on to the ground.
    let ray = camera.ray(PIXEL.0, PIXEL.1, (0.5, 0.5), COLUMNS, ROWS);
    let (_, y) = on_plane(&camera, PIXEL, COLUMNS, ROWS);
    let t_ground = -eye.y / ray.direction.y;
    let crossing = eye + (ray.direction / ray.direction.dot(forward));
    sheet.line(map(eye), map(ray.at(t_ground)), ORANGE, 2.0);
    sheet.dot(map(crossing), ORANGE);
    sheet.dot(map(ray.at(t_ground)), ORANGE);
    sheet.label(
        add_p(map(ray.at(t_ground)), (0.0, 10.0)),
        &format!(
            "row {}'s ray meets the ground at t = {t_ground:.2}",
            PIXEL.1
        ),
        SMALL,
        ORANGE,
        Anchor::TOP_CENTRE,
    );
    sheet.label(
        add_p(map(crossing), (-10.0, 8.0)),
        &format!("y = {y:.4}"),
        SMALL,
        ORANGE,
        Anchor::TOP_RIGHT,
    );
    sheet.text(
        add_p(map(eye), (30.0, -50.0)),
        &format!("fov {fov:.0}°"),
        SMALL,
        TEXT_MUTED,
        Anchor::MIDDLE_LEFT,
    );

    front_view(&mut sheet, &camera, ground + 56.0);
    sheet.note(
        1,
        "Numbers from Camera::lab(): look_at((0, 1.2, 4.5), (0, 0.6, 0), up = y, fov 45°);",
    );
    sheet.note(0, "the plane is divided into 8 × 6 pixels to show them.");
    sheet.finish()
}

/// The image plane seen from the eye, its top at `top`: its pixels, pixel
/// PIXEL's centre, and beside it the formulas that give its coordinates.
fn front_view(sheet: &mut Sheet, camera: &Camera, top: f32) {
    let h = camera.half_height();
    let aspect = COLUMNS as f32 / ROWS as f32;
    let (i, j) = PIXEL;
    let (x, y) = on_plane(camera, PIXEL, COLUMNS, ROWS);
    let lines = [
        format!("pixel (i, j) = ({i}, {j}), centre at (i + 0.5, j + 0.5):"),
        format!("x = (2(i + 0.5)/{COLUMNS} − 1)·{h:.4}·{aspect:.3} = {x:.4}"),
        format!("y = (1 − 2(j + 0.5)/{ROWS})·{h:.4} = {y:.4}"),
        "d = normalize(forward + x·right + y·up)".to_owned(),
    ];
    let k = 180.0;
    let (w2, h2) = (h * aspect, h);
    // The plane and the formulas side by side, centred on the sheet.
    let text_width = lines
        .iter()
        .map(|line| sheet.text_width(line, SMALL))
        .fold(0.0, f32::max);
    let gap = 50.0;
    let plane_left = (sheet.width() - (2.0 * w2 * k + gap + text_width)) / 2.0;
    let (cx, cy) = (plane_left + w2 * k, top + h2 * k);
    let to = |x: f32, y: f32| -> P { (cx + x * k, cy - y * k) };
    let cell = 2.0 * h2 / ROWS as f32;
    let (x0, y0) = (-w2 + i as f32 * cell, h2 - j as f32 * cell);
    sheet.fill_rect(to(x0, y0), (cell * k, cell * k), [253, 226, 204]);
    for c in 0..=COLUMNS {
        let x = -w2 + c as f32 * cell;
        sheet.line(to(x, h2), to(x, -h2), GRID, 1.0);
    }
    for r in 0..=ROWS {
        let y = h2 - r as f32 * cell;
        sheet.line(to(-w2, y), to(w2, y), GRID, 1.0);
    }
    sheet.stroke_rect(to(-w2, h2), (2.0 * w2 * k, 2.0 * h2 * k), AXIS, 1.5);
    sheet.dot(to(x, y), ORANGE);
    sheet.arrow(to(0.0, 0.0), to(0.25, 0.0), TEXT, 1.5);
    sheet.text(
        add_p(to(0.25, 0.0), (4.0, 0.0)),
        "right",
        SMALL,
        TEXT,
        Anchor::MIDDLE_LEFT,
    );
    sheet.arrow(to(0.0, 0.0), to(0.0, 0.2), TEXT, 1.5);
    sheet.text(
        add_p(to(0.0, 0.2), (0.0, -2.0)),
        "up",
        SMALL,
        TEXT,
        Anchor::BOTTOM_CENTRE,
    );
    let text_left = plane_left + 2.0 * w2 * k + gap;
    sheet.text(
        (text_left, top + 8.0),
        &format!("the plane from the eye: {COLUMNS} × {ROWS} pixels"),
        LABEL,
        TEXT,
        Anchor::TOP_LEFT,
    );
    for (n, line) in lines.iter().enumerate() {
        sheet.text(
            (text_left, top + 70.0 + LINE * n as f32),
            line,
            SMALL,
            TEXT,
            anchor_left_baseline(),
        );
    }
}

fn anchor_left_baseline() -> Anchor {
    Anchor::new(HAlign::Left, VAlign::Baseline)
}

fn add_p(a: P, b: P) -> P {
    (a.0 + b.0, a.1 + b.1)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_lab_camera_has_a_45_degree_view_and_half_height_tan_22_5() {
        let camera = Camera::lab();
        // tan(22.5°) = √2 − 1 = 0.41421356…, as f32.
        assert_eq!(camera.half_height(), 0.414_213_57);
        assert!((fov_degrees(&camera) - 45.0).abs() < 1e-4);
    }

    #[test]
    fn a_pixel_centre_ray_crosses_the_plane_where_the_formula_says() {
        // Pixel (5, 4) of 8 × 6: x = (11/8 − 1)·h·4/3 = 0.5·h, y = (1 − 9/6)·h = −0.5·h.
        let camera = Camera::lab();
        let h = camera.half_height();
        let (x, y) = on_plane(&camera, PIXEL, COLUMNS, ROWS);
        assert!((x - 0.5 * h).abs() < 1e-6, "{x}");
        assert!((y + 0.5 * h).abs() < 1e-6, "{y}");
    }
}
