//! Chapter 6's figures, 3: the lab's materials against exact Fresnel, at
//! the glass ball's rim.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use ch06_path_tracing::PathRender;
use raylab::scene::Object;
use raylab::{Camera, Hit, Scene, Vec3};
use raylab_plot::{Colormap, ColourScale, HeatmapFigure, montage};

use super::{COMPARE_SPP, magnified_crop, outline_crop, ratio_row, save_all, seen_at};
use crate::JobError;
use crate::measure::{log2_ratio, mean_luminance, symmetric_range};

fn glass_ball(scene: &Scene) -> (Vec3, f32) {
    let glass = scene
        .sphere_named("glass")
        .expect("the lab has a glass ball");
    let shape = scene.spheres()[glass].shape;
    (shape.centre, shape.radius)
}

pub(super) fn materials_figure(
    dir: &Path,
    lab: &PathRender,
    fresnel: &PathRender,
    hits: &[Option<Hit>],
) -> Result<Vec<PathBuf>, JobError> {
    let (scene, camera) = (Scene::lab(), Camera::lab());
    let (w, h) = (lab.settings.width, lab.settings.height);
    let (centre, radius) = glass_ball(&scene);
    // The ball's upper right rim, where the eye sees it at a grazing angle.
    let diagonal = (camera.up() + camera.right()).normalize();
    let at = seen_at(&camera, centre + 0.8 * radius * diagonal, w, h);
    let side = (w / 8).max(4);
    let scale = (h / side).max(1);
    let (lab8, fresnel8) = (lab.image.to_srgb8(), fresnel.image.to_srgb8());
    let crops = [&lab8, &fresnel8].map(|image| magnified_crop(image, at, (side, side), scale));
    let rim_box = [255, 200, 0];
    let [lab_boxed, fresnel_boxed] =
        [&lab8, &fresnel8].map(|image| outline_crop(image, at, (side, side), rim_box));
    let figure = montage(
        &format!(
            "The glass ball, {w}×{h}, {COMPARE_SPP} paths per pixel: lab materials and Fresnel"
        ),
        &[
            ("--materials lab (yellow box: the rim crop)", &lab_boxed),
            ("--materials fresnel", &fresnel_boxed),
            (
                &format!("lab: the rim, {side}×{side} pixels, ×{scale}"),
                &crops[0],
            ),
            (&format!("fresnel: the rim, ×{scale}"), &crops[1]),
        ],
        2,
    );

    // The rim and the middle of the ball, by the angle the eye sees it at.
    let glass = Object::Sphere(scene.sphere_named("glass").expect("the glass"));
    let band = |low: f32, high: f32| -> Vec<bool> {
        hits.iter()
            .enumerate()
            .map(|(k, hit)| {
                let (i, j) = ((k as u32 % w), (k as u32 / w));
                hit.filter(|x| x.object == glass).is_some_and(|x| {
                    let d = camera.ray(i, j, (0.5, 0.5), w, h).direction;
                    let cos = -d.dot(x.normal);
                    (low..high).contains(&cos)
                })
            })
            .collect()
    };
    let mut text = String::from(
        "| pixels of the glass ball | count | lab | fresnel | fresnel / lab |\n\
         |---|---:|---:|---:|---:|\n",
    );
    for (name, low, high) in [
        ("rim: cos θ below 0.5", 0.0, 0.5),
        ("middle: cos θ above 0.9", 0.9, 1.01),
    ] {
        let mask = band(low, high);
        let ((a, n), (b, _)) = (
            mean_luminance(&lab.image, Some(&mask)),
            mean_luminance(&fresnel.image, Some(&mask)),
        );
        ratio_row(&mut text, name, n, a, b);
    }
    let _ = writeln!(
        text,
        "\nMean luminance (linear) of the pixels whose centre sees the glass ball, by the \
         cosine θ between the eye's ray and the ball's normal there. Exact Fresnel reflects \
         {:.1} % head on (cos θ = 1) and {:.1} % at cos θ = 0.2; the lab's glass reflects 0.1 \
         of its light (and refracts 0.7) at every angle.",
        100.0 * raylab::optics::fresnel(-1.0, 1.0 / 1.5),
        100.0 * raylab::optics::fresnel(-0.2, 1.0 / 1.5)
    );
    // Where the two differ, as a ratio: at this size the pictures look
    // alike, and the table's few per cent would not show by eye. Both use
    // the same seed, so a pixel whose paths never meet the glass is the
    // same in both, and its ratio exactly 1.
    let ratio = log2_ratio(&lab.image, &fresnel.image);
    let range = symmetric_range(&ratio, 0.999).min(3.0);
    let caption = format!(
        "Each pixel: log2 of the Fresnel render's luminance over the lab render's, from −{range} \
         (blue, {:.0} % of the light) to +{range} (red, {:.0} %), clamped beyond; grey: the same. \
         Both use the same seed, so only pixels whose paths meet the glass can differ.",
        100.0 * 2f32.powf(-range),
        100.0 * 2f32.powf(range)
    );
    let ratio_figure = HeatmapFigure {
        title: "Fresnel over the lab's materials: where the glass differs",
        caption: &caption,
        values: &ratio,
        width: w as usize,
        height: h as usize,
        colour_scale: ColourScale::linear(-range, range),
        colour_bar_label: "log2 (fresnel ÷ lab)",
        colormap: Colormap::Diverging,
        pixel_scale: Some(1),
    }
    .render();
    save_all(
        dir,
        &[("materials.png", &figure), ("ratio.png", &ratio_figure)],
        &[("materials.md", &text)],
    )
}
