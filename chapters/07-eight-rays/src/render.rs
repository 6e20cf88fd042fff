//! The whole image: one row per task on every core, each row traced in
//! waves, then each sample's tree summed in the scalar tracer's order.

use std::time::Instant;

use raylab::indicatif::ProgressBar;
use raylab::linear_image::LinearImage;
use raylab::trace::RayCounts;
use raylab::{Camera, RayKind, Rendered, Scene, Settings, Tracer, Vec3};
use rayon::prelude::*;

use crate::EightRays;
use crate::camera::primary_rays;
use crate::intersect::SceneX8;
use crate::shade::Light;
use crate::wave::{Node, Setup, Waves};

/// What a row adds to the image's totals.
#[derive(Clone, Copy, Default)]
struct Tally {
    counts: RayCounts,
    non_finite: usize,
    over_budget: u64,
}

/// One sample's tree, summed: its colour and what it cost.
#[derive(Clone, Copy, Default)]
struct Sum {
    colour: Vec3,
    deepest: u32,
    rays: u32,
}

// ANCHOR: sum
/// Add up the tree under `nodes[depth][index]` in the order the scalar ray
/// stack pops it: a ray's own light first, then its children's subtrees.
fn sum_tree(nodes: &[Vec<Node>], depth: usize, index: usize, sum: &mut Sum) {
    let node = &nodes[depth][index];
    sum.add(node, depth);
    let first = node.first_child as usize;
    for child in first..first + usize::from(node.children) {
        let leaf = &nodes[depth + 1][child];
        // Most rays send nothing on: add those here, without a call.
        if leaf.children == 0 {
            sum.add(leaf, depth + 1);
        } else {
            sum_tree(nodes, depth + 1, child, sum);
        }
    }
}

impl Sum {
    /// Add one ray of depth `depth + 1`: its light, its depth, its rays.
    fn add(&mut self, node: &Node, depth: usize) {
        self.colour += node.added;
        self.deepest = self.deepest.max(depth as u32 + 1);
        self.rays += 1 + u32::from(node.shadow);
    }
}
// ANCHOR_END: sum

/// The rays of a tree by kind, to take a tree's wave-traced part back out
/// of the counts when the scalar tracer traces that sample again.
fn count_tree(nodes: &[Vec<Node>], depth: usize, index: usize, counts: &mut RayCounts) {
    let node = &nodes[depth][index];
    counts.0[node.kind.index()] += 1;
    counts.0[RayKind::Shadow.index()] += u64::from(node.shadow);
    let first = node.first_child as usize;
    for child in first..first + usize::from(node.children) {
        count_tree(nodes, depth + 1, child, counts);
    }
}

/// One worker's tools: its waves, and a scalar tracer for the rare sample
/// whose tree reaches the ray budget.
struct Worker<'s> {
    waves: Waves,
    scalar: Tracer<'s, EightRays>,
}

/// Render `scene` as `step`'s chapter would, eight rays at a time; the
/// image, the ray counts and the per-pixel maps equal `raylab::render`'s.
pub fn render_waves(
    scene: &Scene,
    camera: &Camera,
    step: &EightRays,
    settings: &Settings,
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
    };
    let mut colours = Vec::with_capacity(width * height);
    colours.par_extend(rayon::iter::repeat_n(Vec3::ZERO, width * height));
    let mut deepest = vec![0u8; width * height];
    let mut rays = vec![0u32; width * height];
    let tally = colours
        .par_chunks_mut(width)
        .zip(deepest.par_chunks_mut(width))
        .zip(rays.par_chunks_mut(width))
        .enumerate()
        .map_init(
            || Worker {
                waves: Waves::default(),
                scalar: Tracer::new(scene, step, settings.max_depth, settings.epsilon),
            },
            |worker, (j, ((colour_row, deepest_row), rays_row))| {
                let row = render_row(
                    worker,
                    &setup,
                    camera,
                    settings,
                    j as u32,
                    colour_row,
                    deepest_row,
                    rays_row,
                );
                progress.inc(1);
                row
            },
        )
        .reduce(Tally::default, |a, b| Tally {
            counts: a.counts + b.counts,
            non_finite: a.non_finite + b.non_finite,
            over_budget: a.over_budget + b.over_budget,
        });
    Rendered {
        settings: *settings,
        image: LinearImage::from_pixels(settings.width, settings.height, colours),
        deepest,
        rays,
        counts: tally.counts,
        elapsed: start.elapsed(),
        non_finite: tally.non_finite,
        over_budget: tally.over_budget,
    }
}

// ANCHOR: row
/// One image row: its primary rays as wave 1, every wave traced, then
/// each pixel's samples summed in the pattern's order.
#[allow(clippy::too_many_arguments)]
fn render_row(
    worker: &mut Worker,
    setup: &Setup,
    camera: &Camera,
    settings: &Settings,
    j: u32,
    colour_row: &mut [Vec3],
    deepest_row: &mut [u8],
    rays_row: &mut [u32],
) -> Tally {
    let spp = settings.sampling.spp() as usize;
    let (w, h) = (settings.width, settings.height);
    let waves = &mut worker.waves;
    waves.start(w as usize * spp, settings.max_depth);
    primary_rays(camera, j, settings, &mut waves.rays[0]);
    waves.trace(setup);

    let mut tally = Tally {
        counts: waves.counts,
        ..Tally::default()
    };
    let pixels = colour_row.iter_mut().zip(deepest_row).zip(rays_row);
    for (i, ((colour, deepest), rays)) in pixels.enumerate() {
        let mut sum = Vec3::ZERO;
        let mut pixel = Sum::default();
        for k in 0..spp {
            let sample = i * spp + k;
            let mut traced = Sum::default();
            if waves.over_budget(sample) {
                let mut waved = RayCounts::default();
                count_tree(&waves.nodes, 0, sample, &mut waved);
                tally.counts = tally.counts - waved;
                let before = worker.scalar.counts();
                let offset = settings.sampling.offset((i as u32, j), k as u32);
                let ray = camera.ray(i as u32, j, offset, w, h);
                let scalar = worker.scalar.trace(ray);
                tally.counts = tally.counts + (worker.scalar.counts() - before);
                tally.over_budget += u64::from(scalar.over_budget);
                (traced.colour, traced.deepest, traced.rays) =
                    (scalar.colour, scalar.deepest, scalar.rays);
            } else {
                sum_tree(&waves.nodes, 0, sample, &mut traced);
            }
            sum += traced.colour;
            pixel.deepest = pixel.deepest.max(traced.deepest);
            pixel.rays += traced.rays;
        }
        let average = sum / spp as f32;
        *colour = if average.is_finite() {
            average
        } else {
            tally.non_finite += 1;
            Vec3::ZERO
        };
        *deepest = pixel.deepest as u8;
        *rays = pixel.rays;
    }
    tally
}
// ANCHOR_END: row
