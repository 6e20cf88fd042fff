//! Chapter 9's figures: the tree's boxes over the field, the boxes each
//! pixel's ray tested, rays per second and build time against the number
//! of spheres, and the acne of the lab's offset at the field's scale.
//! Their numbers are measured in [`super::measure`].

use image::RgbImage;
use rayon::prelude::*;

use ch09_many_spheres::Bvh;
use ch09_many_spheres::acne::{SPECKLE, speckled};
use raylab::Scene;
use raylab::camera::Camera;
use raylab_plot::colour::{FRAME, TEXT, WHITE, series_colour};
use raylab_plot::text::Anchor;
use raylab_plot::{Canvas, Colormap, ColourScale, Corner, LinePlot, Series, heatmap_figure};

use super::measure::SpeedPoint;

/// The field whose measurements the `1/N` and `1/log N` shapes pass
/// through: large enough that the tree has many levels (at 5 spheres it
/// is a single leaf, which the search tests as the list does), and the
/// size of the page's showcase.
pub const SHAPE_ANCHOR: usize = 500;

/// Rays per second against the number of spheres, log–log, with the two
/// shapes to read them by: `1/N` (every sphere tested) through the list's
/// point at [`SHAPE_ANCHOR`] spheres, and `1/log₂ N` (a tree's depth)
/// through the tree's (through the nearest measured field, if that one was
/// not).
pub fn speed_figure(points: &[SpeedPoint]) -> RgbImage {
    let anchor = points
        .iter()
        .min_by_key(|p| p.spheres.abs_diff(SHAPE_ANCHOR))
        .copied()
        .expect("at least one point");
    let shape = |n: usize| n.max(2) as f64;
    let n0 = shape(anchor.spheres);
    let one_over_n = points
        .iter()
        .map(|p| (shape(p.spheres), anchor.list * n0 / shape(p.spheres)));
    let one_over_log = points.iter().map(|p| {
        let n = shape(p.spheres);
        (n, anchor.tree * n0.log2() / n.log2())
    });
    LinePlot::new("Rays per second against the number of spheres")
        .x_label("spheres")
        .y_label("million rays per second")
        .log_x()
        .log_y(1e-3)
        .series(Series::new(
            "every sphere tested (the list)",
            series_colour(0),
            points.iter().map(|p| (shape(p.spheres), p.list)),
        ))
        .series(Series::new(
            "through the tree",
            series_colour(1),
            points.iter().map(|p| (shape(p.spheres), p.tree)),
        ))
        .series(
            Series::new(
                format!("shape of 1/N, through the list at {}", anchor.spheres),
                series_colour(2),
                one_over_n,
            )
            .without_markers(),
        )
        .series(
            Series::new(
                format!("shape of 1/log N, through the tree at {}", anchor.spheres),
                series_colour(3),
                one_over_log,
            )
            .without_markers(),
        )
        .legend(Corner::BottomLeft)
        .render(800, 500)
}

/// Build time against the number of spheres, log–log, with `N log N`
/// through the last point.
pub fn build_time_figure(points: &[(usize, f64)]) -> RgbImage {
    let &(n_last, t_last) = points.last().expect("at least one point");
    let nlogn = |n: usize| n.max(2) as f64 * (n.max(2) as f64).log2();
    LinePlot::new("Building the tree, on one core")
        .x_label("spheres")
        .y_label("milliseconds")
        .log_x()
        .log_y(1e-4)
        .series(Series::new(
            "build time",
            series_colour(1),
            points.iter().map(|&(n, t)| (n.max(1) as f64, t)),
        ))
        .series(
            Series::new(
                "shape of N log N",
                series_colour(2),
                points
                    .iter()
                    .map(|&(n, _)| (n.max(1) as f64, t_last * nlogn(n) / nlogn(n_last))),
            )
            .without_markers(),
        )
        .legend(Corner::TopLeft)
        .render(800, 500)
}

/// Per pixel, how many boxes the ray from the eye through its centre
/// tested, as a heat map (log scale).
pub fn visits_figure(scene: &Scene, camera: &Camera, width: u32, height: u32) -> RgbImage {
    let tree = Bvh::build(scene);
    let values: Vec<f32> = (0..width * height)
        .into_par_iter()
        .map(|k| {
            let ray = camera.ray(k % width, k / width, (0.5, 0.5), width, height);
            tree.nearest_hit_counted(&ray).1.boxes as f32
        })
        .collect();
    let max = values.iter().copied().fold(1.0, f32::max);
    let caption = format!(
        "{} spheres: the boxes each primary ray tested on its way to its hit (at most {max}). \
         Rays that pass between the spheres' groups test few; rays that graze many test most.",
        scene.spheres().len()
    );
    heatmap_figure(
        "Boxes tested per pixel",
        &caption,
        &values,
        width as usize,
        height as usize,
        ColourScale::log(1.0, max),
        "boxes tested",
        Colormap::Viridis,
    )
}

/// The render `image` of `scene` through `camera`, with the boxes of the
/// tree's top `levels` levels drawn over it, one colour per level, and a
/// legend that names each level's colour and how many boxes it has.
pub fn tree_figure(scene: &Scene, camera: &Camera, image: &RgbImage, levels: usize) -> RgbImage {
    let tree = Bvh::build(scene);
    let (width, height) = image.dimensions();
    let mut canvas = Canvas::new(width, height, [255, 255, 255]);
    canvas.draw_rgb_image(image, 0, 0, 1);
    let line_width = |level: usize| (2.5 - 0.4 * level as f32).max(1.0);
    let mut boxes = vec![0usize; levels];
    // Walk the flat array depth first, keeping each node's level.
    let mut stack = vec![(0usize, 0usize)];
    while let Some((index, level)) = stack.pop() {
        let Some(node) = tree.nodes().get(index) else {
            continue;
        };
        if level >= levels {
            continue;
        }
        boxes[level] += 1;
        let b = node.bounds();
        let corner = |k: usize| {
            raylab::Vec3::new(
                if k & 1 == 0 { b.min.x } else { b.max.x },
                if k & 2 == 0 { b.min.y } else { b.max.y },
                if k & 4 == 0 { b.min.z } else { b.max.z },
            )
        };
        for (a, c) in EDGES {
            let (Some(p), Some(q)) = (
                camera.project(corner(a), width, height),
                camera.project(corner(c), width, height),
            ) else {
                continue;
            };
            canvas.stroke_line(p.0, p.1, q.0, q.1, series_colour(level), line_width(level));
        }
        if !node.is_leaf() {
            stack.push((node.first as usize, level + 1));
            stack.push((index + 1, level + 1));
        }
    }
    // The legend: one line per level, its colour and width as drawn.
    let size = 14.0;
    let row = 20.0;
    let entries: Vec<String> = boxes
        .iter()
        .enumerate()
        .map(|(level, &n)| match level {
            0 => "level 0: the root, all the spheres".to_owned(),
            _ => format!("level {level}: {n} boxes"),
        })
        .collect();
    let title = format!("the tree's top {levels} levels");
    let widest = entries
        .iter()
        .chain([&title])
        .map(|t| canvas.text_width(t, size))
        .fold(0.0, f32::max);
    let swatch = 28.0;
    let (x0, y0) = (8.0, 8.0);
    let box_height = row * (entries.len() + 1) as f32 + 10.0;
    canvas.fill_rect_translucent(x0, y0, widest + swatch + 26.0, box_height, WHITE, 0.85);
    canvas.stroke_rect(x0, y0, widest + swatch + 26.0, box_height, FRAME, 1.0);
    let mut y = y0 + 6.0;
    canvas.text(x0 + 8.0, y, &title, size, TEXT, Anchor::TOP_LEFT);
    for (level, entry) in entries.iter().enumerate() {
        y += row;
        let middle = y + size * 0.55;
        canvas.stroke_line(
            x0 + 8.0,
            middle,
            x0 + 8.0 + swatch,
            middle,
            series_colour(level),
            line_width(level).max(2.0),
        );
        canvas.text(x0 + 16.0 + swatch, y, entry, size, TEXT, Anchor::TOP_LEFT);
    }
    canvas.to_rgb_image()
}

/// A box's 12 edges, as pairs of corners numbered by their bits (x, y, z).
const EDGES: [(usize, usize); 12] = [
    (0, 1),
    (2, 3),
    (4, 5),
    (6, 7),
    (0, 2),
    (1, 3),
    (4, 6),
    (5, 7),
    (0, 4),
    (1, 5),
    (2, 6),
    (3, 7),
];

/// The window of the field where the lab's offset speckles most: the
/// render at the lab's `lab_epsilon` and at the field's own `own_epsilon`,
/// cropped and enlarged `zoom` times, with the speckled pixels marked.
pub fn acne_figure(
    lab: &RgbImage,
    own: &RgbImage,
    (lab_epsilon, own_epsilon): (f32, f32),
    (corner, size): ((u32, u32), (u32, u32)),
    zoom: u32,
) -> RgbImage {
    let crop = |image: &RgbImage| {
        let part = image::imageops::crop_imm(image, corner.0, corner.1, size.0, size.1).to_image();
        image::imageops::resize(
            &part,
            size.0 * zoom,
            size.1 * zoom,
            image::imageops::FilterType::Nearest,
        )
    };
    let mask = speckled(lab, own);
    let mut marked = lab.clone();
    for (pixel, &speck) in marked.pixels_mut().zip(&mask) {
        // The speckles in red, everything else faded to a pale grey.
        pixel.0 = if speck {
            [220, 20, 60]
        } else {
            let grey = (u16::from(pixel.0[0]) + u16::from(pixel.0[1]) + u16::from(pixel.0[2])) / 3;
            [(170 + grey / 4) as u8; 3]
        };
    }
    let labels = [
        format!("ε = {lab_epsilon:e}, the lab's"),
        format!("ε = {own_epsilon:e}, the field's own"),
        format!("more than {SPECKLE} levels apart (red)"),
    ];
    let tiles = [crop(lab), crop(own), crop(&marked)];
    let tiles: Vec<(&str, &RgbImage)> = labels.iter().map(String::as_str).zip(&tiles).collect();
    raylab_plot::montage(
        &format!(
            "Acne at scale: a {}×{} window, {zoom}× enlarged, where the lab's ε speckles most",
            size.0, size.1
        ),
        &tiles,
        3,
    )
}
