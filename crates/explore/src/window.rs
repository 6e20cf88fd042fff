//! The window: winit's events into the explorer's inputs, the render
//! worker's frames onto the screen through softbuffer, and the scene
//! file's watch and the script polled between events ([`crate::live`]).

use std::num::NonZeroU32;
use std::path::PathBuf;
use std::rc::Rc;
use std::time::{Duration, Instant};

use image::RgbImage;
use winit::application::ApplicationHandler;
use winit::dpi::PhysicalSize;
use winit::event::{ElementState, MouseButton, MouseScrollDelta, WindowEvent};
use winit::event_loop::{ActiveEventLoop, ControlFlow, EventLoop};
use winit::keyboard::{Key as WinitKey, NamedKey};
use winit::window::{Window, WindowId};

use crate::driver::{Driver, frame_summary, write_shot};
use crate::error::ExploreError;
use crate::input::{Button, Input, Key};
use crate::live::{Live, Turn};
use crate::render::Renderer;
use crate::state::Explorer;
use crate::watch::SceneWatch;
use crate::worker::Worker;

/// How often an idle explorer wakes to look at the scene file.
const IDLE_WAKE: Duration = Duration::from_millis(50);

/// The window's pixels, which the explorer writes on the CPU and shows.
type WindowPixels = softbuffer::Surface<Rc<Window>, Rc<Window>>;

/// What the window run is asked for besides the explorer.
pub struct Run {
    pub driver: Driver,
    pub watch: Option<SceneWatch>,
    /// Quit once the script is done and this many frames were shown.
    pub frames: Option<u32>,
    /// Where to write the last frame shown, on quitting.
    pub screenshot: Option<PathBuf>,
}

/// A frame is ready on the render worker: the event loop wakes for it.
struct FrameReady;

struct App {
    live: Live,
    watch: Option<SceneWatch>,
    screenshot: Option<PathBuf>,
    window: Option<(Rc<Window>, WindowPixels)>,
    pointer: (f64, f64),
    /// The frame last put on the screen.
    last: Option<RgbImage>,
    error: Option<ExploreError>,
    redraw: bool,
}

/// Open the window and run until it is closed; the error is one line.
pub fn run(explorer: Explorer, run: Run) -> Result<String, ExploreError> {
    if std::env::var_os("DISPLAY").is_none_or(|d| d.is_empty()) {
        return Err(ExploreError::NoDisplay);
    }
    let event_loop = EventLoop::<FrameReady>::with_user_event()
        .build()
        .map_err(|e| {
            // winit's message starts with the source line it came from.
            let text = e.to_string();
            let reason = text.rsplit(": ").next().unwrap_or(&text).to_owned();
            let display = std::env::var("DISPLAY").unwrap_or_default();
            ExploreError::Display { display, reason }
        })?;
    let proxy = event_loop.create_proxy();
    let worker = Worker::spawn(Renderer::default(), move || {
        // The loop is gone once the window has closed: nothing to wake.
        let _ = proxy.send_event(FrameReady);
    })?;
    let mut app = App {
        live: Live::new(explorer, run.driver, worker, run.frames),
        watch: run.watch,
        screenshot: run.screenshot,
        window: None,
        pointer: (0.0, 0.0),
        last: None,
        error: None,
        redraw: true,
    };
    event_loop
        .run_app(&mut app)
        .map_err(ExploreError::EventLoop)?;
    if let Some(error) = app.error {
        return Err(error);
    }
    if let (Some(path), Some(frame)) = (&app.screenshot, &app.last) {
        raylab_cli::output::save_png(frame, path)?;
    } else if let Some(path) = &app.screenshot {
        write_shot(&app.live.explorer, path)?;
    }
    Ok(format!(
        "{}, {} shown",
        frame_summary(&app.live.times),
        app.live.shown
    ))
}

impl App {
    fn open(&mut self, event_loop: &ActiveEventLoop) -> Result<(), ExploreError> {
        let (width, height) = self.live.explorer.size();
        let attributes = Window::default_attributes()
            .with_title("raylab explorer")
            .with_inner_size(PhysicalSize::new(width, height));
        let window = Rc::new(
            event_loop
                .create_window(attributes)
                .map_err(ExploreError::Window)?,
        );
        let context = softbuffer::Context::new(Rc::clone(&window)).map_err(ExploreError::Draw)?;
        let surface =
            softbuffer::Surface::new(&context, Rc::clone(&window)).map_err(ExploreError::Draw)?;
        self.window = Some((window, surface));
        Ok(())
    }

    fn fail(&mut self, event_loop: &ActiveEventLoop, error: ExploreError) {
        self.error = Some(error);
        event_loop.exit();
    }

    /// An input is answered at once: the state changes now, and the frame
    /// for it follows from the worker.
    fn input(&mut self, event_loop: &ActiveEventLoop, input: Input) {
        if self.live.input(input) {
            event_loop.exit();
        }
        self.redraw = true;
    }

    /// Put the explorer's frame on the screen.
    fn present(&mut self) -> Result<(), ExploreError> {
        let Some((window, surface)) = &mut self.window else {
            return Ok(());
        };
        let size = window.inner_size();
        let (Some(width), Some(height)) =
            (NonZeroU32::new(size.width), NonZeroU32::new(size.height))
        else {
            // Minimised or sized to nothing: there is nothing to draw on,
            // and a script goes on without showing this turn's frame.
            self.live.skipped();
            return Ok(());
        };
        let fail = ExploreError::Draw;
        surface.resize(width, height).map_err(fail)?;
        let frame = self.live.explorer.compose();
        let mut buffer = surface.buffer_mut().map_err(fail)?;
        let pack =
            |p: &image::Rgb<u8>| u32::from(p[0]) << 16 | u32::from(p[1]) << 8 | u32::from(p[2]);
        if frame.dimensions() == (size.width, size.height) {
            for (out, pixel) in buffer.iter_mut().zip(frame.pixels()) {
                *out = pack(pixel);
            }
        } else {
            // The window is a size the explorer has not rendered yet: copy
            // what overlaps, black elsewhere.
            let (w, h) = (size.width as usize, size.height as usize);
            for (y, row) in buffer.chunks_mut(w).enumerate().take(h) {
                for (x, out) in row.iter_mut().enumerate() {
                    *out = frame.get_pixel_checked(x as u32, y as u32).map_or(0, pack);
                }
            }
        }
        buffer.present().map_err(fail)?;
        self.last = Some(frame);
        self.live.presented();
        Ok(())
    }
}

fn key_of(key: &WinitKey) -> Option<Key> {
    Some(match key {
        WinitKey::Named(NamedKey::ArrowUp) => Key::Up,
        WinitKey::Named(NamedKey::ArrowDown) => Key::Down,
        WinitKey::Named(NamedKey::ArrowLeft) => Key::Left,
        WinitKey::Named(NamedKey::ArrowRight) => Key::Right,
        WinitKey::Named(NamedKey::Home) => Key::Home,
        WinitKey::Named(NamedKey::Escape) => Key::Escape,
        WinitKey::Character(text) => Key::Char(text.chars().next()?),
        _ => return None,
    })
}

impl ApplicationHandler<FrameReady> for App {
    fn resumed(&mut self, event_loop: &ActiveEventLoop) {
        if self.window.is_none()
            && let Err(error) = self.open(event_loop)
        {
            self.fail(event_loop, error);
        }
    }

    fn window_event(&mut self, event_loop: &ActiveEventLoop, _: WindowId, event: WindowEvent) {
        match event {
            WindowEvent::CloseRequested => event_loop.exit(),
            WindowEvent::Resized(size) => self.input(
                event_loop,
                Input::Resize {
                    width: size.width,
                    height: size.height,
                },
            ),
            WindowEvent::KeyboardInput { event, .. } if event.state == ElementState::Pressed => {
                if let Some(key) = key_of(&event.logical_key) {
                    self.input(event_loop, Input::Key(key));
                }
            }
            WindowEvent::CursorMoved { position, .. } => {
                self.pointer = (position.x, position.y);
                self.input(
                    event_loop,
                    Input::Move {
                        x: position.x,
                        y: position.y,
                    },
                );
            }
            WindowEvent::MouseInput { state, button, .. } => {
                let button = match button {
                    MouseButton::Left => Button::Left,
                    MouseButton::Right | MouseButton::Middle => Button::Right,
                    _ => return,
                };
                let (x, y) = self.pointer;
                let input = match state {
                    ElementState::Pressed => Input::Press { button, x, y },
                    ElementState::Released => Input::Release { button, x, y },
                };
                self.input(event_loop, input);
            }
            WindowEvent::MouseWheel { delta, .. } => {
                let steps = match delta {
                    MouseScrollDelta::LineDelta(_, y) => y,
                    MouseScrollDelta::PixelDelta(p) => (p.y / 40.0) as f32,
                };
                self.input(event_loop, Input::Wheel(steps));
            }
            WindowEvent::RedrawRequested => {
                if let Err(error) = self.present() {
                    self.fail(event_loop, error);
                }
            }
            _ => {}
        }
    }

    fn user_event(&mut self, _: &ActiveEventLoop, _: FrameReady) {
        self.redraw |= self.live.frame_ready();
    }

    fn about_to_wait(&mut self, event_loop: &ActiveEventLoop) {
        if let Some(watch) = &mut self.watch
            && watch.poll(&mut self.live.explorer)
        {
            self.redraw = true;
        }
        let turn = match self.live.turn() {
            Ok(turn) => turn,
            Err(error) => return self.fail(event_loop, error),
        };
        if turn == Turn::Quit {
            return event_loop.exit();
        }
        self.redraw |= turn == Turn::Redraw;
        if let Some((window, _)) = &self.window
            && std::mem::take(&mut self.redraw)
        {
            window.request_redraw();
        }
        // The worker wakes the loop when a frame is ready; the file watch
        // is looked at every IDLE_WAKE.
        let busy = turn == Turn::Redraw || self.watch.as_ref().is_some_and(|w| w.pending());
        event_loop.set_control_flow(if busy {
            ControlFlow::Poll
        } else {
            ControlFlow::WaitUntil(Instant::now() + IDLE_WAKE)
        });
    }
}
