//! The render worker: the window's event loop answers a key while a frame
//! renders, and only the latest view's frame is rendered and shown.
//!
//! The event loop's code path is [`Live`], the window without its
//! window; the renderer is a stand-in that holds each job until the test
//! lets it go, as slow as the test wants and never slower than it knows.

use std::collections::VecDeque;
use std::sync::mpsc::{Receiver, Sender, channel};
use std::time::{Duration, Instant};

use raylab_explore::driver::Driver;
use raylab_explore::live::{Live, Turn};
use raylab_explore::overlay::status_lines;
use raylab_explore::render::{Frame, Job, Render, Renderer};
use raylab_explore::source::Loaded;
use raylab_explore::worker::Worker;
use raylab_explore::{Explorer, Input, Key};

const W: u32 = 64;
const H: u32 = 48;
/// The window's own size, where the overlay's lines are not cut short.
const WINDOW: (u32, u32) = (640, 480);
/// Longer than any wait below can take on a loaded machine: a test that
/// reaches it has found a worker that does not answer.
const PATIENCE: Duration = Duration::from_secs(30);

/// The explorer's own renderer, behind a gate: it says which job it has
/// started, and renders it only once the test sends a go.
struct Gated {
    started: Sender<u64>,
    go: Receiver<()>,
    renderer: Renderer,
}

impl Render for Gated {
    fn render(&mut self, job: Job) -> Frame {
        let _ = self.started.send(job.generation);
        let _ = self.go.recv_timeout(PATIENCE);
        self.renderer.render(job)
    }
}

/// A learner's run (no script, no counted frames) on a gated worker.
fn gated_live((width, height): (u32, u32)) -> (Live, Receiver<u64>, Sender<()>) {
    let (started, started_rx) = channel();
    let (go, go_rx) = channel();
    let renderer = Gated {
        started,
        go: go_rx,
        renderer: Renderer::default(),
    };
    let worker = Worker::spawn(renderer, || {}).unwrap();
    let explorer = Explorer::new(Loaded::lab(), width, height);
    let driver = Driver::new(VecDeque::new(), std::env::temp_dir());
    (Live::new(explorer, driver, worker, None), started_rx, go)
}

fn press(live: &mut Live, c: char) {
    assert!(!live.input(Input::Key(Key::Char(c))));
}

/// Take frames as the window does when the worker wakes it, until one is
/// taken.
fn wait_for_frame(live: &mut Live) {
    let start = Instant::now();
    while !live.frame_ready() {
        assert!(start.elapsed() < PATIENCE, "no frame from the worker");
        std::thread::sleep(Duration::from_millis(5));
    }
}

#[test]
fn a_key_is_answered_within_50_ms_while_a_frame_renders() {
    let (mut live, started, _go) = gated_live(WINDOW);
    assert_eq!(live.turn().unwrap(), Turn::Wait);
    // The first frame is on the worker, and stays there.
    assert_eq!(started.recv_timeout(PATIENCE), Ok(0));
    let epsilon = live.explorer.knobs.epsilon;
    let lines = status_lines(&live.explorer);
    let shown = live.explorer.compose();

    // The event loop's answer to a key: the input, the turn after it
    // (which sends the new view's job), and the overlay's new lines. The
    // clock runs over this code path only, not over a window's redraw.
    let start = Instant::now();
    press(&mut live, 'e');
    live.turn().unwrap();
    let new_lines = status_lines(&live.explorer);
    let answered = start.elapsed();

    assert_ne!(live.explorer.knobs.epsilon, epsilon);
    assert_ne!(new_lines, lines, "the overlay shows the new ε");
    assert!(
        live.explorer.compose() != shown,
        "the frame shown has the new overlay"
    );
    assert!(
        live.explorer.is_waiting(),
        "the new view's frame is still to come"
    );
    assert!(
        answered < Duration::from_millis(50),
        "the key took {answered:?} while a frame rendered"
    );
}

#[test]
fn only_the_latest_view_is_rendered_and_an_older_frame_is_never_shown() {
    let (mut live, started, go) = gated_live((W, H));
    live.turn().unwrap();
    assert_eq!(started.recv_timeout(PATIENCE), Ok(0));
    press(&mut live, 'e');
    // The first frame finishes for a view that is gone; the worker starts
    // the new view's (generation 1) and holds it.
    go.send(()).unwrap();
    assert_eq!(started.recv_timeout(PATIENCE), Ok(1));
    assert!(!live.frame_ready(), "generation 0's frame is dropped");
    assert!(*live.explorer.image() == image::RgbImage::new(W, H));

    // Two more changes while generation 1 renders: the job for the first
    // is replaced by the second's before the worker is free.
    press(&mut live, 'r');
    press(&mut live, ']');
    go.send(()).unwrap();
    assert_eq!(started.recv_timeout(PATIENCE), Ok(3));
    go.send(()).unwrap();
    wait_for_frame(&mut live);
    assert_eq!(live.explorer.generation(), 3);
    assert!(live.explorer.is_settled());

    // The frame taken is the one the explorer renders itself for the same keys.
    let mut alone = Explorer::new(Loaded::lab(), W, H);
    for c in ['e', 'r', ']'] {
        alone.handle(Input::Key(Key::Char(c)));
    }
    alone.settle(10);
    assert!(*live.explorer.image() == *alone.image());
    assert_eq!(live.explorer.samples(), alone.samples());
}
