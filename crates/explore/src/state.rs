//! The explorer without its window: inputs turn knobs and move the camera,
//! and each frame renders what they ask for with the fast floor (chapter
//! 7's waves, chapter 8's paths). The window, a `--script` and the tests
//! all drive this one state, so what the tests see is what the window shows.

use std::time::{Duration, Instant};

use ch07_eight_rays::render::render_waves;
use ch08_eight_paths::render_eight;
use image::RgbImage;
use raylab::probe::{self, SampleTree};
use raylab::srgb::EncodeTable;
use raylab::{Camera, Keep, NoProgress, Scene, Vec3};
use raylab_cli::probe_text::{self, Listing};
use rayon::prelude::*;

use crate::gpu::{Comparison, CpuFrame};
use crate::input::{Button, Input, Key};
use crate::knobs::Knobs;
use crate::orbit::View;
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

/// How far the current image has come.
#[derive(Clone, Debug, PartialEq)]
enum Progress {
    /// Something changed: the image is out of date.
    Stale,
    /// One ray per pixel, drawn while the camera moves.
    Preview,
    /// The Whitted frame at the chosen rays per pixel: nothing more to do.
    Done,
    /// Path tracing: the sum of every pass's radiance, and the passes.
    Paths { sum: Vec<Vec3>, passes: u32 },
}

#[derive(Clone, Copy, Debug)]
struct Drag {
    button: Button,
    start: (f64, f64),
    last: (f64, f64),
    moved: bool,
}

/// A clicked pixel's ray trees, kept in the scene's space so that they
/// stay put while the camera moves.
#[derive(Clone, Debug)]
pub struct Probe {
    pub pixel: (u32, u32),
    /// The camera the pixel was clicked through.
    pub camera: Camera,
    pub trees: Vec<SampleTree>,
    /// `raylab_cli::probe_text`'s text of the trees.
    pub text: String,
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

/// The explorer's state: scene, knobs, camera, and the frame they make.
pub struct Explorer {
    pub knobs: Knobs,
    pub view: View,
    scene: Scene,
    source: Source,
    width: u32,
    height: u32,
    image: RgbImage,
    progress: Progress,
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
}

impl Explorer {
    /// An explorer of `loaded` at `width` × `height` (each at least 1).
    pub fn new(loaded: Loaded, width: u32, height: u32) -> Explorer {
        let (width, height) = (width.max(1), height.max(1));
        Explorer {
            knobs: Knobs::default(),
            view: View::new(loaded.camera, loaded.target),
            scene: loaded.scene,
            source: loaded.source,
            width,
            height,
            image: RgbImage::new(width, height),
            progress: Progress::Stale,
            camera_moved: false,
            drag: None,
            pointer: (0.0, 0.0),
            probe: None,
            status: None,
            messages: Vec::new(),
            stats: Stats::default(),
            hidden: false,
            gpu: Comparison::default(),
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
            Progress::Stale => 0,
            Progress::Preview => 1,
            Progress::Done => self.knobs.spp,
            Progress::Paths { passes, .. } => *passes,
        };
        (done, self.knobs.spp)
    }

    /// Whether the image has reached what the knobs ask for.
    pub fn is_settled(&self) -> bool {
        match &self.progress {
            Progress::Done => true,
            Progress::Paths { passes, .. } => *passes >= self.knobs.spp,
            _ => false,
        }
    }

    /// Whether a frame now would draw anything new.
    pub fn wants_frame(&self) -> bool {
        // A preview held still with the button down waits for the release.
        let waiting =
            self.progress == Progress::Preview && self.drag.is_some() && !self.camera_moved;
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
        self.progress = Progress::Stale;
    }

    fn knobs_changed(&mut self) {
        self.progress = Progress::Stale;
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
        self.scene = loaded.scene;
        self.source = loaded.source;
        self.view.set_home(loaded.camera, loaded.target);
        self.probe = None;
        self.status = None;
        self.progress = Progress::Stale;
    }

    /// Render one frame if there is anything new to draw; whether it did.
    pub fn frame(&mut self) -> bool {
        if !self.wants_frame() {
            return false;
        }
        if self.is_settled() {
            // Only the GPU's half is missing.
            self.compare_on_gpu();
            return true;
        }
        let moving = std::mem::take(&mut self.camera_moved) || self.drag.is_some_and(|d| d.moved);
        let start = Instant::now();
        let rays = if self.knobs.paths {
            self.path_pass(moving)
        } else {
            self.whitted(moving)
        };
        match rays {
            Ok(rays) => {
                self.stats = Stats {
                    frame: start.elapsed(),
                    rays,
                };
                self.compare_on_gpu();
                true
            }
            Err(error) => {
                self.status = Some(error);
                self.progress = Progress::Done;
                false
            }
        }
    }

    /// With `g` on, the frame just rendered again by chapter 10's shader,
    /// with the same settings. A new reason why it cannot be is printed in
    /// the terminal too, where it is not cut to the window's width.
    fn compare_on_gpu(&mut self) {
        if !self.gpu.is_on() {
            return;
        }
        let before = self.gpu.refusal().map(str::to_owned);
        let camera = self.camera();
        let (done, _) = self.samples();
        match self.knobs.whitted(self.width, self.height, done.max(1)) {
            // A GPU frame takes seconds on a CPU's Vulkan driver: it is
            // rendered for the finished view, not for every preview and
            // refinement on the way, so the window stays live.
            Ok(settings) => self.gpu.render(&CpuFrame {
                scene: &self.scene,
                camera: &camera,
                knobs: &self.knobs,
                settings: &settings,
                cpu: &self.image,
                still: self.is_settled(),
            }),
            Err(error) => self.gpu.refuse(format!("no GPU half: {error}")),
        }
        if let Some(why) = self.gpu.refusal()
            && before.as_deref() != Some(why)
        {
            self.messages.push(why.to_owned());
        }
    }

    /// Render until the image is what the knobs ask for (at most `limit`
    /// frames): a still frame.
    pub fn settle(&mut self, limit: u32) {
        self.camera_moved = false;
        for _ in 0..limit {
            if !self.frame() {
                break;
            }
        }
    }

    /// A Whitted frame: one ray per pixel while the camera moves, else the
    /// chosen count, in one render, exactly as the chapter renders it.
    fn whitted(&mut self, moving: bool) -> Result<u64, String> {
        let preview = moving && self.knobs.spp > 1;
        let spp = if preview { 1 } else { self.knobs.spp };
        let settings = self
            .knobs
            .whitted(self.width, self.height, spp)
            .map_err(|e| e.to_string())?;
        let step = self.knobs.step();
        let rendered = render_waves(
            &self.scene,
            &self.camera(),
            &step,
            &settings,
            Keep::IMAGE,
            &NoProgress,
        );
        self.image = rendered.srgb;
        self.progress = if preview {
            Progress::Preview
        } else {
            Progress::Done
        };
        Ok(rendered.counts.total())
    }

    /// One more path per pixel, averaged into the image; a moving camera
    /// starts the average again.
    fn path_pass(&mut self, moving: bool) -> Result<u64, String> {
        let pixels = (self.width * self.height) as usize;
        let (mut sum, passes) = match std::mem::replace(&mut self.progress, Progress::Stale) {
            Progress::Paths { sum, passes } if !moving && sum.len() == pixels => (sum, passes),
            _ => (vec![Vec3::ZERO; pixels], 0),
        };
        let settings = self
            .knobs
            .path_pass(self.width, self.height, passes)
            .map_err(|e| e.to_string())?;
        let render = render_eight(&self.scene, &self.camera(), &settings, &NoProgress);
        let passes = passes + 1;
        let scale = 1.0 / passes as f32;
        let table = EncodeTable::get();
        sum.par_iter_mut()
            .zip(render.image.pixels().par_iter())
            .zip(self.image.par_chunks_mut(3))
            .for_each(|((total, &new), out)| {
                *total += new;
                // One pass is chapter 8's own image: `x * 1.0` is `x`.
                out.copy_from_slice(&table.encode_rgb(*total * scale));
            });
        self.progress = Progress::Paths { sum, passes };
        Ok(render.rays)
    }

    /// The scene as the window shows it, without the overlay: the image,
    /// or with `g` on, its left half beside the GPU's right half.
    pub fn scene_frame(&self) -> RgbImage {
        match self.gpu.frame(self.image.dimensions()) {
            Some(gpu) => crate::gpu::split(&self.image, &gpu.image),
            None => self.image.clone(),
        }
    }

    /// The frame the window shows: the scene, the clicked pixel's ray
    /// tree in 3D, and the overlay.
    pub fn compose(&self) -> RgbImage {
        let mut frame = self.scene_frame();
        crate::overlay::draw_seam(&mut frame, self);
        let Some(probe) = &self.probe else {
            crate::overlay::draw_on(&mut frame, self);
            return frame;
        };
        // The tree may cross the whole frame: draw everything on a canvas.
        let mut canvas = raylab_plot::Canvas::new(self.width, self.height, [0, 0, 0]);
        canvas.draw_rgb_image(&frame, 0, 0, 1);
        crate::tree3d::draw(&mut canvas, &self.camera(), probe);
        crate::overlay::draw(&mut canvas, self);
        canvas.to_rgb_image()
    }
}
