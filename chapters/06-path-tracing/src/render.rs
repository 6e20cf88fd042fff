//! Chapter 6's render loop: many paths per pixel on every core, and what
//! they add up to — the image, its variance, and its terms.

use std::fmt;
use std::time::{Duration, Instant};

use rayon::prelude::*;

use raylab::indicatif::ProgressBar;
use raylab::linear_image::LinearImage;
use raylab::render::thousands;
use raylab::{Camera, Scene, Vec3};

use crate::caustics::{CausticMap, KERNEL_RADIUS};
use crate::integrator::{Materials, PathTracer, Terms};
use crate::lanes::SceneLanes;
use crate::random::Random;
use crate::sun::Sunlight;
use raylab::sampling::{PixelHash, Sampling, Stream};

/// What to render.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PathSettings {
    pub width: u32,
    pub height: u32,
    pub sampling: Sampling,
    /// The most surface hits on a path, the first one included.
    pub max_depth: u32,
    pub epsilon: f32,
    pub materials: Materials,
    /// `--sun-size` in degrees; `None` for a point sun.
    pub sun_size: Option<f32>,
    pub caustics: bool,
    /// With `--caustics`: photons sent towards each mirror or glass sphere.
    pub photons_per_sphere: u32,
    /// `--tracer`: one path at a time, or eight (the same bytes).
    pub tracer: Tracer,
    /// Whether the five term images are made: not with `--no-diagrams`,
    /// which writes only the render and its variance.
    pub keep_terms: bool,
}

/// `--tracer`: how the paths are traced. Both give the same image to the
/// bit; [`PathTracer::trace`] is the definition, and eight lanes are faster.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, clap::ValueEnum)]
pub enum Tracer {
    /// One path at a time (`PathTracer::trace`), the chapter's definition
    Scalar,
    /// Eight paths at a time in SIMD lanes, to the same bytes
    #[default]
    Eight,
}

/// A rendered image and everything measured along the way.
#[derive(Clone, Debug)]
pub struct PathRender {
    pub settings: PathSettings,
    /// Each pixel's mean radiance (linear).
    pub image: LinearImage,
    /// Each pixel's variance of that mean, estimated from its samples:
    /// `s² / N`; all zero with one sample per pixel, where it is unknown.
    pub variance: LinearImage,
    /// The image split by term, in the order of [`Terms::NAMES`], when
    /// [`PathSettings::keep_terms`] asked for it.
    pub terms: Option<[LinearImage; 5]>,
    pub paths: u64,
    /// Every segment of every path (from the eye and after each bounce),
    /// and every shadow ray.
    pub rays: u64,
    pub elapsed: Duration,
    /// Samples whose radiance came out NaN or infinite and were dropped.
    /// Always 0 for a correct integrator; reported, not hidden.
    pub non_finite: u64,
    /// With `--caustics`: photons sent, landed, rays and time.
    pub caustics: Option<CausticStats>,
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CausticStats {
    pub sent: u64,
    pub landed: usize,
    pub rays: u64,
    pub elapsed: Duration,
}

/// One pixel's sums over its samples.
#[derive(Clone, Copy, Default)]
pub(crate) struct PixelSums {
    mean: Vec3,
    variance: Vec3,
    terms: Terms,
    rays: u64,
    non_finite: u64,
}

/// A pixel's running sums as its samples come in, in sample order (float
/// sums depend on the order).
#[derive(Clone, Copy, Default)]
pub(crate) struct SampleSums {
    sum: [f64; 3],
    sum_sq: [f64; 3],
    terms: Terms,
    /// Every ray of the pixel's paths.
    pub rays: u32,
    non_finite: u64,
}

// ANCHOR: pixel
/// Trace a pixel's paths and average them.
fn render_pixel(
    tracer: &PathTracer,
    camera: &Camera,
    settings: &PathSettings,
    pixel: (u32, u32),
) -> PixelSums {
    let sampling = &settings.sampling;
    let mut sums = SampleSums::default();
    // What the pixel's samples share, hashed once: where they go in the
    // pixel, and the pixel's half of every path's generator.
    let samples = sampling.pixel(pixel);
    let hash = PixelHash::new(sampling.seed(), pixel);
    for sample in 0..sampling.spp() {
        let offset = samples.offset(sample);
        let ray = camera.ray(pixel.0, pixel.1, offset, settings.width, settings.height);
        let mut random = Random(hash.sample_rng(sample, Stream::Path));
        let terms = tracer.trace(ray, &mut random, &mut sums.rays);
        sums.add(&terms);
    }
    sums.finish(sampling.spp())
}

impl SampleSums {
    /// One more sample's light; a NaN or infinite one is counted, not summed.
    pub(crate) fn add(&mut self, terms: &Terms) {
        let radiance = terms.total();
        if !radiance.is_finite() {
            self.non_finite += 1;
            return;
        }
        self.terms += *terms;
        for (c, x) in radiance.to_array().into_iter().enumerate() {
            let x = f64::from(x);
            self.sum[c] += x;
            self.sum_sq[c] += x * x;
        }
    }

    /// The mean of `n` samples, and the variance of that mean from the
    /// same samples: `(Σx² − N·x̄²) / (N − 1) / N`, summed in f64 because a
    /// sun disc seen in the mirror is 37,000 times brighter than the sky
    /// and its squares would swamp an f32 sum.
    pub(crate) fn finish(self, n: u32) -> PixelSums {
        let n = f64::from(n);
        let mean = self.sum.map(|s| s / n);
        let variance = std::array::from_fn(|c| {
            if n < 2.0 {
                return 0.0;
            }
            ((self.sum_sq[c] - n * mean[c] * mean[c]) / (n - 1.0)).max(0.0) / n
        });
        let to_vec = |a: [f64; 3]| Vec3::new(a[0] as f32, a[1] as f32, a[2] as f32);
        let terms = self.terms.as_array().map(|t| t / n as f32);
        PixelSums {
            mean: to_vec(mean),
            variance: to_vec(variance),
            terms: Terms {
                seen: terms[0],
                sun_direct: terms[1],
                sky_direct: terms[2],
                indirect: terms[3],
                caustics: terms[4],
            },
            rays: u64::from(self.rays),
            non_finite: self.non_finite,
        }
    }
}
// ANCHOR_END: pixel

/// Render on every core, one image row per task, ticking `progress` per row.
pub fn render(
    scene: &Scene,
    camera: &Camera,
    settings: &PathSettings,
    progress: &ProgressBar,
) -> PathRender {
    let scene_lanes = SceneLanes::new(scene);
    let mut tracer = PathTracer {
        scene,
        scene_lanes: &scene_lanes,
        sun: Sunlight::new(&scene.sun, settings.sun_size),
        materials: settings.materials,
        max_depth: settings.max_depth,
        epsilon: settings.epsilon,
        caustics: None,
    };
    let map = settings.caustics.then(|| {
        let start = Instant::now();
        let map = CausticMap::trace(
            &tracer,
            settings.photons_per_sphere,
            settings.sampling.seed(),
        );
        let stats = CausticStats {
            sent: map.sent,
            landed: map.len(),
            rays: map.rays,
            elapsed: start.elapsed(),
        };
        (map, stats)
    });
    tracer.caustics = map.as_ref().map(|(m, _)| m);
    let eye_start = Instant::now();
    let (width, height) = (settings.width as usize, settings.height as usize);
    let mut images = Images::new(width * height, settings.keep_terms);
    // ANCHOR: rows
    // Every row on every core, each written by its worker straight into
    // its place in the output images.
    let rows = images.rows(width).into_par_iter().enumerate();
    let (rays, non_finite) = match settings.tracer {
        Tracer::Eight => crate::eight::render_rows(&tracer, camera, settings, progress, rows),
        Tracer::Scalar => rows
            .map(|(j, mut row)| {
                for i in 0..width {
                    let pixel = (i as u32, j as u32);
                    row.set(i, render_pixel(&tracer, camera, settings, pixel));
                }
                progress.inc(1);
                (row.rays, row.non_finite)
            })
            .reduce(|| (0, 0), |a, b| (a.0 + b.0, a.1 + b.1)),
    };
    // ANCHOR_END: rows
    let elapsed = eye_start.elapsed();
    let image = |pixels| LinearImage::from_pixels(settings.width, settings.height, pixels);
    PathRender {
        settings: *settings,
        image: image(images.mean),
        variance: image(images.variance),
        terms: images.terms.map(|terms| terms.map(image)),
        paths: (width * height) as u64 * u64::from(settings.sampling.spp()),
        rays,
        elapsed,
        non_finite,
        caustics: map.map(|(_, stats)| stats),
    }
}

/// The images a render fills in: each pixel's mean, the variance of that
/// mean and, when kept, its five terms.
struct Images {
    mean: Vec<Vec3>,
    variance: Vec<Vec3>,
    terms: Option<[Vec<Vec3>; 5]>,
}

impl Images {
    /// `pixels` black pixels in each image, cleared by this thread before
    /// the render (clearing them on every core, with `par_extend`, measured
    /// the same: 587 against 599 ms over 11 interleaved runs of the whole
    /// program).
    fn new(pixels: usize, keep_terms: bool) -> Images {
        let black = || vec![Vec3::ZERO; pixels];
        Images {
            mean: black(),
            variance: black(),
            terms: keep_terms.then(|| std::array::from_fn(|_| black())),
        }
    }

    /// Each row's share of every image, `width` pixels each.
    fn rows(&mut self, width: usize) -> Vec<RowImages<'_>> {
        let mut term_rows =
            (self.terms.as_mut()).map(|terms| terms.each_mut().map(|term| term.chunks_mut(width)));
        let mut next_term_rows = move || {
            let rows = term_rows.as_mut()?;
            Some(
                rows.each_mut()
                    .map(|r| r.next().expect("every image has the rows")),
            )
        };
        (self.mean.chunks_mut(width))
            .zip(self.variance.chunks_mut(width))
            .map(|(mean, variance)| RowImages {
                mean,
                variance,
                terms: next_term_rows(),
                rays: 0,
                non_finite: 0,
            })
            .collect()
    }
}

/// One image row's pixels in each output image, filled in by one task,
/// and the rays and non-finite samples of its pixels.
pub(crate) struct RowImages<'a> {
    mean: &'a mut [Vec3],
    variance: &'a mut [Vec3],
    terms: Option<[&'a mut [Vec3]; 5]>,
    pub rays: u64,
    pub non_finite: u64,
}

impl RowImages<'_> {
    /// Pixel `i` of the row, from its sums.
    pub(crate) fn set(&mut self, i: usize, pixel: PixelSums) {
        self.mean[i] = pixel.mean;
        self.variance[i] = pixel.variance;
        if let Some(terms) = &mut self.terms {
            for (image, term) in terms.iter_mut().zip(pixel.terms.as_array()) {
                image[i] = term;
            }
        }
        self.rays += pixel.rays;
        self.non_finite += pixel.non_finite;
    }
}

impl PathRender {
    /// The five term images, in the order of [`Terms::NAMES`]. Only a
    /// render whose settings kept them has them (`keep_terms`).
    pub fn terms(&self) -> &[LinearImage; 5] {
        self.terms
            .as_ref()
            .expect("the render was asked to keep its terms (PathSettings::keep_terms)")
    }

    pub fn paths_per_second(&self) -> f64 {
        self.paths as f64 / self.elapsed.as_secs_f64().max(1e-9)
    }

    pub fn mrays_per_second(&self) -> f64 {
        self.rays as f64 / self.elapsed.as_secs_f64().max(1e-9) / 1e6
    }
}

/// "800×600, 256 spp (random, seed 1), max depth 10, lab materials, point sun".
impl fmt::Display for PathSettings {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{}×{}, {} spp ({}, seed {}), max depth {}, {} materials, ",
            self.width,
            self.height,
            self.sampling.spp(),
            self.sampling.pattern().map_or("pixel centre", |p| p.name()),
            self.sampling.seed(),
            self.max_depth,
            self.materials.name()
        )?;
        match self.sun_size {
            None => write!(f, "point sun")?,
            Some(d) => write!(f, "{d}° sun")?,
        }
        if self.caustics {
            write!(f, ", caustics")?;
        }
        if self.tracer == Tracer::Scalar {
            write!(f, ", scalar tracer")?;
        }
        Ok(())
    }
}

/// The summary line: what was rendered, how many paths and rays, how fast.
impl fmt::Display for PathRender {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{}: {} paths, {} rays in {:.2} s, {:.1} M paths/s, {:.1} Mrays/s",
            self.settings,
            thousands(self.paths),
            thousands(self.rays),
            self.elapsed.as_secs_f64(),
            self.paths_per_second() / 1e6,
            self.mrays_per_second()
        )?;
        if let Some(c) = &self.caustics {
            write!(
                f,
                "; caustics: {} photons from the sun, {} on the ground, {} rays in {:.0} ms \
                 (kernel radius {KERNEL_RADIUS})",
                thousands(c.sent),
                thousands(c.landed as u64),
                thousands(c.rays),
                c.elapsed.as_secs_f64() * 1e3
            )?;
        }
        if self.non_finite > 0 {
            write!(
                f,
                "; WARNING: {} samples were NaN or infinite and were dropped",
                thousands(self.non_finite)
            )?;
        }
        Ok(())
    }
}
