//! Chapter 6's figures, 4: the sun's size and the penumbrae it casts.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use ch06_path_tracing::PathRender;
use ch06_path_tracing::sun::Sunlight;
use image::RgbImage;
use raylab::{Camera, Scene, Vec3};
use raylab_plot::montage;

use super::{COMPARE_SPP, SUN_SIZES, magnified_crop, outline_crop, save_all, seen_at, sun_name};
use crate::{JobError, penumbra};

pub(super) fn sun_figure(dir: &Path, suns: &[PathRender]) -> Result<Vec<PathBuf>, JobError> {
    let camera = Camera::lab();
    let (w, h) = (suns[0].settings.width, suns[0].settings.height);
    // The far tips of the glass ball's and the mirror ball's shadows,
    // where the ground is furthest from the edge that casts them (1.5 to 2
    // units), so the penumbra is widest: that distance × the sun's angle.
    let tips = [
        ("the glass ball's shadow", Vec3::new(2.15, 0.0, -0.12)),
        ("the mirror ball's shadow", Vec3::new(-0.28, 0.0, -0.27)),
    ];
    // A tenth of the picture each way, magnified back to the picture's
    // size, so that every tile of the montage is the same size.
    let crop = ((w / 10).max(4), (h / 10).max(3));
    let scale = (w / crop.0).max(1);
    let images: Vec<RgbImage> = suns.iter().map(|r| r.image.to_srgb8()).collect();
    let boxes = [[255, 200, 0], [255, 64, 160]];
    let mut tiles: Vec<(String, RgbImage)> = Vec::new();
    for (sun, image) in SUN_SIZES.iter().zip(&images) {
        let mut outlined = image.clone();
        for ((_, point), colour) in tips.iter().zip(boxes) {
            outlined = outline_crop(&outlined, seen_at(&camera, *point, w, h), crop, colour);
        }
        tiles.push((
            format!("{} (boxes: the crops below)", sun_name(*sun)),
            outlined,
        ));
    }
    for ((name, point), colour) in tips.iter().zip(boxes) {
        let at = seen_at(&camera, *point, w, h);
        let frame = if colour == boxes[0] { "yellow" } else { "pink" };
        for (sun, image) in SUN_SIZES.iter().zip(&images) {
            tiles.push((
                format!(
                    "{}: {name} ({frame} box), {}×{} pixels ×{scale}",
                    sun_name(*sun),
                    crop.0,
                    crop.1
                ),
                magnified_crop(image, at, crop, scale),
            ));
        }
    }
    let refs: Vec<(&str, &RgbImage)> = tiles.iter().map(|(l, i)| (l.as_str(), i)).collect();
    let figure = montage(
        &format!(
            "The sun as a point, as the real 0.53° disc and as 5°: {w}×{h}, {COMPARE_SPP} paths \
             per pixel"
        ),
        &refs,
        3,
    );
    let table = penumbra_table(&Scene::lab(), &camera, w, h);
    save_all(
        dir,
        &[("penumbrae.png", &figure)],
        &[("penumbrae.md", &table)],
    )
}

/// The penumbrae at the far tips of the glass and the mirror ball's
/// shadows, measured on the ground for each disc of [`SUN_SIZES`], against
/// the first-order estimate, and in pixels of the figure's images.
fn penumbra_table(scene: &Scene, camera: &Camera, w: u32, h: u32) -> String {
    let mut text = format!(
        "| sun | ball | from the ball | width on the ground | estimate d·D/sin e | pixels at {w}×{h} |\n\
         |---|---|---:|---:|---:|---:|\n"
    );
    for size in SUN_SIZES.iter().flatten() {
        let sun = Sunlight::new(&scene.sun, Some(*size));
        for name in ["glass", "mirror"] {
            let Some(ball) = scene.sphere_named(name).map(|i| &scene.spheres()[i]) else {
                continue;
            };
            let p = penumbra::at_shadow_tip(&sun, ball);
            let pixels = p
                .pixels(camera, w, h)
                .map_or("off the image".to_owned(), |px| format!("{px:.2}"));
            let _ = writeln!(
                text,
                "| {size}° | {name} | {:.2} | {:.4} | {:.4} | {pixels} |",
                p.distance_to_ball,
                p.width(),
                p.estimate(*size, sun.direction),
            );
        }
    }
    text
}
