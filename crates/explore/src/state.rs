//! The explorer without its window: inputs turn knobs and move the camera,
//! and each frame renders what they ask for with the fast floor (chapter
//! 7's waves, chapter 8's paths). The window, a `--script` and the tests
//! all drive this one state, so what the tests see is what the window shows.
//!
//! A frame is asked for as a [`Job`] and taken as a [`Frame`]
//! ([`crate::render`]): [`Explorer::frame`] renders the job here and now,
//! the window hands it to its render worker and takes the frame when it
//! is ready. Every change to what is rendered counts one more generation,
//! and a frame of an older generation is dropped.

use std::sync::Arc;

use image::RgbImage;
use raylab::probe;
use raylab::sampling::SamplingError;
use raylab::{Camera, Scene, Vec3};
use raylab_cli::probe_text::{self, Listing};

use crate::gpu::Comparison;
use crate::input::{Button, Input, Key};
use crate::knobs::Knobs;
use crate::orbit::View;
use crate::probe::Probe;
pub use crate::render::Stats;
use crate::render::{CpuJob, Frame, GpuJob, Job, Refinement, Render, Renderer};
use crate::source::{Loaded, Source};

/// Degrees the orbit turns per pixel dragged.
const TURN_PER_PIXEL: f32 = 0.3;
/// Degrees the arrow keys turn the orbit.
const TURN_PER_KEY: f32 = 5.0;
/// A press and release closer than this (pixels) is a click, not a drag.
const CLICK_SLOP: f64 = 3.0;

/// What the runner must do after an input.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Action {
    None,
    Save,
    Quit,
}

#[derive(Clone, Copy, Debug)]
struct Drag {
    button: Button,
    start: (f64, f64),
    last: (f64, f64),
    moved: bool,
}

/// The explorer's state: scene, knobs, camera, and the frame they make.
pub struct Explorer {
    pub knobs: Knobs,
    pub view: View,
    scene: Arc<Scene>,
    source: Source,
    width: u32,
    height: u32,
    image: RgbImage,
    progress: Refinement,
    camera_moved: bool,
    drag: Option<Drag>,
    pointer: (f64, f64),
    probe: Option<Probe>,
    /// One line the overlay shows: the last error or what was just done.
    status: Option<String>,
    /// Lines for the terminal (the probe's text, saved files), taken by
    /// the runner.
    messages: Vec<String>,
    stats: Stats,
    /// Minimised, or sized to nothing: no frame is rendered.
    hidden: bool,
    /// `g`: the same view from chapter 10's shader, beside this one.
    gpu: Comparison,
    /// How many changes to what is rendered there have been.
    generation: u64,
    /// The generation of the last job asked for and not yet taken.
    asked: Option<u64>,
    /// The renderer [`Explorer::frame`] renders with, on this thread.
    renderer: Renderer,
}

impl Explorer {
    /// An explorer of `loaded` at `width` × `height` (each at least 1).
    pub fn new(loaded: Loaded, width: u32, height: u32) -> Explorer {
        let (width, height) = (width.max(1), height.max(1));
        Explorer {
            knobs: Knobs::default(),
            view: View::new(loaded.camera, loaded.target),
            scene: Arc::new(loaded.scene),
            source: loaded.source,
            width,
            height,
            image: RgbImage::new(width, height),
            progress: Refinement::Stale,
            camera_moved: false,
            drag: None,
            pointer: (0.0, 0.0),
            probe: None,
            status: None,
            messages: Vec::new(),
            stats: Stats::default(),
            hidden: false,
            gpu: Comparison::default(),
            generation: 0,
            asked: None,
            renderer: Renderer::default(),
        }
    }

    pub fn size(&self) -> (u32, u32) {
        (self.width, self.height)
    }

    pub fn scene(&self) -> &Scene {
        &self.scene
    }

    pub fn source(&self) -> &Source {
        &self.source
    }

    pub fn camera(&self) -> Camera {
        self.view.camera()
    }

    /// The scene as last rendered, without the overlay.
    pub fn image(&self) -> &RgbImage {
        &self.image
    }

    /// The GPU comparison (`g`).
    pub fn gpu(&self) -> &Comparison {
        &self.gpu
    }

    pub fn probe(&self) -> Option<&Probe> {
        self.probe.as_ref()
    }

    pub fn status(&self) -> Option<&str> {
        self.status.as_deref()
    }

    pub fn set_status(&mut self, line: impl Into<String>) {
        self.status = Some(line.into());
    }

    pub fn stats(&self) -> Stats {
        self.stats
    }

    /// A line for the terminal.
    pub fn say(&mut self, line: impl Into<String>) {
        self.messages.push(line.into());
    }

    pub fn take_messages(&mut self) -> Vec<String> {
        std::mem::take(&mut self.messages)
    }

    /// Rays (or paths) per pixel in the image now, and the count asked for.
    pub fn samples(&self) -> (u32, u32) {
        let done = match &self.progress {
            Refinement::Stale => 0,
            Refinement::Preview => 1,
            Refinement::Done => self.knobs.spp,
            Refinement::Paths { passes, .. } => *passes,
        };
        (done, self.knobs.spp)
    }

    /// Whether the image has reached what the knobs ask for.
    pub fn is_settled(&self) -> bool {
        match &self.progress {
            Refinement::Done => true,
            Refinement::Paths { passes, .. } => *passes >= self.knobs.spp,
            _ => false,
        }
    }

    /// Whether a frame now would draw anything new.
    pub fn wants_frame(&self) -> bool {
        // A preview held still with the button down waits for the release.
        let waiting =
            self.progress == Refinement::Preview && self.drag.is_some() && !self.camera_moved;
        let settled = self.is_settled() && !self.gpu.is_pending();
        !(self.hidden || settled || waiting)
    }

    /// Take one input; the runner does what the returned action asks.
    pub fn handle(&mut self, input: Input) -> Action {
        match input {
            Input::Key(key) => return self.key(key),
            Input::Press { button, x, y } => {
                self.pointer = (x, y);
                self.drag = Some(Drag {
                    button,
                    start: (x, y),
                    last: (x, y),
                    moved: false,
                });
            }
            Input::Move { x, y } => {
                self.pointer = (x, y);
                if let Some(mut drag) = self.drag {
                    let (dx, dy) = (x - drag.last.0, y - drag.last.1);
                    let far = (x - drag.start.0).hypot(y - drag.start.1) > CLICK_SLOP;
                    if drag.moved || far {
                        drag.moved = true;
                        drag.last = (x, y);
                        self.drag = Some(drag);
                        self.drag_by(drag.button, dx as f32, dy as f32);
                    }
                }
            }
            Input::Release { button, x, y } => {
                self.pointer = (x, y);
                if let Some(drag) = self.drag.take()
                    && !drag.moved
                    && button == Button::Left
                {
                    self.click(x, y);
                }
            }
            Input::Wheel(steps) => {
                self.view.orbit_mut().zoom(steps);
                self.camera_changed();
            }
            Input::Resize { width, height } => self.resize(width, height),
        }
        Action::None
    }

    fn key(&mut self, key: Key) -> Action {
        let knobs = &mut self.knobs;
        match key {
            Key::Char(c @ '1'..='6') => {
                knobs.chapter(c.to_digit(10).unwrap_or(5));
            }
            Key::Up => knobs.deeper(1),
            Key::Down => knobs.deeper(-1),
            Key::Char('r') => knobs.step_spp(true),
            Key::Char('R') => knobs.step_spp(false),
            Key::Char('e') => knobs.toggle_epsilon(),
            Key::Char(']') => knobs.step_sun(true),
            Key::Char('[') => knobs.step_sun(false),
            Key::Char('m') => knobs.toggle_materials(),
            Key::Char('g') => {
                // The CPU's image stays: the next frame adds the GPU's.
                self.gpu.toggle();
                self.generation += 1;
                return Action::None;
            }
            Key::Char('?' | 'h') => {
                knobs.help = !knobs.help;
                return Action::None;
            }
            Key::Escape => {
                if knobs.help {
                    knobs.help = false;
                } else {
                    self.probe = None;
                }
                return Action::None;
            }
            Key::Char('c') | Key::Home => {
                self.view.reset();
                self.camera_changed();
                return Action::None;
            }
            Key::Left | Key::Right => {
                let yaw = if key == Key::Left {
                    -TURN_PER_KEY
                } else {
                    TURN_PER_KEY
                };
                self.view.orbit_mut().turn(yaw, 0.0);
                self.camera_changed();
                return Action::None;
            }
            Key::Char('+' | '=') => {
                self.view.orbit_mut().zoom(1.0);
                self.camera_changed();
                return Action::None;
            }
            Key::Char('-') => {
                self.view.orbit_mut().zoom(-1.0);
                self.camera_changed();
                return Action::None;
            }
            Key::Char('w') => return Action::Save,
            Key::Char('q') => return Action::Quit,
            Key::Char(_) => return Action::None,
        }
        self.knobs_changed();
        Action::None
    }

    fn drag_by(&mut self, button: Button, dx: f32, dy: f32) {
        let camera = self.camera();
        let height = self.height as f32;
        let orbit = self.view.orbit_mut();
        match button {
            Button::Left => orbit.turn(dx * TURN_PER_PIXEL, dy * TURN_PER_PIXEL),
            Button::Right => orbit.pan(&camera, -dx / height, dy / height),
        }
        self.camera_changed();
    }

    fn camera_changed(&mut self) {
        self.camera_moved = true;
        self.progress = Refinement::Stale;
        self.generation += 1;
    }

    fn knobs_changed(&mut self) {
        self.progress = Refinement::Stale;
        self.generation += 1;
        if let Some(probe) = &self.probe {
            let (pixel, camera) = (probe.pixel, probe.camera);
            self.probe = Some(self.probe_pixel(pixel, camera));
        }
    }

    fn resize(&mut self, width: u32, height: u32) {
        self.hidden = width == 0 || height == 0;
        if self.hidden || (width, height) == (self.width, self.height) {
            return;
        }
        if u64::from(width) * u64::from(height) > raylab_cli::MAX_PIXELS {
            self.status = Some(format!("{width}×{height} is too many pixels to trace"));
            self.hidden = true;
            return;
        }
        self.width = width;
        self.height = height;
        self.image = RgbImage::new(width, height);
        // A ray tree belongs to the pixel grid it was clicked on.
        self.probe = None;
        self.camera_changed();
    }

    /// Probe the pixel under a click, if the click is on the image.
    fn click(&mut self, x: f64, y: f64) {
        let inside =
            x >= 0.0 && y >= 0.0 && x < f64::from(self.width) && y < f64::from(self.height);
        if !inside {
            self.status = Some(format!(
                "the click at {x:.0},{y:.0} is outside the {}×{} image",
                self.width, self.height
            ));
            return;
        }
        let probe = self.probe_pixel((x as u32, y as u32), self.camera());
        self.messages.push(probe.text.clone());
        self.probe = Some(probe);
    }

    fn probe_pixel(&self, pixel: (u32, u32), camera: Camera) -> Probe {
        // Path tracing has no ray tree: a click there shows the tree of
        // the Whitted chapter chosen last, at that chapter's rays per
        // pixel (not the hundreds of paths per pixel asked for).
        let spp = if self.knobs.paths {
            self.knobs.like.defaults().spp
        } else {
            self.knobs.spp
        };
        let trees = match self.knobs.whitted(self.width, self.height, spp) {
            Ok(settings) => {
                probe::probe(&self.scene, &camera, &self.knobs.step(), &settings, pixel)
            }
            Err(_) => Vec::new(),
        };
        let text = probe_text::format_tree(&self.scene, pixel, &trees, Listing::Folded);
        Probe {
            pixel,
            camera,
            trees,
            text,
        }
    }

    /// Take the scene from a new load of its file (a save in the editor):
    /// the camera follows the file's unless the learner has moved it.
    pub fn replace_scene(&mut self, loaded: Loaded) {
        self.scene = Arc::new(loaded.scene);
        self.source = loaded.source;
        self.view.set_home(loaded.camera, loaded.target);
        self.probe = None;
        self.status = None;
        self.progress = Refinement::Stale;
        self.generation += 1;
    }

    /// Render one frame here and now if there is anything new to draw;
    /// whether it did.
    pub fn frame(&mut self) -> bool {
        match self.job() {
            Some(job) => {
                let frame = self.renderer.render(job);
                self.take(frame)
            }
            None => false,
        }
    }

    /// How many changes to what is rendered there have been.
    pub fn generation(&self) -> u64 {
        self.generation
    }

    /// Whether a job should be asked for: a frame would draw something
    /// new, and no job for the view as it is now is out.
    pub fn needs_job(&self) -> bool {
        self.wants_frame() && self.asked != Some(self.generation)
    }

    /// Whether a job is out whose frame has not been taken.
    pub fn is_waiting(&self) -> bool {
        self.asked.is_some()
    }

    /// The next frame to render, if there is anything new to draw: the
    /// view and knobs as they are now. A moving camera's frame is a
    /// one-ray preview.
    pub fn job(&mut self) -> Option<Job> {
        if !self.wants_frame() {
            return None;
        }
        let cpu = if self.is_settled() {
            // Only the GPU's half is missing.
            None
        } else {
            let moving =
                std::mem::take(&mut self.camera_moved) || self.drag.is_some_and(|d| d.moved);
            match self.cpu_job(moving) {
                Ok(job) => Some(job),
                Err(error) => {
                    self.status = Some(error.to_string());
                    self.progress = Refinement::Done;
                    return None;
                }
            }
        };
        let gpu = self.gpu.is_on().then(|| self.gpu_job(cpu.as_ref()));
        self.asked = Some(self.generation);
        Some(Job {
            generation: self.generation,
            scene: Arc::clone(&self.scene),
            camera: self.camera(),
            knobs: self.knobs,
            cpu,
            gpu,
        })
    }

    /// A Whitted frame: one ray per pixel while the camera moves, else the
    /// chosen count, in one render, exactly as the chapter renders it. Or
    /// one more path per pixel, averaged into the image; a moving camera
    /// starts the average again.
    fn cpu_job(&self, moving: bool) -> Result<CpuJob, SamplingError> {
        if !self.knobs.paths {
            let preview = moving && self.knobs.spp > 1;
            let spp = if preview { 1 } else { self.knobs.spp };
            let settings = self.knobs.whitted(self.width, self.height, spp)?;
            return Ok(CpuJob::Whitted { settings, preview });
        }
        let pixels = (self.width * self.height) as usize;
        let (sum, passes) = match &self.progress {
            Refinement::Paths { sum, passes } if !moving && sum.len() == pixels => {
                (sum.clone(), *passes)
            }
            _ => (vec![Vec3::ZERO; pixels], 0),
        };
        let settings = self.knobs.path_pass(self.width, self.height, passes)?;
        Ok(CpuJob::Paths {
            settings,
            sum,
            passes,
        })
    }

    /// With `g` on, the frame the CPU's part leaves rendered again by
    /// chapter 10's shader, with the same settings. A GPU frame takes
    /// seconds on a CPU's Vulkan driver: it is rendered for the finished
    /// view, not for every preview and refinement on the way.
    fn gpu_job(&self, cpu: Option<&CpuJob>) -> GpuJob {
        let (done, still) = match cpu {
            Some(CpuJob::Whitted { preview, .. }) => {
                (if *preview { 1 } else { self.knobs.spp }, !preview)
            }
            Some(CpuJob::Paths { passes, .. }) => (passes + 1, passes + 1 >= self.knobs.spp),
            None => (self.samples().0, self.is_settled()),
        };
        GpuJob {
            settings: self
                .knobs
                .whitted(self.width, self.height, done.max(1))
                .map_err(|error| format!("no GPU half: {error}")),
            still,
            cpu: cpu.is_none().then(|| self.image.clone()),
        }
    }

    /// Take a rendered frame, unless the view has changed since its job
    /// was asked for, or a frame for this view was taken since (`w`
    /// renders a still frame here and now); whether it was taken. A new
    /// reason why there is no GPU half is printed in the terminal too,
    /// where it is not cut to the window's width.
    pub fn take(&mut self, frame: Frame) -> bool {
        if frame.generation != self.generation || self.asked != Some(frame.generation) {
            return false;
        }
        self.asked = None;
        if let Some(cpu) = frame.cpu {
            self.image = cpu.image;
            self.progress = cpu.progress;
            self.stats = cpu.stats;
        }
        if let Some((outcome, adapter)) = frame.gpu {
            let before = self.gpu.refusal().map(str::to_owned);
            self.gpu.take(outcome, adapter);
            if let Some(why) = self.gpu.refusal()
                && before.as_deref() != Some(why)
            {
                self.messages.push(why.to_owned());
            }
        }
        true
    }

    /// Render until the image is what the knobs ask for (at most `limit`
    /// frames): a still frame.
    pub fn settle(&mut self, limit: u32) {
        self.hold_still();
        for _ in 0..limit {
            if !self.frame() {
                break;
            }
        }
    }

    /// The camera is still from now on: the next frame is not a preview.
    pub fn hold_still(&mut self) {
        self.camera_moved = false;
    }
}
