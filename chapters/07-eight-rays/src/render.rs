//! The whole image: one row per task on every core, each row traced in
//! waves, then each sample's tree summed in the scalar tracer's order.

use std::time::Instant;

use raylab::indicatif::ProgressBar;
use raylab::linear_image::LinearImage;
use raylab::render::{RowTally, map_rows};
use raylab::trace::RayCounts;
use raylab::{Camera, Maps, PixelMaps, RayKind, Rendered, Scene, Settings, Tracer, Vec3};
use rayon::prelude::*;

use crate::EightRays;
use crate::camera::primary_rays;
use crate::intersect::SceneX8;
use crate::shade::Light;
use crate::wave::{Node, Setup, Waves};

// ANCHOR: sum
/// Add up the tree under `nodes[depth][index]` into `colour` in the order
/// the scalar ray stack pops it: a ray's own light first, then its
/// children's subtrees.
#[inline]
fn sum_tree(nodes: &[Vec<Node>], depth: usize, index: usize, colour: &mut Vec3) {
    // Most samples' trees are their primary ray alone: no call for those.
    *colour += Vec3::from_array(nodes[depth][index].added);
    if !Node::children(&nodes[depth], index).is_empty() {
        sum_children(nodes, depth, index, colour);
    }
}

/// Add up the subtrees of `nodes[depth][index]`'s children, in order.
fn sum_children(nodes: &[Vec<Node>], depth: usize, index: usize, colour: &mut Vec3) {
    for child in Node::children(&nodes[depth], index) {
        *colour += Vec3::from_array(nodes[depth + 1][child].added);
        // Most rays send nothing on: those are done without a call.
        if !Node::children(&nodes[depth + 1], child).is_empty() {
            sum_children(nodes, depth + 1, child, colour);
        }
    }
}
// ANCHOR_END: sum

/// The rays of a tree by kind, to take a tree's wave-traced part back out
/// of the counts when the scalar tracer traces that sample again.
fn count_tree(waves: &Waves, depth: usize, index: usize, counts: &mut RayCounts) {
    counts.0[waves.rays[depth].kind[index].index()] += 1;
    counts.0[RayKind::Shadow.index()] += u64::from(waves.cast_shadow[depth][index]);
    for child in Node::children(&waves.nodes[depth], index) {
        count_tree(waves, depth + 1, child, counts);
    }
}

/// One worker's tools: its waves, and a scalar tracer for the rare sample
/// whose tree reaches the ray budget.
struct Worker<'s> {
    waves: Waves,
    scalar: Tracer<'s, EightRays>,
}

/// Render `scene` as `step`'s chapter would, eight rays at a time; the
/// image, the ray counts and (with [`Maps::Keep`]) the per-pixel maps
/// equal `raylab::render`'s.
pub fn render_waves(
    scene: &Scene,
    camera: &Camera,
    step: &EightRays,
    settings: &Settings,
    maps: Maps,
    progress: &ProgressBar,
) -> Rendered {
    let start = Instant::now();
    let (width, height) = (settings.width as usize, settings.height as usize);
    let features = step.like.features();
    let setup = Setup {
        scene: SceneX8::new(scene, features),
        light: Light::new(scene),
        features,
        max_depth: settings.max_depth,
        epsilon: settings.epsilon,
        maps: maps == Maps::Keep,
    };
    let mut colours = Vec::with_capacity(width * height);
    colours.par_extend(rayon::iter::repeat_n(Vec3::ZERO, width * height));
    let mut pixel_maps = setup.maps.then(|| PixelMaps::zeroed(width * height));
    let map_rows = map_rows(pixel_maps.as_mut(), width, height);
    let tally = colours
        .par_chunks_mut(width)
        .zip(map_rows)
        .enumerate()
        .map_init(
            || Worker {
                waves: Waves::default(),
                scalar: Tracer::new(scene, step, settings.max_depth, settings.epsilon),
            },
            |worker, (j, (colour_row, map_row))| {
                let row = Row {
                    j: j as u32,
                    colours: colour_row,
                    maps: map_row,
                };
                let tally = render_row(worker, &setup, camera, settings, row);
                progress.inc(1);
                tally
            },
        )
        .reduce(RowTally::default, |a, b| a + b);
    Rendered {
        settings: *settings,
        image: LinearImage::from_pixels(settings.width, settings.height, colours),
        maps: pixel_maps,
        counts: tally.counts,
        elapsed: start.elapsed(),
        non_finite: tally.non_finite,
        over_budget: tally.over_budget,
    }
}

/// One image row's outputs: its colours and, when kept, its maps' rows.
struct Row<'a> {
    j: u32,
    colours: &'a mut [Vec3],
    maps: Option<(&'a mut [u8], &'a mut [u32])>,
}

// ANCHOR: row
/// One image row: its primary rays as wave 1, every wave traced, then
/// each pixel's samples summed in the pattern's order.
fn render_row(
    worker: &mut Worker,
    setup: &Setup,
    camera: &Camera,
    settings: &Settings,
    mut row: Row,
) -> RowTally {
    let spp = settings.sampling.spp() as usize;
    let j = row.j;
    let waves = &mut worker.waves;
    waves.start(settings.width as usize * spp, setup);
    primary_rays(camera, j, settings, &mut waves.rays[0]);
    waves.counts.0[RayKind::Primary.index()] += waves.rays[0].len() as u64;
    waves.trace(setup);

    let mut tally = RowTally {
        counts: waves.counts,
        ..RowTally::default()
    };
    for (i, colour) in row.colours.iter_mut().enumerate() {
        let mut sum = Vec3::ZERO;
        let (mut deepest, mut rays) = (0, 0);
        for k in 0..spp {
            let sample = i * spp + k;
            let mut traced = Vec3::ZERO;
            if waves.over_budget(sample) {
                let mut waved = RayCounts::default();
                count_tree(waves, 0, sample, &mut waved);
                tally.counts = tally.counts - waved;
                let before = worker.scalar.counts();
                let offset = settings.sampling.offset((i as u32, j), k as u32);
                let ray = camera.ray(i as u32, j, offset, settings.width, settings.height);
                let scalar = worker.scalar.trace(ray);
                tally.counts = tally.counts + (worker.scalar.counts() - before);
                tally.over_budget += u64::from(scalar.over_budget);
                traced = scalar.colour;
                deepest = deepest.max(scalar.deepest as u8);
                rays += scalar.rays;
            } else {
                sum_tree(&waves.nodes, 0, sample, &mut traced);
                if setup.maps {
                    deepest = deepest.max(waves.sample_deepest[sample]);
                    rays += waves.sample_rays[sample];
                }
            }
            sum += traced;
        }
        let average = sum / spp as f32;
        *colour = if average.is_finite() {
            average
        } else {
            tally.non_finite += 1;
            Vec3::ZERO
        };
        if let Some((deepest_row, rays_row)) = &mut row.maps {
            (deepest_row[i], rays_row[i]) = (deepest, rays);
        }
    }
    tally
}
// ANCHOR_END: row
