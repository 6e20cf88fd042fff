//! Rendering a whole image on every core, one ray at a time.

use std::time::Instant;

use rayon::prelude::*;

use crate::Vec3;
use crate::camera::Camera;
use crate::frame::{Keep, Rendered, RowTally, Settings};
use crate::linear_image::LinearImage;
use crate::outputs::Outputs;
use crate::scene::{Scene, SceneQuery};
use crate::trace::{Step, Tracer};

/// Told once per finished image row, from any worker: how a program shows
/// a render's progress (the bench draws a bar with it). Any `Fn()` closure
/// is one, and [`NoProgress`] shows nothing.
pub trait Progress: Sync {
    /// One more row of the image is finished.
    fn row_done(&self);
}

impl<F: Fn() + Sync> Progress for F {
    fn row_done(&self) {
        self()
    }
}

/// No progress to show: for tests, benchmarks and quiet runs.
#[derive(Clone, Copy, Debug, Default)]
pub struct NoProgress;

impl Progress for NoProgress {
    fn row_done(&self) {}
}

#[derive(Clone, Copy, Default)]
struct PixelResult {
    colour: Vec3,
    deepest: u8,
    rays: u32,
    over_budget: u32,
}

// ANCHOR: pixel
/// A pixel's colour: the plain average of its samples' colours, in linear
/// light, summed in sample order and divided by their number. Nothing is
/// allocated: each offset is computed from (seed, pixel, sample) on the spot.
fn render_pixel<S: Step + ?Sized, Q: SceneQuery>(
    tracer: &mut Tracer<'_, S, Q>,
    camera: &Camera,
    (i, j): (u32, u32),
    settings: &Settings,
) -> PixelResult {
    let mut sum = Vec3::ZERO;
    let mut result = PixelResult::default();
    for offset in settings.sampling.offsets((i, j)) {
        let ray = camera.ray(i, j, offset, settings.width, settings.height);
        let traced = tracer.trace(ray);
        sum += traced.colour;
        result.deepest = result.deepest.max(traced.deepest as u8);
        result.rays += traced.rays;
        result.over_budget += u32::from(traced.over_budget);
    }
    result.colour = sum / settings.sampling.spp() as f32;
    result
}
// ANCHOR_END: pixel

/// Render `scene` through `camera` with a chapter's `step`, one image row
/// per task on every core, ticking `progress` once per row; the 8-bit
/// image, and what `keep` asks for besides.
pub fn render<S: Step + ?Sized>(
    scene: &Scene,
    camera: &Camera,
    step: &S,
    settings: &Settings,
    keep: Keep,
    progress: &dyn Progress,
) -> Rendered {
    render_with_query(scene, scene, camera, step, settings, keep, progress)
}

/// [`render`], with every ray's hit found by `objects` (a [`SceneQuery`]
/// that gives the scene's own answers faster, such as a tree of boxes)
/// instead of by testing the scene's objects one by one.
///
/// The one rule for plugging in a query, here and in the chapters'
/// renderers: `render_X` tests every object, and `render_X_with_query`
/// takes the query as a type parameter `Q`, not a `&dyn SceneQuery`, so
/// that its search is compiled into the trace loop instead of costing
/// every ray a call and a copy of its `Hit`.
pub fn render_with_query<S: Step + ?Sized, Q: SceneQuery>(
    scene: &Scene,
    objects: &Q,
    camera: &Camera,
    step: &S,
    settings: &Settings,
    keep: Keep,
    progress: &dyn Progress,
) -> Rendered {
    let start = Instant::now();
    let mut outputs = Outputs::new(settings.width, settings.height, keep);
    // ANCHOR: rows
    let tally = outputs
        .rows()
        .enumerate()
        // One tracer (and so one ray stack) per piece of work, which is a
        // row (`Outputs::rows`): made in a microsecond, against a tenth of
        // a millisecond and more to render the row, and reused for all of
        // the row's pixels.
        .map_init(
            || Tracer::with_query(scene, objects, step, settings.max_depth, settings.epsilon),
            |tracer, (j, mut out)| {
                let before = tracer.counts();
                let mut row = RowTally::default();
                for i in 0..settings.width as usize {
                    let pixel = render_pixel(tracer, camera, (i as u32, j as u32), settings);
                    if !out.set_colour(i, pixel.colour) {
                        row.non_finite += 1;
                    }
                    out.set_maps(i, pixel.deepest, pixel.rays);
                    row.over_budget += u64::from(pixel.over_budget);
                }
                progress.row_done();
                row.counts = tracer.counts() - before;
                row
            },
        )
        .reduce(RowTally::default, |a, b| a + b);
    // ANCHOR_END: rows
    outputs.finish(settings, tally, start)
}

/// Render the image at every max depth from 1 to `settings.max_depth` at
/// once: one trace per sample, with each ray's contribution added to the
/// images of every depth limit that would have traced it. The last image
/// equals [`render`]'s, to the bit.
pub fn render_every_depth<S: Step + ?Sized>(
    scene: &Scene,
    camera: &Camera,
    step: &S,
    settings: &Settings,
    progress: &dyn Progress,
) -> Vec<LinearImage> {
    let (width, height) = (settings.width as usize, settings.height as usize);
    let depths = settings.max_depth as usize;
    let samples = settings.sampling.spp() as f32;
    // Pixel by pixel, the colours at depth 1, 2, … side by side.
    let mut colours = vec![Vec3::ZERO; width * height * depths];
    colours
        .par_chunks_mut(width * depths)
        .enumerate()
        .for_each_init(
            || Tracer::new(scene, step, settings.max_depth, settings.epsilon).with_depth_colours(),
            |tracer, (j, row)| {
                for (i, pixel) in row.chunks_mut(depths).enumerate() {
                    let (i, j) = (i as u32, j as u32);
                    for offset in settings.sampling.offsets((i, j)) {
                        let ray = camera.ray(i, j, offset, settings.width, settings.height);
                        tracer.trace(ray);
                        for (d, sum) in pixel.iter_mut().enumerate() {
                            *sum += tracer
                                .colour_at_depth(d as u32 + 1)
                                .expect("kept per depth");
                        }
                    }
                    for sum in pixel.iter_mut() {
                        let average = *sum / samples;
                        *sum = if average.is_finite() {
                            average
                        } else {
                            Vec3::ZERO
                        };
                    }
                }
                progress.row_done();
            },
        );
    (0..depths)
        .map(|d| {
            let pixels = colours.iter().skip(d).step_by(depths).copied().collect();
            LinearImage::from_pixels(settings.width, settings.height, pixels)
        })
        .collect()
}
