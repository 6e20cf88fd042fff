//! The window: winit's events into the explorer's inputs, the explorer's
//! frames onto the screen through softbuffer, and the scene file's watch
//! and the script polled between frames.

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

use crate::driver::{Driver, Tick, act, frame_summary, print_messages, write_shot};
use crate::input::{Button, Input, Key};
use crate::state::Explorer;
use crate::watch::SceneWatch;

/// How often an idle explorer wakes to look at the scene file.
const IDLE_WAKE: Duration = Duration::from_millis(50);

type Surface = softbuffer::Surface<Rc<Window>, Rc<Window>>;

/// What the window run is asked for besides the explorer.
pub struct Run {
    pub driver: Driver,
    pub watch: Option<SceneWatch>,
    /// Quit once the script is done and this many frames were shown.
    pub frames: Option<u32>,
    /// Where to write the last frame shown, on quitting.
    pub screenshot: Option<PathBuf>,
}

struct App {
    explorer: Explorer,
    run: Run,
    window: Option<(Rc<Window>, Surface)>,
    pointer: (f64, f64),
    shown: u32,
    /// The frame last put on the screen.
    last: Option<RgbImage>,
    times: Vec<Duration>,
    error: Option<String>,
    redraw: bool,
}

/// Open the window and run until it is closed; the error is one line.
pub fn run(explorer: Explorer, run: Run) -> Result<String, String> {
    if std::env::var_os("DISPLAY").is_none_or(|d| d.is_empty()) {
        return Err(
            "no display: DISPLAY is not set (run it on a desktop, under xvfb-run, or with --headless)"
                .into(),
        );
    }
    let event_loop = EventLoop::new().map_err(|e| {
        // winit's message starts with the source line it came from.
        let text = e.to_string();
        let reason = text.rsplit(": ").next().unwrap_or(&text).to_owned();
        let display = std::env::var("DISPLAY").unwrap_or_default();
        format!("cannot open the display '{display}': {reason}")
    })?;
    let mut app = App {
        explorer,
        run,
        window: None,
        pointer: (0.0, 0.0),
        shown: 0,
        last: None,
        times: Vec::new(),
        error: None,
        redraw: true,
    };
    event_loop
        .run_app(&mut app)
        .map_err(|e| format!("the window's event loop failed: {e}"))?;
    if let Some(error) = app.error {
        return Err(error);
    }
    if let (Some(path), Some(frame)) = (&app.run.screenshot, &app.last) {
        raylab_cli::output::save_png(frame, path).map_err(|e| e.to_string())?;
    } else if let Some(path) = &app.run.screenshot {
        write_shot(&app.explorer, path)?;
    }
    Ok(format!(
        "{}, {} shown",
        frame_summary(&app.times),
        app.shown
    ))
}

impl App {
    fn open(&mut self, event_loop: &ActiveEventLoop) -> Result<(), String> {
        let (width, height) = self.explorer.size();
        let attributes = Window::default_attributes()
            .with_title("raylab explorer")
            .with_inner_size(PhysicalSize::new(width, height));
        let window = Rc::new(
            event_loop
                .create_window(attributes)
                .map_err(|e| format!("cannot open a window: {e}"))?,
        );
        let context = softbuffer::Context::new(Rc::clone(&window))
            .map_err(|e| format!("cannot draw into the window: {e}"))?;
        let surface = softbuffer::Surface::new(&context, Rc::clone(&window))
            .map_err(|e| format!("cannot draw into the window: {e}"))?;
        self.window = Some((window, surface));
        Ok(())
    }

    fn fail(&mut self, event_loop: &ActiveEventLoop, error: String) {
        self.error = Some(error);
        event_loop.exit();
    }

    fn input(&mut self, event_loop: &ActiveEventLoop, input: Input) {
        let action = self.explorer.handle(input);
        if act(&mut self.explorer, action, &self.run.driver.out_dir) {
            event_loop.exit();
        }
        print_messages(&mut self.explorer);
        self.redraw = true;
    }

    /// Put the explorer's frame on the screen.
    fn present(&mut self) -> Result<(), String> {
        let Some((window, surface)) = &mut self.window else {
            return Ok(());
        };
        let size = window.inner_size();
        let (Some(width), Some(height)) =
            (NonZeroU32::new(size.width), NonZeroU32::new(size.height))
        else {
            // Minimised or sized to nothing: there is nothing to draw on.
            return Ok(());
        };
        let fail = |e: softbuffer::SoftBufferError| format!("cannot draw into the window: {e}");
        surface.resize(width, height).map_err(fail)?;
        let frame = self.explorer.compose();
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
        self.shown += 1;
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

impl ApplicationHandler for App {
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

    fn about_to_wait(&mut self, event_loop: &ActiveEventLoop) {
        if let Some(watch) = &mut self.run.watch
            && watch.poll(&mut self.explorer)
        {
            self.redraw = true;
        }
        if !self.run.driver.is_done() {
            match self.run.driver.tick(&mut self.explorer) {
                Ok(Tick::Quit) => event_loop.exit(),
                Ok(_) => {}
                Err(error) => return self.fail(event_loop, error),
            }
            print_messages(&mut self.explorer);
            self.redraw = true;
        }
        if self.explorer.frame() {
            self.times.push(self.explorer.stats().frame);
            print_messages(&mut self.explorer);
            self.redraw = true;
        }
        // A counted run shows a frame every turn, so that it ends.
        self.redraw |= self.run.frames.is_some();
        if let Some((window, _)) = &self.window
            && std::mem::take(&mut self.redraw)
        {
            window.request_redraw();
        }
        let done = self.run.driver.is_done();
        if done && self.run.frames.is_some_and(|n| self.shown >= n) {
            event_loop.exit();
        }
        let busy = self.explorer.wants_frame()
            || !done
            || self.run.watch.as_ref().is_some_and(|w| w.pending())
            || self.run.frames.is_some();
        event_loop.set_control_flow(if busy {
            ControlFlow::Poll
        } else {
            ControlFlow::WaitUntil(Instant::now() + IDLE_WAKE)
        });
    }
}
