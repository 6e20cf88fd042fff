//! Chapter 6's render loop: many paths per pixel on every core, and what
//! they add up to — the image, its variance, and its terms.

use std::fmt;
use std::time::{Duration, Instant};

use rayon::prelude::*;

use raylab::frame::thousands;
use raylab::linear_image::LinearImage;
use raylab::render::Progress;
use raylab::sampling::{PixelHash, Sampling, Stream};
use raylab::{Camera, Scene, SceneQuery};

use crate::caustics::KERNEL_RADIUS;
use crate::integrator::{Materials, PathTracer};
use crate::photons::trace_caustics;
use crate::pixel::{Images, PixelSums, RowImages, SampleSums};
use crate::random::Random;
use crate::sun::Sunlight;

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
    /// Whether the five term images are made: not with `--no-diagrams`,
    /// which writes only the render and its variance.
    pub keep_terms: bool,
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

// ANCHOR: pixel
/// Trace a pixel's paths and average them.
fn render_pixel(
    tracer: &PathTracer<'_, impl SceneQuery>,
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

// ANCHOR_END: pixel

/// Render on every core, one path at a time: the chapter's definition.
/// Each image row is one task, and `progress` is told of each row done.
pub fn render_paths(
    scene: &Scene,
    camera: &Camera,
    settings: &PathSettings,
    progress: &dyn Progress,
) -> PathRender {
    render_paths_with_query(scene, scene, camera, settings, progress)
}

/// [`render_paths`], with every hit found by `objects`: a [`SceneQuery`]
/// that gives the scene's own answers another way (chapter 9's tree),
/// named and typed by the core's rule ([`raylab::render::render_with_query`]).
pub fn render_paths_with_query<Q: SceneQuery>(
    scene: &Scene,
    objects: &Q,
    camera: &Camera,
    settings: &PathSettings,
    progress: &dyn Progress,
) -> PathRender {
    let width = settings.width as usize;
    path_frame(scene, objects, settings, |tracer, rows| {
        // ANCHOR: rows
        // Every row on every core, each written by its worker straight
        // into its place in the output images.
        rows.into_par_iter()
            .enumerate()
            .map(|(j, mut row)| {
                for i in 0..width {
                    let pixel = (i as u32, j as u32);
                    row.set(i, render_pixel(tracer, camera, settings, pixel));
                }
                progress.row_done();
                (row.rays, row.non_finite)
            })
            .reduce(|| (0, 0), |a, b| (a.0 + b.0, a.1 + b.1))
        // ANCHOR_END: rows
    })
}

/// What every path render does around its rows: make the tracer, whose
/// hit queries `objects` answers (the scene itself, or a faster
/// [`SceneQuery`] that gives the same answers), trace the caustic map
/// first if asked for, hand `rows` the output images row by row, and
/// gather the result. `rows` returns the rays traced and the samples that
/// came out NaN or infinite. It is the frame, not a renderer (hence not a
/// `render_…` name): the renderers of chapters 6 and 8 are the rows they
/// hand it.
pub fn path_frame<Q: SceneQuery>(
    scene: &Scene,
    objects: &Q,
    settings: &PathSettings,
    rows: impl FnOnce(&PathTracer<'_, Q>, Vec<RowImages<'_>>) -> (u64, u64),
) -> PathRender {
    let mut tracer = PathTracer {
        scene,
        objects,
        sun: Sunlight::new(&scene.sun, settings.sun_size),
        materials: settings.materials,
        max_depth: settings.max_depth,
        epsilon: settings.epsilon,
        caustics: None,
    };
    let map = settings.caustics.then(|| {
        let start = Instant::now();
        let map = trace_caustics(
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
    let (rays, non_finite) = rows(&tracer, images.rows(width));
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
