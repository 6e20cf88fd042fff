//! The window's event loop without the window: inputs go straight to the
//! explorer, frames are rendered by the [`Worker`], and the script is
//! played between them. [`crate::window`] calls these from winit's
//! events; the tests call them with no screen.
//!
//! Two rhythms. A learner's run never waits for a render: an input
//! changes the state at once (the overlay shows it on the next redraw),
//! and the frame for the new view follows when the worker has it. A
//! scripted or counted run (`--script`, `--frames`) goes in lock-step:
//! each turn plays the script's next input, renders its frame and shows
//! it, exactly as `--headless` does, so the frame it ends on is the same
//! whatever the machine's speed.

use std::time::Duration;

use crate::driver::{Driver, SETTLE_LIMIT, Tick, act, print_messages};
use crate::error::ExploreError;
use crate::input::Input;
use crate::state::Explorer;
use crate::worker::Worker;

/// What the window does after a turn.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Turn {
    /// Wait for an input or the worker's frame.
    Wait,
    /// Show the frame and come back at once: the script goes on.
    Redraw,
    Quit,
}

/// The explorer, its worker and its script, as the event loop runs them.
pub struct Live {
    pub explorer: Explorer,
    pub driver: Driver,
    worker: Worker,
    /// Quit once the script is done and this many frames were shown.
    frames: Option<u32>,
    /// Frames rendered so far by a script's `settle`, while it lasts.
    settling: Option<u32>,
    /// A frame was taken (or the turn needed none) and is not yet shown.
    fresh: bool,
    /// Frames shown (in lock-step, one per turn).
    pub shown: u32,
    /// How long each frame took to render.
    pub times: Vec<Duration>,
}

impl Live {
    pub fn new(explorer: Explorer, driver: Driver, worker: Worker, frames: Option<u32>) -> Live {
        Live {
            explorer,
            driver,
            worker,
            frames,
            settling: None,
            fresh: false,
            shown: 0,
            times: Vec::new(),
        }
    }

    /// Whether the run goes in lock-step: a script to play or frames to count.
    pub fn lock_step(&self) -> bool {
        !self.driver.is_done() || self.settling.is_some() || self.frames.is_some()
    }

    /// A learner's input, taken at once; whether to quit. A learner's run
    /// asks for the new view's frame straight away.
    pub fn input(&mut self, input: Input) -> bool {
        let action = self.explorer.handle(input);
        let quit = act(&mut self.explorer, action, &self.driver.out_dir);
        print_messages(&mut self.explorer);
        if !self.lock_step() {
            self.ask();
        }
        quit
    }

    /// Take the worker's newest frame, if it has one for the view as it is
    /// now; whether it was taken (and the window should show it).
    pub fn frame_ready(&mut self) -> bool {
        let Some(frame) = self.worker.take() else {
            return false;
        };
        if !self.explorer.take(frame) {
            return false;
        }
        self.times.push(self.explorer.stats().frame);
        print_messages(&mut self.explorer);
        if let Some(settled) = &mut self.settling {
            *settled += 1;
        }
        self.fresh = true;
        if !self.lock_step() {
            // Path tracing's next pass, or the GPU's half.
            self.ask();
        }
        true
    }

    /// The window showed a frame.
    pub fn presented(&mut self) {
        if std::mem::take(&mut self.fresh) || !self.lock_step() {
            self.shown += 1;
        }
    }

    /// The window had nothing to show the frame on (minimised).
    pub fn skipped(&mut self) {
        self.fresh = false;
    }

    /// Between events: play the script one turn on, and ask for the next
    /// frame if one is wanted.
    pub fn turn(&mut self) -> Result<Turn, ExploreError> {
        if !self.lock_step() {
            self.ask();
            return Ok(Turn::Wait);
        }
        if self.explorer.is_waiting() {
            return Ok(Turn::Wait);
        }
        if self.fresh {
            // Show this turn's frame before the script goes on.
            return Ok(Turn::Redraw);
        }
        if let Some(settled) = self.settling
            && (!self.explorer.wants_frame() || settled >= SETTLE_LIMIT)
        {
            self.settling = None;
        }
        if self.settling.is_none() {
            if self.driver.is_done() && self.frames.is_some_and(|n| self.shown >= n) {
                return Ok(Turn::Quit);
            }
            if !self.driver.is_done() {
                match self.driver.tick(&mut self.explorer)? {
                    Tick::Quit => return Ok(Turn::Quit),
                    Tick::Settle => {
                        self.explorer.hold_still();
                        self.settling = Some(0);
                    }
                    Tick::Busy | Tick::Done => {}
                }
                print_messages(&mut self.explorer);
            }
        }
        if self.ask() {
            Ok(Turn::Wait)
        } else {
            // Nothing to render: the frame as it is is this turn's.
            self.fresh = true;
            Ok(Turn::Redraw)
        }
    }

    /// Send the worker the next job, if the view needs one; whether it did.
    fn ask(&mut self) -> bool {
        if !self.explorer.needs_job() {
            return false;
        }
        match self.explorer.job() {
            Some(job) => {
                self.worker.send(job);
                true
            }
            None => {
                print_messages(&mut self.explorer);
                false
            }
        }
    }
}
