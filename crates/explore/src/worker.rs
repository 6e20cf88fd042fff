//! The render worker: a thread that owns the renderer, so that the
//! window's event loop never waits for a frame. A GPU frame on a CPU's
//! Vulkan driver takes seconds, a path-traced pass at a large size a good
//! part of one; keys and the mouse are answered all the while.
//!
//! The event loop [`Worker::send`]s jobs and [`Worker::take`]s frames.
//! Only the latest job matters: one waiting when another is sent is
//! dropped unrendered, and the explorer drops a finished frame whose
//! view has changed since ([`crate::state::Explorer::take`]).

use std::sync::{Arc, Condvar, Mutex, MutexGuard, PoisonError};
use std::thread;

use crate::error::ExploreError;
use crate::render::{Frame, Job, Render};

/// What the two threads share.
#[derive(Default)]
struct Slots {
    /// The job to render next; a newer one replaces it.
    job: Option<Job>,
    /// The newest finished frame; a newer one replaces it.
    frame: Option<Frame>,
    /// The event loop is gone: the worker ends after its current job.
    closed: bool,
}

struct Shared {
    slots: Mutex<Slots>,
    wake: Condvar,
}

impl Shared {
    fn lock(&self) -> MutexGuard<'_, Slots> {
        // A renderer that panicked leaves nothing half-written in the
        // slots (each is replaced whole), so they stay usable.
        self.slots.lock().unwrap_or_else(PoisonError::into_inner)
    }
}

/// The event loop's end of the worker.
pub struct Worker {
    shared: Arc<Shared>,
}

impl Worker {
    /// Start a worker rendering with `renderer`; `ready` is called on the
    /// worker's thread after each frame (the window wakes its event loop).
    pub fn spawn(
        mut renderer: impl Render + Send + 'static,
        ready: impl Fn() + Send + 'static,
    ) -> Result<Worker, ExploreError> {
        let shared = Arc::new(Shared {
            slots: Mutex::new(Slots::default()),
            wake: Condvar::new(),
        });
        let theirs = Arc::clone(&shared);
        thread::Builder::new()
            .name("raylab-explore render".into())
            .spawn(move || {
                while let Some(job) = next_job(&theirs) {
                    let frame = renderer.render(job);
                    theirs.lock().frame = Some(frame);
                    ready();
                }
            })
            .map_err(ExploreError::Thread)?;
        Ok(Worker { shared })
    }

    /// Ask for a frame; a job still waiting is dropped for this one.
    pub fn send(&self, job: Job) {
        self.shared.lock().job = Some(job);
        self.shared.wake.notify_one();
    }

    /// The newest finished frame, if one has come since the last call.
    pub fn take(&self) -> Option<Frame> {
        self.shared.lock().frame.take()
    }
}

impl Drop for Worker {
    fn drop(&mut self) {
        self.shared.lock().closed = true;
        self.shared.wake.notify_one();
    }
}

/// Wait for the next job; `None` once the event loop is gone.
fn next_job(shared: &Shared) -> Option<Job> {
    let mut slots = shared.lock();
    loop {
        if slots.closed {
            return None;
        }
        if let Some(job) = slots.job.take() {
            return Some(job);
        }
        slots = shared
            .wake
            .wait(slots)
            .unwrap_or_else(PoisonError::into_inner);
    }
}
