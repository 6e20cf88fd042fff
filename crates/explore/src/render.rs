//! Rendering, apart from the state that asks for it: a [`Job`] holds
//! everything a frame needs (scene, camera, knobs, settings), a
//! [`Render`] turns it into a [`Frame`], and the explorer takes the frame
//! if nothing has changed since it asked. So the same renderer runs in
//! the explorer's own thread (tests, `--headless`) and on the window's
//! render worker ([`crate::worker`]).

use std::sync::Arc;
use std::time::{Duration, Instant};

use ch06_path_tracing::PathSettings;
use ch07_eight_rays::render::render_waves;
use ch08_eight_paths::render_eight;
use image::RgbImage;
use raylab::srgb::EncodeTable;
use raylab::{Camera, Keep, NoProgress, Scene, Settings, Vec3};
use rayon::prelude::*;

use crate::gpu::{CpuFrame, GpuHalf, Outcome};
use crate::knobs::Knobs;

/// How far an image has come.
#[derive(Clone, Debug, PartialEq)]
pub enum Refinement {
    /// Something changed: the image is out of date.
    Stale,
    /// One ray per pixel, drawn while the camera moves.
    Preview,
    /// The Whitted frame at the chosen rays per pixel: nothing more to do.
    Done,
    /// Path tracing: the sum of every pass's radiance, and the passes.
    Paths { sum: Vec<Vec3>, passes: u32 },
}

/// What the last frame cost.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Stats {
    /// The whole frame: render, encode (paths) and nothing else.
    pub frame: Duration,
    /// Rays traced by the frame, shadow rays included.
    pub rays: u64,
}

impl Stats {
    pub fn mrays_per_second(&self) -> f64 {
        self.rays as f64 / self.frame.as_secs_f64().max(1e-9) / 1e6
    }
}

/// The CPU's part of a job.
#[derive(Clone, Debug)]
pub enum CpuJob {
    /// A Whitted frame, exactly as the chapter renders it; `preview` when
    /// it is the one-ray frame drawn while the camera moves.
    Whitted { settings: Settings, preview: bool },
    /// One more path per pixel, added to `sum` (the `passes` before it).
    Paths {
        settings: PathSettings,
        sum: Vec<Vec3>,
        passes: u32,
    },
}

/// The GPU's part of a job (`g`): the shader renders the view the CPU's
/// part leaves, with these settings.
#[derive(Clone, Debug)]
pub struct GpuJob {
    /// The chapter's settings at the CPU image's rays per pixel, or why
    /// there are none.
    pub settings: Result<Settings, String>,
    /// Whether the CPU's image is finished (the only kind the GPU renders).
    pub still: bool,
    /// The CPU's image to compare with, when the job has no CPU part.
    pub cpu: Option<RgbImage>,
}

/// One frame to render: the view, the knobs and what to do with them.
#[derive(Clone, Debug)]
pub struct Job {
    /// The explorer's count of changes when it asked: a frame of an older
    /// count is for a view that is gone.
    pub generation: u64,
    pub scene: Arc<Scene>,
    pub camera: Camera,
    pub knobs: Knobs,
    pub cpu: Option<CpuJob>,
    pub gpu: Option<GpuJob>,
}

/// The CPU's image of a job, and how far it has come.
#[derive(Clone, Debug)]
pub struct CpuImage {
    pub image: RgbImage,
    pub progress: Refinement,
    pub stats: Stats,
}

/// A job's result.
#[derive(Clone, Debug)]
pub struct Frame {
    pub generation: u64,
    pub cpu: Option<CpuImage>,
    /// The comparison's outcome and the adapter's name, with `g` on.
    pub gpu: Option<(Outcome, Option<String>)>,
}

/// What renders a job: [`Renderer`], or a stand-in in a test.
pub trait Render {
    fn render(&mut self, job: Job) -> Frame;
}

/// The explorer's renderer: chapter 7's waves, chapter 8's paths, and
/// chapter 10's shader for `g` (its device made on the first GPU job).
#[derive(Default)]
pub struct Renderer {
    gpu: GpuHalf,
}

impl Render for Renderer {
    fn render(&mut self, job: Job) -> Frame {
        let cpu = job.cpu.clone().map(|part| cpu_image(&job, part));
        let gpu = job.gpu.as_ref().map(|part| {
            let image = match (&cpu, &part.cpu) {
                (Some(rendered), _) => &rendered.image,
                (None, Some(image)) => image,
                (None, None) => return (Outcome::Pending, None),
            };
            let outcome = match &part.settings {
                Ok(settings) => self.gpu.render(&CpuFrame {
                    scene: &job.scene,
                    camera: &job.camera,
                    knobs: &job.knobs,
                    settings,
                    cpu: image,
                    still: part.still,
                }),
                Err(why) => Outcome::Refused(why.clone()),
            };
            (outcome, self.gpu.adapter().map(str::to_owned))
        });
        Frame {
            generation: job.generation,
            cpu,
            gpu,
        }
    }
}

/// The CPU's part of a job.
fn cpu_image(job: &Job, part: CpuJob) -> CpuImage {
    let start = Instant::now();
    match part {
        CpuJob::Whitted { settings, preview } => {
            let rendered = render_waves(
                &job.scene,
                &job.camera,
                &job.knobs.step(),
                &settings,
                Keep::IMAGE,
                &NoProgress,
            );
            CpuImage {
                image: rendered.srgb,
                progress: if preview {
                    Refinement::Preview
                } else {
                    Refinement::Done
                },
                stats: Stats {
                    frame: start.elapsed(),
                    rays: rendered.counts.total(),
                },
            }
        }
        CpuJob::Paths {
            settings,
            mut sum,
            passes,
        } => {
            let render = render_eight(&job.scene, &job.camera, &settings, &NoProgress);
            let passes = passes + 1;
            let scale = 1.0 / passes as f32;
            let table = EncodeTable::get();
            let mut image = RgbImage::new(settings.width, settings.height);
            sum.par_iter_mut()
                .zip(render.image.pixels().par_iter())
                .zip(image.par_chunks_mut(3))
                .for_each(|((total, &new), out)| {
                    *total += new;
                    // One pass is chapter 8's own image: `x * 1.0` is `x`.
                    out.copy_from_slice(&table.encode_rgb(*total * scale));
                });
            CpuImage {
                image,
                progress: Refinement::Paths { sum, passes },
                stats: Stats {
                    frame: start.elapsed(),
                    rays: render.rays,
                },
            }
        }
    }
}
