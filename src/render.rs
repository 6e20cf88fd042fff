//! Rendering a whole image on every core, and what it cost.

use std::fmt;
use std::time::{Duration, Instant};

use image::RgbImage;
use indicatif::ProgressBar;
use rayon::prelude::*;

use crate::Vec3;
use crate::camera::Camera;
use crate::linear_image::LinearImage;
use crate::outputs::{Keep, Outputs, PixelMaps};
use crate::ray::RayKind;
use crate::sampling::Sampling;
use crate::scene::Scene;
use crate::trace::{RAY_BUDGET, RayCounts, Step, Tracer};

/// How to render: the image size, the limits of the ray tree and the samples.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Settings {
    pub width: u32,
    pub height: u32,
    /// The deepest ray traced; 1 traces only the primary rays.
    pub max_depth: u32,
    /// How far secondary and shadow rays start from their surface.
    pub epsilon: f32,
    /// How many rays per pixel, where, and the seed of their random choices.
    pub sampling: Sampling,
}

/// A rendered image, with what the renderer did to make it.
#[derive(Clone, Debug)]
pub struct Rendered {
    pub settings: Settings,
    /// The image as `render.png` stores it: LAB.md's 8-bit sRGB, encoded
    /// by the workers as they finish each row.
    pub srgb: RgbImage,
    /// The image in linear light, when the render was asked to keep it.
    pub linear: Option<LinearImage>,
    /// The depth and ray-count maps, when the render was asked to keep them.
    pub maps: Option<PixelMaps>,
    pub counts: RayCounts,
    pub elapsed: Duration,
    /// Pixels whose colour came out NaN or infinite and were set to black.
    /// Always 0 for a correct step; reported rather than hidden.
    pub non_finite: usize,
    /// Samples whose ray tree reached [`RAY_BUDGET`] and was cut short.
    pub over_budget: u64,
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
fn render_pixel<S: Step + ?Sized>(
    tracer: &mut Tracer<'_, S>,
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

/// What a row of the image adds to the totals, besides its pixels (rows
/// are summed with `+`; chapter 7's wave renderer keeps the same tally).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct RowTally {
    pub counts: RayCounts,
    /// Pixels that came out NaN or infinite.
    pub non_finite: usize,
    /// Samples whose tree reached the ray budget.
    pub over_budget: u64,
}

impl std::ops::Add for RowTally {
    type Output = RowTally;
    fn add(self, other: RowTally) -> RowTally {
        RowTally {
            counts: self.counts + other.counts,
            non_finite: self.non_finite + other.non_finite,
            over_budget: self.over_budget + other.over_budget,
        }
    }
}

/// Render `scene` through `camera` with a chapter's `step`, one image row
/// per task on every core, ticking `progress` once per row; the 8-bit
/// image, and what `keep` asks for besides.
pub fn render<S: Step + ?Sized>(
    scene: &Scene,
    camera: &Camera,
    step: &S,
    settings: &Settings,
    keep: Keep,
    progress: &ProgressBar,
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
            || Tracer::new(scene, step, settings.max_depth, settings.epsilon),
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
                progress.inc(1);
                row.counts = tracer.counts() - before;
                row
            },
        )
        .reduce(RowTally::default, |a, b| a + b);
    // ANCHOR_END: rows
    outputs.finish(settings, tally, start)
}

impl Rendered {
    /// The image in linear light.
    ///
    /// # Panics
    /// If the render was not asked to keep it ([`Keep::linear`]).
    pub fn linear_image(&self) -> &LinearImage {
        self.linear
            .as_ref()
            .expect("a render asked to keep its linear image (Keep::linear)")
    }

    /// Millions of rays traced per second of wall time.
    pub fn mrays_per_second(&self) -> f64 {
        self.counts.total() as f64 / self.elapsed.as_secs_f64().max(1e-9) / 1e6
    }
}

/// "800×600, 1 spp, max depth 10": what a render was asked for.
impl fmt::Display for Settings {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{}×{}, {}, max depth {}",
            self.width, self.height, self.sampling, self.max_depth
        )
    }
}

/// The one-line summary: resolution, rays by kind, time and speed.
impl fmt::Display for Rendered {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{}: {} rays (",
            self.settings,
            thousands(self.counts.total())
        )?;
        for (n, kind) in RayKind::ALL.into_iter().enumerate() {
            let sep = if n == 0 { "" } else { ", " };
            write!(
                f,
                "{sep}{} {}",
                thousands(self.counts.get(kind)),
                kind.name()
            )?;
        }
        write!(
            f,
            ") in {:.1} ms, {:.1} Mrays/s",
            self.elapsed.as_secs_f64() * 1e3,
            self.mrays_per_second()
        )?;
        if self.over_budget > 0 {
            write!(
                f,
                "; WARNING: {} samples reached the budget of {RAY_BUDGET} rays and were cut short \
                 (is --epsilon 0?)",
                thousands(self.over_budget)
            )?;
        }
        if self.non_finite > 0 {
            write!(
                f,
                "; WARNING: {} pixels were NaN or infinite",
                self.non_finite
            )?;
        }
        Ok(())
    }
}

/// `1234567` as `1,234,567`.
pub fn thousands(n: u64) -> String {
    let digits = n.to_string();
    let mut out = String::with_capacity(digits.len() + digits.len() / 3);
    for (i, c) in digits.chars().enumerate() {
        if i > 0 && (digits.len() - i).is_multiple_of(3) {
            out.push(',');
        }
        out.push(c);
    }
    out
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
    progress: &ProgressBar,
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
                progress.inc(1);
            },
        );
    (0..depths)
        .map(|d| {
            let pixels = colours.iter().skip(d).step_by(depths).copied().collect();
            LinearImage::from_pixels(settings.width, settings.height, pixels)
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn thousands_are_grouped_by_three() {
        assert_eq!(thousands(0), "0");
        assert_eq!(thousands(999), "999");
        assert_eq!(thousands(1000), "1,000");
        assert_eq!(thousands(12_345_678), "12,345,678");
    }
}
