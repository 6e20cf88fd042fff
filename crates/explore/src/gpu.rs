//! `g`: the same view traced by chapter 10's shader, beside the CPU's.
//!
//! The lab's tracer ran on a GPU; chapter 10 runs chapters 1–5 as a WGSL
//! compute shader. With `g` on, every finished Whitted frame the explorer
//! renders (not the previews while the camera moves, nor the refinements
//! on the way) is rendered a second time by that shader, with the same scene, camera,
//! chapter, rays per pixel, depth and epsilon, and the two are compared
//! with the lab model's tolerance, the one the golden images are held to.
//!
//! The device is made on the first frame that asks for it and kept by
//! the renderer ([`GpuHalf`], on the render worker in the window): the
//! explorer starts without looking for a GPU, and runs where there is
//! none. Whatever stops the comparison (no adapter, path tracing, a
//! pattern the shader refuses) is one line for the overlay, never a panic.

use std::collections::HashMap;
use std::collections::hash_map::Entry;
use std::time::Duration;

use ch10_gpu::gpu::{Gpu, Pipeline};
use ch10_gpu::run::render_image;
use ch10_gpu::scene_buffer::{self, PackError};
use ch10_gpu::shader::Source;
use image::RgbImage;
use raylab::tolerance::{Agreement, compare};
use raylab::{Camera, Scene, Settings};

use crate::knobs::Knobs;

/// A frame from the shader, and how it compares with the CPU's.
#[derive(Clone, Debug)]
pub struct GpuFrame {
    pub image: RgbImage,
    /// Dispatch and readback: the GPU's part of the frame (the sRGB
    /// encoding after it is the core's, on the CPU, as for any chapter).
    pub time: Duration,
    /// The shader's image (ours) against the CPU's (the reference).
    pub agreement: Agreement,
}

/// The view the CPU just rendered, for the shader to render again.
#[derive(Clone, Copy)]
pub struct CpuFrame<'a> {
    pub scene: &'a Scene,
    pub camera: &'a Camera,
    pub knobs: &'a Knobs,
    pub settings: &'a Settings,
    /// The CPU's image, which the GPU's is compared with.
    pub cpu: &'a RgbImage,
    /// Whether it is finished (not a preview or a refinement on the way).
    pub still: bool,
}

/// What the comparison has to show.
#[derive(Clone, Debug)]
pub enum Outcome {
    /// Nothing yet: `g` was pressed and the next frame will render it.
    Pending,
    Frame(GpuFrame),
    /// Why there is no GPU frame, in one line.
    Refused(String),
}

/// The comparison as the explorer shows it: whether it is on, the
/// adapter's name once a device is made, and the last outcome. The device
/// itself is the renderer's ([`GpuHalf`]), on the thread that renders.
#[derive(Debug)]
pub struct Comparison {
    on: bool,
    adapter: Option<String>,
    outcome: Outcome,
}

impl Default for Comparison {
    fn default() -> Comparison {
        Comparison {
            on: false,
            adapter: None,
            outcome: Outcome::Pending,
        }
    }
}

impl Comparison {
    pub fn is_on(&self) -> bool {
        self.on
    }

    /// Switch the comparison on (the next frame renders it) or off.
    pub fn toggle(&mut self) {
        self.on = !self.on;
        self.outcome = Outcome::Pending;
    }

    /// On, and waiting for a frame.
    pub fn is_pending(&self) -> bool {
        self.on && matches!(self.outcome, Outcome::Pending)
    }

    /// The last outcome, while the comparison is on.
    pub fn outcome(&self) -> Option<&Outcome> {
        self.on.then_some(&self.outcome)
    }

    /// The GPU frame to show beside a CPU frame of `size`, if there is one.
    pub fn frame(&self, size: (u32, u32)) -> Option<&GpuFrame> {
        match self.outcome()? {
            Outcome::Frame(frame) if frame.image.dimensions() == size => Some(frame),
            _ => None,
        }
    }

    /// Why there is no GPU frame, while the comparison is on.
    pub fn refusal(&self) -> Option<&str> {
        match self.outcome()? {
            Outcome::Refused(why) => Some(why),
            _ => None,
        }
    }

    /// The adapter's name (without its driver), once a device is made.
    pub fn adapter(&self) -> Option<&str> {
        self.adapter.as_deref()
    }

    /// No GPU frame, for a reason found outside.
    pub fn refuse(&mut self, why: String) {
        self.outcome = Outcome::Refused(why);
    }

    /// Take what the renderer's [`GpuHalf`] made of a frame.
    pub fn take(&mut self, outcome: Outcome, adapter: Option<String>) {
        self.outcome = outcome;
        if adapter.is_some() {
            self.adapter = adapter;
        }
    }
}

/// The renderer's half of the comparison: the device once made, and a
/// compiled tracer per max depth (the shader's ray stack is sized for it).
#[derive(Default)]
pub struct GpuHalf {
    device: Option<Result<Gpu, String>>,
    tracers: HashMap<u32, Pipeline>,
}

impl GpuHalf {
    /// The adapter's name (without its driver), once a device is made.
    pub fn adapter(&self) -> Option<&str> {
        match &self.device {
            Some(Ok(gpu)) => gpu.adapter.split(" (").next(),
            _ => None,
        }
    }

    /// Render the view the CPU just rendered, if it is finished, and
    /// compare. A view still on its way is only checked for a refusal.
    pub fn render(&mut self, view: &CpuFrame) -> Outcome {
        match self.try_render(view) {
            Ok(Some(frame)) => Outcome::Frame(frame),
            Ok(None) => Outcome::Pending,
            Err(why) => Outcome::Refused(why),
        }
    }

    fn try_render(&mut self, view: &CpuFrame) -> Result<Option<GpuFrame>, String> {
        let CpuFrame {
            scene,
            camera,
            knobs,
            settings,
            cpu,
            still,
        } = *view;
        if knobs.paths {
            return Err(
                "no GPU half in path tracing: chapter 10's shader traces chapters 1–5 \
                        (press 1–5)"
                    .into(),
            );
        }
        // Checked before any device is made: a refusal needs no GPU.
        scene_buffer::pack(scene, camera, settings, knobs.like.features()).map_err(
            |PackError::PerPixelPattern(pattern)| {
                format!(
                    "no GPU half at {} rays/px: {pattern} points differ in every pixel, the \
                     shader takes one set",
                    settings.sampling.spp()
                )
            },
        )?;
        if !still {
            return Ok(None);
        }
        let gpu = match self
            .device
            .get_or_insert_with(|| Gpu::new().map_err(|e| format!("no GPU half: {e}")))
        {
            Ok(gpu) => gpu,
            Err(why) => return Err(why.clone()),
        };
        let tracer = match self.tracers.entry(settings.max_depth) {
            Entry::Occupied(entry) => entry.into_mut(),
            Entry::Vacant(entry) => entry.insert(
                gpu.compile(&Source::built_in(), settings.max_depth)
                    .map_err(|e| format!("no GPU half: {e}"))?,
            ),
        };
        let view = (scene.clone(), *camera);
        let framed = render_image(gpu, tracer, knobs.like, settings, &view, false)
            .map_err(|e| format!("no GPU half: {e}"))?;
        let image = framed.rendered.srgb;
        if image.dimensions() != cpu.dimensions() {
            return Err("no GPU half: the shader's image is not the CPU's size".into());
        }
        let agreement = compare(&image, cpu);
        Ok(Some(GpuFrame {
            image,
            time: framed.dispatch + framed.readback,
            agreement,
        }))
    }
}

/// The view split down the middle: the CPU's left half, the GPU's right.
/// Both images are the whole view, so the seam shows where they differ.
pub fn split(cpu: &RgbImage, gpu: &RgbImage) -> RgbImage {
    let mut frame = cpu.clone();
    let half = cpu.width() / 2;
    for (x, y, pixel) in frame.enumerate_pixels_mut() {
        if x >= half
            && let Some(theirs) = gpu.get_pixel_checked(x, y)
        {
            *pixel = *theirs;
        }
    }
    frame
}

#[cfg(test)]
mod tests {
    use super::*;
    use image::Rgb;

    #[test]
    fn the_split_frame_is_the_cpu_image_left_of_the_middle_and_the_gpu_image_right_of_it() {
        let cpu = RgbImage::from_pixel(5, 2, Rgb([1, 1, 1]));
        let gpu = RgbImage::from_pixel(5, 2, Rgb([9, 9, 9]));
        let frame = split(&cpu, &gpu);
        let row: Vec<u8> = (0..5).map(|x| frame.get_pixel(x, 1)[0]).collect();
        assert_eq!(row, [1, 1, 9, 9, 9]);
    }

    #[test]
    fn path_tracing_and_per_pixel_patterns_are_refused_before_any_device_is_made() {
        let mut half = GpuHalf::default();
        let (scene, camera) = (Scene::lab(), Camera::lab());
        let cpu = RgbImage::new(8, 6);
        let knobs = Knobs {
            spp: 16,
            ..Knobs::default()
        };
        let settings = knobs.whitted(8, 6, 16).unwrap();
        let view = |knobs| CpuFrame {
            scene: &scene,
            camera: &camera,
            knobs,
            settings: &settings,
            cpu: &cpu,
            still: true,
        };
        let outcome = half.render(&view(&knobs));
        let Outcome::Refused(why) = outcome else {
            panic!("{outcome:?}")
        };
        assert!(
            why.contains("16 rays/px") && why.contains("jittered"),
            "{why}"
        );
        let mut paths = knobs;
        paths.chapter(6);
        let outcome = half.render(&view(&paths));
        assert!(matches!(&outcome, Outcome::Refused(why) if why.contains("path tracing")));
        assert!(half.device.is_none());
    }
}
